"""MouseJoint: Box2D's soft point constraint towards a target, solved once per substep.

Box2D's mouse joint is a *soft* constraint: a spring of stiffness ``k = m·ω²``
and damping ``d = 2·m·ζ·ω`` (ω = 2π·frequency_hz, m the body's mass) written
in impulse form. Per step of length h, with ``γ = 1/(h·(d + h·k))`` and
``β = h·k·γ``, the impulse P solves ``K·P + γ·P = -(Cdot + β·C)``, i.e.

    P = -(K + γ·I)⁻¹ · (Cdot + β·C)     (K: the body's 2x2 point mass matrix)

clamped to ``|P| ≤ max_force·h``. The compliance γ is what makes a dragged body
hang ``g/ω²`` below the target under gravity. A pymunk ``PivotJoint`` with a
soft ``error_bias`` cannot do that (it cancels gravity exactly and only eases
existing errors), so the step is custom, run from the carrier's ``pre_solve``
with this substep's gravity predicted. Box2D also multiplies the body's angular
velocity by 0.98 every step; ``before_step`` reproduces that.

``body_a`` is Box2D's dummy ground body. The carrier between it and the
dragged body always lets them collide when ``body_a`` is the world's ground,
so a dragged body still lands on static colliders.
"""

from __future__ import annotations

import math
from typing import Any

import pymunk

from kge.components.joints import MouseJoint
from kge.components.tracked import raw_set
from kge.physics.joint_api import JointContext, register
from kge.physics.joints.base import Composite
from kge.physics.joints.mechanics import cog_world, inv_mass, is_dynamic

#: Box2D's per-step angular damping of a dragged body
SPIN_DAMPING = 0.98


class Mouse(Composite):
    def __init__(self, ctx: JointContext, entity: int, j: MouseJoint) -> None:
        super().__init__(ctx, entity, j)
        self.active = self.can_act()
        lb = j.local_anchor_b
        if lb is None:
            grab = j.grab_point if j.grab_point is not None else j.target
            w = self.b.world_to_local(grab)
            lb = (float(w.x), float(w.y))
            raw_set(j, "local_anchor_b", lb)
        self.lb: tuple[float, float] = lb
        self.settings = j
        self.impulse = pymunk.Vec2d(0.0, 0.0)
        self.h = ctx.dt
        if not self.active:
            return
        self.every_substep(self.solve)
        if j.body_a is None and self._carrier is not None:
            self._carrier.collide_bodies = True
            self.own_collide.add(self._carrier)

    def can_act(self) -> bool:
        """Only the dragged body B must be dynamic (A is Box2D's dummy ground)."""
        return self.a is not self.b and is_dynamic(self.b)

    def configure(self, j: Any) -> None:
        self.settings = j
        if j.local_anchor_b is not None:
            self.lb = j.local_anchor_b

    def solve(self, h: float) -> None:
        j = self.settings
        b = self.b
        m = b.mass
        omega = 2.0 * math.pi * j.frequency_hz
        k = m * omega * omega
        d = 2.0 * m * j.damping_ratio * omega
        soft = h * (d + h * k)
        gamma = 1.0 / soft if soft > 0 else 0.0
        beta = h * k * gamma
        im, ii = inv_mass(b)
        p = b.local_to_world(self.lb)
        r = p - cog_world(b)
        k11 = im + ii * r.y * r.y + gamma
        k12 = -ii * r.x * r.y
        k22 = im + ii * r.x * r.x + gamma
        gx, gy = self.space.gravity
        v = b.velocity + (gx * h, gy * h) + pymunk.Vec2d(-r.y, r.x) * b.angular_velocity
        c = p - j.target
        rx = -(v.x + beta * c.x)
        ry = -(v.y + beta * c.y)
        det = k11 * k22 - k12 * k12
        if abs(det) < 1e-12:
            return
        px = (k22 * rx - k12 * ry) / det
        py = (-k12 * rx + k11 * ry) / det
        cap = j.max_force * h
        n = math.hypot(px, py)
        if n > cap:
            px, py = px * cap / n, py * cap / n
        b.velocity = b.velocity + pymunk.Vec2d(im * px, im * py)
        b.angular_velocity = b.angular_velocity + ii * (r.x * py - r.y * px)
        self.impulse = pymunk.Vec2d(px, py)
        self.h = h

    def before_step(self, dt: float) -> None:
        super().before_step(dt)
        if self.active and is_dynamic(self.b):
            self.b.angular_velocity = self.b.angular_velocity * SPIN_DAMPING

    def read_live(self, j: Any, dt: float) -> None:
        f = self.impulse / self.h
        self._force, self._torque = float(abs(f)), 0.0
        raw_set(j, "reaction_force", (float(f.x), float(f.y)))
        raw_set(j, "reaction_torque", 0.0)


def build(ctx: JointContext, entity: int, j: Any) -> Mouse:
    return Mouse(ctx, entity, j)


register(MouseJoint, build)
