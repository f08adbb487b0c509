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
  handles), solved once per substep with Baumgarte position correction.

The gear's bodies are ``joint_a``'s and ``joint_b``'s ``body_b`` (Box2D). If
either joint is not built yet, the gear waits and resolves itself before a
later step.
"""

from __future__ import annotations

from typing import Any

import pymunk

from kge.components.joints import GearJoint
from kge.components.tracked import raw_set
from kge.errors import ValidationError
from kge.physics.joint_api import JointContext, register
from kge.physics.joints.base import Composite
from kge.physics.joints.mechanics import is_dynamic
from kge.physics.joints.prismatic import Prismatic
from kge.physics.joints.revolute import Revolute
from kge.physics.joints.rows import BAUMGARTE, VelocityStep

Coupled = Revolute | Prismatic


class Gear(Composite):
    def __init__(self, ctx: JointContext, entity: int, g: GearJoint) -> None:
        # a gear has no bodies of its own until its joints are known: until then it
        # sits inert on the ground body (a = b = the static body)
        super().__init__(ctx, entity, g)
        self.depends_on = (g.joint_a, g.joint_b)
        self.body_a = self.body_b = -1
        self.active = False
        self.ready = False
        self.gear: pymunk.GearJoint | None = None
        self.impulse = 0.0
        self.h = ctx.dt
        self.resolve()

    def resolve(self) -> None:
        """Find both joints; build once they exist."""
        g = self.component
        ja, jb = self.ctx.joint(g.joint_a), self.ctx.joint(g.joint_b)
        if ja is None or jb is None:
            return
        for name, joint in (("joint_a", ja), ("joint_b", jb)):
            if not isinstance(joint, (Revolute, Prismatic)):
                raise ValidationError(
                    f"entity {self.entity}, GearJoint.{name} must name a RevoluteJoint or "
                    f"PrismaticJoint, got {type(joint).__name__}"
                )
        assert isinstance(ja, (Revolute, Prismatic)) and isinstance(jb, (Revolute, Prismatic))
        self.ja: Coupled = ja
        self.jb: Coupled = jb
        self.a, self.b = ja.b, jb.b
        self.body_a, self.body_b = ja.body_b, jb.body_b
        raw_set(g, "body_a", None if ja.body_b < 0 else ja.body_b)
        raw_set(g, "body_b", None if jb.body_b < 0 else jb.body_b)
        self.ready = True
        self.active = ja.active and jb.active and (is_dynamic(self.a) or is_dynamic(self.b))
        if not self.active:
            return
        self.ratio = g.ratio
        self.constant = self.coordinate()
        if (
            isinstance(ja, Revolute)
            and isinstance(jb, Revolute)
            and ja.a.body_type == pymunk.Body.STATIC
            and jb.a.body_type == pymunk.Body.STATIC
        ):
            r = -g.ratio
            self.gear = pymunk.GearJoint(self.a, self.b, r * self.b.angle - self.a.angle, r)
            self.add(self.gear)
        else:
            self.every_substep(self.solve)

    def coordinate(self) -> float:
        return self.ja.coordinate() + self.ratio * self.jb.coordinate()

    def solve(self, h: float) -> None:
        error = self.coordinate() - self.constant
        rows = self.ja.rows(1.0) + self.jb.rows(self.ratio)
        self.impulse = VelocityStep.solve(self.space, rows, -BAUMGARTE * error / h, h)
        self.h = h

    def configure(self, g: Any) -> None:
        if g.ratio != self.ratio:
            self.ratio = g.ratio
            self.constant = self.coordinate()
            if self.gear is not None:
                r = -g.ratio
                self.gear.ratio = r
                self.gear.phase = r * self.b.angle - self.a.angle


    def before_step(self, dt: float) -> None:
        if not self.ready:
            self.resolve()
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
