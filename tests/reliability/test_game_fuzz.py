"""A fuzz of random game-layer operations: field writes of hostile and ordinary values,
tweens, bursts, spawns and despawns, with frames in between.

Every operation either works or raises a :class:`~kge.errors.KgeError` that leaves the
world exactly as it was (no other exception type, no half-applied write); after every
frame each pose, camera, particle row and tween row is finite. Seeded, so a failure
replays: the message carries the seed and the operations so far.
"""

from __future__ import annotations

import dataclasses
import math
import random
import shutil
from typing import Any

import pytest

import kge
from kge.components.tracked import Tracked
from kge.errors import KgeError

from .game_catalogue import Game, _finite_state, build_game
from .harness import state_dump

NUMBERS: tuple[Any, ...] = (
    0, 1, -1, 0.5, 2.0, 255, 256, -0.0, 1e-300, 1e6, -1e6, 1e9, 1e300, -1e300, 1e308,
    -1e308, math.inf, -math.inf, math.nan, 2**31, 2**63, 10**400, True,
)  # fmt: skip
OTHERS: tuple[Any, ...] = (None, "", "x", "sheet.png", "missing.png", b"\x00", [], {}, (1,))


def _value(rng: random.Random) -> Any:
    kind = rng.random()
    if kind < 0.55:
        return rng.choice(NUMBERS)
    if kind < 0.85:
        return tuple(rng.choice(NUMBERS) for _ in range(rng.choice((2, 2, 3, 4))))
    return rng.choice(OTHERS)


def _components(world: kge.World) -> list[tuple[int, Tracked]]:
    return [
        (e, c) for e in sorted(world.entities()) for c in world.components(e)
        if isinstance(c, Tracked) and type(c)._checks
    ]  # fmt: skip


def _operation(rng: random.Random, game: Game) -> str:
    """Python source of one random operation on ``game``'s world."""
    world = game.app.world
    roll = rng.random()
    if roll < 0.7:
        comps = _components(world)
        entity, comp = rng.choice(comps)
        field = rng.choice(sorted(type(comp)._checks))
        return f"world.get({entity}, {type(comp).__name__}).{field} = {_value(rng)!r}"
    if roll < 0.8:
        entity = rng.choice([*sorted(world.entities()), 999])
        target = _value(rng)
        return f"tweens.to({entity}, Transform, 'x', {target!r}, {rng.choice(NUMBERS)!r})"
    if roll < 0.9:
        emitter = rng.choice([*sorted(world.entities()), 999, -1])
        return f"world.emit(ParticleBurst({emitter}, {rng.choice(NUMBERS)!r}))"
    pose = ", ".join(repr(rng.choice(NUMBERS)) for _ in range(3))
    return rng.choice((
        f"world.spawn(Transform({pose}), ParticleEmitter(rate={rng.choice(NUMBERS)!r}))",
        f"world.spawn(Transform({pose}), draw.Circle({rng.choice(NUMBERS)!r}))",
        f"world.spawn(UINode(offset={_value(rng)!r}), Label({_value(rng)!r}))",
    ))  # fmt: skip


def _names(game: Game) -> dict[str, Any]:
    ns = dict(game.ns)
    ns.update({t.__name__: t for t in (kge.Transform, kge.ParticleBurst)})
    for comp_type in {type(c) for _, c in _components(game.app.world)}:
        ns.setdefault(comp_type.__name__, comp_type)
    return ns


@pytest.mark.parametrize("seed", range(4))
def test_random_game_layer_operations_never_corrupt_the_world(seed: int) -> None:
    rng = random.Random(seed)
    game = build_game()
    done: list[str] = []
    try:
        world = game.app.world
        ns = _names(game)
        for i in range(150):
            op = _operation(rng, game)
            done.append(op)
            before = state_dump(world)
            try:
                exec(op, ns)
            except KgeError:
                assert state_dump(world) == before, f"seed {seed}: {op} changed the world"
            except Exception as exc:  # anything else is a bug: replay with the seed
                raise AssertionError(
                    f"seed {seed}, operation {i}: {op} raised {type(exc).__name__}: {exc}\n"
                    + "\n".join(done[-10:])
                ) from exc
            if i % 5 == 4:
                game.app.step()
                _finite_state(world)
        assert any(dataclasses.is_dataclass(c) for _, c in _components(world))
    finally:
        game.app.close()
        shutil.rmtree(game.root, ignore_errors=True)
