"""WheelJoint = a point-on-line row (axis) + DampedSpring (suspension) + SimpleMotor (drive).

:class:`~kge.physics.joints.line.Line` keeps the wheel's anchor on the line
along ``local_axis_a`` through A's anchor (a scalar row with a position pass,
as in Box2D; pymunk's ``GrooveJoint`` flings light bodies, see there), and the
wheel turns freely. The suspension spring hangs from a
point 100 m up the axis on body A to the wheel's anchor with rest length 100 m,
which makes its line of action the axis itself (to within the tiny angle the
wheel's travel subtends). Its constants come from the effective mass along the
axis (``k = m_eff·ω²``, ``c = 2·m_eff·ζ·ω``), so the static sag is ``g/ω²``
whatever the masses, as in Box2D. The motor drives ``w_b - w_a`` to
``motor_speed`` (pymunk's rate is its negative).
"""

from __future__ import annotations

import math
from typing import Any

import pymunk

from kge.components.joints import WheelJoint
from kge.components.tracked import raw_set
from kge.physics.joint_api import JointContext, register
from kge.physics.joints.base import PROJECTED_ERROR_BIAS, Composite
from kge.physics.joints.line import Line
from kge.physics.joints.mechanics import point_mass
from kge.physics.joints.positions import MAX_CORRECTION
from kge.physics.joints.rows import motor_speed

#: how far up the axis the spring hangs from, m
SPRING_ARM = 100.0


class Wheel(Composite):
    def __init__(self, ctx: JointContext, entity: int, j: WheelJoint) -> None:
        super().__init__(ctx, entity, j)
        self.local_anchors(j)
        self.axis = pymunk.Vec2d(*j.local_axis_a)
        self.line = Line(self.a, self.b)
        self.line.place(j.local_anchor_a, self.axis, j.local_anchor_b)
        self.spring: pymunk.DampedSpring | None = None
        self.motor: pymunk.SimpleMotor | None = None
        self.freq = self.zeta = 0.0
        if not self.active:
            return
        self.spring = pymunk.DampedSpring(
            self.a, self.b, (0, 0), j.local_anchor_b, SPRING_ARM, 0.0, 0.0
        )
        self.motor = pymunk.SimpleMotor(self.a, self.b, 0.0)
        self.add(self.line.make_pin(), error_bias=PROJECTED_ERROR_BIAS)
        self.add(self.spring, self.motor, enabled=False)
        self.configure(j)

    def configure(self, j: Any) -> None:
        assert self.spring is not None and self.motor is not None
        la = pymunk.Vec2d(*j.local_anchor_a)
        self.axis = pymunk.Vec2d(*j.local_axis_a)
        self.line.place(la, self.axis, j.local_anchor_b)
        self.spring.anchor_a = la + self.axis * SPRING_ARM
        self.spring.anchor_b = j.local_anchor_b
        self.freq, self.zeta = j.frequency_hz, j.damping_ratio
        self.enable(self.spring, self.freq > 0)
        if self.freq > 0:
            self.tune()
        self.motor.rate = -motor_speed(j.motor_speed)
        self.motor.max_force = j.max_motor_torque
        self.enable(self.motor, j.enable_motor)

    def tune(self) -> None:
        assert self.spring is not None
        pa, pb = self.world_anchors(self.line.anchor_a, self.line.anchor_b)
        u = self.axis.rotated(self.a.angle)
        k = point_mass(self.a, pa, u) + point_mass(self.b, pb, u)
        m_eff = 1.0 / k if k > 0 else 0.0
        omega = self.spring_omega(self.freq)
        self.spring.stiffness = m_eff * omega * omega
        self.spring.damping = 2.0 * m_eff * self.zeta * omega

    def before_step(self, dt: float) -> None:
        super().before_step(dt)
        if self.active and self.freq > 0:
            self.tune()

    def project(self) -> None:
        """Box2D's position pass: the wheel's anchor back onto the axis line."""
        if self.is_on(self.line.pin):
            self.jolt(self.line.project(), MAX_CORRECTION)

    def read_live(self, j: Any, dt: float) -> None:
        translation = self.line.translation()
        self.line.follow(translation)
        raw_set(j, "translation", translation)
        raw_set(j, "speed", float(self.b.angular_velocity - self.a.angular_velocity))
        raw_set(j, "motor_torque", self.impulse_force(self.motor))
        perp = self.impulse_force(self.line.pin)
        along = 0.0
        if self.spring is not None and self.freq > 0:
            top = self.a.local_to_world(self.spring.anchor_a)
            pb = self.b.local_to_world(self.line.anchor_b)
            along = self.spring.stiffness * abs(abs(pb - top) - SPRING_ARM)
        self.write_reaction(j, dt, math.hypot(perp, along), 0.0)


def build(ctx: JointContext, entity: int, j: Any) -> Wheel:
    return Wheel(ctx, entity, j)


register(WheelJoint, build)
