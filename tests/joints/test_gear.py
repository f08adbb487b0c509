"""GearJoint: ratios and signs of box2d-reference.md's gear row, plus moving bases."""

from __future__ import annotations

import pytest

from kge.components.joints import GearJoint, PrismaticJoint, RevoluteJoint
from tests.joints.conftest import Sim


def driven_disc(sim: Sim, base: int | None, at: tuple[float, float]) -> tuple[int, RevoluteJoint]:
    disc = sim.add_body(at, circle=1.0)
    j = RevoluteJoint(base, disc, anchor=at, enable_motor=True, motor_speed=2.0,
                      max_motor_torque=1000.0)
    return disc, j


def test_revolute_revolute_ratio_two() -> None:
    sim = Sim(gravity=(0.0, 0.0))
    d1, j1 = driven_disc(sim, None, (0.0, 0.0))
    d2 = sim.add_body((3.0, 0.0), circle=2.0)
    j2 = RevoluteJoint(None, d2, anchor=(3.0, 0.0))
    e1, e2 = sim.add_joint(j1), sim.add_joint(j2)
    g = GearJoint(e1, e2, ratio=2.0)
    sim.add_joint(g)
    assert (g.body_a, g.body_b) == (d1, d2)  # Box2D: joint1.bodyB, joint2.bodyB
    sim.step(60)
    assert j2.speed == pytest.approx(-1.0, rel=0.01)  # Box2D -1.0 = -ω1/ratio
    assert j1.angle + 2.0 * j2.angle == pytest.approx(0.0, abs=0.01)


@pytest.mark.parametrize(("ratio", "speed"), [(-1.0, 2.0), (1.0, -2.0), (0.5, -4.0)])
def test_revolute_prismatic_rack_and_pinion(ratio: float, speed: float) -> None:
    sim = Sim(gravity=(0.0, 0.0))
    _, j1 = driven_disc(sim, None, (0.0, 0.0))
    rack = sim.add_body((0.0, -1.5), box=(2.0, 0.25))
    j2 = PrismaticJoint(None, rack, anchor=(0.0, -1.5), local_axis_a=(1.0, 0.0))
    e1, e2 = sim.add_joint(j1), sim.add_joint(j2)
    sim.add_joint(GearJoint(e1, e2, ratio=ratio))
    sim.step(60)
    assert j2.speed == pytest.approx(speed, rel=0.01)  # Box2D +2.0 (ratio -1), -4.0 (0.5)
    assert j1.angle + ratio * j2.translation == pytest.approx(0.0, abs=0.01)


def test_prismatic_prismatic() -> None:
    sim = Sim(gravity=(0.0, 0.0))
    s1 = sim.add_body((0.0, 0.0), box=(0.5, 0.5))
    s2 = sim.add_body((0.0, 3.0), box=(0.5, 0.5))
    j1 = PrismaticJoint(None, s1, anchor=(0.0, 0.0), enable_motor=True, motor_speed=1.0,
                        max_motor_force=1000.0)
    j2 = PrismaticJoint(None, s2, anchor=(0.0, 3.0), local_axis_a=(0.0, 1.0))
    e1, e2 = sim.add_joint(j1), sim.add_joint(j2)
    sim.add_joint(GearJoint(e1, e2, ratio=2.0))
    sim.step(60)
    assert j2.speed == pytest.approx(-0.5, rel=0.01)
    assert j1.translation + 2.0 * j2.translation == pytest.approx(0.0, abs=0.01)


def test_gear_on_a_spinning_chassis_uses_joint_coordinates() -> None:
    """Both discs sit on a free chassis that turns: pymunk's absolute-angle gear
    would give the second disc -1.5 rad/s relative to the chassis; Box2D and kge -1."""
    sim = Sim(gravity=(0.0, 0.0))
    chassis = sim.add_body((0.0, 0.0), box=(3.0, 0.5), density=5.0)
    sim.bodies[chassis].angular_velocity = 1.0
    _d1, j1 = driven_disc(sim, chassis, (-1.5, 0.0))
    d2 = sim.add_body((1.5, 0.0), circle=0.5)
    j2 = RevoluteJoint(chassis, d2, anchor=(1.5, 0.0))
    e1, e2 = sim.add_joint(j1), sim.add_joint(j2)
    sim.add_joint(GearJoint(e1, e2, ratio=2.0))
    sim.step(120)
    assert j1.speed == pytest.approx(2.0, rel=0.01)
    assert j2.speed == pytest.approx(-1.0, rel=0.01)
    assert j1.angle + 2.0 * j2.angle == pytest.approx(0.0, abs=0.02)
    assert abs(sim.bodies[chassis].angular_velocity) > 0.1  # the chassis really turns


def test_gear_waits_for_joints_built_later() -> None:
    from kge.physics.joint_api import BUILDERS

    sim = Sim(gravity=(0.0, 0.0))
    d1 = sim.add_body((0.0, 0.0), circle=1.0)
    d2 = sim.add_body((3.0, 0.0), circle=2.0)
    # the two joints will be entities 3 and 4; the gear (99) is built before them
    g = GearJoint(3, 4, ratio=2.0)
    sim.joints[99] = g
    sim.handles[99] = BUILDERS[GearJoint](sim, 99, g)
    assert sim.handles[99].depends_on == (3, 4)
    sim.step()  # nothing to couple yet
    j1 = RevoluteJoint(None, d1, enable_motor=True, motor_speed=2.0, max_motor_torque=1000.0)
    j2 = RevoluteJoint(None, d2)
    assert (sim.add_joint(j1), sim.add_joint(j2)) == (3, 4)
    sim.step(60)
    assert (g.body_a, g.body_b) == (d1, d2)
    assert j2.speed == pytest.approx(-1.0, rel=0.01)


def test_gear_on_a_non_hinge_joint_waits_inert() -> None:
    """The world refuses such a gear at spawn (the bad-input catalogue); a joint
    replaced by another kind afterwards must not make the step raise."""
    from kge.components.joints import RopeJoint

    sim = Sim()
    b1 = sim.add_body((0.0, 0.0), circle=0.5)
    b2 = sim.add_body((2.0, 0.0), circle=0.5)
    e1 = sim.add_joint(RopeJoint(None, b1, max_length=1.0))
    e2 = sim.add_joint(RevoluteJoint(None, b2))
    g = GearJoint(e1, e2)
    e = sim.add_joint(g)
    sim.step(5)
    assert sim.handles[e].constraints == []
    assert g.body_a is None and g.body_b is None
