"""The editing session that made the platformer's levels, as a script.

``kge edit examples/levels/level1.scene.toml --game examples/platformer.py`` is how they
are made and changed by hand: add the terrain map, place the player, coins and door,
save. This script drives the same editor model (``kge.editor.EditorModel``, what the
window's tools call) so the files can be rebuilt from scratch, and checked by a test:
``python examples/platformer_levels.py`` writes ``examples/levels/``.
"""

from __future__ import annotations

from pathlib import Path

import kge_required  # noqa: F401  (first: names the Python to use when kge is missing)

from kge import App, Behaviour, Bloom, Box, Camera, CharacterBody, Circle, Collider, Transform, draw
from kge.editor import EditorModel
from kge.testbed.samples.tilemaps import LEVEL_SPECS, write_terrain

LEVELS = Path(__file__).resolve().parent / "levels"
ROWS = 15  # the maps are 15 tiles (metres) high; the ground's top is 3 m up


def build(number: int, folder: Path = LEVELS) -> Path:
    """Write ``level{number}.scene.toml`` (and the terrain maps) into ``folder``."""
    from platformer import JUMP_SPEED, Player

    write_terrain(folder)
    path = folder / f"level{number}.scene.toml"
    path.unlink(missing_ok=True)
    cols, _, ledges, _ = LEVEL_SPECS[number - 1]
    model = EditorModel(App(lambda w: None, headless=True).world, path)
    model.add_map(folder / f"terrain{number}.tmx")
    ground = float(ROWS - 12)
    player = model.create(Transform(3.5, ground + 1.0),
                          CharacterBody(Box(0.4, 0.45), jump_speed=JUMP_SPEED),
                          draw.Rect(0.8, 0.9, color=(220, 60, 60, 255), layer=1),
                          Behaviour(Player()), name="player")
    model.create(Camera(pixels_per_meter=40.0, follow=player,
                        bounds=(0.0, 0.0, float(cols), float(ROWS)),
                        post=(Bloom(threshold=0.75, intensity=1.3, radius=10.0),)),
                 name="camera")
    for row, a, b in ledges:
        for c in range(a, b, 2):
            model.create(Transform(c + 0.5, ROWS - row + 0.5),
                         Collider(Circle(0.3), sensor=True),
                         draw.Circle(0.3, color=(250, 220, 40, 255)), name="coin")
    model.create(Transform(cols - 2.5, ground + 1.0), Collider(Box(0.5, 1.0), sensor=True),
                 draw.Rect(1.0, 2.0, color=(70, 40, 20, 255)), name="door")
    return model.save()


if __name__ == "__main__":
    for n in (1, 2):
        print(build(n))
