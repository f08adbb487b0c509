"""Rendering samples: text layout and rich text, materials, blend modes, post effects,
split screen, a minimap with a monitor, a turning camera.

The art is painted in code (:mod:`kge.testbed.paint`), drawn with linear filtering.
"""

from __future__ import annotations

import itertools
import math
from typing import Any

from kge.components import Behaviour, Name, Script, Transform
from kge.components.blend import Blend
from kge.components.camera import Camera
from kge.components.collider import Collider
from kge.components.debug import DebugDraw
from kge.components.drawables import Circle as Disc
from kge.components.drawables import Polygon as Shape
from kge.components.drawables import Rect
from kge.components.material import Material, Shader
from kge.components.particles import EmitCircle, ParticleEmitter
from kge.components.post import CRT, Bloom, ColorGrade, Vignette
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Circle, Polygon
from kge.components.sprite import Sprite, TextureFilter
from kge.components.text import Text, TextAlign, TextOverflow
from kge.components.tween import Tween
from kge.input import Input
from kge.keys import Key
from kge.render.images import RenderTexture, from_array
from kge.systems.animation import tweens_of
from kge.testbed import paint
from kge.testbed.registry import sample
from kge.testbed.samples.build import named
from kge.world import World

#: painted art: sampled smoothly when scaled or turned
SMOOTH = TextureFilter.LINEAR
PARAGRAPH = ("Long labels wrap inside their box, lines sit where align puts them, and text "
             "that does not fit is clipped, ends with an ellipsis or shrinks to fit.")
def _clean(world: World) -> None:
    """Pictures, not physics: the debug view starts off (F1 turns it on)."""
    world.insert_resource(DebugDraw(enabled=False))


BOXES: tuple[tuple[TextAlign, TextOverflow, dict[str, Any]], ...] = (
    (TextAlign.LEFT, TextOverflow.VISIBLE, {}),
    (TextAlign.CENTER, TextOverflow.VISIBLE, {}),
    (TextAlign.RIGHT, TextOverflow.VISIBLE, {}),
    (TextAlign.JUSTIFY, TextOverflow.VISIBLE, {}),
    (TextAlign.LEFT, TextOverflow.CLIP, {"height": 0.75}),
    (TextAlign.LEFT, TextOverflow.ELLIPSIS, {"height": 0.75}),
    (TextAlign.LEFT, TextOverflow.SHRINK, {"height": 0.75}),
    (TextAlign.CENTER, TextOverflow.VISIBLE, {"line_spacing": 1.6}),
)


@sample("Text", "Text Layout", camera=(0.0, 0.4, 0.75),
        help="One paragraph in eight boxes: left, centre, right and justified alignment; "
        "clip, ellipsis and shrink when it does not fit; wider line spacing.")
def text_layout(world: World) -> None:
    _clean(world)
    for i, (align, overflow, extra) in enumerate(BOXES):
        x, top = -6.9 + (i % 4) * 4.6, 3.6 - (i // 4) * 4.4
        label = Text(PARAGRAPH, size=10, width=4.0, align=align, overflow=overflow,
                     anchor=(0.5, 1.0), layer=1, **extra)  # fmt: skip
        from kge.render.text import measure

        height = measure(PARAGRAPH, label.style(64.0)).height / 64.0
        world.spawn(Transform(x, top - height / 2), Rect(4.2, height + 0.2, color=(40, 46, 70)))
        world.spawn(Transform(x, top + 0.35), Text(f"{align}, {overflow}" + (
            ", spacing 1.6" if "line_spacing" in extra else ""), size=9,
            color=(255, 210, 120, 255)))  # fmt: skip
        world.spawn(Transform(x, top), Name("layout"), label)


@text_layout.claim
def _boxes_hold_their_text(app) -> None:  # type: ignore[no-untyped-def]
    from kge.render.text import measure

    for e in named(app.world, "layout"):
        t = app.world.get(e, Text)
        box = measure(t.text, t.style(64.0))
        if t.overflow != "visible":
            assert box.height <= t.style(64.0).height + 1e-6
            assert box.truncated or box.scale < 1.0, "the paragraph does not fit 0.75 m"
        assert all(line.width <= box.width + 1e-6 for line in box.lines)


class _Zoom(Script):
    """Breathes the camera's zoom: the world text is re-rasterised as it changes."""

    def on_update(self, dt: float) -> None:
        cam = self.world.resource(Camera)
        self.t = getattr(self, "t", 0.0) + dt
        cam.zoom = 1.0 + 0.15 * math.sin(self.t * 0.8)


@sample("Text", "Rich Text", camera=(0.0, 0.0, 1.0),
        help="Markup (bold, italic, colours, sizes, inline images), outline and drop "
        "shadow, weights from thin to black, a bitmap font, and world text that stays "
        "crisp while the camera zooms.")
def rich_text(world: World) -> None:
    _clean(world)
    from kge.render.text import BitmapFont, register_bitmap_font, register_icon

    world.insert_resource(Camera(pixels_per_meter=64))
    register_icon("orb", from_array(paint.orb(32)))
    sheet, chars = paint.pixel_font_sheet()
    register_bitmap_font("kge-pixel", BitmapFont(from_array(sheet), chars, cell=(6, 8),
                                                 baseline=1, spacing=0))  # fmt: skip
    world.spawn(Transform(0.0, 3.0), Text(
        "[b]Rich[/b] [i]text[/i]: [color=#ffcc33]gold[/color], [color=cyan]cyan[/color], "
        "[size=22]big[/size], [weight=thin]thin[/weight], [img]orb[/img] x 3",
        size=15, markup=True))  # fmt: skip
    world.spawn(Transform(-3.5, 1.9), Text("Outlined", size=24, outline=3.0,
                                           outline_color=(20, 30, 90, 255)))  # fmt: skip
    world.spawn(Transform(3.5, 1.9), Text("Shadowed", size=24, shadow=(3.0, -3.0),
                                          shadow_blur=2.0))  # fmt: skip
    for i, weight in enumerate(("thin", "light", "normal", "bold", "black")):
        world.spawn(Transform(-4.8 + 2.4 * i, 0.8), Text(weight, size=16, weight=weight,
                                                          font="DejaVu Sans"))  # fmt: skip
    world.spawn(Transform(0.0, -0.3), Text("Italic, and UTF-8: ünïcødé — ½ ✓ ★", size=16,
                                           italic=True))  # fmt: skip
    world.spawn(Transform(0.0, -1.4), Text("PIXEL FONT 123!", font="kge-pixel", size=18))
    spinner = world.spawn(Transform(0.0, -2.7), Name("spinner"),
                          Text("I turn and zoom", size=14, color=(180, 255, 200, 255)))
    tweens_of(world).start(spinner, Tween(Transform, "angle", 2 * math.pi, 8.0, repeat=-1))
    world.spawn(Behaviour(_Zoom()))


@rich_text.claim
def _markup_and_turning_text(app) -> None:  # type: ignore[no-untyped-def]
    t = app.world.get(named(app.world, "spinner")[0], Transform)
    assert 0.5 < t.angle < 2 * math.pi, "the world text turns"
    assert app.world.resource(Camera).zoom != 1.0


DISSOLVE = Shader("""
uniform float amount;   // 0: whole, 1: gone
vec4 effect(vec4 color, sampler2D tex, vec2 uv, vec2 world)
{
    vec4 c = texture(tex, uv) * color;
    float n = fract(sin(dot(floor(world * 12.0), vec2(12.9898, 78.233))) * 43758.5453);
    float edge = smoothstep(amount, amount + 0.08, n);
    vec3 burn = mix(vec3(1.0, 0.5, 0.1), c.rgb, smoothstep(amount + 0.02, amount + 0.1, n));
    return vec4(burn, c.a * edge);
}""", name="dissolve")

WAVE = Shader("""
uniform float speed;
vec4 effect(vec4 color, sampler2D tex, vec2 uv, vec2 world)
{
    float band = 0.5 + 0.5 * sin(world.x * 2.0 - time * speed);
    return vec4(color.rgb * (0.55 + 0.45 * band), color.a);
}""", name="wave")

HUE = Shader("""
vec4 effect(vec4 color, sampler2D tex, vec2 uv, vec2 world)
{
    float h = time * 0.5 + world.y * 0.3;
    vec3 tint = 0.5 + 0.5 * cos(6.2831853 * (h + vec3(0.0, 0.33, 0.67)));
    return texture(tex, uv) * vec4(tint, color.a);
}""", name="hue")


@sample("Materials", "Shader Materials", camera=(0.0, 0.0, 1.0),
        help="Custom GLSL on a crate (a dissolve whose amount a tween animates), on shapes "
        "(a travelling wave) and on particles (a shifting hue).")
def shader_materials(world: World) -> None:
    _clean(world)
    crate_image = from_array(paint.crate(64))
    crate = world.spawn(Transform(-4.0, 0.5), Name("dissolving"),
                        Sprite(crate_image, size=(3.0, 3.0), filter=SMOOTH),
                        Material(DISSOLVE, {"amount": 0.0}))  # fmt: skip
    tweens_of(world).start(crate, Tween(Material, "uniforms.amount", 1.0, 2.2, ease="sine_in_out",
                                        repeat=-1, yoyo=True))  # fmt: skip
    for i in range(3):
        world.spawn(Transform(1.5 + 1.8 * i, 1.5), Rect(1.4, 1.4, color=(90, 180, 255)),
                    Material(WAVE, {"speed": 2.0 + i}))  # fmt: skip
    world.spawn(Transform(3.3, -1.0), Disc(1.0, color=(255, 120, 180)),
                Material(WAVE, {"speed": 4.0}))
    world.spawn(Transform(0.0, -3.0), ParticleEmitter(
        rate=80.0, lifetime=2.0, speed=(1.0, 2.5), direction=math.pi / 2, spread=0.8,
        size=(0.35, 0.1), shape=EmitCircle(0.5), seed=3), Material(HUE))  # fmt: skip


@shader_materials.claim
def _the_dissolve_moves(app) -> None:  # type: ignore[no-untyped-def]
    m = app.world.get(named(app.world, "dissolving")[0], Material)
    assert 0.0 < m.uniforms["amount"] <= 1.0


@sample("Materials", "Blend Modes", camera=(0.0, 0.3, 0.85),
        help="The same glowing orbs and grey squares drawn over a painted sky with alpha, "
        "add, multiply and screen blending.")
def blend_modes(world: World) -> None:
    _clean(world)
    world.spawn(Transform(0.0, 0.0), Sprite(from_array(paint.sky(256, 128)), size=(20.0, 10.0),
                                            filter=SMOOTH))  # fmt: skip
    orb = from_array(paint.orb(64, (90, 170, 255)))
    for i, mode in enumerate((Blend.ALPHA, Blend.ADDITIVE, Blend.MULTIPLY, Blend.SCREEN)):
        x = -6.75 + 4.5 * i
        world.spawn(Transform(x, 3.4), Text(mode, size=14, outline=2.0, layer=2))
        world.spawn(Transform(x, 1.3), Sprite(orb, size=(3.0, 3.0), filter=SMOOTH, blend=mode,
                                              layer=1))  # fmt: skip
        world.spawn(Transform(x, -2.0), Rect(2.6, 2.6, color=(140, 140, 140, 200), blend=mode,
                                             layer=1))  # fmt: skip


@blend_modes.claim
def _four_modes(app) -> None:  # type: ignore[no-untyped-def]
    modes = sorted({s.blend for _, (s,) in app.world.query(Sprite)})
    assert modes == ["additive", "alpha", "multiply", "screen"]


class _ToggleEffects(Script):
    """Keys 1-4 switch bloom, colour grading, vignette and CRT on and off."""

    def on_update(self, dt: float) -> None:
        keys = self.world.resource(Input)
        cam = self.get(Camera)
        for key, effect in zip((Key._1, Key._2, Key._3, Key._4), cam.post, strict=False):
            if keys.pressed(key):
                effect.enabled = not effect.enabled


@sample("Materials", "Post Effects", keys={"1-4": "bloom, grade, vignette, CRT on/off"},
        help="A camera's post-processing stack: glowing orbs bloom, colours graded, the "
        "corners vignetted and the picture curved with scanlines like an old screen.")
def post_effects(world: World) -> None:
    _clean(world)
    world.spawn(Camera(pixels_per_meter=40, post=(
        Bloom(threshold=0.6, intensity=1.4, radius=10.0), ColorGrade(saturation=1.25, contrast=1.1),
        Vignette(strength=0.6), CRT(scanlines=0.25, curvature=0.06))), Name("camera"),
        Behaviour(_ToggleEffects()))  # fmt: skip
    world.spawn(Transform(0.0, 0.0), Sprite(from_array(paint.sky(256, 128, (20, 24, 60),
                                                                 (90, 60, 110))),
                                            size=(26.0, 14.0), filter=SMOOTH))  # fmt: skip
    world.spawn(Transform(0.0, -4.0), Collider(Box(12.0, 0.5)), Rect(24.0, 1.0, color=(50, 60, 80)))
    orb = from_array(paint.orb(64))
    for i in range(7):
        world.spawn(Transform(-7.5 + 2.5 * i, 1.0 + 1.5 * math.sin(i)), RigidBody(),
                    Collider(Circle(0.5), restitution=0.6),
                    Sprite(orb, size=(1.0, 1.0), filter=SMOOTH))  # fmt: skip
    crate = from_array(paint.crate(64))
    for i in range(4):
        world.spawn(Transform(-3.0 + 2.0 * i, -3.0), RigidBody(), Collider(Box(0.5, 0.5)),
                    Sprite(crate, size=(1.0, 1.0), filter=SMOOTH))  # fmt: skip


@post_effects.claim
def _four_effects(app) -> None:  # type: ignore[no-untyped-def]
    cam = app.world.get(named(app.world, "camera")[0], Camera)
    assert [type(e).__name__ for e in cam.post] == ["Bloom", "ColorGrade", "Vignette", "CRT"]


def _terrain(world: World) -> None:
    pts = [(x, -0.3 * x + 1.2 * math.sin(x * 0.3)) for x in range(-40, 41, 4)]
    for (x0, y0), (x1, y1) in itertools.pairwise(pts):
        quad = [(x0, y0 - 3), (x1, y1 - 3), (x1, y1), (x0, y0)]
        world.spawn(Transform(), Collider(Polygon(quad)),
                    Shape(quad, color=(70, 100, 70), layer=1))  # fmt: skip
    world.spawn(Transform(0.0, 2.0), Sprite(from_array(paint.sky(256, 128)), size=(100.0, 50.0),
                                            filter=SMOOTH))  # fmt: skip


@sample("Cameras", "Split Screen", help="Two balls roll down a long slope; each half of "
        "the window has a camera following one of them. The HUD is drawn once over both.")
def split_screen(world: World) -> None:
    _clean(world)
    _terrain(world)
    hero = from_array(paint.hero(64))
    for i, (x, body) in enumerate(((-32.0, (225, 80, 70)), (-37.0, (80, 140, 230)))):
        ball = world.spawn(Transform(x, 13.0), Name(f"ball-{i}"), RigidBody(),
                           Collider(Circle(0.6), friction=0.9 - 0.5 * i),
                           Sprite(from_array(paint.hero(64, body)) if i else hero, size=(1.2, 1.2),
                                  filter=SMOOTH))  # fmt: skip
        world.spawn(Name(f"camera-{i}"), Camera(
            pixels_per_meter=32, follow=ball, smoothing=0.2,
            viewport=(0.5 * i, 0.0, 0.5, 1.0)))  # fmt: skip
    world.spawn(Text("split screen: two cameras", size=14, screen_space=True, offset=(10, 10),
                     anchor=(0, 0), outline=2.0))  # fmt: skip


@split_screen.claim
def _each_camera_follows_its_ball(app) -> None:  # type: ignore[no-untyped-def]
    for i in range(2):
        ball = app.world.get(named(app.world, f"ball-{i}")[0], Transform)
        cam = app.world.get(named(app.world, f"camera-{i}")[0], Camera)
        assert math.hypot(cam.center[0] - ball.x, cam.center[1] - ball.y) < 2.5


class _Spin(Script):
    def on_update(self, dt: float) -> None:
        self.transform.angle += dt


@sample("Cameras", "Minimap and Monitor",
        help="The main camera follows a ball; a minimap in the corner shows the whole level "
        "without decoration (its own layers); a monitor on the wall is a sprite showing what "
        "a third camera sees of a spinning crate (render to texture).")
def minimap(world: World) -> None:
    _clean(world)
    _terrain(world)
    ball = world.spawn(Transform(-34.0, 13.0), Name("ball"), RigidBody(),
                       Collider(Circle(0.6), friction=0.9),
                       Sprite(from_array(paint.hero(64)), size=(1.2, 1.2), filter=SMOOTH),
                       Disc(1.2, color=(255, 80, 60), layer=5))  # fmt: skip
    world.spawn(Camera(pixels_per_meter=32, follow=ball, layers=(0, 1, 2)))
    world.spawn(Camera(pixels_per_meter=3, center=(0.0, 0.0), viewport=(0.72, 0.7, 0.26, 0.28),
                       background=(10, 12, 20), layers=(1, 5), order=1))  # fmt: skip
    world.spawn(Transform(100.0, 0.0), Name("spinner"), Behaviour(_Spin()),
                Sprite(from_array(paint.crate(64)), size=(2.0, 2.0), filter=SMOOTH, layer=9))
    world.spawn(Camera(center=(100.0, 0.0), pixels_per_meter=24, target="monitor",
                       target_size=(128, 96), background=(30, 40, 70), layers=(9,)))  # fmt: skip
    world.spawn(Transform(-28.0, 14.0), Name("monitor"),
                Sprite(RenderTexture("monitor"), size=(4.0, 3.0), layer=1),
                Rect(4.4, 3.4, color=(20, 20, 20), layer=0))  # fmt: skip


@minimap.claim
def _the_monitor_shows_the_crate(app) -> None:  # type: ignore[no-untyped-def]
    from kge.render.setup import frame_pixels

    world = app.world
    monitor = world.get(named(world, "monitor")[0], Transform)
    cams = [c for _, (c,) in world.query(Camera)]
    main = next(c for c in cams if c.target is None and c.order == 0)
    main.center = (monitor.x, monitor.y)
    main.follow = None
    app.render()
    sx, sy = main.world_to_screen((monitor.x + 1.4, monitor.y), app.size)
    px = frame_pixels(app)[int(sy), int(sx), :3]
    assert tuple(px) == (30, 40, 70), f"the monitor shows the other camera's picture: {px}"


@sample("Cameras", "Camera Rotation", camera=(0.0, 3.0, 1.0),
        help="A camera slowly turning around a tower of crates: the world, its text and "
        "the mouse picking turn with it.")
def camera_rotation(world: World) -> None:
    _clean(world)
    cam = world.spawn(Name("camera"), Camera(center=(0.0, 3.0), pixels_per_meter=40))
    tweens_of(world).start(cam, Tween(Camera, "rotation", 0.6, 3.0, ease="sine_in_out",
                                      repeat=-1, yoyo=True, start=-0.6))  # fmt: skip
    world.spawn(Transform(0.0, -0.5), Collider(Box(8.0, 0.5)), Rect(16.0, 1.0, color=(60, 70, 90)))
    crate = from_array(paint.crate(64))
    for row in range(6):
        world.spawn(Transform(0.0, 0.5 + row * 1.0), Name("crate"), RigidBody(),
                    Collider(Box(0.5, 0.5), friction=0.8),
                    Sprite(crate, size=(1.0, 1.0), filter=SMOOTH))  # fmt: skip
    world.spawn(Transform(0.0, 7.5), Text("turning camera", size=18, outline=2.0))


@camera_rotation.claim
def _it_turns_and_the_tower_stands(app) -> None:  # type: ignore[no-untyped-def]
    cam = app.world.get(named(app.world, "camera")[0], Camera)
    assert abs(cam.rotation) > 0.05
    for e in named(app.world, "crate"):
        assert abs(app.world.get(e, Transform).x) < 0.2
