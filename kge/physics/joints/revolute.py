"""RevoluteJoint = pymunk PivotJoint + a custom motor and limit on the hinge angle.

The point is pymunk's ``PivotJoint``, solved in pymunk's iterations. The motor
and the limit are not pymunk's ``SimpleMotor`` / ``RotaryLimitJoint``: those
act on each body's own moment of inertia, which for a bob hung 2 m from its
pivot is 800x too small, so they converge poorly (a brake slips, a limit throws
the bob back). Instead they are solved once per substep on
:func:`~kge.physics.joints.rows.hinge_rows`, the hinge angle's Jacobian with
the pivot folded in (Box2D's block solve), before pymunk's iterations:

* motor: drives ``speed`` to ``motor_speed`` with an impulse capped at
  ``max_motor_torque·h``;
* limit: speculative one-sided bounds at ``lower_angle`` / ``upper_angle``.

Joint angle = ``θb - θa - reference_angle``; ``speed = ωb - ωa`` (CCW positive).
"""

from __future__ import annotations

from typing import Any

import pymunk

from kge.components.joints import RevoluteJoint
from kge.components.tracked import raw_set
from kge.physics.joint_api import JointContext, register
from kge.physics.joints.base import PROJECTED_ERROR_BIAS, Composite
from kge.physics.joints.positions import (
    MAX_ANGULAR_CORRECTION,
    MAX_CORRECTION,
    project_limit,
    project_point,
)
from kge.physics.joints.rows import Row, hinge_rows, motor_and_limits


class Revolute(Composite):
    def __init__(self, ctx: JointContext, entity: int, j: RevoluteJoint) -> None:
        super().__init__(ctx, entity, j)
        self.local_anchors(j)
        self.ref = self.reference_angle(j)
        self.la, self.lb = j.local_anchor_a, j.local_anchor_b
        self.settings = j
        self.motor_impulse = self.limit_impulse = 0.0
        self.h = ctx.dt
        self.pivot: pymunk.PivotJoint | None = None
        if not self.active:
            return
        self.pivot = pymunk.PivotJoint(self.a, self.b, j.local_anchor_a, j.local_anchor_b)
        self.add(self.pivot, error_bias=PROJECTED_ERROR_BIAS)
        self.every_substep(self.solve)
        self.configure(j)

    def configure(self, j: Any) -> None:
        assert self.pivot is not None
        self.la, self.lb = j.local_anchor_a, j.local_anchor_b
        self.pivot.anchor_a, self.pivot.anchor_b = self.la, self.lb
        self.ref = j.reference_angle
        self.settings = j
        self.run_substeps(j.enable_motor or j.enable_limit)
        if not j.enable_motor:
            self.motor_impulse = 0.0
        if not j.enable_limit:
            self.limit_impulse = 0.0

    def solve(self, h: float) -> None:
        j = self.settings
        if not (j.enable_motor or j.enable_limit):
            return
        pa, pb = self.world_anchors(self.la, self.lb)
        rows = hinge_rows(self.a, self.b, pa, pb)
        motor = (j.motor_speed, j.max_motor_torque) if j.enable_motor else None
        lo, hi = (j.lower_angle, j.upper_angle) if j.enable_limit else (None, None)
        self.motor_impulse, self.limit_impulse = motor_and_limits(
            self.space, rows, self.coordinate(), h, motor, lo, hi, MAX_ANGULAR_CORRECTION
        )
        self.h = h

    # -- joint coordinate, for gears ---------------------------------------------------
    def coordinate(self) -> float:
        return float(self.b.angle - self.a.angle - self.ref)

    def rows(self, scale: float) -> list[Row]:
        """d(angle)/dt = w_b - w_a."""
        return [(self.b, 0.0, 0.0, scale), (self.a, 0.0, 0.0, -scale)]

    def project(self) -> None:
        """Box2D's position pass: the limit (8° per step at most), then the point."""
        if self.pivot is None:
            return
        j = self.settings
        if j.enable_limit:
            project_limit(self.rows(1.0), self.coordinate(), j.lower_angle, j.upper_angle,
                          MAX_ANGULAR_CORRECTION)
        gap = project_point(self.a, self.b, self.pivot.anchor_a, self.pivot.anchor_b)
        self.jolt(gap, MAX_CORRECTION)

    def read_live(self, j: Any, dt: float) -> None:
        raw_set(j, "angle", self.coordinate())
        raw_set(j, "speed", float(self.b.angular_velocity - self.a.angular_velocity))
        raw_set(j, "motor_torque", self.motor_impulse / self.h)
        self.write_reaction(j, dt, self.impulse_force(self.pivot), 0.0)
        torque = self.limit_impulse / self.h
        self._torque = abs(torque)
        raw_set(j, "reaction_torque", torque)


def build(ctx: JointContext, entity: int, j: Any) -> Revolute:
    return Revolute(ctx, entity, j)


register(RevoluteJoint, build)
