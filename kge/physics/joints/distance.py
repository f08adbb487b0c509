"""DistanceJoint = PinJoint (rigid) or DampedSpring (soft), (+ SlideJoint for min/max).

Soft joints: Box2D makes the frequency independent of mass by using the
constraint's effective mass ``m_eff = 1 / (1/mA + 1/mB + (rA×u)²/IA + (rB×u)²/IB)``.
The spring gets ``k = m_eff·ω²`` and ``c = 2·m_eff·ζ·ω`` with ω = 2π·frequency_hz,
recomputed before every step because the lever arms change as the bodies turn.
pymunk integrates the spring analytically-ish, so it rings longer than Box2D's
numerically damped soft constraint (period and static sag match).
"""

from __future__ import annotations

import math
from typing import Any

import pymunk

from kge.components.joints import DistanceJoint
from kge.components.tracked import raw_set
from kge.physics.joint_api import JointContext, register
from kge.physics.joints.base import PROJECTED_ERROR_BIAS, Composite
from kge.physics.joints.mechanics import point_mass
from kge.physics.joints.positions import MAX_CORRECTION, project_length


class Distance(Composite):
    def __init__(self, ctx: JointContext, entity: int, j: DistanceJoint) -> None:
        super().__init__(ctx, entity, j)
        self.split_anchors(j)
        if j.length is None:
            pa, pb = self.world_anchors(j.local_anchor_a, j.local_anchor_b)
            raw_set(j, "length", float(abs(pb - pa)))
        self.pin = self.spring = self.range = None
        if not self.active:
            return
        la, lb = j.local_anchor_a, j.local_anchor_b
        self.pin = pymunk.PinJoint(self.a, self.b, la, lb)
        self.spring = pymunk.DampedSpring(self.a, self.b, la, lb, 0.0, 0.0, 0.0)
        self.range = pymunk.SlideJoint(self.a, self.b, la, lb, 0.0, math.inf)
        self.add(self.pin, enabled=False, error_bias=PROJECTED_ERROR_BIAS)
        self.add(self.spring, self.range, enabled=False)
        self.configure(j)

    def configure(self, j: Any) -> None:
        assert self.pin is not None and self.spring is not None and self.range is not None
        for c in (self.pin, self.spring, self.range):
            c.anchor_a, c.anchor_b = j.local_anchor_a, j.local_anchor_b
        soft = j.frequency_hz > 0
        ranged = j.min_length is not None or j.max_length is not None
        self.pin.distance = j.length
        self.spring.rest_length = j.length
        self.freq, self.zeta = j.frequency_hz, j.damping_ratio
        # Box2D 2.4: a range without a spring is slack between its bounds (no rod)
        self.enable(self.pin, not soft and not ranged)
        self.enable(self.spring, soft)
        self.range.min = j.min_length if j.min_length is not None else 0.0
        self.range.max = j.max_length if j.max_length is not None else 1e9
        self.enable(self.range, ranged)
        if soft:
            self.tune()

    def tune(self) -> None:
        """Spring constants from the current effective mass (Box2D's soft constraint)."""
        assert self.spring is not None
        pa, pb = self.world_anchors(self.spring.anchor_a, self.spring.anchor_b)
        d = pb - pa
        n = abs(d)
        u = d / n if n > 1e-9 else pymunk.Vec2d(1.0, 0.0)
        k = point_mass(self.a, pa, u) + point_mass(self.b, pb, u)
        m_eff = 1.0 / k if k > 0 else 0.0
        omega = self.spring_omega(self.freq)
        self.spring.stiffness = m_eff * omega * omega
        self.spring.damping = 2.0 * m_eff * self.zeta * omega

    def before_step(self, dt: float) -> None:
        super().before_step(dt)
        if self.is_on(self.spring):
            self.tune()

    def project(self) -> None:
        if self.pin is not None and self.is_on(self.pin):
            error = project_length(
                self.a, self.b, self.pin.anchor_a, self.pin.anchor_b, self.pin.distance
            )
            self.jolt(error, MAX_CORRECTION)

    def read_live(self, j: Any, dt: float) -> None:
        assert self.spring is not None
        pa, pb = self.world_anchors(j.local_anchor_a, j.local_anchor_b)
        d = pb - pa
        n = abs(d)
        if n < 1e-9:
            self.write_reaction(j, dt, self.impulse_force(self.pin), 0.0)
            return
        u = d / n
        # the pin and the range act along the rod with a size pymunk reports, the
        # spring with a size we know: -(k·stretch + c·stretch rate) on B
        along = self.impulse_force(self.pin) + self.impulse_force(self.range)
        bx, by, _ = self.balance(dt)
        if bx * u.x + by * u.y < 0:
            along = -along
        if self.is_on(self.spring):
            rel = self.b.velocity_at_world_point(pb) - self.a.velocity_at_world_point(pa)
            along -= self.spring.stiffness * (n - j.length) + self.spring.damping * rel.dot(u)
        self._force, self._torque = abs(along), 0.0
        raw_set(j, "reaction_force", (float(along * u.x), float(along * u.y)))
        raw_set(j, "reaction_torque", 0.0)


def build(ctx: JointContext, entity: int, j: Any) -> Distance:
    return Distance(ctx, entity, j)


register(DistanceJoint, build)
