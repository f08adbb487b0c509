"""WheelJoint = GrooveJoint (axis) + DampedSpring (suspension) + SimpleMotor (drive).

The groove runs ±1e4 m along ``local_axis_a`` through A's anchor, so the wheel
keeps to the axis line and turns freely. The suspension spring hangs from a
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
from kge.physics.joints.base import Composite
from kge.physics.joints.mechanics import point_mass
from kge.physics.joints.prismatic import UNLIMITED

#: how far up the axis the spring hangs from, m
SPRING_ARM = 100.0


class Wheel(Composite):
    def __init__(self, ctx: JointContext, entity: int, j: WheelJoint) -> None:
        super().__init__(ctx, entity, j)
        self.local_anchors(j)
        self.groove = self.spring = self.motor = None
        self.freq = self.zeta = 0.0
        if not self.active:
            return
        self.groove = pymunk.GrooveJoint(self.a, self.b, (0, 0), (1, 0), j.local_anchor_b)
        self.spring = pymunk.DampedSpring(
            self.a, self.b, (0, 0), j.local_anchor_b, SPRING_ARM, 0.0, 0.0
        )
        self.motor = pymunk.SimpleMotor(self.a, self.b, 0.0)
        self.add(self.groove)
        self.add(self.spring, self.motor, enabled=False)
        self.configure(j)

    def configure(self, j: Any) -> None:
        assert self.groove is not None and self.spring is not None and self.motor is not None
        la = pymunk.Vec2d(*j.local_anchor_a)
        self.axis = pymunk.Vec2d(*j.local_axis_a)
        self.la, self.lb = la, pymunk.Vec2d(*j.local_anchor_b)
        self.groove.groove_a = la - self.axis * UNLIMITED
        self.groove.groove_b = la + self.axis * UNLIMITED
        self.groove.anchor_b = self.lb
        self.spring.anchor_a = la + self.axis * SPRING_ARM
        self.spring.anchor_b = self.lb
        self.freq, self.zeta = j.frequency_hz, j.damping_ratio
        self.enable(self.spring, self.freq > 0)
        if self.freq > 0:
            self.tune()
        self.motor.rate = -j.motor_speed
        self.motor.max_force = j.max_motor_torque
        self.enable(self.motor, j.enable_motor)

    def tune(self) -> None:
        assert self.spring is not None
        pa, pb = self.world_anchors(self.la, self.lb)
        u = self.axis.rotated(self.a.angle)
        k = point_mass(self.a, pa, u) + point_mass(self.b, pb, u)
        m_eff = 1.0 / k if k > 0 else 0.0
        omega = 2.0 * math.pi * self.freq
        self.spring.stiffness = m_eff * omega * omega
        self.spring.damping = 2.0 * m_eff * self.zeta * omega

    def before_step(self, dt: float) -> None:
        super().before_step(dt)
        if self.active and self.freq > 0:
            self.tune()

    def read_live(self, j: Any, dt: float) -> None:
        pa, pb = self.world_anchors(self.la, self.lb)
        u = self.axis.rotated(self.a.angle)
        raw_set(j, "translation", float((pb - pa).dot(u)))
        raw_set(j, "speed", float(self.b.angular_velocity - self.a.angular_velocity))
        raw_set(j, "motor_torque", self.impulse_force(self.motor))
        perp = self.impulse_force(self.groove)
        along = 0.0
        if self.spring is not None and self.freq > 0:
            top = self.a.local_to_world(self.spring.anchor_a)
            along = self.spring.stiffness * abs(abs(pb - top) - SPRING_ARM)
        self.write_reaction(j, dt, math.hypot(perp, along), 0.0)


def build(ctx: JointContext, entity: int, j: Any) -> Wheel:
    return Wheel(ctx, entity, j)


register(WheelJoint, build)
