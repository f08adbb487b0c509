"""FrictionJoint = PivotJoint + GearJoint, both velocity-only and force-capped.

``max_bias = 0`` turns off position correction, so the pivot only opposes the
relative velocity of the anchor points (with at most ``max_force``) and the gear
only the relative spin (with at most ``max_torque``): exactly Box2D's friction
joint, a velocity constraint with clamped impulses.
"""

from __future__ import annotations

from typing import Any

import pymunk

from kge.components.joints import FrictionJoint
from kge.physics.joint_api import JointContext, register
from kge.physics.joints.base import Composite


class Friction(Composite):
    def __init__(self, ctx: JointContext, entity: int, j: FrictionJoint) -> None:
        super().__init__(ctx, entity, j)
        self.local_anchors(j)
        self.linear = self.angular = None
        if not self.active:
            return
        self.linear = pymunk.PivotJoint(self.a, self.b, j.local_anchor_a, j.local_anchor_b)
        self.angular = pymunk.GearJoint(self.a, self.b, 0.0, 1.0)
        for c in (self.linear, self.angular):
            c.max_bias = 0.0
        self.add(self.linear, self.angular)
        self.configure(j)

    def configure(self, j: Any) -> None:
        assert self.linear is not None and self.angular is not None
        self.linear.anchor_a, self.linear.anchor_b = j.local_anchor_a, j.local_anchor_b
        self.linear.max_force = j.max_force
        self.angular.max_force = j.max_torque

    def read_live(self, j: Any, dt: float) -> None:
        self.write_reaction(
            j, dt, self.impulse_force(self.linear), self.impulse_force(self.angular)
        )


def build(ctx: JointContext, entity: int, j: Any) -> Friction:
    return Friction(ctx, entity, j)


register(FrictionJoint, build)
