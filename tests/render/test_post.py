"""Post-processing stacks per camera: bloom, colour grading, vignette, CRT, custom passes."""

from __future__ import annotations

import numpy as np
import pytest

from kge import Transform, Tween, Tweens
from kge.components.camera import Camera
from kge.components.drawables import Rect
from kge.components.material import Material, Shader
from kge.components.post import CRT, Bloom, ColorGrade, Vignette
from kge.errors import ValidationError

from .conftest import SIZE, pixels

MID = (SIZE[1] // 2, SIZE[0] // 2)


def _scene(*post, background=(0, 0, 0), color=(120, 160, 200)):
    def scene(world):
        world.spawn(Camera(pixels_per_meter=20, post=post))
        world.spawn(Transform(), Rect(40.0, 40.0, color=color))

    return scene


def test_no_effect_enabled_draws_the_picture_unchanged(make_app):
    plain = pixels(make_app(_scene()))
    off = pixels(make_app(_scene(Vignette(enabled=False), ColorGrade(enabled=False))))
    assert np.array_equal(plain, off)


def test_colour_grading_desaturates_brightens_and_tints(make_app):
    grey = pixels(make_app(_scene(ColorGrade(saturation=0.0))))[MID][:3].astype(int)
    assert max(grey) - min(grey) <= 1  # saturation 0: a grey
    lum = 0.2126 * 120 + 0.7152 * 160 + 0.0722 * 200
    assert abs(grey[0] - lum) <= 2
    bright = pixels(make_app(_scene(ColorGrade(brightness=0.2))))[MID][:3].astype(int)
    assert np.all(np.abs(bright - (171, 211, 251)) <= 2)
    tint = pixels(make_app(_scene(ColorGrade(tint=(255, 0, 0)))))[MID][:3]
    assert tuple(tint) == (120, 0, 0)


def test_the_vignette_darkens_corners_not_the_centre(make_app):
    px = pixels(make_app(_scene(Vignette(strength=1.0, radius=0.3, softness=0.6))))
    assert tuple(px[MID][:3]) == (120, 160, 200)
    assert px[2, 2, :3].max() < 30


def test_bloom_makes_bright_pixels_glow_past_their_edge(make_app):
    def scene(world, bloom):
        post = (Bloom(threshold=0.5, intensity=1.5, radius=8.0),) if bloom else ()
        world.spawn(Camera(pixels_per_meter=20, post=post))
        world.spawn(Transform(-2.0, 0.0), Rect(1.0, 1.0, color=(255, 255, 255)))  # bright
        world.spawn(Transform(2.0, 0.0), Rect(1.0, 1.0, color=(90, 90, 90)))  # dim

    plain = pixels(make_app(lambda w: scene(w, False)))
    glow = pixels(make_app(lambda w: scene(w, True)))
    y = MID[0]
    bright_edge = MID[1] - 40 + 14  # 4 pixels right of the bright square
    dim_edge = MID[1] + 40 + 14
    assert plain[y, bright_edge, 0] == 0 and glow[y, bright_edge, 0] > 40
    assert glow[y, dim_edge, 0] <= 2  # below the threshold: no glow


def test_crt_curves_the_picture_and_draws_scanlines(make_app):
    px = pixels(make_app(_scene(CRT(scanlines=0.8, curvature=0.3, aberration=0.0))))
    assert px[1, 1, :3].max() == 0  # the corners fall off the curved screen
    column = px[MID[0] - 20 : MID[0] + 20, MID[1], 2].astype(int)
    assert column.max() - column.min() > 60  # rows alternate light and dark


def test_a_material_is_a_custom_full_screen_pass(make_app):
    invert = Shader("""
vec4 effect(vec4 color, sampler2D tex, vec2 uv, vec2 pixel)
{
    return vec4(1.0 - color.rgb, 1.0);
}""", name="invert")
    px = pixels(make_app(_scene(Material(invert))))
    assert tuple(px[MID][:3]) == (135, 95, 55)


def test_effects_are_tweened_by_targeting_them(make_app):
    grade = ColorGrade(brightness=0.0)
    app = make_app(_scene(grade))
    app.world.resource(Tweens).start(grade, Tween(ColorGrade, "brightness", -0.4, 0.5))
    app.step(40)
    assert grade.brightness == -0.4
    assert np.all(np.abs(pixels(app)[MID][:3].astype(int) - (18, 58, 98)) <= 2)


def test_post_effects_refuse_bad_values():
    with pytest.raises(ValidationError, match="Bloom.intensity"):
        Bloom(intensity=-1.0)
    with pytest.raises(ValidationError, match="CRT.curvature"):
        CRT(curvature=2.0)
    bloom = Bloom()
    with pytest.raises(ValidationError):
        bloom.radius = float("nan")
