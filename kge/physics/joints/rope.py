"""RopeJoint = SlideJoint(min=0, max=max_length) + a speculative pull.

A pymunk ``SlideJoint`` only acts once the rope is already too long, so a ball
falling into a taut rope overshoots by one step of motion (5 cm at 4.5 m/s) and
is pulled back. Box2D's rope is speculative: while slack it already limits the
approach speed to ``-C/h`` (C = length - max_length < 0), so the rope goes taut
exactly at its length. The same rule runs here once per substep, before
pymunk's solver; the slide joint stays as the iterated hard limit.
"""

from __future__ import annotations

from typing import Any

import pymunk

from kge.components.joints import RopeJoint
from kge.components.tracked import raw_set
from kge.physics.joint_api import JointContext, register
from kge.physics.joints.base import RIGID_CORRECTION, Composite
from kge.physics.joints.positions import MAX_CORRECTION
from kge.physics.joints.rows import VelocityStep, correction, line_rows


class Rope(Composite):
    def __init__(self, ctx: JointContext, entity: int, j: RopeJoint) -> None:
        super().__init__(ctx, entity, j)
        self.split_anchors(j)
        length = j.max_length
        if length is None:
            pa, pb = self.world_anchors(j.local_anchor_a, j.local_anchor_b)
            length = float(abs(pb - pa))
            raw_set(j, "max_length", length)
        self.slide: pymunk.SlideJoint | None = None
        self.pull = 0.0  # force of the speculative step, N
        self.la, self.lb = j.local_anchor_a, j.local_anchor_b
        self.max_length = length
        if not self.active:
            return
        self.slide = pymunk.SlideJoint(
            self.a, self.b, self.la, self.lb, 0.0, self.max_length
        )
        self.add(self.slide)
        self.every_substep(self.speculate)

    def speculate(self, h: float) -> None:
        pa, pb = self.world_anchors(self.la, self.lb)
        rows, length = line_rows(self.a, self.b, pa, pb)
        c = length - self.max_length
        target = -c / h if c <= 0 else -correction(c, MAX_CORRECTION, RIGID_CORRECTION) / h
        self.pull = -VelocityStep.solve(self.space, rows, target, h, hi=0.0) / h

    def configure(self, j: Any) -> None:
        assert self.slide is not None
        self.slide.anchor_a, self.slide.anchor_b = j.local_anchor_a, j.local_anchor_b
        self.slide.max = j.max_length
        self.la, self.lb, self.max_length = j.local_anchor_a, j.local_anchor_b, j.max_length

    def read_live(self, j: Any, dt: float) -> None:
        pa, pb = self.world_anchors(j.local_anchor_a, j.local_anchor_b)
        d = pb - pa
        n = abs(d)
        u = (d.x / n, d.y / n) if n > 1e-9 else None
        self.write_reaction(j, dt, self.pull + self.impulse_force(self.slide), 0.0, u)


def build(ctx: JointContext, entity: int, j: Any) -> Rope:
    return Rope(ctx, entity, j)


register(RopeJoint, build)
