"""kge: a data-oriented 2D game engine (esper ECS, pymunk physics with Box2D
semantics, pyglet rendering and audio).

``import kge`` is headless: it never imports pyglet's window, GL or media
modules. The names of the audio, asset and image modules are loaded on first use
(``kge.Audio``, ``kge.Assets``, ``kge.solid``...), so a physics-only App never
imports them; rendering and audio load pyglet when an App first needs them.
"""

from importlib import import_module
from typing import TYPE_CHECKING, Any

import kge.dependencies  # noqa: F401  (first: a missing dependency is named, with the venv to use)
from kge import collision as collision  # Box2D's collision module, no World needed
from kge.animation import (
    AnimationEvent,
    AnimationEvents,
    AnimationFinished,
    CubicBezier,
    EaseCurve,
    TweenFinished,
    TweenHandle,
    Tweens,
    ease,
    gif_clip,
)
from kge.app import App, run
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
from kge.components.animation import Animator, Clip, FrameRef, Loop, Transition
from kge.components.audio import AudioListener, AudioSource, ImpactSound
from kge.components.blend import Blend
from kge.components.camera import Camera
from kge.components.character import Capsule, CharacterBody, CharacterMode  # docs/character.md
from kge.components.debug import DebugDraw

# particles and lights (issue 18): components here, plugins and the resource on first use
from kge.components.lights import DirectionalLight, Light, Lighting, ShadowCaster
from kge.components.material import Material, Shader, ShaderWarning
from kge.components.particle_flipbook import ParticleFlipbook
from kge.components.particle_stretch import ParticleStretch
from kge.components.particle_subemitters import ParticleSubEmitters, SubEmitEvent, SubEmitter
from kge.components.particle_trail import ParticleTrail, TrailMode
from kge.components.particle_turbulence import ParticleTurbulence
from kge.components.particles import (
    BurstOnHit,
    EmitBox,
    EmitCircle,
    EmitCollider,
    EmitLine,
    EmitPoint,
    ParticleAttractor,
    ParticleBurst,
    ParticleCollision,
    ParticleEmitter,
    ParticleSpace,
)
from kge.components.post import CRT, Bloom, ColorGrade, Vignette
from kge.components.resolution import Resolution, ScaleMode
from kge.components.shake import CameraShake
from kge.components.sprite import Sprite, TextureFilter, TextureWrap
from kge.components.text import Text, TextAlign, TextOverflow, TextStyle, VerticalAlign
from kge.components.tilemap import MapObject, TileCollider  # tile maps (docs/tilemaps.md)
from kge.components.tween import Call, Delay, Parallel, Tween, TweenSequence
from kge.coroutines import Coroutine, Wait, WaitFrames
from kge.errors import (
    ComponentTypeError,
    DisplayError,
    EntityNotFoundError,
    HookSignatureError,
    KgeError,
    MissingComponentError,
    MissingResourceError,
    SceneStackError,
    ScheduleError,
    ValidationError,
    WorldLockedError,
)
from kge.host import CloseRequested
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
from kge.physics.queries import QueryHit, RayHit, RayMode
from kge.physics.resource import Physics
from kge.physics.settings import PhysicsSettings
from kge.platform import has_display
from kge.plugin import FunctionPlugin, Plugin, PluginError
from kge.plugins import default_plugins
from kge.scene import Scene, Time
from kge.scene_carry import RestoreWarning
from kge.scenefile import (  # scene, prefab and save files (docs/scene-files.md)
    SceneFile,
    SceneFileError,
    instantiate,
    load_game,
    load_scene,
    register_script,
    register_type,
    save_game,
    save_prefab,
    save_scene,
)
from kge.schedule import Stage, System, SystemSet
from kge.snapshot import SnapshotError
from kge.sound import SoundData
from kge.systems.behaviour import BehaviourPlugin
from kge.systems.character import CharacterPlugin
from kge.systems.physics import PhysicsPlugin
from kge.text.fonts import FontWarning
from kge.tilemap import Spawn, Spawners, TileMap, TilemapError, TilemapWarning, load_map
from kge.timestep import FixedTimestep
from kge.timings import SystemTimings
from kge.world import World

# isort: split
# -- UI, scenes and input actions (docs/ui-scenes-input.md) --
from kge.action_clock import ActionPressed, ActionReleased
from kge.actions import InputMap, UnknownActionError
from kge.components.ui import (
    Button,
    ColorPicker,
    Dialog,
    DialogButton,
    Draggable,
    Dropdown,
    DropTarget,
    Label,
    Panel,
    ProgressBar,
    RadioGroup,
    RichText,
    ScrollList,
    ScrollView,
    Slider,
    SpinBox,
    Style,
    Tabs,
    TextArea,
    TextInput,
    Toggle,
    Tooltip,
    TreeItem,
    TreeView,
    UIImage,
    UINode,
)
from kge.input import Gamepad, GamepadEvent, TextEvent
from kge.touch import (
    DragGesture,
    PinchGesture,
    RotateGesture,
    TapGesture,
    TouchPoint,
)
from kge.transitions import Crossfade, Fade, Slide, Wipe  # base class: kge.transitions.Transition
from kge.ui import (
    ButtonClicked,
    DialogClosed,
    DragCancelled,
    DragStarted,
    Dropped,
    FocusChanged,
    ItemActivated,
    ItemToggled,
    TextSubmitted,
    Theme,
    TreeDrop,
    UIEvents,
    UISettings,
    ValueChanged,
)
from kge.ui.dialogs import confirm, message_box

if TYPE_CHECKING:
    from kge.assets import (
        AssetDecodeError,
        AssetError,
        AssetNotFoundError,
        Assets,
        DecoderMissingError,
    )
    from kge.audio import Audio, SoundHandle
    from kge.export import ExportError
    from kge.particles import Particles
    from kge.render.images import (
        ImageRegion,
        PixelImage,
        RenderTexture,
        checker,
        from_array,
        solid,
    )
    from kge.render.sheets import SheetError, SpriteSheet, load_sheet
    from kge.scaffold import ScaffoldError
    from kge.systems.animation import AnimationPlugin, Animations, shake
    from kge.systems.audio import AudioPlugin
    from kge.systems.lighting import LightingPlugin
    from kge.systems.particle_effects import ParticleEffectsPlugin
    from kge.systems.particles import ParticlesPlugin
    from kge.systems.render import RenderPlugin
    from kge.systems.tilemap import TilemapPlugin
    from kge.testing import GoldenMismatch, StepTimeout, UITargetError

    # isort: split
    from kge.systems.loading import LoadingScreen
    from kge.systems.ui import UIPlugin, focus

#: names whose modules load pyglet or the asset store: imported on first use
_LAZY = {
    "AssetDecodeError": "kge.assets",
    "AssetError": "kge.assets",
    "AssetNotFoundError": "kge.assets",
    "Assets": "kge.assets",
    "DecoderMissingError": "kge.assets",
    "ScaffoldError": "kge.scaffold",
    "ExportError": "kge.export",
    "GoldenMismatch": "kge.testing",
    "StepTimeout": "kge.testing",
    "UITargetError": "kge.testing",
    "Audio": "kge.audio",
    "SoundHandle": "kge.audio",
    "PixelImage": "kge.render.images",
    "ImageRegion": "kge.render.images",
    "RenderTexture": "kge.render.images",
    "checker": "kge.render.images",
    "from_array": "kge.render.images",
    "solid": "kge.render.images",
    "SheetError": "kge.render.sheets",
    "SpriteSheet": "kge.render.sheets",
    "load_sheet": "kge.render.sheets",
    "AudioPlugin": "kge.systems.audio",
    "AnimationPlugin": "kge.systems.animation",
    "Animations": "kge.systems.animation",
    "shake": "kge.systems.animation",
    "RenderPlugin": "kge.systems.render",
    "LoadingScreen": "kge.systems.loading",
    "UIPlugin": "kge.systems.ui",
    "focus": "kge.systems.ui",
    "Particles": "kge.particles",
    "ParticleEffectsPlugin": "kge.systems.particle_effects",
    "ParticlesPlugin": "kge.systems.particles",
    "LightingPlugin": "kge.systems.lighting",
    "TilemapPlugin": "kge.systems.tilemap",
}


#: old names kept for one release: name -> (module, new name); reading one warns
_RENAMED = {
    "Sequence": ("kge.components.tween", "TweenSequence"),  # shadowed typing.Sequence
}


def __getattr__(name: str) -> Any:
    renamed = _RENAMED.get(name)
    if renamed is not None:
        from kge.deprecation import warn

        warn(f"kge.{name} is now kge.{renamed[1]}")
        return getattr(import_module(renamed[0]), renamed[1])
    module = _LAZY.get(name)
    if module is None:
        raise AttributeError(f"module 'kge' has no attribute {name!r}")
    value = getattr(import_module(module), name)
    globals()[name] = value  # later lookups skip this function
    return value


__version__ = "2.0.0a1"

__all__ = [
    "CRT",
    "AnimationEvent",
    "AnimationEvents",
    "AnimationFinished",
    "AnimationPlugin",
    "Animations",
    "Animator",
    "App",
    "AssetDecodeError",
    "AssetError",
    "AssetNotFoundError",
    "Assets",
    "Audio",
    "AudioListener",
    "AudioPlugin",
    "AudioSource",
    "Behaviour",
    "BehaviourPlugin",
    "Blend",
    "Bloom",
    "BodyType",
    "Box",
    "BurstOnHit",
    "Call",
    "Camera",
    "CameraShake",
    "Capsule",
    "Chain",
    "CharacterBody",
    "CharacterMode",
    "CharacterPlugin",
    "Circle",
    "Clip",
    "CloseRequested",
    "Collider",
    "ColorGrade",
    "ComponentTypeError",
    "ContactBegin",
    "ContactEnd",
    "Coroutine",
    "CubicBezier",
    "DebugDraw",
    "DecoderMissingError",
    "Delay",
    "DirectionalLight",
    "DisplayError",
    "DistanceJoint",
    "EaseCurve",
    "Edge",
    "EmitBox",
    "EmitCircle",
    "EmitCollider",
    "EmitLine",
    "EmitPoint",
    "EntityNotFoundError",
    "ExportError",
    "Filter",
    "FixedTimestep",
    "FontWarning",
    "FrameRef",
    "FrictionJoint",
    "FunctionPlugin",
    "GearJoint",
    "GoldenMismatch",
    "Hit",
    "HookSignatureError",
    "ImageRegion",
    "ImpactSound",
    "Input",
    "Joint",
    "JointBroken",
    "JointDestroyed",
    "Key",
    "KeyEvent",
    "KgeError",
    "Light",
    "Lighting",
    "LightingPlugin",
    "Loop",
    "MapObject",
    "MassData",
    "Material",
    "MissingComponentError",
    "MissingResourceError",
    "Mod",
    "MotorJoint",
    "Mouse",
    "MouseEvent",
    "MouseJoint",
    "Name",
    "OneWayPlatform",
    "Parallel",
    "ParticleAttractor",
    "ParticleBurst",
    "ParticleCollision",
    "ParticleEffectsPlugin",
    "ParticleEmitter",
    "ParticleFlipbook",
    "ParticleSpace",
    "ParticleStretch",
    "ParticleSubEmitters",
    "ParticleTrail",
    "ParticleTurbulence",
    "Particles",
    "ParticlesPlugin",
    "Physics",
    "PhysicsEvents",
    "PhysicsPlugin",
    "PhysicsSettings",
    "PixelImage",
    "Plugin",
    "PluginError",
    "Polygon",
    "PostSolve",
    "PreSolve",
    "PrismaticJoint",
    "PulleyJoint",
    "QueryHit",
    "RayHit",
    "RayMode",
    "RenderPlugin",
    "RenderTexture",
    "Resolution",
    "RestoreWarning",
    "RevoluteJoint",
    "RigidBody",
    "RopeJoint",
    "ScaffoldError",
    "ScaleMode",
    "Scene",
    "SceneFile",
    "SceneFileError",
    "SceneStackError",
    "ScheduleError",
    "Script",
    "SensorBegin",
    "SensorEnd",
    "Shader",
    "ShaderWarning",
    "ShadowCaster",
    "SheetError",
    "SnapshotError",
    "SoundData",
    "SoundHandle",
    "Spawn",
    "Spawners",
    "Sprite",
    "SpriteSheet",
    "Stage",
    "StepTimeout",
    "SubEmitEvent",
    "SubEmitter",
    "System",
    "SystemSet",
    "Text",
    "TextAlign",
    "TextOverflow",
    "TextStyle",
    "TextureFilter",
    "TextureWrap",
    "TileCollider",
    "TileMap",
    "TilemapError",
    "TilemapPlugin",
    "TilemapWarning",
    "Time",
    "TrailMode",
    "Transform",
    "Transition",
    "Tween",
    "TweenFinished",
    "TweenHandle",
    "TweenSequence",
    "Tweens",
    "UITargetError",
    "ValidationError",
    "VerticalAlign",
    "Vignette",
    "Wait",
    "WaitFrames",
    "WeldJoint",
    "WheelJoint",
    "World",
    "WorldLockedError",
    "checker",
    "collision",
    "default_plugins",
    "draw",
    "ease",
    "from_array",
    "gif_clip",
    "has_display",
    "instantiate",
    "load_game",
    "load_map",
    "load_scene",
    "load_sheet",
    "register_script",
    "register_type",
    "run",
    "save_game",
    "save_prefab",
    "save_scene",
    "shake",
    "solid",
]

# UI, scenes and input actions (docs/ui-scenes-input.md)
__all__ += [
    "ActionPressed",
    "ActionReleased",
    "Button",
    "ButtonClicked",
    "ColorPicker",
    "Crossfade",
    "Dialog",
    "DialogButton",
    "DialogClosed",
    "DragCancelled",
    "DragGesture",
    "DragStarted",
    "Draggable",
    "DropTarget",
    "Dropdown",
    "Dropped",
    "Fade",
    "FocusChanged",
    "Gamepad",
    "GamepadEvent",
    "InputMap",
    "ItemActivated",
    "ItemToggled",
    "Label",
    "LoadingScreen",
    "Panel",
    "PinchGesture",
    "ProgressBar",
    "RadioGroup",
    "RichText",
    "RotateGesture",
    "ScrollList",
    "ScrollView",
    "Slide",
    "Slider",
    "SpinBox",
    "Style",
    "Tabs",
    "TapGesture",
    "TextArea",
    "TextEvent",
    "TextInput",
    "TextSubmitted",
    "Theme",
    "Toggle",
    "Tooltip",
    "TouchPoint",
    "TreeDrop",
    "TreeItem",
    "TreeView",
    "UIEvents",
    "UIImage",
    "UINode",
    "UIPlugin",
    "UISettings",
    "UnknownActionError",
    "ValueChanged",
    "Wipe",
    "confirm",
    "focus",
    "message_box",
]

# -- debug tools (docs/debug.md): gizmos, console, live inspector, system timings --
if TYPE_CHECKING:
    from kge.debug import Console, ConsoleError, DebugPlugin, Gizmos, Inspector

_LAZY.update(
    {
        "Console": "kge.debug",
        "ConsoleError": "kge.debug",
        "DebugPlugin": "kge.debug",
        "Gizmos": "kge.debug",
        "Inspector": "kge.debug",
    }
)
__all__ += ["Console", "ConsoleError", "DebugPlugin", "Gizmos", "Inspector", "SystemTimings"]
