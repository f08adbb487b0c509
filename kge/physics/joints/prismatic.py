"""PrismaticJoint = GrooveJoint + GearJoint (no rotation) + a custom motor and limit.

The groove lies on body A along ``local_axis_a`` (±1e4 m); B's anchor slides
in it. A ``GearJoint`` with ratio 1 and phase = reference angle stops relative
rotation. Both are solved in pymunk's iterations.

pymunk has no linear motor, and its groove ends overshoot a limit by several
centimetres, so the motor and the limit are custom, solved once per substep
from the carrier's ``pre_solve`` on the translation's Jacobian (which includes
body A's rotation of the axis, so a slider on a moving body is right) with the
groove and the rotation lock folded in (:func:`~kge.physics.joints.base.fold`):

* motor: ``|impulse| ≤ max_motor_force·h`` towards ``motor_speed``;
* limit: speculative one-sided bounds, so the slider stops at the bound.
"""

from __future__ import annotations

from typing import Any

import pymunk

from kge.components.joints import PrismaticJoint
from kge.components.tracked import raw_set
from kge.physics.joint_api import JointContext, register
from kge.physics.joints.base import Composite
from kge.physics.joints.mechanics import cog_world, cross
from kge.physics.joints.rows import Row, fold, motor_and_limits, spin_rows

#: groove half-length for an unlimited slider, m
UNLIMITED = 1e4


class Prismatic(Composite):
    def __init__(self, ctx: JointContext, entity: int, j: PrismaticJoint) -> None:
        super().__init__(ctx, entity, j)
        self.local_anchors(j)
        self.ref = self.reference_angle(j)
        self.la = pymunk.Vec2d(*j.local_anchor_a)
        self.lb = pymunk.Vec2d(*j.local_anchor_b)
        self.axis = pymunk.Vec2d(*j.local_axis_a)
        self.settings = j
        self.motor_impulse = self.limit_impulse = 0.0
        self.motor_h = ctx.dt
        self.groove = self.lock = None
        if not self.active:
            return
        self.groove = pymunk.GrooveJoint(self.a, self.b, (0, 0), (1, 0), j.local_anchor_b)
        self.lock = pymunk.GearJoint(self.a, self.b, self.ref, 1.0)
        self.add(self.groove, self.lock)
        self.every_substep(self.drive)
        self.configure(j)

    def configure(self, j: Any) -> None:
        assert self.groove is not None and self.lock is not None
        self.la = pymunk.Vec2d(*j.local_anchor_a)
        self.lb = pymunk.Vec2d(*j.local_anchor_b)
        self.axis = pymunk.Vec2d(*j.local_axis_a)
        self.ref = j.reference_angle
        self.groove.groove_a = self.la - self.axis * UNLIMITED
        self.groove.groove_b = self.la + self.axis * UNLIMITED
        self.groove.anchor_b = self.lb
        self.lock.phase = self.ref
        self.settings = j
        self.run_substeps(j.enable_motor or j.enable_limit)
        if not j.enable_motor:
            self.motor_impulse = 0.0
        if not j.enable_limit:
            self.limit_impulse = 0.0

    # -- joint coordinate, for the motor and gears ---------------------------------------
    def coordinate(self) -> float:
        pa, pb = self.world_anchors(self.la, self.lb)
        return float((pb - pa).dot(self.axis.rotated(self.a.angle)))

    def rows(self, scale: float, axis: pymunk.Vec2d | None = None) -> list[Row]:
        """d(translation)/dt, with body A's rotation of the axis included.

        With ``axis`` (a unit vector in A's frame) the rate along that axis instead:
        the perpendicular one is the groove's constraint.
        """
        pa, pb = self.world_anchors(self.la, self.lb)
        u = (self.axis if axis is None else axis).rotated(self.a.angle)
        d = pb - pa
        rb = pb - cog_world(self.b)
        ra = pa - cog_world(self.a)
        return [
            (self.b, scale * u.x, scale * u.y, scale * cross(rb.x, rb.y, u.x, u.y)),
            (self.a, -scale * u.x, -scale * u.y, -scale * cross(ra.x + d.x, ra.y + d.y, u.x, u.y)),
        ]

    def drive(self, h: float) -> None:
        j = self.settings
        if not (j.enable_motor or j.enable_limit):
            return
        keep = [self.rows(1.0, self.axis.perpendicular()), spin_rows(self.a, self.b)]
        rows = fold(self.rows(1.0), keep)
        motor = (j.motor_speed, j.max_motor_force) if j.enable_motor else None
        lo, hi = (j.lower_translation, j.upper_translation) if j.enable_limit else (None, None)
        self.motor_impulse, self.limit_impulse = motor_and_limits(
            self.space, rows, self.coordinate(), h, motor, lo, hi
        )
        self.motor_h = h

    def speed(self) -> float:
        return sum(
            jx * body.velocity.x + jy * body.velocity.y + jw * body.angular_velocity
            for body, jx, jy, jw in self.rows(1.0)
        )

    def read_live(self, j: Any, dt: float) -> None:
        raw_set(j, "translation", self.coordinate())
        raw_set(j, "speed", float(self.speed()))
        raw_set(j, "motor_force", self.motor_impulse / self.motor_h)
        # the groove's push is perpendicular to the axis (its sign from B's momentum
        # balance); the motor and the limit push along it, with known signs
        u = self.axis.rotated(self.a.angle)
        n = u.perpendicular()
        bx, by, _ = self.balance(dt)
        perp = self.impulse_force(self.groove)
        if bx * n.x + by * n.y < 0:
            perp = -perp
        along = (self.motor_impulse + self.limit_impulse) / self.motor_h
        self.write_reaction(j, dt, 0.0, self.impulse_force(self.lock))
        self._force = abs(complex(perp, along))
        raw_set(j, "reaction_force", (perp * n.x + along * u.x, perp * n.y + along * u.y))


def build(ctx: JointContext, entity: int, j: Any) -> Prismatic:
    return Prismatic(ctx, entity, j)


register(PrismaticJoint, build)
