"""kge: a data-oriented 2D game engine (esper ECS, pymunk physics with Box2D
semantics, pyglet rendering and audio).

``import kge`` is headless: it never imports pyglet's window, GL or media
modules; rendering and audio load them when an App first needs them.
"""

from kge.app import App, has_display, run
from kge.assets import AssetDecodeError, AssetError, AssetNotFoundError, Assets, SoundData
from kge.audio import Audio, SoundHandle
from kge.components import Behaviour, Name, Script, Transform
from kge.components.audio import AudioListener, AudioSource, ImpactSound
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
    "AssetDecodeError",
    "AssetError",
    "AssetNotFoundError",
    "Assets",
    "Audio",
    "AudioListener",
    "AudioSource",
    "Behaviour",
    "ComponentTypeError",
    "Coroutine",
    "EntityNotFoundError",
    "FixedTimestep",
    "HookSignatureError",
    "ImpactSound",
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
    "SoundData",
    "SoundHandle",
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
