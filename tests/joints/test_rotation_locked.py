"""Rotation-only constraints between two bodies that cannot rotate must not make NaN.

Found by the long fuzz run: a prismatic joint (its rotation lock is a pymunk
GearJoint) between the ground and a massless dynamic body (1 kg, no rotational
inertia, as in Box2D) turned the body's pose into NaN at the next step.
"""

from __future__ import annotations

import math

import pytest

from kge import App, Box, Collider, PrismaticJoint, RevoluteJoint, RigidBody, Transform, World
from kge.components.joints import Joint, WeldJoint


def _finite(t: Transform) -> bool:
    return all(map(math.isfinite, (t.x, t.y, t.angle)))


@pytest.mark.parametrize("make_body", ["massless", "fixed_rotation"])
@pytest.mark.parametrize("joint", ["prismatic", "revolute_limit_motor", "weld"])
def test_joint_to_the_ground_of_a_body_that_cannot_rotate(make_body: str, joint: str) -> None:
    ids: dict[str, int] = {}

    def scene(world: World) -> None:
        world.spawn(Transform(0, -1), Collider(Box(10, 1)))
        rb = RigidBody(fixed_rotation=make_body == "fixed_rotation")
        density = 0.0 if make_body == "massless" else 1.0
        body = world.spawn(Transform(0, 2), rb, Collider(Box(0.5, 0.5), density=density))
        ids["body"] = body
        j: Joint
        if joint == "prismatic":
            j = PrismaticJoint(body, None, anchor=(0, 2), local_axis_a=(1, 0),
                               enable_limit=True, lower_translation=-1, upper_translation=1)
        elif joint == "weld":
            j = WeldJoint(None, body, anchor=(0, 2))
        else:
            j = RevoluteJoint(None, body, anchor=(0, 2), enable_limit=True, lower_angle=-0.5,
                              upper_angle=0.5, enable_motor=True, motor_speed=1.0,
                              max_motor_torque=10.0)
        ids["joint"] = world.spawn(j)

    app = App(scene, headless=True)
    app.step(30)
    body = app.world.get(ids["body"], Transform)
    assert _finite(body), body
    rb = app.world.get(ids["body"], RigidBody)
    # the body can still turn rotation back on; the constraints come back with it
    rb.fixed_rotation = False
    app.world.get(ids["body"], Collider).density = 1.0
    app.step(30)
    assert _finite(app.world.get(ids["body"], Transform))
    app.close()
