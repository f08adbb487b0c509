"""How far a restored world drifts from the one it was saved from (figures for the docs).

A snapshot holds every component, so poses, velocities, sleep state and joint
settings come back exactly; pymunk's contact cache (accumulated impulses used to
warm-start the solver) and joints' accumulated impulses cannot be exported, so a
restored scene re-solves its contacts from zero. :func:`divergence` runs a scene,
saves it at step ``at``, continues it for ``after`` steps, restores the save in a
second App, runs the same number of steps and returns the largest position and
angle difference over all dynamic bodies.

Run it for the table in docs/reliability.md::

    .venv/bin/python -m tests.reliability.snapshot_divergence
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from kge import App, Box, Circle, Collider, RevoluteJoint, RigidBody, Transform, World
from kge.testbed.samples.stacking import pyramid


def free_fall(world: World) -> None:
    """Twenty bodies in the air, spinning and drifting, none touching (no contacts)."""
    for i in range(20):
        shape = Circle(0.3) if i % 2 else Box(0.3, 0.2)
        world.spawn(
            Transform(-10.0 + 1.0 * i, 50.0 + 0.5 * i, 0.1 * i),
            RigidBody(velocity=(0.3 * i - 3.0, 2.0), angular_velocity=0.2 * i - 2.0),
            Collider(shape, density=1.0 + 0.1 * i),
        )


def pendulum_chain(world: World) -> None:
    """A hanging chain of 10 links (joints, no contacts)."""
    prev = None
    for i in range(10):
        link = world.spawn(Transform(0.5 + i, 20.0), RigidBody(), Collider(Box(0.5, 0.1)))
        world.spawn(RevoluteJoint(prev, link, anchor=(float(i), 20.0)))
        prev = link


def tall_stack(world: World) -> None:
    """Twenty 1 m boxes stacked on the ground, sleeping off: an awake, loaded stack."""
    from kge import PhysicsSettings

    world.insert_resource(PhysicsSettings(sleep=False))
    world.spawn(Transform(0.0, -1.0), Collider(Box(10.0, 1.0)))
    for i in range(20):
        world.spawn(Transform(0.0, 0.5 + 1.0 * i), RigidBody(), Collider(Box(0.5, 0.5)))


def poses(app: App) -> dict[int, tuple[float, float, float]]:
    return {e: (t.x, t.y, t.angle) for e, (t, _) in app.world.query(Transform, RigidBody)}


def divergence(scene: Callable[..., Any], at: int, after: int, **kwargs: Any) -> dict[str, float]:
    """Max |position| (m) and |angle| (rad) difference ``after`` steps past a restore."""
    original = App(scene, headless=True, **kwargs)
    original.step(at)
    saved = original.world.snapshot()
    original.step(after)
    restored = App(scene, headless=True, **kwargs)
    restored.restore(saved)
    restored.step(after)
    a, b = poses(original), poses(restored)
    assert a.keys() == b.keys()
    dpos = max(math.dist(a[e][:2], b[e][:2]) for e in a)
    dang = max(abs(a[e][2] - b[e][2]) for e in a)
    original.close()
    restored.close()
    return {"position": dpos, "angle": dang}


SCENES: list[tuple[str, Callable[..., Any], int, int]] = [
    ("free fall, 20 bodies, no contacts", free_fall, 30, 120),
    ("pendulum chain, 10 revolute joints", pendulum_chain, 30, 120),
    ("pyramid of 55 boxes, saved while settling (step 30)", pyramid, 30, 120),
    ("pyramid of 55 boxes, saved at rest, awake (step 60)", pyramid, 60, 120),
    ("pyramid of 55 boxes, saved asleep (step 400)", pyramid, 400, 120),
    ("tall stack of 20 boxes, sleep off, saved at step 120", tall_stack, 120, 120),
    ("tall stack of 20 boxes, sleep off, saved at step 120, 600 steps", tall_stack, 120, 600),
]


if __name__ == "__main__":
    print("| scene | saved at step | steps after | max position diff (m) | max angle diff (rad) |")
    print("|---|---|---|---|---|")
    for name, scene, at, after in SCENES:
        d = divergence(scene, at, after)
        print(f"| {name} | {at} | {after} | {d['position']:.3g} | {d['angle']:.3g} |")
