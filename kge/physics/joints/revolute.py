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

import math
from typing import Any

import pymunk

from kge.components.joints import RevoluteJoint
from kge.components.tracked import raw_set
from kge.physics.cp import body_handle, constraint_handle, lib
from kge.physics.joint_api import JointContext, register
from kge.physics.joints.base import (
    PROJECTED_ERROR_BIAS,
    RIGID_ERROR_BIAS,
    Composite,
    in_space,
)
from kge.physics.joints.positions import (
    ANGULAR_SLOP,
    ITERATED_PIVOT_TOLERANCE,
    LINEAR_SLOP,
    MAX_ANGULAR_CORRECTION,
    MAX_CORRECTION,
    project_gap,
    project_limit,
)
from kge.physics.joints.rows import Row, hinge_rows, motor_and_limits, motor_speed

_get_angle = lib.cpBodyGetAngle
_get_angular_velocity = lib.cpBodyGetAngularVelocity
_get_impulse = lib.cpConstraintGetImpulse
_local_to_world = lib.cpBodyLocalToWorld

#: iterated hinges with no push (``PhysicsSettings.hinge_limit_push`` 0): the limit's
#: ``error_bias``, so close to 1 that pymunk adds no push-back speed (about 1e-9
#: rad/s per radian of overshoot): the limit only stops the hinge, as Box2D's
#: velocity solver does. Not exactly 1: pymunk's RotaryLimitJoint takes a zero bias
#: for "within the limits" and does nothing at all.
ITERATED_LIMIT_ERROR_BIAS = 1.0 - 1e-9


class Revolute(Composite):
    def __init__(self, ctx: JointContext, entity: int, j: RevoluteJoint) -> None:
        super().__init__(ctx, entity, j)
        self.local_anchors(j)
        self.ref = self.reference_angle(j)
        self.la, self.lb = j.local_anchor_a, j.local_anchor_b
        self.settings = j
        self.motor_impulse = self.limit_impulse = 0.0
        self.h = ctx.dt
        self.ctx = ctx
        #: pymunk's own motor and limit, when ``PhysicsSettings.iterated_hinges`` is on
        self.motor: pymunk.SimpleMotor | None = None
        self.limit: pymunk.RotaryLimitJoint | None = None
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
        iterated = j.enable_motor and self.ctx.iterated_hinges
        if iterated:
            if self.motor is None:
                self.motor = pymunk.SimpleMotor(self.a, self.b, 0.0)
                self.add(self.motor, enabled=False)
            self.motor.rate = -motor_speed(j.motor_speed)  # Chipmunk drives w_b - w_a to -rate
            self.motor.max_force = j.max_motor_torque
        if self.motor is not None:
            self.enable(self.motor, iterated)
        limited = j.enable_limit and self.ctx.iterated_hinges
        if limited:
            if self.limit is None:
                self.limit = pymunk.RotaryLimitJoint(self.a, self.b, 0.0, 0.0)
                self.add(self.limit, enabled=False)
            self.push_back(self.limit, self.ctx.hinge_limit_push)
            self.limit.min = j.lower_angle + self.ref
            self.limit.max = j.upper_angle + self.ref
        if self.limit is not None:
            self.enable(self.limit, limited)
        self.run_substeps(
            (j.enable_motor and not iterated) or (j.enable_limit and not limited))
        if not j.enable_motor:
            self.motor_impulse = 0.0
        if not j.enable_limit:
            self.limit_impulse = 0.0

    @staticmethod
    def push_back(limit: pymunk.RotaryLimitJoint, speed: float) -> None:
        """How fast pymunk pushes an overshooting hinge back: at most ``speed`` rad/s
        (its usual bias, capped), or, for 0, not at all (see ``hinge_limit_push``)."""
        if speed > 0.0:
            limit.error_bias, limit.max_bias = RIGID_ERROR_BIAS, speed
        else:
            limit.error_bias, limit.max_bias = ITERATED_LIMIT_ERROR_BIAS, math.inf

    def solve(self, h: float) -> None:
        j = self.settings
        if not (j.enable_motor or j.enable_limit):
            return
        pa, pb = self.world_anchors(self.la, self.lb)
        rows = hinge_rows(self.a, self.b, pa, pb)
        iterated = self.ctx.iterated_hinges
        motor = (j.motor_speed, j.max_motor_torque) if j.enable_motor and not iterated else None
        lo, hi = (j.lower_angle, j.upper_angle) if j.enable_limit and not iterated else (None, None)
        impulse, self.limit_impulse = motor_and_limits(
            self.space, rows, self.coordinate(), h, motor, lo, hi, MAX_ANGULAR_CORRECTION
        )
        if not iterated:
            self.motor_impulse = impulse
        self.h = h

    # -- joint coordinate, for gears ---------------------------------------------------
    def coordinate(self) -> float:
        return float(self.b.angle - self.a.angle - self.ref)

    def rows(self, scale: float) -> list[Row]:
        """d(angle)/dt = w_b - w_a."""
        return [(self.b, 0.0, 0.0, scale), (self.a, 0.0, 0.0, -scale)]

    def project(self) -> bool:
        """Box2D's position pass: the limit (8° per step at most), then the point.

        Returns Box2D's verdict: the pivot gap within b2_linearSlop and the limit
        within b2_angularSlop (measured before this pass's correction).
        """
        pivot = self.pivot
        if pivot is None:
            return True
        j = self.settings
        iterated = self.ctx.iterated_hinges
        ca, cb = body_handle(self.a), body_handle(self.b)
        angular = 0.0
        if j.enable_limit:
            # iterated hinges leave Box2D's b2_angularSlop alone, as its position pass
            # does: a motor holding a leg on its limit must not move (and so wake) it
            slop = ANGULAR_SLOP if iterated else 0.0
            angle = _get_angle(cb) - _get_angle(ca) - self.ref
            lo, hi = j.lower_angle - slop, j.upper_angle + slop
            if angle < lo or angle > hi:
                angular = max(j.lower_angle - angle, angle - j.upper_angle)
                project_limit(self.rows(1.0), angle, lo, hi, MAX_ANGULAR_CORRECTION)
        pa, pb = _local_to_world(ca, self.la), _local_to_world(cb, self.lb)
        pax, pay, pbx, pby = pa.x, pa.y, pb.x, pb.y
        # iterated hinges: a gap this small is left alone: moving a body wakes it
        # (pymunk), and a motor holding a load leaves such a gap at every step
        if iterated and math.hypot(pbx - pax, pby - pay) < ITERATED_PIVOT_TOLERANCE:
            return angular <= ANGULAR_SLOP
        gap = project_gap(self.a, self.b, pax, pay, pbx, pby)
        self.jolt(gap, MAX_CORRECTION)
        return gap <= LINEAR_SLOP and angular <= ANGULAR_SLOP

    def _impulse(self, c: pymunk.Constraint | None) -> float:
        """pymunk's last impulse of ``c``; 0 while it is switched off (as when neither
        body can turn: ``track_rotation``), whatever it held before."""
        if c is None or not in_space(self.space, c):
            return 0.0
        return float(_get_impulse(constraint_handle(c)))

    def read_live(self, j: Any, dt: float) -> None:
        ca, cb = body_handle(self.a), body_handle(self.b)
        raw_set(j, "angle", float(_get_angle(cb) - _get_angle(ca) - self.ref))
        raw_set(j, "speed", float(_get_angular_velocity(cb) - _get_angular_velocity(ca)))
        h = self.h
        if self.ctx.iterated_hinges:
            # pymunk's impulse is the last substep's (so over the substep's time);
            # Box2D's sign (torque on body b)
            h = self.step_time()
            self.motor_impulse = -self._impulse(self.motor) if j.enable_motor else 0.0
            self.limit_impulse = -self._impulse(self.limit) if j.enable_limit else 0.0
        raw_set(j, "motor_torque", self.motor_impulse / h)
        self.write_reaction(j, dt, self.impulse_force(self.pivot), 0.0)
        torque = self.limit_impulse / h
        self._torque = abs(torque)
        raw_set(j, "reaction_torque", torque)


def build(ctx: JointContext, entity: int, j: Any) -> Revolute:
    return Revolute(ctx, entity, j)


register(RevoluteJoint, build)
