"""kge: a data-oriented 2D game engine (esper ECS, pymunk physics with Box2D
semantics, pyglet rendering and audio).

``import kge`` is headless: it never imports pyglet's window, GL or media
modules; rendering and audio load them when an App first needs them.
"""

from kge.app import App, has_display, run
from kge.components import Behaviour, Name, Script, Transform
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
from kge.scene import Scene, Time
from kge.schedule import Stage, System
from kge.timestep import FixedTimestep
from kge.world import World

__version__ = "0.1.0"

__all__ = [
    "App",
    "Behaviour",
    "ComponentTypeError",
    "Coroutine",
    "EntityNotFoundError",
    "FixedTimestep",
    "HookSignatureError",
    "Input",
    "Key",
    "KeyEvent",
    "KgeError",
    "MissingComponentError",
    "MissingResourceError",
    "Mod",
    "Mouse",
    "MouseEvent",
    "Name",
    "Scene",
    "Script",
    "Stage",
    "System",
    "Time",
    "Transform",
    "ValidationError",
    "Wait",
    "WaitFrames",
    "World",
    "WorldLockedError",
    "has_display",
    "run",
]
