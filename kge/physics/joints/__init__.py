"""Box2D's eleven joints as pymunk compositions; importing this registers them all.

One module per joint. Each builds a :class:`~kge.physics.joint_api.JointHandle`
(a :class:`~kge.physics.joints.base.Composite`) from its component; the physics
system drives the handles (see :mod:`kge.physics.joint_api`). Shared pieces:
:mod:`~kge.physics.joints.mechanics` (body masses and lever arms),
:mod:`~kge.physics.joints.rows` (custom velocity steps),
:mod:`~kge.physics.joints.positions` (Box2D's position pass),
:mod:`~kge.physics.joints.pivots` (the same pass and the read-back for all plain
revolute joints at once, with numpy). The mapping, its
sign conventions and the measured comparison with Box2D are in ``docs/joints.md``.
"""

from kge.physics.joints import (
    distance,
    friction,
    gear,
    motor,
    mouse,
    prismatic,
    pulley,
    revolute,
    rope,
    weld,
    wheel,
)

__all__ = [
    "distance",
    "friction",
    "gear",
    "motor",
    "mouse",
    "prismatic",
    "pulley",
    "revolute",
    "rope",
    "weld",
    "wheel",
]
