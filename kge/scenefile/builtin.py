"""kge's own types, registered under the names users know them by.

Every component, resource and nested value type kge ships is here, with its
entity-reference, asset and world-point fields marked. Drawables are registered
as ``draw.Rect``, ``draw.Circle``... (their names in ``kge.draw``), so they do
not clash with the physics shapes ``Circle`` and ``Polygon``.
"""

from __future__ import annotations

from kge.components import drawables as draw
from kge.components.animation import Animator, Clip, FrameRef, Transition
from kge.components.audio import AudioListener, AudioSource, ImpactSound
from kge.components.camera import Camera
from kge.components.character import Capsule, CharacterBody
from kge.components.collider import Collider
from kge.components.debug import DebugDraw
from kge.components.filter import Filter
from kge.components.joints import (
    DistanceJoint,
    FrictionJoint,
    GearJoint,
    MotorJoint,
    MouseJoint,
    PrismaticJoint,
    PulleyJoint,
    RevoluteJoint,
    RopeJoint,
    WeldJoint,
    WheelJoint,
)
from kge.components.lights import DirectionalLight, Light, Lighting, ShadowCaster
from kge.components.material import Material, Shader
from kge.components.name import Name
from kge.components.particles import (
    BurstOnHit,
    EmitBox,
    EmitCircle,
    EmitCollider,
    EmitLine,
    EmitPoint,
    ParticleAttractor,
    ParticleEmitter,
)
from kge.components.platform import OneWayPlatform
from kge.components.post import CRT, Bloom, ColorGrade, Vignette
from kge.components.resolution import Resolution
from kge.components.rigidbody import RigidBody
from kge.components.shake import CameraShake
from kge.components.shapes import Box, Chain, Circle, Edge, Polygon
from kge.components.sprite import Sprite
from kge.components.text import Text
from kge.components.tilemap import MapObject, TileCollider
from kge.components.transform import Transform
from kge.components.ui import (
    Button,
    Dropdown,
    Label,
    Panel,
    ProgressBar,
    ScrollList,
    Slider,
    TextInput,
    Toggle,
    UIImage,
    UINode,
)
from kge.physics.settings import PhysicsSettings
from kge.scenefile.registry import COMPONENT, RESOURCE, VALUE, TypeRegistry
from kge.ui.theme import Theme

_BODIES = ("body_a", "body_b")


def register_builtin(reg: TypeRegistry) -> None:
    """Register every kge type in ``reg``."""
    plain: tuple[type, ...] = (Transform, RigidBody, Name, OneWayPlatform, ShadowCaster,
                               AudioListener)
    for cls in plain:
        reg.register(cls)
    reg.register(Collider, entity_fields=("body",))
    reg.register(CharacterBody, entity_fields=("floor_collider", "wall_collider"))
    # joints: body references, and the world points a prefab placement moves
    for joint in (RevoluteJoint, WeldJoint, FrictionJoint):
        reg.register(joint, entity_fields=_BODIES, point_fields=("anchor",))
    reg.register(PrismaticJoint, entity_fields=_BODIES, point_fields=("anchor",))
    reg.register(WheelJoint, entity_fields=_BODIES, point_fields=("anchor",))
    for rod in (DistanceJoint, RopeJoint):
        reg.register(rod, entity_fields=_BODIES, point_fields=("anchor_a", "anchor_b"))
    reg.register(PulleyJoint, entity_fields=_BODIES,
                 point_fields=("anchor_a", "anchor_b", "ground_anchor_a", "ground_anchor_b"))
    reg.register(MouseJoint, entity_fields=_BODIES, point_fields=("target", "grab_point"))
    reg.register(MotorJoint, entity_fields=_BODIES)
    reg.register(GearJoint, entity_fields=(*_BODIES, "joint_a", "joint_b"))
    # drawing
    reg.register(Sprite, asset_fields=("image", "normal_map"))
    reg.register(Material)
    reg.register(Text)
    drawables: tuple[type, ...] = (draw.Rect, draw.Circle, draw.Triangle, draw.Polygon,
                                   draw.Line)
    for cls in drawables:
        reg.register(cls, name=f"draw.{cls.__name__}")
    reg.register(Camera, kinds=(COMPONENT, RESOURCE), entity_fields=("follow",))
    reg.register(CameraShake, kinds=(COMPONENT, RESOURCE))
    reg.register(DebugDraw, kinds=(RESOURCE,))
    reg.register(Animator)
    # audio, lights, particles
    reg.register(AudioSource, asset_fields=("sound",))
    reg.register(ImpactSound, asset_fields=("sound",))
    reg.register(Light, asset_fields=("texture",))
    reg.register(DirectionalLight)
    reg.register(Lighting, kinds=(RESOURCE,))
    reg.register(ParticleEmitter, asset_fields=("texture",))
    reg.register(BurstOnHit, entity_fields=("emitter",))
    reg.register(ParticleAttractor)
    # UI
    reg.register(UINode, entity_fields=("parent",))
    reg.register(UIImage, asset_fields=("image",))
    reg.register(Panel, asset_fields=("image",))
    reg.register(Button, asset_fields=("image",))
    widgets: tuple[type, ...] = (Label, Toggle, Slider, ProgressBar, TextInput, Dropdown,
                                 ScrollList)
    for cls in widgets:
        reg.register(cls)
    # tile maps: entities a map made are saved as the map's reference; these are for
    # entities a game gives such components itself
    reg.register(MapObject)
    reg.register(TileCollider)
    # resources
    reg.register(PhysicsSettings, kinds=(RESOURCE,))
    reg.register(Theme, kinds=(RESOURCE,))
    reg.register(Resolution, kinds=(RESOURCE,))
    # values nested in fields
    values: tuple[type, ...] = (Box, Circle, Polygon, Edge, Chain, Capsule, Filter, EmitPoint,
                                EmitCircle, EmitBox, EmitLine, EmitCollider, Clip, Transition,
                                Shader, Bloom, ColorGrade, Vignette, CRT)
    for cls in values:
        reg.register(cls, kinds=(VALUE,))
    reg.register(FrameRef, kinds=(VALUE,), asset_fields=("image",))

