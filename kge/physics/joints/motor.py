"""MotorJoint = PivotJoint(A at linear_offset, B's origin) + GearJoint(phase=angular_offset).

Both are force-capped (``max_force`` / ``max_torque``). Box2D's motor joint
removes ``correction_factor`` of the pose error per step; pymunk's
``error_bias`` is the error left after one second, so
``error_bias = (1 - correction_factor)^(1/h)``.
"""

from __future__ import annotations

from typing import Any

import pymunk

from kge.components.joints import MotorJoint
from kge.physics.joint_api import JointContext, register
from kge.physics.joints.base import Composite


class Motor(Composite):
    def __init__(self, ctx: JointContext, entity: int, j: MotorJoint) -> None:
        super().__init__(ctx, entity, j)
        self.h = ctx.dt
        self.linear = self.angular = None
        if not self.active:
            return
        self.linear = pymunk.PivotJoint(self.a, self.b, j.linear_offset, (0, 0))
        self.angular = pymunk.GearJoint(self.a, self.b, j.angular_offset, 1.0)
        # its correction is what it is for, bounded by max_force / max_torque
        self.add(self.linear, self.angular, capped=False)
        self.configure(j)

    def configure(self, j: Any) -> None:
        assert self.linear is not None and self.angular is not None
        self.linear.anchor_a = j.linear_offset
        self.angular.phase = j.angular_offset
        self.linear.max_force = j.max_force
        self.angular.max_force = j.max_torque
        bias = (1.0 - j.correction_factor) ** (1.0 / self.h)
        self.linear.error_bias = self.angular.error_bias = bias

    def read_live(self, j: Any, dt: float) -> None:
        self.write_reaction(
            j, dt, self.impulse_force(self.linear), self.impulse_force(self.angular)
        )


def build(ctx: JointContext, entity: int, j: Any) -> Motor:
    return Motor(ctx, entity, j)


register(MotorJoint, build)
