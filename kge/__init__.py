"""kge: a data-oriented 2D game engine (esper ECS, pymunk physics with Box2D
semantics, pyglet rendering and audio).

``import kge`` is headless: it never imports pyglet's window, GL or media
modules; rendering and audio load them when an App first needs them.
"""

from kge.app import App, has_display, run
from kge.assets import AssetDecodeError, AssetError, AssetNotFoundError, Assets, SoundData
from kge.audio import Audio, SoundHandle
from kge.components import (
    Behaviour,
    BodyType,
    Box,
    Chain,
    Circle,
    Collider,
    DistanceJoint,
    Edge,
    Filter,
    FrictionJoint,
    GearJoint,
    Joint,
    MotorJoint,
    MouseJoint,
    Name,
    OneWayPlatform,
    Polygon,
    PrismaticJoint,
    PulleyJoint,
    RevoluteJoint,
    RigidBody,
    RopeJoint,
    Script,
    Transform,
    WeldJoint,
    WheelJoint,
)
from kge.components import drawables as draw
from kge.components.audio import AudioListener, AudioSource, ImpactSound
from kge.components.camera import Camera
from kge.components.debug import DebugDraw
from kge.components.sprite import Sprite
from kge.components.text import Text
from kge.coroutines import Coroutine, Wait, WaitFrames
from kge.errors import (
    ComponentTypeError,
    EntityNotFoundError,
    HookSignatureError,
    KgeError,
    MissingComponentError,
    MissingResourceError,
    ValidationError,
    WorldLockedError,
)
from kge.input import Input, KeyEvent, MouseEvent
from kge.keys import Key, Mod, Mouse
from kge.physics.contacts import PostSolve, PreSolve
from kge.physics.events import (
    ContactBegin,
    ContactEnd,
    Hit,
    JointBroken,
    JointDestroyed,
    PhysicsEvents,
    SensorBegin,
    SensorEnd,
)
from kge.physics.mass import MassData
from kge.physics.queries import QueryHit, RayHit
from kge.physics.resource import Physics
from kge.physics.settings import PhysicsSettings
from kge.render.images import PixelImage, checker, from_array, solid
from kge.scene import Scene, Time
from kge.schedule import Stage, System
from kge.timestep import FixedTimestep
from kge.world import World

__version__ = "0.1.0"

__all__ = [
    "App",
    "AssetDecodeError",
    "AssetError",
    "AssetNotFoundError",
    "Assets",
    "Audio",
    "AudioListener",
    "AudioSource",
    "Behaviour",
    "BodyType",
    "Box",
    "Camera",
    "Chain",
    "Circle",
    "Collider",
    "ComponentTypeError",
    "ContactBegin",
    "ContactEnd",
    "Coroutine",
    "DebugDraw",
    "DistanceJoint",
    "Edge",
    "EntityNotFoundError",
    "Filter",
    "FixedTimestep",
    "FrictionJoint",
    "GearJoint",
    "Hit",
    "HookSignatureError",
    "ImpactSound",
    "Input",
    "Joint",
    "JointBroken",
    "JointDestroyed",
    "Key",
    "KeyEvent",
    "KgeError",
    "MassData",
    "MissingComponentError",
    "MissingResourceError",
    "Mod",
    "MotorJoint",
    "Mouse",
    "MouseEvent",
    "MouseJoint",
    "Name",
    "OneWayPlatform",
    "Physics",
    "PhysicsEvents",
    "PhysicsSettings",
    "PixelImage",
    "Polygon",
    "PostSolve",
    "PreSolve",
    "PrismaticJoint",
    "PulleyJoint",
    "QueryHit",
    "RayHit",
    "RevoluteJoint",
    "RigidBody",
    "RopeJoint",
    "Scene",
    "Script",
    "SensorBegin",
    "SensorEnd",
    "SoundData",
    "SoundHandle",
    "Sprite",
    "Stage",
    "System",
    "Text",
    "Time",
    "Transform",
    "ValidationError",
    "Wait",
    "WaitFrames",
    "WeldJoint",
    "WheelJoint",
    "World",
    "WorldLockedError",
    "checker",
    "draw",
    "from_array",
    "has_display",
    "run",
    "solid",
]
