"""The physics side of the joint contract: build, apply, read back, break, destroy."""

from __future__ import annotations

import math

import pytest

from kge.components.collider import Collider
from kge.components.joints import DistanceJoint, RevoluteJoint
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Circle
from kge.components.transform import Transform

from .conftest import Sim


def test_pendulum_is_built_after_its_body_and_reads_back(sim: Sim) -> None:
    bob = sim.dynamic(Circle(0.1), 2.0, 10.0, density=10.0)
    j = sim.spawn(RevoluteJoint(None, bob, anchor=(0.0, 10.0)))
    sim.step(30)
    t = sim.t(bob)
    assert math.hypot(t.x, t.y - 10.0) == pytest.approx(2.0, abs=0.01)
    joint = sim.world.get(j, RevoluteJoint)
    assert joint.angle != 0.0 and joint.speed != 0.0


def test_joint_waits_for_a_body_spawned_later(sim: Sim) -> None:
    a = sim.dynamic(Circle(0.2), 0.0, 5.0)
    b = sim.dynamic(Circle(0.2), 1.0, 5.0)
    sim.spawn(DistanceJoint(a, b))
    sim.step(60)
    ta, tb = sim.t(a), sim.t(b)
    assert math.hypot(tb.x - ta.x, tb.y - ta.y) == pytest.approx(1.0, abs=0.02)


def test_component_change_is_applied(zero_g: Sim) -> None:
    hub = zero_g.spawn(Transform(), Collider(Circle(0.1)))
    wheel = zero_g.dynamic(Circle(1.0), 0.0, 0.0)
    j = zero_g.spawn(RevoluteJoint(hub, wheel, anchor=(0.0, 0.0), enable_motor=True,
                                   motor_speed=0.0, max_motor_torque=100.0))
    zero_g.step(5)
    zero_g.world.get(j, RevoluteJoint).motor_speed = 2.0
    zero_g.step(30)
    assert zero_g.rb(wheel).angular_velocity == pytest.approx(2.0, abs=0.01)


def test_breakable_joint_breaks_once(sim: Sim) -> None:
    box = sim.dynamic(Box(0.5, 0.5), 0.0, 5.0, density=2.0)  # 2 kg: reaction 20 N
    j = sim.spawn(RevoluteJoint(None, box, anchor=(0.0, 5.5), break_force=5.0))
    broken = []
    for _ in range(10):
        sim.step()
        broken += sim.events.joint_broken
    assert [b.joint for b in broken] == [j]
    assert math.hypot(*broken[0].reaction_force) > 5.0
    assert not sim.world.exists(j)
    assert sim.events.joint_destroyed == []
    assert sim.t(box).y < 5.0


def test_disabled_body_takes_its_joint_out(sim: Sim) -> None:
    a = sim.dynamic(Circle(0.2), 0.0, 5.0, body=RigidBody(gravity_scale=0.0))
    b = sim.dynamic(Circle(0.2), 1.0, 5.0)
    sim.spawn(DistanceJoint(a, b))
    sim.step(2)
    space = sim.system.sim.space
    assert len(space.constraints) >= 1
    sim.rb(a).enabled = False
    sim.step(2)
    assert len(space.constraints) == 0
    sim.rb(a).enabled = True
    sim.step(2)
    assert len(space.constraints) >= 1


def test_type_changes_of_jointed_bodies_are_safe(sim: Sim) -> None:
    from kge.components.rigidbody import BodyType

    sim.ground()
    a = sim.dynamic(Box(0.5, 0.5), 0.0, 0.515, body=RigidBody(awake=False))
    b = sim.dynamic(Box(0.5, 0.5), 0.0, 1.53)
    sim.spawn(RevoluteJoint(a, b, anchor=(0.0, 1.0)))
    sim.step(30)
    space = sim.system.sim.space
    for kind in (BodyType.STATIC, BodyType.KINEMATIC, BodyType.DYNAMIC, BodyType.STATIC):
        sim.rb(a).type = kind
        sim.step(2)
        assert len(space.constraints) >= 1  # b is dynamic: the joint acts
    sim.rb(b).type = BodyType.KINEMATIC
    sim.step(2)
    assert len(space.constraints) == 0  # two non-dynamic bodies: joint idle, as in Box2D
    sim.rb(b).type = BodyType.DYNAMIC
    sim.step(2)
    assert len(space.constraints) >= 1
