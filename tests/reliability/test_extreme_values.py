"""Extreme finite values: refused at the write, or simulated without NaN, inf or errors.

kge's promise: no finite input produces NaN, inf or an exception in a later step.
Positions and anchors are bounded (``kge.validate.MAX_COORDINATE``, 1e7 m), spring
frequencies too (1e6 Hz), settings' skins and per-step caps; everything else
(velocities to 1e307, gravity, forces, motor speeds and torques to 1e300) is
accepted and kept finite by the overflow-safe speed cap. The sweep sets every
float field of every joint to extreme values and steps on.
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from collections.abc import Callable
from typing import Any

import pytest

from kge import (
    Box,
    Collider,
    DistanceJoint,
    FrictionJoint,
    MotorJoint,
    MouseJoint,
    PrismaticJoint,
    PulleyJoint,
    RevoluteJoint,
    RigidBody,
    RopeJoint,
    Transform,
    WeldJoint,
    WheelJoint,
)
from kge.errors import KgeError

from .harness import PhysicsWorld, check_invariants

JOINTS: dict[str, Callable[[int, int], Any]] = {
    "revolute": lambda a, b: RevoluteJoint(
        a, b, anchor=(1.0, 0.5), enable_motor=True, max_motor_torque=10.0, enable_limit=True,
        lower_angle=-1.0, upper_angle=1.0),
    "prismatic": lambda a, b: PrismaticJoint(
        a, b, anchor=(1.0, 0.5), local_axis_a=(1.0, 0.0), enable_motor=True,
        max_motor_force=10.0, enable_limit=True, lower_translation=-1.0, upper_translation=1.0),
    "distance": lambda a, b: DistanceJoint(a, b, frequency_hz=2.0, damping_ratio=0.5),
    "weld": lambda a, b: WeldJoint(a, b, anchor=(1.0, 0.5), frequency_hz=2.0, damping_ratio=0.5),
    "wheel": lambda a, b: WheelJoint(
        a, b, anchor=(2.0, 0.5), local_axis_a=(0.0, 1.0), enable_motor=True, max_motor_torque=10.0),
    "rope": lambda a, b: RopeJoint(a, b, max_length=3.0),
    "pulley": lambda a, b: PulleyJoint(
        a, b, ground_anchor_a=(0.0, 3.0), ground_anchor_b=(2.0, 3.0), anchor_a=(0.0, 0.5),
        anchor_b=(2.0, 0.5)),
    "friction": lambda a, b: FrictionJoint(a, b, anchor=(1.0, 0.5), max_force=10.0, max_torque=10.0),
    "motor": lambda a, b: MotorJoint(a, b, max_force=10.0, max_torque=10.0),
    "mouse": lambda a, b: MouseJoint(None, b, target=(2.0, 1.0), max_force=100.0),
}


def _scene(joint: str | None = None) -> tuple[PhysicsWorld, int, int, int | None]:
    pw = PhysicsWorld()
    w = pw.world
    w.spawn(Transform(0.0, -1.0), Collider(Box(10.0, 1.0)))
    a = w.spawn(Transform(0.0, 0.5), RigidBody(), Collider(Box(0.5, 0.5), contact_hooks=True))
    b = w.spawn(Transform(2.0, 0.5), RigidBody(), Collider(Box(0.5, 0.5)))
    j = None if joint is None else w.spawn(JOINTS[joint](a, b))
    pw.step()
    return pw, a, b, j


def _steps_stay_finite(pw: PhysicsWorld, n: int) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # numpy overflow warnings count as failures
        for _ in range(n):
            pw.step()
            check_invariants(pw)  # no NaN / inf in any Transform, velocity or pymunk body


ACCEPTED: dict[str, Callable[[PhysicsWorld, int, int], Any]] = {
    "velocity 1e307": lambda pw, a, b: setattr(pw.world.get(a, RigidBody), "velocity",
                                               (1e307, -1e307)),
    "angular velocity 1e307": lambda pw, a, b: setattr(pw.world.get(a, RigidBody),
                                                       "angular_velocity", -1e307),
    "gravity 1e300": lambda pw, a, b: setattr(pw.physics.settings, "gravity", (1e300, -1e300)),
    "gravity scale 1e300": lambda pw, a, b: setattr(pw.world.get(a, RigidBody),
                                                    "gravity_scale", 1e300),
    "force 1e300": lambda pw, a, b: pw.physics.apply_force(a, (1e300, 1e300)),
    "torque 1e300": lambda pw, a, b: pw.physics.apply_torque(b, -1e300),
    "impulse 1e300": lambda pw, a, b: pw.physics.apply_linear_impulse(a, (1e300, 0.0)),
    "damping 1e300": lambda pw, a, b: setattr(pw.world.get(a, RigidBody), "linear_damping", 1e300),
    "pre-solve restitution 1e300": lambda pw, a, b: pw.physics.on_pre_solve(
        lambda c: setattr(c, "restitution", 1e300)),
    "pre-solve tangent speed 1e300": lambda pw, a, b: pw.physics.on_pre_solve(
        lambda c: setattr(c, "tangent_speed", -1e300)),
    "pre-solve friction 1e300": lambda pw, a, b: pw.physics.on_pre_solve(
        lambda c: setattr(c, "friction", 1e300)),
}


@pytest.mark.parametrize("name", sorted(ACCEPTED))
def test_huge_but_accepted_values_keep_every_step_finite(name: str) -> None:
    pw, a, b, _ = _scene()
    ACCEPTED[name](pw, a, b)
    _steps_stay_finite(pw, 30)
    pw.close()


@pytest.mark.parametrize("joint", sorted(JOINTS))
def test_every_joint_field_at_extreme_values_is_refused_or_stays_finite(joint: str) -> None:
    pw, a, b, j = _scene(joint)
    assert j is not None
    comp = pw.world.get(j, type(JOINTS[joint](a, b)))
    names = [f.name for f in dataclasses.fields(comp)
             if f.name in type(comp)._checks and f.name not in ("body_a", "body_b", "user_data")]
    pw.close()
    refused = accepted = 0
    for name in [*names, "teleport"]:
        for value in (1e300, -1e160, 1e8):
            pw, a, b, j = _scene(joint)
            assert j is not None
            comp = pw.world.get(j, type(comp))
            try:
                if name == "teleport":
                    pw.world.get(b, Transform).x = value
                else:
                    current = getattr(comp, name)
                    if isinstance(current, bool):
                        pw.close()
                        continue
                    pair = isinstance(current, tuple) or "anchor" in name or name in (
                        "target", "grab_point", "linear_offset")
                    setattr(comp, name, (value, value) if pair else value)
            except KgeError:
                refused += 1
            else:
                accepted += 1
                _steps_stay_finite(pw, 15)
            pw.close()
    assert refused and accepted


def test_the_speed_cap_keeps_the_direction_of_a_velocity_near_the_float_limit() -> None:
    pw, a, _, _ = _scene()
    pw.physics.settings.gravity = (0.0, 0.0)
    pw.world.get(a, RigidBody).velocity = (1e307, 1e307)
    pw.step()
    vx, vy = pw.world.get(a, RigidBody).velocity
    assert math.isclose(vx, vy) and math.isclose(math.hypot(vx, vy), 120.0, rel_tol=1e-6)
    pw.close()
