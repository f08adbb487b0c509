"""GearJoint: ``coordinate_a + ratio·coordinate_b = constant`` over two joints.

Box2D's gear couples *joint coordinates* (a revolute's angle, a prismatic's
translation). pymunk's ``GearJoint`` couples two bodies' absolute angles, which
is the same thing only for two revolutes whose base bodies never turn. So:

* revolute + revolute on static bases: pymunk ``GearJoint(bodyA, bodyB,
  phase, ratio=-ratio)`` (it enforces ``r·θb - θa = phase``), solved inside
  pymunk's iterations: the stiffest option;
* every other case (a prismatic side, or a base that moves, like gears on a
  car's chassis): a custom velocity constraint over the four bodies, built from
  the two joints' coordinate Jacobians (``rows()`` of the revolute and prismatic
  handles), solved once per substep.

Either way the velocity part has no bias: the drift of the gear's coordinate is
removed by a position pass after the step (Box2D's position solver), at most 8°
(or 0.2 m) per step.

The gear's bodies are ``joint_a``'s and ``joint_b``'s ``body_b`` (Box2D). If
either joint is not built yet, the gear waits and resolves itself before a
later step; it rebuilds itself when its joints are rebuilt or renamed, and
stays inert while its two bodies are one (see :meth:`Gear.can_act`).
"""

from __future__ import annotations

from typing import Any

import pymunk

from kge.components.joints import GearJoint
from kge.components.tracked import raw_set
from kge.physics.joint_api import JointContext, in_space, register
from kge.physics.joints.base import PROJECTED_ERROR_BIAS, Composite
from kge.physics.joints.positions import (
    MAX_ANGULAR_CORRECTION,
    MAX_CORRECTION,
    SETTLED,
    project_rows,
)
from kge.physics.joints.prismatic import Prismatic
from kge.physics.joints.revolute import Revolute
from kge.physics.joints.rows import Row, VelocityStep

Coupled = Revolute | Prismatic


class Gear(Composite):
    fixed_ends = False  # its bodies are its joints' (resolve), its joints the component's

    def __init__(self, ctx: JointContext, entity: int, g: GearJoint) -> None:
        # a gear has no bodies of its own until its joints are known: until then it
        # sits inert on the ground body (a = b = the static body)
        super().__init__(ctx, entity, g)
        self.depends_on = (g.joint_a, g.joint_b)
        self.body_a = self.body_b = -1
        self.active = False
        self.ready = False
        self.ja: Coupled | None = None
        self.jb: Coupled | None = None
        self.gear: pymunk.GearJoint | None = None
        self.ratio = g.ratio
        self.constant = 0.0
        self.impulse = 0.0
        self.h = ctx.dt
        self.resolve()

    def resolve(self) -> None:
        """Find both joints; build once they exist and can act.

        A joint that is not built yet, or is not a hinge or slider (the component
        was replaced after the gear was spawned, where that was checked), leaves
        the gear waiting, inert: raising here would fail the step, not the call
        that caused it.
        """
        g = self.component
        ja, jb = self.ctx.joint(g.joint_a), self.ctx.joint(g.joint_b)
        if not (isinstance(ja, Coupled) and isinstance(jb, Coupled)):
            return
        self.ja, self.jb = ja, jb
        self.a, self.b = ja.b, jb.b
        self.body_a, self.body_b = ja.body_b, jb.body_b
        raw_set(g, "body_a", None if ja.body_b < 0 else ja.body_b)
        raw_set(g, "body_b", None if jb.body_b < 0 else jb.body_b)
        self.ready = True
        self.active = self.can_act()
        if not self.active:
            return
        self.ratio = g.ratio
        self.constant = self.coordinate()
        if self.on_fixed_bases():
            r = -g.ratio
            self.gear = pymunk.GearJoint(self.a, self.b, r * self.b.angle - self.a.angle, r)
            self.add(self.gear, error_bias=PROJECTED_ERROR_BIAS)
        else:
            self.every_substep(self.solve)

    def can_act(self) -> bool:
        """Both joints live, and two different bodies of which one is dynamic.

        Box2D asserts that a joint's two bodies differ (``b2Joint``'s constructor);
        for a gear they are the joints' body B. Such a gear (two hinges between the
        same pair of bodies, or a joint's body reassigned onto the other's) does
        nothing in kge until its bodies differ again: pymunk asserts ``a is not b``
        for every constraint, and with ratio -1 the gear's rows cancel out.
        """
        ja, jb = self.ja, self.jb
        return ja is not None and jb is not None and ja.active and jb.active and super().can_act()

    def on_fixed_bases(self) -> bool:
        """Two revolutes on static bases: pymunk's absolute-angle gear is exact there."""
        ja, jb = self.ja, self.jb
        return (
            isinstance(ja, Revolute)
            and isinstance(jb, Revolute)
            and ja.a.body_type == pymunk.Body.STATIC
            and jb.a.body_type == pymunk.Body.STATIC
        )

    def stale(self) -> bool:
        """True when the gear must be rebuilt before this step.

        Its joints may have been rebuilt (a body reassigned: a new handle) or
        renamed (``joint_a`` / ``joint_b`` written), a joint or body may have come
        alive since the gear was built inert, or a joint's base may have turned
        non-static under a pymunk gear that assumes it is static.
        """
        g = self.component
        if self.ctx.joint(g.joint_a) is not self.ja or self.ctx.joint(g.joint_b) is not self.jb:
            return True
        if not self.ready:
            return False
        if not self.active:
            return self.can_act()
        return (self.gear is not None) != self.on_fixed_bases()

    def rebuild(self) -> None:
        """Start again from the component (Box2D would create a new gear)."""
        for c in self.parts:
            if in_space(self.space, c):
                self.space.remove(c)
        type(self).__init__(self, self.ctx, self.entity, self.component)

    def coordinate(self) -> float:
        assert self.ja is not None and self.jb is not None
        return self.ja.coordinate() + self.ratio * self.jb.coordinate()

    def gear_rows(self) -> list[Row]:
        assert self.ja is not None and self.jb is not None
        return self.ja.rows(1.0) + self.jb.rows(self.ratio)

    def solve(self, h: float) -> None:
        """The velocity part, as Box2D's: no relative motion along the gear, no bias."""
        self.impulse = VelocityStep.solve(self.space, self.gear_rows(), 0.0, h)
        self.h = h

    def project(self) -> None:
        """Box2D's position pass: remove the drift of the gear's coordinate.

        A velocity bias here would fight any other joint that disagrees about the
        same bodies (a slider's rotation lock, a second gear) with velocities the
        bodies keep; moved positions fight without adding energy.
        """
        if not (self.is_on(self.gear) or self.is_on(self._carrier)):
            return
        error = self.coordinate() - self.constant
        if abs(error) > SETTLED:
            limit = MAX_ANGULAR_CORRECTION if isinstance(self.ja, Revolute) else MAX_CORRECTION
            self.jolt(project_rows(self.gear_rows(), error, limit), limit)

    def configure(self, g: Any) -> None:
        if g.ratio != self.ratio:
            self.ratio = g.ratio
            self.constant = self.coordinate()
            if self.gear is not None:
                r = -g.ratio
                self.gear.ratio = r
                self.gear.phase = r * self.b.angle - self.a.angle

    def before_step(self, dt: float) -> None:
        if self.stale():
            self.rebuild()
        if self.ready:
            self.track_body_types()
            self.track_rotation()
            self.before_step_momentum()

    def read_back(self, component: Any, dt: float) -> None:
        if not self.ready:
            return
        super().read_back(component, dt)

    def read_live(self, g: Any, dt: float) -> None:
        if self.gear is not None:
            torque = self.impulse_force(self.gear)
        else:
            torque = abs(self.impulse) / self.h
        self.write_reaction(g, dt, 0.0, torque)


def build(ctx: JointContext, entity: int, g: Any) -> Gear:
    return Gear(ctx, entity, g)


register(GearJoint, build)
