"""Falling hinges: the scene Box2D uses to check that a simulation is deterministic.

Four columns of thirty small boxes, each pair of boxes hinged by a revolute
joint with an angle limit, start tilted and fall onto the ground in a heap.
Every box touches many others, joints hit their limits, bodies fall asleep:
nearly every code path of the solver runs, so any dependence on memory
addresses, hash seeds or set ordering would change the result.

:func:`pose_hash` condenses every dynamic pose into one SHA-256, and
:func:`falling_hinges_hash` runs the scene headless and returns it, so two runs
(in one process, or in separate ones with different ``PYTHONHASHSEED``) can be
compared, and the tests pin the value for the supported platform.

>>> len(falling_hinges_hash(steps=1, columns=1, rows=2))
64
"""

from __future__ import annotations

import hashlib
import math
import struct

from kge.components import Name, Transform
from kge.components.collider import Collider
from kge.components.joints import RevoluteJoint
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box
from kge.testbed.registry import sample
from kge.world import World

#: half size of a box (Box2D: h = 0.25)
H = 0.25
#: limits of every hinge, radians (Box2D: -0.1 pi .. 0.2 pi)
LOWER, UPPER = -0.1 * math.pi, 0.2 * math.pi


@sample(
    "Determinism",
    "Falling Hinges",
    help="4 x 30 boxes hinged in pairs with limited revolute joints fall in a heap "
    "(Box2D's determinism test); the pose hash after 500 steps is pinned by the tests.",
)
def falling_hinges(world: World, columns: int = 4, rows: int = 30) -> None:
    world.spawn(Transform(0.0, -1.0), Collider(Box(20.0, 1.0), friction=0.6), Name("ground"))
    offset = 0.4 * H
    dx = 10.0 * H
    x_root = -0.5 * dx * (columns - 1.0)
    for j in range(columns):
        x = x_root + j * dx
        prev: int | None = None
        for i in range(rows):
            body = world.spawn(
                Transform(x + offset * i, H + 2.0 * H * i, 0.1 * i - 1.0),
                RigidBody(),
                Collider(Box(H, H), density=1.0, friction=0.6),
                Name("hinge box"),
            )
            if i % 2 == 0:
                prev = body
            else:
                world.spawn(
                    RevoluteJoint(
                        prev, body, local_anchor_a=(H, H), local_anchor_b=(offset, -H),
                        enable_limit=True, lower_angle=LOWER, upper_angle=UPPER,
                    )
                )
                prev = None


@falling_hinges.claim
def _heap_rests_on_the_ground(app) -> None:  # type: ignore[no-untyped-def]
    world = app.world
    ys = [t.y for _, (t, _rb) in world.query(Transform, RigidBody)]
    assert len(ys) == 120 and min(ys) > 0.0, f"a box is below the ground (min y {min(ys):.3f})"
    for _, (j,) in world.query(RevoluteJoint):
        assert LOWER - 0.1 < j.angle < UPPER + 0.1, f"a hinge left its limits: {j.angle:.3f}"


def pose_hash(world: World) -> str:
    """SHA-256 of every dynamic body's (x, y, angle) as float64 bytes, in entity order."""
    h = hashlib.sha256()
    for e, (t, _rb) in sorted(world.query(Transform, RigidBody), key=lambda item: item[0]):
        h.update(struct.pack("<q3d", e, t.x, t.y, t.angle))
    return h.hexdigest()


def falling_hinges_hash(steps: int = 500, columns: int = 4, rows: int = 30) -> str:
    """Run the scene headless for ``steps`` fixed steps and return :func:`pose_hash`."""
    from kge.app import App

    app = App(falling_hinges, headless=True, columns=columns, rows=rows)
    try:
        app.step(steps)
        return pose_hash(app.world)
    finally:
        app.close()


if __name__ == "__main__":
    print(falling_hinges_hash())
