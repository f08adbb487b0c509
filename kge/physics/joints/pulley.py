"""PulleyJoint: a custom velocity constraint ``length_a + ratio·length_b = constant``.

pymunk has no pulley. With ``u_a``, ``u_b`` the unit directions from the ground
anchors to the body anchors, the rope length changes at
``rate = u_a·v_a + ratio·u_b·v_b`` (v at the anchors). Once per substep, from
the carrier's ``pre_solve``, an impulse brings that rate to ``-β·C/h`` (C the
length error clamped to 0.2 m, β = 0.2 like Box2D's Baumgarte), with this substep's gravity
predicted. Being solved once per substep rather than inside pymunk's
iterations, it is softer than Box2D's under heavy contact load; the invariant
still holds to millimetres in the reference scenarios. Optional maximum lengths
are ``SlideJoint``\\ s from the (static) ground anchor to each body.
"""

from __future__ import annotations

import math
from typing import Any

import pymunk

from kge.components.joints import PulleyJoint
from kge.components.tracked import raw_set
from kge.physics.joint_api import JointContext, register
from kge.physics.joints.base import Composite
from kge.physics.joints.mechanics import cog_world, cross, is_dynamic
from kge.physics.joints.positions import MAX_CORRECTION
from kge.physics.joints.rows import Row, VelocityStep, correction


class Pulley(Composite):
    def __init__(self, ctx: JointContext, entity: int, j: PulleyJoint) -> None:
        super().__init__(ctx, entity, j)
        self.split_anchors(j)
        self.configure_geometry(j)
        self.constant = self.length(self.a, self.ga, self.la) + self.ratio * self.length(
            self.b, self.gb, self.lb
        )
        self.impulse = 0.0
        self.h = 1.0 / 60.0
        self.max_a: pymunk.SlideJoint | None = None
        self.max_b: pymunk.SlideJoint | None = None
        if not self.active:
            return
        ground = self.space.static_body
        if is_dynamic(self.a):
            self.max_a = pymunk.SlideJoint(ground, self.a, self.ga, self.la, 0.0, 1e9)
        if is_dynamic(self.b):
            self.max_b = pymunk.SlideJoint(ground, self.b, self.gb, self.lb, 0.0, 1e9)
        for slide in (self.max_a, self.max_b):
            if slide is not None:
                self.add(slide, enabled=False)
                slide.collide_bodies = True  # a rope to the ground must not stop ground contacts
                self.own_collide.add(slide)
        self.every_substep(self.solve)
        self.configure(j)

    def configure_geometry(self, j: Any) -> None:
        self.ga = pymunk.Vec2d(*j.ground_anchor_a)
        self.gb = pymunk.Vec2d(*j.ground_anchor_b)
        self.la = pymunk.Vec2d(*j.local_anchor_a)
        self.lb = pymunk.Vec2d(*j.local_anchor_b)
        self.ratio = j.ratio

    def configure(self, j: Any) -> None:
        old = (self.ga, self.gb, self.la, self.lb, self.ratio)
        self.configure_geometry(j)
        if old != (self.ga, self.gb, self.la, self.lb, self.ratio):
            # geometry was edited: the rope is re-measured as it hangs now
            self.constant = self.length(self.a, self.ga, self.la) + self.ratio * self.length(
                self.b, self.gb, self.lb
            )
        for slide, ground, anchor, limit in (
            (self.max_a, self.ga, self.la, j.max_length_a),
            (self.max_b, self.gb, self.lb, j.max_length_b),
        ):
            if slide is None:
                continue
            slide.anchor_a, slide.anchor_b = ground, anchor
            if limit is not None:
                slide.max = limit
            self.enable(slide, limit is not None)

    @staticmethod
    def length(body: pymunk.Body, ground: pymunk.Vec2d, local: pymunk.Vec2d) -> float:
        return float(abs(body.local_to_world(local) - ground))

    def side(self, body: pymunk.Body, ground: pymunk.Vec2d, local: pymunk.Vec2d, s: float) -> Row:
        p = body.local_to_world(local)
        d = p - ground
        n = abs(d)
        u = d / n if n > 1e-9 else pymunk.Vec2d(0.0, -1.0)
        r = p - cog_world(body)
        return (body, s * u.x, s * u.y, s * cross(r.x, r.y, u.x, u.y))

    def solve(self, h: float) -> None:
        la = self.length(self.a, self.ga, self.la)
        lb = self.length(self.b, self.gb, self.lb)
        error = la + self.ratio * lb - self.constant
        rows = [
            self.side(self.a, self.ga, self.la, 1.0),
            self.side(self.b, self.gb, self.lb, self.ratio),
        ]
        target = -correction(error, MAX_CORRECTION) / h
        self.impulse = VelocityStep.solve(self.space, rows, target, h)
        self.h = h

    def read_live(self, j: Any, dt: float) -> None:
        raw_set(j, "length_a", self.length(self.a, self.ga, self.la))
        raw_set(j, "length_b", self.length(self.b, self.gb, self.lb))
        # the rope pulls B towards its ground anchor with ratio * tension
        _, ux, uy, _ = self.side(self.b, self.gb, self.lb, 1.0)
        f = self.ratio * self.impulse / self.h
        self._force, self._torque = abs(f), 0.0
        raw_set(j, "reaction_force", (f * ux, f * uy))
        raw_set(j, "reaction_torque", 0.0)
        if not math.isfinite(f):  # pragma: no cover - defensive
            raw_set(j, "reaction_force", (0.0, 0.0))


def build(ctx: JointContext, entity: int, j: Any) -> Pulley:
    return Pulley(ctx, entity, j)


register(PulleyJoint, build)
