"""Box2D's position iterations and pybox2d's joint-definition rules on kge.box2d.

Reference values were measured with pybox2d 2.3.10 running the same programs
(``benchmarks/gym_box2d.py`` shows how to load both in one process).
"""

from __future__ import annotations

import math

import pytest

import kge.box2d as b2


def _two_boxes() -> tuple[b2.b2World, b2.b2Body, b2.b2Body]:
    world = b2.b2World(gravity=(0, -10))
    a = world.CreateDynamicBody(position=(0, 5), angle=0.3)
    a.CreatePolygonFixture(box=(0.5, 0.5), density=1)
    b = world.CreateDynamicBody(position=(2, 5), angle=0.5)
    b.CreatePolygonFixture(box=(0.5, 0.5), density=1)
    return world, a, b


def test_defs_built_with_both_bodies_take_the_angle_between_them() -> None:
    _, a, b = _two_boxes()
    # pybox2d 2.3.10: 0.2 for all three; an explicit referenceAngle is kept; bodies
    # assigned after construction leave Box2D's default 0
    for cls in (b2.b2RevoluteJointDef, b2.b2WeldJointDef, b2.b2PrismaticJointDef):
        assert cls(bodyA=a, bodyB=b).referenceAngle == pytest.approx(0.2)
        assert cls(bodyA=a, bodyB=b, referenceAngle=0.1).referenceAngle == 0.1
        late = cls()
        late.bodyA, late.bodyB = a, b
        assert late.referenceAngle == 0.0


def test_position_iterations_close_a_joint_built_apart_in_one_step() -> None:
    def gap_after(position_iterations: int) -> tuple[float, float]:
        world, a, b = _two_boxes()
        joint = world.CreateJoint(b2.b2RevoluteJointDef(
            bodyA=a, bodyB=b, localAnchorA=(1, 0), localAnchorB=(-0.5, 0)))
        before = (joint.anchorB - joint.anchorA).length
        world.Step(1 / 50, 180, position_iterations)
        return before, (joint.anchorB - joint.anchorA).length

    before, after = gap_after(60)
    assert before == pytest.approx(0.8084, abs=1e-3)  # pybox2d: 0.8084
    assert after < 0.005  # pybox2d: 1e-7 (b2_linearSlop is 0.005)
    # one position pass moves at most b2_maxLinearCorrection (kge keeps that bound)
    _, one = gap_after(1)
    assert one == pytest.approx(before - 0.2, abs=0.01)


def test_motorised_hinges_iterate_too() -> None:
    world, a, b = _two_boxes()
    joint = world.CreateJoint(b2.b2RevoluteJointDef(
        bodyA=a, bodyB=b, localAnchorA=(1, 0), localAnchorB=(-0.5, 0),
        enableMotor=True, maxMotorTorque=10.0, motorSpeed=0.5,
        enableLimit=True, lowerAngle=-1.0, upperAngle=1.0))
    world.Step(1 / 50, 180, 60)
    assert (joint.anchorB - joint.anchorA).length < 0.005


def test_contacts_hold_while_the_joint_pulls() -> None:
    """A hinge to a static body pulls a leg standing on the ground 0.32 m down.

    Box2D's position iterations alternate contacts and joints: the leg cannot go
    through the ground, so it tips over until the joint closes (pybox2d: angle
    -0.91, y 0.393, gap 0). A joint pass alone would push it 0.3 m into the ground.
    """
    world = b2.b2World(gravity=(0, -10))
    world.CreateStaticBody(shapes=b2.b2EdgeShape(vertices=[(-10, 0), (10, 0)]))
    leg = world.CreateDynamicBody(position=(0, 0.5))
    leg.CreatePolygonFixture(box=(0.1, 0.5), density=1, friction=0.5)
    hip = world.CreateStaticBody(position=(0.05, 1.6))
    for _ in range(10):
        world.Step(1 / 50, 180, 60)
    joint = world.CreateJoint(b2.b2RevoluteJointDef(
        bodyA=hip, bodyB=leg, localAnchorA=(0, -0.9), localAnchorB=(0, 0.5)))
    assert (joint.anchorB - joint.anchorA).length > 0.3
    world.Step(1 / 50, 180, 60)
    assert (joint.anchorB - joint.anchorA).length < 0.005
    assert leg.angle < -0.6  # tipped over (pybox2d -0.91)
    shape = leg.fixtures[0].shape
    assert isinstance(shape, b2.b2PolygonShape)
    lowest = min(leg.GetWorldPoint(v).y for v in shape.vertices)
    assert lowest > -0.05  # not pushed through the ground
    assert math.isfinite(leg.position.y) and leg.position.y > 0.3  # pybox2d 0.393
