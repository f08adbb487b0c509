"""Garbage into every kge.box2d entry point: a kge error or TypeError/ValueError at the
call, never a crash, never a NaN pose, and the world keeps stepping."""

from __future__ import annotations

import contextlib
import math
import random
from collections.abc import Callable
from typing import Any

import kge.box2d as b2
from kge.errors import KgeError

BAD: list[Any] = [float("nan"), float("inf"), -1e300, 1e300, None, "x", (1,), (1, 2, 3),
                  object(), -1, 0, [], {}, True]


def _scene() -> tuple[b2.b2World, b2.b2Body, b2.b2Body, b2.b2Joint]:
    world = b2.b2World(gravity=(0, -10))
    world.CreateStaticBody(shapes=b2.b2EdgeShape(vertices=[(-20, 0), (20, 0)]))
    body = world.CreateDynamicBody(position=(0, 2))
    body.CreatePolygonFixture(box=(0.5, 0.5), density=1)
    other = world.CreateDynamicBody(position=(2, 2))
    other.CreateCircleFixture(radius=0.5, density=1)
    joint = world.CreateRevoluteJoint(bodyA=body, bodyB=other, anchor=(1, 2),
                                      enableMotor=True, maxMotorTorque=10)
    return world, body, other, joint


def _calls(world: b2.b2World, body: b2.b2Body, joint: b2.b2Joint
           ) -> list[Callable[[Any], object]]:
    fixture = body.fixtures[0]
    return [
        lambda v: setattr(body, "position", v),
        lambda v: setattr(body, "angle", v),
        lambda v: setattr(body, "linearVelocity", v),
        lambda v: setattr(body, "angularVelocity", v),
        lambda v: setattr(body, "type", v),
        lambda v: setattr(body, "mass", v),
        lambda v: setattr(body, "linearDamping", v),
        lambda v: body.ApplyForce(v, (0, 0), True),
        lambda v: body.ApplyForceToCenter(v, True),
        lambda v: body.ApplyTorque(v, True),
        lambda v: body.ApplyLinearImpulse(v, body.worldCenter, True),
        lambda v: body.ApplyAngularImpulse(v, True),
        lambda v: body.GetWorldPoint(v),
        lambda v: body.CreatePolygonFixture(box=v, density=1),
        lambda v: body.CreateCircleFixture(radius=v, density=1),
        lambda v: body.CreatePolygonFixture(vertices=v),
        lambda v: body.CreateEdgeFixture(vertices=[(0, 0), v]),
        lambda v: setattr(fixture, "density", v),
        lambda v: setattr(fixture, "friction", v),
        lambda v: setattr(fixture, "restitution", v),
        lambda v: setattr(fixture, "filterData", v),
        lambda v: setattr(joint, "motorSpeed", v),
        lambda v: setattr(joint, "maxMotorTorque", v),
        lambda v: joint.SetLimits(v, 0.5),
        lambda v: setattr(world, "gravity", v),
        lambda v: world.Step(v, 8, 3),
        lambda v: world.Step(1 / 60, v, 3),
        lambda v: world.CreateDynamicBody(position=v),
        lambda v: world.CreateJoint(v),
        lambda v: world.DestroyBody(v),
        lambda v: world.RayCast(v, (0, 0), (1, 1)),
        lambda v: world.QueryAABB(v, b2.b2AABB()),
        lambda v: b2.b2Vec2(v),
        lambda v: b2.b2Transform() * v,
    ]


def test_garbage_never_crashes_or_makes_nan() -> None:
    rng = random.Random(17)
    world, body, other, joint = _scene()
    calls = _calls(world, body, joint)
    for _ in range(400):
        call, value = rng.choice(calls), rng.choice(BAD)
        with contextlib.suppress(KgeError, TypeError, ValueError):  # refused at the call
            call(value)
        world.Step(1 / 60, 8, 3)
        for b in world.bodies:
            assert all(math.isfinite(c) for c in (*b.position, b.angle)), b
    assert body in world.bodies and other in world.bodies
