"""FrictionJoint, MotorJoint, breaking, and component validation."""

from __future__ import annotations

import math

import pytest

from kge.components.joints import (
    DistanceJoint,
    FrictionJoint,
    GearJoint,
    MotorJoint,
    MouseJoint,
    PrismaticJoint,
    PulleyJoint,
    RevoluteJoint,
    RopeJoint,
    WeldJoint,
    WheelJoint,
)
from kge.errors import ComponentTypeError, ValidationError
from tests.joints.conftest import Sim


def test_friction_joint_stops_sliding_and_spinning() -> None:
    sim = Sim(gravity=(0.0, 0.0))
    box = sim.add_body((0.0, 0.0), box=(0.5, 0.5))  # m = 1, I = 1/6
    sim.bodies[box].velocity = (5.0, 0.0)
    sim.bodies[box].angular_velocity = 5.0
    sim.add_joint(FrictionJoint(None, box, anchor=(0.0, 0.0), max_force=10.0, max_torque=0.5))
    linear_stop = spin_stop = None
    for step in range(1, 150):
        sim.step()
        if linear_stop is None and sim.bodies[box].velocity.length < 1e-6:
            linear_stop = step
        if spin_stop is None and abs(sim.bodies[box].angular_velocity) < 1e-6:
            spin_stop = step
    assert linear_stop == pytest.approx(30, abs=2)  # Box2D step 30
    assert spin_stop == pytest.approx(100, abs=2)  # Box2D step 100 (I·ω/τ = 1.667 s)
    # Box2D 1.2083; pymunk moves before it integrates velocity: one step more (0.083 m)
    assert sim.pos(box).x == pytest.approx(1.2083, abs=0.1)


def test_motor_joint_converges_on_its_offsets() -> None:
    sim = Sim(gravity=(0.0, 0.0))
    box = sim.add_body((0.0, 0.0), box=(0.5, 0.5))
    sim.add_joint(MotorJoint(None, box, linear_offset=(2.0, 1.0), angular_offset=0.5,
                             max_force=50.0, max_torque=20.0, correction_factor=0.3))
    sim.step(30)
    x_half = sim.pos(box).x
    sim.step(150)
    assert abs(sim.pos(box) - (2.0, 1.0)) < 0.01  # converged by 3 s (Box2D by 2 s)
    assert sim.angle(box) == pytest.approx(0.5, abs=0.01)
    assert 1.5 < x_half < 3.0  # Box2D 2.80 at 0.5 s (overshoot allowed)


def test_break_force_reports_exceeding_reaction() -> None:
    sim = Sim()
    box = sim.add_body((0.0, 5.0), box=(0.5, 0.5), density=2.0)  # 20 N hanging
    weak = sim.add_joint(RevoluteJoint(None, box, anchor=(0.0, 5.5), break_force=15.0))
    sim.step(5)
    assert weak in sim.broken
    sim2 = Sim()
    box2 = sim2.add_body((0.0, 5.0), box=(0.5, 0.5), density=2.0)
    strong = sim2.add_joint(RevoluteJoint(None, box2, anchor=(0.0, 5.5), break_force=25.0))
    sim2.step(60)
    assert strong not in sim2.broken


def test_break_torque() -> None:
    sim = Sim()
    beam = sim.add_body((1.0, 5.0), box=(1.0, 0.1))  # m = 0.4, needs 4 N·m at the root
    e = sim.add_joint(WeldJoint(None, beam, anchor=(0.0, 5.0), break_torque=3.0))
    sim.step(5)
    assert e in sim.broken


@pytest.mark.parametrize(
    ("make", "message"),
    [
        (lambda: RevoluteJoint(None, 1, lower_angle=1.0, upper_angle=0.0), "upper_angle must be >="),
        (lambda: RevoluteJoint(None, 1, max_motor_torque=-1.0), "max_motor_torque must be >= 0"),
        (lambda: RevoluteJoint(None, 1, motor_speed=math.nan), "motor_speed must be finite"),
        (lambda: PrismaticJoint(1, 2, lower_translation=2.0, upper_translation=1.0), "upper"),
        (lambda: PrismaticJoint(1, 2, max_motor_force=-5.0), "max_motor_force must be >= 0"),
        (lambda: DistanceJoint(1, 2, frequency_hz=-1.0), "frequency_hz must be >= 0"),
        (lambda: DistanceJoint(1, 2, min_length=3.0, max_length=2.0), "max_length must be >="),
        (lambda: PulleyJoint(1, 2, ratio=0.0), "ratio must be > 0"),
        (lambda: GearJoint(1, 2, ratio=0.0), "ratio must not be 0"),
        (lambda: GearJoint(1, 1), "joint_b must differ"),
        (lambda: MouseJoint(None, 1, max_force=-1.0), "max_force must be >= 0"),
        (lambda: WheelJoint(1, 2, local_axis_a=(0.0, 0.0)), "non-zero direction"),
        (lambda: WeldJoint(1, 2, damping_ratio=-0.1), "damping_ratio must be >= 0"),
        (lambda: RopeJoint(1, 2, max_length=-1.0), "max_length must be >= 0"),
        (lambda: FrictionJoint(1, 2, max_torque=math.inf), "max_torque must be finite"),
        (lambda: MotorJoint(1, 2, correction_factor=2.0), "correction_factor must be in"),
        (lambda: RevoluteJoint(-1, 2), "entity id >= 0"),
        (lambda: RevoluteJoint(None, 1, break_force=-1.0), "break_force must be >= 0"),
    ],
)
def test_bad_values_are_refused_with_the_field_named(make: object, message: str) -> None:
    with pytest.raises(ValidationError, match=message):
        make()  # type: ignore[operator]


def test_wrong_types_are_refused() -> None:
    with pytest.raises(ComponentTypeError, match="body_b must be an entity id"):
        RevoluteJoint(None, "ground")  # type: ignore[arg-type]
    with pytest.raises(ComponentTypeError, match="enable_motor must be True or False"):
        RevoluteJoint(None, 1, enable_motor=1)  # type: ignore[arg-type]


def test_assignment_is_validated_and_leaves_the_value() -> None:
    j = RevoluteJoint(None, 1, lower_angle=-1.0, upper_angle=1.0)
    with pytest.raises(ValidationError):
        j.lower_angle = 2.0
    assert j.lower_angle == -1.0
    j.set_limits(2.0, 3.0)
    assert (j.lower_angle, j.upper_angle) == (2.0, 3.0)
    with pytest.raises(ValidationError):
        j.set_limits(3.0, 2.0)
    assert (j.lower_angle, j.upper_angle) == (2.0, 3.0)
