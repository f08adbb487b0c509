"""PrismaticJoint = a point-on-line row + GearJoint (no rotation) + a custom motor and limit.

B's anchor is kept on the line through A's anchor along ``local_axis_a`` by
:class:`~kge.physics.joints.line.Line` (a scalar row, as in Box2D; pymunk's
``GrooveJoint`` flings light bodies, see there). A ``GearJoint`` with ratio 1
and phase = reference angle stops relative rotation. Both are solved in
pymunk's iterations without velocity bias; their drift is removed by a
position pass after the step, as Box2D does.

pymunk has no linear motor, and a groove's ends would overshoot a limit by
several centimetres, so the motor and the limit are custom, solved once per
substep from the carrier's ``pre_solve`` on the translation's Jacobian (which
includes body A's rotation of the axis, so a slider on a moving body is right)
with the line and the rotation lock folded in
(:func:`~kge.physics.joints.rows.fold`):

* motor: ``|impulse| ≤ max_motor_force·h`` towards ``motor_speed``;
* limit: speculative one-sided bounds, so the slider stops at the bound.

With ``PhysicsSettings.iterated_hinges`` (kge.box2d) the limit is solved inside
pymunk's iterations instead, with the contacts, as Box2D solves it: a limit
applied once per substep is undone on body A by A's own contacts (a slider
hanging on its lower bound from a body lying on the ground kept 2 cm/s of
downward speed that the position pass turned back every step, so it never slept;
pybox2d's collision_filtering example). The limit is a pymunk ``SlideJoint``
from a point ``LIMIT_REACH`` back along the axis on A to B's anchor: its length
is ``LIMIT_REACH + translation`` (B stays on the line), its Jacobian the
translation's. Like Box2D's, it only stops the slider (no push back); the
position pass leaves ``b2_linearSlop`` past the bound, so the limit stays
engaged at rest.
"""

from __future__ import annotations

from typing import Any

import pymunk

from kge.components.joints import PrismaticJoint
from kge.components.tracked import raw_set
from kge.physics.joint_api import JointContext, register
from kge.physics.joints.base import PROJECTED_ERROR_BIAS, Composite
from kge.physics.joints.line import Line
from kge.physics.joints.positions import (
    LINEAR_SLOP,
    MAX_ANGULAR_CORRECTION,
    MAX_CORRECTION,
    SETTLED,
    project_limit,
    project_rows,
)
from kge.physics.joints.rows import Row, fold, motor_and_limits, spin_rows

#: iterated limits: how far back along the axis (on body A) the limit's slide joint
#: is anchored, m; over one step's travel (2 m at most) B's anchor departs from the
#: axis by far less than the line pin lets it, so the joint's length is the
#: translation to within 1e-10 m
LIMIT_REACH = 1e4


class Prismatic(Composite):
    def __init__(self, ctx: JointContext, entity: int, j: PrismaticJoint) -> None:
        super().__init__(ctx, entity, j)
        self.local_anchors(j)
        self.ref = self.reference_angle(j)
        self.axis = pymunk.Vec2d(*j.local_axis_a)
        self.line = Line(self.a, self.b)
        self.line.place(j.local_anchor_a, self.axis, j.local_anchor_b)
        self.settings = j
        self.motor_impulse = self.limit_impulse = 0.0
        self.motor_h = ctx.dt
        self.lock: pymunk.GearJoint | None = None
        #: pymunk's slide joint holding the limit, when ``iterated_hinges`` is on
        self.limit: pymunk.SlideJoint | None = None
        if not self.active:
            return
        self.lock = pymunk.GearJoint(self.a, self.b, self.ref, 1.0)
        self.add(self.line.make_pin(), self.lock, error_bias=PROJECTED_ERROR_BIAS)
        self.every_substep(self.drive)
        self.configure(j)

    def configure(self, j: Any) -> None:
        assert self.lock is not None
        self.axis = pymunk.Vec2d(*j.local_axis_a)
        self.ref = j.reference_angle
        self.line.place(j.local_anchor_a, self.axis, j.local_anchor_b)
        self.lock.phase = self.ref
        self.settings = j
        limited = j.enable_limit and self.ctx.iterated_hinges
        if limited:
            if self.limit is None:
                self.limit = pymunk.SlideJoint(self.a, self.b, (0.0, 0.0), (0.0, 0.0), 0.0, 0.0)
                self.add(self.limit, enabled=False)
                self.limit.max_bias = 0.0  # it stops the slider; the position pass corrects
            anchor_a = pymunk.Vec2d(*j.local_anchor_a) - self.axis * LIMIT_REACH
            self.limit.anchor_a, self.limit.anchor_b = anchor_a, j.local_anchor_b
            self.limit.min = LIMIT_REACH + j.lower_translation
            self.limit.max = LIMIT_REACH + j.upper_translation
        if self.limit is not None:
            self.enable(self.limit, limited)
        self.run_substeps(j.enable_motor or (j.enable_limit and not limited))
        if not j.enable_motor:
            self.motor_impulse = 0.0
        if not j.enable_limit:
            self.limit_impulse = 0.0

    def project(self) -> None:
        """Box2D's position pass: angle (8° per step at most), limit, then line (0.2 m)."""
        error = self.b.angle - self.a.angle - self.ref
        if abs(error) > SETTLED and self.is_on(self.lock):
            project_rows(spin_rows(self.a, self.b), error, MAX_ANGULAR_CORRECTION)
            self.jolt(abs(error), MAX_ANGULAR_CORRECTION)
        j = self.settings
        if j.enable_limit and self.is_on(self.line.pin):
            # an iterated limit is left b2_linearSlop past its bound, as Box2D's
            # position pass leaves it (and its velocity row engaged)
            slop = LINEAR_SLOP if self.is_on(self.limit) else 0.0
            project_limit(self.rows(1.0), self.coordinate(), j.lower_translation - slop,
                          j.upper_translation + slop, MAX_CORRECTION)
        if self.is_on(self.line.pin):
            self.jolt(self.line.project(), MAX_CORRECTION)

    # -- joint coordinate, for the motor and gears ---------------------------------------
    def coordinate(self) -> float:
        return self.line.translation()

    def rows(self, scale: float, axis: pymunk.Vec2d | None = None) -> list[Row]:
        """d(translation)/dt, with body A's rotation of the axis included.

        With ``axis`` (a unit vector in A's frame) the rate along that axis instead:
        the perpendicular one is the line's constraint.
        """
        return self.line.rows(scale, axis)

    def drive(self, h: float) -> None:
        j = self.settings
        if not (j.enable_motor or j.enable_limit):
            return
        keep = [self.rows(1.0, self.axis.perpendicular()), spin_rows(self.a, self.b)]
        rows = fold(self.rows(1.0), keep)
        motor = (j.motor_speed, j.max_motor_force) if j.enable_motor else None
        custom = j.enable_limit and not self.is_on(self.limit)
        lo, hi = (j.lower_translation, j.upper_translation) if custom else (None, None)
        self.motor_impulse, limit_impulse = motor_and_limits(
            self.space, rows, self.coordinate(), h, motor, lo, hi, MAX_CORRECTION
        )
        if custom:
            self.limit_impulse = limit_impulse
        self.motor_h = h

    def speed(self) -> float:
        return sum(
            jx * body.velocity.x + jy * body.velocity.y + jw * body.angular_velocity
            for body, jx, jy, jw in self.rows(1.0)
        )

    def read_live(self, j: Any, dt: float) -> None:
        translation = self.coordinate()
        self.line.follow(translation)
        raw_set(j, "translation", translation)
        raw_set(j, "speed", float(self.speed()))
        raw_set(j, "motor_force", self.motor_impulse / self.motor_h)
        # the line's push is perpendicular to the axis (its sign from B's momentum
        # balance); the motor and the limit push along it, with known signs
        u = self.axis.rotated(self.a.angle)
        n = u.perpendicular()
        bx, by, _ = self.balance(dt)
        perp = self.impulse_force(self.line.pin)
        if bx * n.x + by * n.y < 0:
            perp = -perp
        along = self.motor_impulse / self.motor_h + self._limit_force(translation)
        self.write_reaction(j, dt, 0.0, self.impulse_force(self.lock))
        self._force = abs(complex(perp, along))
        raw_set(j, "reaction_force", (perp * n.x + along * u.x, perp * n.y + along * u.y))


    def _limit_force(self, translation: float) -> float:
        """The limit's push on B along the axis, N (positive: towards the upper bound)."""
        if not self.is_on(self.limit):
            return self.limit_impulse / self.motor_h
        j = self.settings
        # pymunk reports the slide joint's impulse unsigned: the lower bound pushes B up
        # the axis, the upper one down
        lower = translation < 0.5 * (j.lower_translation + j.upper_translation)
        force = self.impulse_force(self.limit)
        return force if lower else -force


def build(ctx: JointContext, entity: int, j: Any) -> Prismatic:
    return Prismatic(ctx, entity, j)


register(PrismaticJoint, build)
