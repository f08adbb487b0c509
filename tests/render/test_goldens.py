"""Golden images of the rendering features: 8-bit headless frames compared with PNGs in
``goldens/`` (``pytest --kge-update-goldens`` rewrites them; look at them first).

The numeric pixel tests beside this file check each feature's meaning; these catch any
other change to what a player sees. No text (fonts differ between machines).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from kge import (
    CRT,
    Blend,
    Bloom,
    Camera,
    Collider,
    ColorGrade,
    DirectionalLight,
    ImageRegion,
    Light,
    Lighting,
    Material,
    RenderTexture,
    Shader,
    ShadowCaster,
    Sprite,
    TextureFilter,
    TextureWrap,
    Transform,
    Vignette,
    draw,
)
from kge.components.shapes import Box, Circle
from kge.render.images import checker, from_array, solid
from kge.testbed import paint

from .conftest import SIZE


def _art(world: Any) -> None:
    world.spawn(Transform(0.0, 0.0), Sprite(from_array(paint.sky(128, 64)), size=(12.0, 9.0),
                                            filter=TextureFilter.LINEAR))  # fmt: skip
    world.spawn(Transform(-2.5, -1.5), Sprite(from_array(paint.crate(32)), size=(2.0, 2.0),
                                              filter=TextureFilter.LINEAR))  # fmt: skip
    world.spawn(Transform(2.5, 1.0), Sprite(from_array(paint.orb(32)), size=(2.0, 2.0),
                                            filter=TextureFilter.LINEAR, layer=1))  # fmt: skip


def blends(world: Any) -> None:
    world.insert_resource(Camera(pixels_per_meter=20))
    world.spawn(Transform(), Sprite(from_array(paint.sky(128, 64)), size=(10.0, 8.0),
                                    filter=TextureFilter.LINEAR))  # fmt: skip
    orb = from_array(paint.orb(32, (90, 170, 255)))
    for i, mode in enumerate((Blend.ALPHA, Blend.ADDITIVE, Blend.MULTIPLY, Blend.SCREEN)):
        x = -3.6 + 2.4 * i
        world.spawn(Transform(x, 1.2), Sprite(orb, size=(2.0, 2.0), filter=TextureFilter.LINEAR,
                                              blend=mode, layer=1))  # fmt: skip
        world.spawn(Transform(x, -1.6), draw.Rect(1.8, 1.8, color=(140, 140, 140, 200),
                                                  blend=mode, layer=1))  # fmt: skip


def textures(world: Any) -> None:
    world.insert_resource(Camera(pixels_per_meter=20))
    pattern = checker(8, 8, 2, (230, 90, 40), (40, 60, 200))
    world.spawn(Transform(-2.5, 2.0), Sprite(pattern, size=(3.5, 3.0)))  # nearest
    world.spawn(Transform(2.5, 2.0), Sprite(pattern, size=(3.5, 3.0), filter=TextureFilter.LINEAR))
    world.spawn(Transform(0.0, -0.9), Sprite(from_array(paint.hills(64, 32)), size=(9.0, 1.6),
                                             wrap=TextureWrap.MIRROR, tile=(3.0, 1.6),
                                             filter=TextureFilter.LINEAR))  # fmt: skip
    panel = np.full((12, 12, 4), (200, 200, 220, 255), np.uint8)
    panel[3:9, 3:9] = (60, 70, 90, 255)
    world.spawn(Transform(-2.5, -2.8), Sprite(from_array(panel), size=(4.0, 1.4),
                                              nine_patch=(3, 3, 3, 3)))  # fmt: skip
    world.spawn(Transform(2.5, -2.8), Sprite(ImageRegion(from_array(paint.crate(32)),
                                                         (0, 0, 16, 16)), size=(1.4, 1.4)))


def lights(world: Any) -> None:
    world.insert_resource(Camera(pixels_per_meter=20))
    world.insert_resource(Lighting(ambient=(30, 30, 45)))
    world.spawn(Transform(), Sprite(solid(2, 2, (220, 220, 220)), size=(10.0, 8.0)))
    world.spawn(Transform(-2.5, 1.5), Light(color=(255, 200, 120), radius=5.0, shadows=True,
                                            shadow_softness=0.3))  # fmt: skip
    world.spawn(Transform(2.5, 1.5), Light(color=(120, 180, 255), radius=4.0, shadows=True,
                                           cone=math.pi / 2, direction=-math.pi / 2,
                                           shadow_color=(60, 0, 60)))  # fmt: skip
    world.spawn(DirectionalLight(color=(60, 60, 80), angle=-1.2, shadows=True))
    for x in (-1.5, 0.5, 2.5):
        world.spawn(Transform(x, -0.5), Collider(Box(0.4, 0.4)), ShadowCaster(),
                    draw.Rect(0.8, 0.8, color=(90, 70, 60)))  # fmt: skip
    world.spawn(Transform(-3.0, -2.0), Collider(Circle(0.5)), ShadowCaster(),
                draw.Circle(0.5, color=(70, 90, 60)))  # fmt: skip


def post(world: Any) -> None:
    world.spawn(Camera(pixels_per_meter=20, post=(
        Bloom(threshold=0.6, intensity=1.2), ColorGrade(saturation=1.3, tint=(255, 235, 215)),
        Vignette(strength=0.6), CRT(scanlines=0.3, curvature=0.05))))  # fmt: skip
    _art(world)


def cameras(world: Any) -> None:
    _art(world)
    world.spawn(Camera(pixels_per_meter=20, center=(-2.0, 0.0), viewport=(0.0, 0.0, 0.5, 1.0)))
    world.spawn(Camera(pixels_per_meter=25, center=(2.0, 0.5), rotation=0.3,
                       viewport=(0.5, 0.0, 0.5, 1.0)))  # fmt: skip
    world.spawn(Camera(pixels_per_meter=6, viewport=(0.7, 0.68, 0.28, 0.3), order=1,
                       background=(10, 12, 20)))  # fmt: skip
    world.spawn(Camera(pixels_per_meter=12, center=(2.5, 1.0), target="monitor",
                       target_size=(48, 36), background=(30, 40, 70)))  # fmt: skip
    world.spawn(Transform(-3.5, -2.6), Sprite(RenderTexture("monitor"), size=(2.4, 1.8), layer=3))


def material(world: Any) -> None:
    world.insert_resource(Camera(pixels_per_meter=20))
    stripes = Shader("""
uniform vec3 edge;
vec4 effect(vec4 color, sampler2D tex, vec2 uv, vec2 world)
{
    vec4 c = texture(tex, uv) * color;
    float s = step(0.5, fract(world.x + world.y));
    return vec4(mix(c.rgb, edge, 0.6 * s), c.a);
}""", name="stripes")
    _art(world)
    world.spawn(Transform(0.0, -2.5), draw.Rect(8.0, 1.5, color=(60, 60, 60)),
                Material(stripes, {"edge": (1.0, 0.3, 0.2)}))  # fmt: skip
    world.spawn(Transform(-2.5, -1.5), Sprite(from_array(paint.crate(32)), size=(2.0, 2.0),
                                              filter=TextureFilter.LINEAR, layer=2),
                Material(stripes, {"edge": (0.2, 1.0, 0.4)}))  # fmt: skip


SCENES = {"blends": blends, "textures": textures, "lights": lights, "post": post,
          "cameras": cameras, "material": material}  # fmt: skip


@pytest.mark.parametrize("name", sorted(SCENES))
def test_the_frame_matches_its_golden(make_app, kge_golden, name: str) -> None:
    app = make_app(SCENES[name], size=SIZE, background=(0, 0, 0))
    app.step(2)
    kge_golden(app, name)


def test_every_golden_is_an_8_bit_rgba_picture() -> None:
    from kge.testing import read_png

    for name in SCENES:
        px = read_png(Path(__file__).parent / "goldens" / f"{name}.png")
        assert px.shape == (SIZE[1], SIZE[0], 4) and px.dtype == np.uint8
        assert len(np.unique(px[..., :3].reshape(-1, 3), axis=0)) > 64  # not banded to 16-bit
