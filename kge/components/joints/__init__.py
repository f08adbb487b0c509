"""The eleven Box2D joint components (pure data; built by :mod:`kge.physics.joints`).

Every joint is an entity of its own. All but :class:`GearJoint` name two body
entities ``body_a`` and ``body_b`` (None = the world's static ground); a gear
names two joint entities ``joint_a`` and ``joint_b``.
"""

from kge.components.joints.base import Joint
from kge.components.joints.distance import DistanceJoint
from kge.components.joints.friction import FrictionJoint
from kge.components.joints.gear import GearJoint
from kge.components.joints.motor import MotorJoint
from kge.components.joints.mouse import MouseJoint
from kge.components.joints.prismatic import PrismaticJoint
from kge.components.joints.pulley import PulleyJoint
from kge.components.joints.revolute import RevoluteJoint
from kge.components.joints.rope import RopeJoint
from kge.components.joints.weld import WeldJoint
from kge.components.joints.wheel import WheelJoint

__all__ = [
    "DistanceJoint",
    "FrictionJoint",
    "GearJoint",
    "Joint",
    "MotorJoint",
    "MouseJoint",
    "PrismaticJoint",
    "PulleyJoint",
    "RevoluteJoint",
    "RopeJoint",
    "WeldJoint",
    "WheelJoint",
]
