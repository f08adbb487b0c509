"""Games: Lantern Woods, kge's showcase game (``examples/lantern.py``), in the testbed.

The game lives beside the package in a source checkout (``examples/``), with its
generated assets; an installed kge without the examples simply has no "Games"
category. The testbed runs the game's level without its menus: arrows (or A/D) run,
space jumps, a gamepad works too.
"""

from __future__ import annotations

import importlib
import sys
from pathlib import Path
from types import ModuleType

from kge.testbed.registry import sample
from kge.world import World

EXAMPLES = Path(__file__).resolve().parents[3] / "examples"


def lantern() -> ModuleType:
    """The example module (``examples/`` joins ``sys.path`` the first time)."""
    if str(EXAMPLES) not in sys.path:
        sys.path.append(str(EXAMPLES))
    return importlib.import_module("lantern")


if (EXAMPLES / "lantern.py").exists():

    @sample(
        "Games",
        "Lantern Woods",
        help="The showcase game: a Tiled level with parallax, an animated fox, night lights "
        "with shadows, particles, sound. Arrows/A-D run, space jumps (hold: higher).",
        keys={"arrows / A D": "run", "space": "jump"},
    )
    def lantern_woods(world: World) -> None:
        lantern().level(world, menus=False)

    @lantern_woods.claim
    def _the_fox_stands_on_the_ground_in_the_woods(app: object) -> None:
        from kge.components import Transform

        game = lantern()
        world = app.world  # type: ignore[attr-defined]
        fox = next(e for e, (b,) in world.query(game.Behaviour) if isinstance(b.script, game.Fox))
        t = world.get(fox, Transform)
        assert 4.0 < t.y < 5.0, f"the fox should stand on the floor (y ~4.4), is at {t.y:.2f}"
