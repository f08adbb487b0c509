"""Pure-data components. None of them holds a pymunk or pyglet object."""

from kge.components.audio import AudioListener, AudioSource, ImpactSound
from kge.components.behaviour import Behaviour, Script
from kge.components.collider import Collider
from kge.components.filter import Filter
from kge.components.joints import (
    DistanceJoint,
    FrictionJoint,
    GearJoint,
    Joint,
    MotorJoint,
    MouseJoint,
    PrismaticJoint,
    PulleyJoint,
    RevoluteJoint,
    RopeJoint,
    WeldJoint,
    WheelJoint,
)
from kge.components.name import Name
from kge.components.platform import OneWayPlatform
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Chain, Circle, Edge, Polygon
from kge.components.transform import Transform

__all__ = [
    "AudioListener",
    "AudioSource",
    "Behaviour",
    "BodyType",
    "Box",
    "Chain",
    "Circle",
    "Collider",
    "DistanceJoint",
    "Edge",
    "Filter",
    "FrictionJoint",
    "GearJoint",
    "ImpactSound",
    "Joint",
    "MotorJoint",
    "MouseJoint",
    "Name",
    "OneWayPlatform",
    "Polygon",
    "PrismaticJoint",
    "PulleyJoint",
    "RevoluteJoint",
    "RigidBody",
    "RopeJoint",
    "Script",
    "Transform",
    "WeldJoint",
    "WheelJoint",
]
