"""Worlds and files the scene-file tests share: one entity of every kge component."""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

from PIL import Image

from kge import (
    Animator,
    AudioListener,
    AudioSource,
    Behaviour,
    Bloom,
    BodyType,
    Box,
    BurstOnHit,
    Button,
    Camera,
    CameraShake,
    Capsule,
    Chain,
    CharacterBody,
    CharacterMode,
    Circle,
    Clip,
    Collider,
    DebugDraw,
    DirectionalLight,
    DistanceJoint,
    Dropdown,
    Edge,
    EmitBox,
    Filter,
    FrictionJoint,
    GearJoint,
    ImpactSound,
    Label,
    Light,
    Lighting,
    Material,
    MotorJoint,
    MouseJoint,
    Name,
    OneWayPlatform,
    Panel,
    ParticleAttractor,
    ParticleEmitter,
    PhysicsSettings,
    Polygon,
    PrismaticJoint,
    ProgressBar,
    PulleyJoint,
    RevoluteJoint,
    RigidBody,
    RopeJoint,
    Script,
    ScrollList,
    Shader,
    ShadowCaster,
    Slider,
    Sprite,
    Text,
    TextInput,
    Toggle,
    Transform,
    UIImage,
    UINode,
    Vignette,
    WeldJoint,
    WheelJoint,
    World,
    draw,
)
from kge.components.tilemap import MapObject, TileCollider
from kge.scenefile import register_script, register_type
from kge.sound import tone


@register_type(kinds=("component", "resource"))
@dataclass(slots=True)
class Health:
    """A game's own component (and resource)."""

    hp: int = 3
    shield: float = 0.5
    tags: list[str] | None = None


@register_script
class Patrol(Script):
    """A game's own script: its data attributes are saved."""

    def __init__(self) -> None:
        self.speed = 2.0
        self.path = [(0.0, 0.0), (3.0, 0.0)]
        self.label = "guard"

    def on_update(self, dt: float) -> None:
        self.transform.x += self.speed * dt * 0.0


def make_assets(folder: Path) -> Path:
    """art/ship.png, art/sheet.png (4 x 2 frames of 8 px) and sfx/hit.wav under ``folder``."""
    (folder / "art").mkdir(parents=True, exist_ok=True)
    (folder / "sfx").mkdir(exist_ok=True)
    Image.new("RGBA", (16, 8), (200, 40, 40, 255)).save(folder / "art" / "ship.png")
    Image.new("RGBA", (32, 16), (40, 200, 40, 255)).save(folder / "art" / "sheet.png")
    (folder / "sfx" / "hit.wav").write_bytes(tone(440, 0.05, rate=8000).to_wav())
    return folder


def everything(world: World, art: Path) -> None:
    """One entity (at least) of every component kge ships, with non-default fields."""
    world.insert_resource(PhysicsSettings(gravity=(0.5, -9.0), substeps=3))
    world.insert_resource(Lighting(ambient=(30, 30, 50)))
    world.insert_resource(DebugDraw(aabbs=True))
    world.insert_resource(Health(hp=9))
    ground = world.spawn(Name("Ground"), Transform(0.0, -1.0), Collider(
        Box(20.0, 1.0), friction=0.6, filter=Filter(category_bits=0x2, group_index=-1)),
        OneWayPlatform(up=(0.0, 1.0)), ShadowCaster())
    world.spawn(Transform(-8.0, 0.0), Collider(Chain([(0.0, 0.0), (1.0, 1.0), (2.0, 1.0)])))
    world.spawn(Transform(8.0, 0.0), Collider(Edge((0.0, 0.0), (1.0, 2.0))))
    hull = world.spawn(Name("Hull"), Transform(0.0, 4.0, 0.25), RigidBody(
        linear_damping=0.1, angular_velocity=0.5, bullet=True),
        Collider(Polygon([(-1.0, -0.5), (1.0, -0.5), (0.0, 0.8)]), density=2.0),
        Sprite(str(art / "art" / "ship.png"), size=(1.0, 0.5), tint=(255, 200, 200), layer=2),
        Health(hp=5, tags=["boss"]), Behaviour(Patrol()),
        AudioSource(str(art / "sfx" / "hit.wav"), volume=0.5),
        ImpactSound(str(art / "sfx" / "hit.wav"), hit_threshold=2.0))
    world.spawn(Transform(0.5, 0.0), Collider(Circle(0.3, center=(0.1, 0.0)), body=hull))
    wheel = world.spawn(Transform(2.0, 4.0), RigidBody(), Collider(Circle(0.4)))
    arm = world.spawn(Transform(-2.0, 4.0), RigidBody(type=BodyType.DYNAMIC, fixed_rotation=False),
                      Collider(Box(0.5, 0.1, center=(0.1, 0.0), angle=0.2)))
    slider = world.spawn(Transform(4.0, 6.0), RigidBody(), Collider(Box(0.2, 0.2)))
    kin = world.spawn(Transform(-4.0, 6.0), RigidBody(type=BodyType.KINEMATIC, velocity=(0.5, 0.0)),
                      Collider(Box(0.3, 0.3)))
    rev = world.spawn(RevoluteJoint(hull, arm, anchor=(-1.0, 4.0), enable_limit=True,
                                    lower_angle=-0.5, upper_angle=0.5))
    pri = world.spawn(PrismaticJoint(None, slider, anchor=(4.0, 6.0), local_axis_a=(0.0, 1.0),
                                     enable_limit=True, lower_translation=-1.0,
                                     upper_translation=1.0))
    world.spawn(GearJoint(rev, pri, ratio=2.0))
    world.spawn(WheelJoint(hull, wheel, anchor=(2.0, 4.0), frequency_hz=4.0))
    world.spawn(DistanceJoint(hull, kin, anchor_a=(0.0, 4.0), anchor_b=(-4.0, 6.0),
                              frequency_hz=2.0, damping_ratio=0.5))
    world.spawn(RopeJoint(hull, slider, max_length=6.0))
    world.spawn(WeldJoint(None, kin, anchor=(-4.0, 6.0), frequency_hz=1.0))
    world.spawn(FrictionJoint(None, wheel, anchor=(2.0, 4.0), max_force=1.0))
    world.spawn(MotorJoint(None, arm, max_force=5.0, correction_factor=0.2))
    world.spawn(PulleyJoint(wheel, slider, ground_anchor_a=(2.0, 8.0), ground_anchor_b=(4.0, 8.0),
                            ratio=1.5))
    world.spawn(MouseJoint(None, kin, target=(-4.0, 6.0), max_force=10.0))
    world.spawn(Transform(1.0, 1.0), Text("hello", size=20.0, color=(255, 0, 0)),
                draw.Rect(1.0, 0.5, color=(0, 0, 255, 128), filled=False),
                Light(color=(255, 240, 200), radius=6.0, shadows=True), AudioListener(),
                Camera(zoom=2.0, follow=hull, bounds=(-20.0, -5.0, 20.0, 15.0)),
                CameraShake(decay=2.0))
    world.spawn(Transform(2.0, 1.0), draw.Circle(0.5, segments=12), Name("Dot"),
                Material(Shader("uniform float glow;\nvec4 effect(vec4 c, sampler2D t, vec2 u, "
                                "vec2 w) { return c * glow; }", name="glow"), {"glow": 1.5}))
    world.spawn(DirectionalLight(angle=-1.2, shadows=True, shadow_softness=0.1),
                Camera(viewport=(0.75, 0.75, 0.25, 0.25), layers=(0, 2), order=1,
                       background=(0, 0, 40), post=(Bloom(intensity=2.0), Vignette())))
    world.spawn(Transform(3.0, 1.0), draw.Triangle((0.0, 0.0), (1.0, 0.0), (0.0, 1.0)))
    world.spawn(Transform(4.0, 1.0), draw.Polygon([(0.0, 0.0), (1.0, 0.0), (1.0, 1.0)]))
    world.spawn(Transform(5.0, 1.0), draw.Line((0.0, 0.0), (1.0, 1.0), thickness=0.1))
    walk = Clip.grid(str(art / "art" / "sheet.png"), (4, 2), frames=range(4), fps=8,
                     events={1: "step"})
    world.spawn(Transform(6.0, 1.0), Sprite(str(art / "art" / "sheet.png"), region=0,
                                             grid=(4, 2)), Animator({"walk": walk}, speed=1.5))
    emitter = world.spawn(Transform(7.0, 1.0), ParticleEmitter(
        rate=20.0, shape=EmitBox(1.0, 0.5), lifetime=(0.5, 1.0), color=((255, 0, 0), (0, 0, 255)),
        seed=7, texture=str(art / "art" / "ship.png")))
    world.spawn(Transform(7.5, 1.0), BurstOnHit(emitter, count=5))
    world.spawn(Transform(8.0, 2.0), ParticleAttractor(strength=-4.0, radius=2.5))
    panel = world.spawn(UINode(anchor="top_left", width=200.0, height="auto", layout="column"),
                        Panel(color=(20, 20, 20, 200)))
    for widget in (Label("Score", size=18.0), Button("Go", image=str(art / "art" / "ship.png")),
                   Toggle(True, "Sound"), Slider(0.0, 10.0, 2.5, step=0.5),
                   ProgressBar(0.3), TextInput("name", max_length=12),
                   Dropdown(["a", "b"], selected=1), ScrollList(["x", "y", "z"], selected=2),
                   UIImage(str(art / "art" / "ship.png"))):
        world.spawn(UINode(parent=panel, width="100%"), widget)
    world.spawn(Transform(9.0, 1.0), MapObject("m.tmx", "objects", 3, "door", "Door", "point",
                                               {"locked": True, "keys": 2}))
    world.spawn(TileCollider("ground", "outline", (0, 0, 4, 1)))
    world.spawn(Transform(-6.0, 1.0), CharacterBody(Capsule(0.3, 0.8), jump_speed=6.5,
                                                    step_height=0.2, mode=CharacterMode.TOP_DOWN))
    assert ground and math.isfinite(world.get(hull, Transform).x)
