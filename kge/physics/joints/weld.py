"""WeldJoint = PivotJoint + an angle lock (rigid) or a DampedRotarySpring (soft).

Rigid: the relative angle is held at the reference angle by a custom velocity
step on the hinge Jacobian with the pivot folded in
(:func:`~kge.physics.joints.rows.hinge_rows`), removing the whole angle error
each substep (the speculative "be there next step" target ``-C/h``). pymunk's
``GearJoint`` would act on each body's own small moment of inertia instead: an
8-box welded cantilever then flails metres up and down; with the folded lock its
tip drop stays within 0.2-1.7 m (Box2D 8/3: 0.19-2.77 m).

Soft: ``DampedRotarySpring.rest_angle`` is expressed as ``θa - θb``, so it is
``-ref``, with ``k = I_eff·ω²`` and ``c = 2·I_eff·ζ·ω`` where
``I_eff = 1 / (1/IA + 1/IB)`` (Box2D 2.3's choice).
"""

from __future__ import annotations

from typing import Any

import pymunk

from kge.components.joints import WeldJoint
from kge.components.tracked import raw_set
from kge.physics.joint_api import JointContext, register
from kge.physics.joints.base import PROJECTED_ERROR_BIAS, Composite
from kge.physics.joints.mechanics import inv_mass
from kge.physics.joints.positions import MAX_ANGULAR_CORRECTION, MAX_CORRECTION, project_point
from kge.physics.joints.rows import VelocityStep, correction, hinge_rows


class Weld(Composite):
    def __init__(self, ctx: JointContext, entity: int, j: WeldJoint) -> None:
        super().__init__(ctx, entity, j)
        self.local_anchors(j)
        self.ref = self.reference_angle(j)
        self.rigid = j.frequency_hz == 0
        self.lock_impulse = 0.0
        self.h = ctx.dt
        self.pivot: pymunk.PivotJoint | None = None
        self.spring: pymunk.DampedRotarySpring | None = None
        if not self.active:
            return
        self.pivot = pymunk.PivotJoint(self.a, self.b, j.local_anchor_a, j.local_anchor_b)
        self.spring = pymunk.DampedRotarySpring(self.a, self.b, -self.ref, 0.0, 0.0)
        self.add(self.pivot, error_bias=PROJECTED_ERROR_BIAS)
        self.add(self.spring, enabled=False)
        self.every_substep(self.lock)
        self.configure(j)

    def configure(self, j: Any) -> None:
        assert self.pivot is not None and self.spring is not None
        self.pivot.anchor_a, self.pivot.anchor_b = j.local_anchor_a, j.local_anchor_b
        self.ref = j.reference_angle
        self.spring.rest_angle = -self.ref
        self.rigid = j.frequency_hz == 0
        if not self.rigid:
            inv_i = inv_mass(self.a)[1] + inv_mass(self.b)[1]
            i_eff = 1.0 / inv_i if inv_i > 0 else 0.0
            omega = self.spring_omega(j.frequency_hz)
            self.spring.stiffness = i_eff * omega * omega
            self.spring.damping = 2.0 * i_eff * j.damping_ratio * omega
            self.lock_impulse = 0.0
        self.enable(self.spring, not self.rigid)

    def lock(self, h: float) -> None:
        if not self.rigid or self.pivot is None:
            return
        pa, pb = self.world_anchors(self.pivot.anchor_a, self.pivot.anchor_b)
        # the whole error each substep, but at most 8° of it: a weld made with a
        # reference angle far from the pose turns its bodies round over a few
        # substeps instead of spinning them at (error / h) for one
        error = correction(self.b.angle - self.a.angle - self.ref, MAX_ANGULAR_CORRECTION, 1.0)
        rows = hinge_rows(self.a, self.b, pa, pb)
        self.lock_impulse = VelocityStep.solve(self.space, rows, -error / h, h)
        self.h = h

    def project(self) -> None:
        if self.pivot is not None:
            gap = project_point(self.a, self.b, self.pivot.anchor_a, self.pivot.anchor_b)
            self.jolt(gap, MAX_CORRECTION)

    def read_live(self, j: Any, dt: float) -> None:
        if self.is_on(self.spring):
            assert self.spring is not None
            torque = -self.spring.stiffness * (self.b.angle - self.a.angle - self.ref)
        else:
            torque = self.lock_impulse / self.h
        self.write_reaction(j, dt, self.impulse_force(self.pivot), 0.0)
        self._torque = abs(torque)
        raw_set(j, "reaction_torque", float(torque))


def build(ctx: JointContext, entity: int, j: Any) -> Weld:
    return Weld(ctx, entity, j)


register(WeldJoint, build)
