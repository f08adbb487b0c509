"""Iris and user-shader scene transitions: timing, pixels, bad input, a broken shader."""

from __future__ import annotations

import warnings
from typing import Any

import pytest

from kge import App, Transform, World
from kge.components.camera import Camera
from kge.components.drawables import Rect
from kge.components.material import ShaderWarning
from kge.errors import ComponentTypeError, ValidationError
from kge.transition_shaders import Iris, ShaderTransition
from kge.transitions import ActiveTransition

from .conftest import mask, pixels

RED = (255, 0, 0, 255)
BLUE = (0, 0, 255, 255)
WHITE = (255, 255, 255, 255)


def red_scene(world: World) -> None:
    world.insert_resource(Camera(pixels_per_meter=20))  # a 200 px window, all red
    world.spawn(Transform(0, 0), Rect(12.0, 12.0, color=RED))


def blue_scene(world: World) -> None:
    world.insert_resource(Camera(pixels_per_meter=20))
    world.spawn(Transform(0, 0), Rect(12.0, 12.0, color=BLUE))


def test_the_iris_shuts_at_half_time_and_opens_again() -> None:
    iris = Iris(1.0, ease=lambda p: p)
    active = ActiveTransition(iris)
    seen = []
    for _ in range(4):
        active.advance(0.25)
        seen.append((round(iris.progress(active.t, False), 6), active.swap_due))
    assert seen == [(0.5, False), (1.0, True), (0.5, True), (0.0, True)]


def test_iris_pixels_close_on_the_centre_then_show_the_new_scene(make_app: Any) -> None:
    app = make_app(red_scene)
    assert mask(pixels(app), RED[:3]).sum() > 30_000
    app.replace_scene(blue_scene, transition=Iris(0.8, color=(255, 255, 255),
                                                  ease=lambda p: p))
    app.advance(0.2)  # half shut: the corners are white, the centre still red
    px = pixels(app)
    h, w = px.shape[:2]
    assert tuple(px[h // 2, w // 2, :3]) == (255, 0, 0)
    assert tuple(px[2, 2, :3]) == (255, 255, 255) and tuple(px[h - 3, w - 3, :3]) == (255,) * 3
    # the edge is a circle: a pixel at 0.45 of the reach is red, one at 0.55 white
    reach = ((w / 2) ** 2 + (h / 2) ** 2) ** 0.5
    inside, outside = int(w / 2 + 0.45 * reach), int(w / 2 + 0.55 * reach)
    assert tuple(px[h // 2, min(inside, w - 1), :3]) == (255, 0, 0)
    if outside < w:
        assert tuple(px[h // 2, outside, :3]) == (255, 255, 255)
    app.advance(0.2)  # shut: all white; the scene changes now
    assert mask(pixels(app), WHITE[:3], tol=1).sum() == w * h
    app.advance(0.3)  # opening on blue
    px = pixels(app)
    assert tuple(px[h // 2, w // 2, :3]) == (0, 0, 255) and mask(px, RED[:3]).sum() == 0
    app.advance(0.2)
    assert app.transition is None and mask(pixels(app), BLUE[:3]).sum() == w * h


SPLIT = """
uniform float edge_width;
vec4 transition(sampler2D old_scene, vec2 uv, float progress) {
    // the old picture stays left of a line sweeping right to left
    if (uv.x > 1.0 - progress) return vec4(0.0);
    vec4 c = texture(old_scene, uv);
    return uv.x > 1.0 - progress - edge_width ? vec4(0.0, 1.0, 0.0, 1.0) : c;
}
"""


def test_a_user_shader_draws_the_old_picture_with_its_progress(make_app: Any) -> None:
    app = make_app(red_scene)
    pixels(app)
    app.replace_scene(blue_scene, transition=ShaderTransition(
        SPLIT, duration=1.0, ease=lambda p: p, uniforms={"edge_width": 0.05}))
    pixels(app)  # the last frame of the old scene: its picture is taken, the scene changes
    app.advance(0.25)
    px = pixels(app)
    h, w = px.shape[:2]
    row = px[h // 2, :, :3]
    # left of 0.70: the old (red) picture; 0.70..0.75 the green edge; right of 0.75 new blue
    assert tuple(row[int(0.6 * w)]) == (255, 0, 0)
    assert tuple(row[int(0.725 * w)]) == (0, 255, 0)
    assert tuple(row[int(0.8 * w)]) == (0, 0, 255)
    for _ in range(4):
        app.advance(0.2)
    assert app.transition is None and mask(pixels(app), BLUE[:3]).sum() == w * h


def test_a_shader_that_does_not_compile_warns_and_crossfades(make_app: Any) -> None:
    app = make_app(red_scene)
    pixels(app)
    broken = ShaderTransition("vec4 transition(sampler2D s, vec2 uv, float p) { return nope; }",
                              duration=1.0, ease=lambda p: p)
    app.replace_scene(blue_scene, transition=broken)
    pixels(app)
    app.advance(0.25)
    app.advance(0.25)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        px = pixels(app)
    assert any(issubclass(c.category, ShaderWarning) and "line 1" in str(c.message)
               for c in caught)
    h, w = px.shape[:2]
    r, g, b = (int(v) for v in px[h // 2, w // 2, :3])
    assert abs(r - 128) <= 3 and g == 0 and abs(b - 127) <= 3


def test_bad_shader_transitions_are_refused_at_the_call() -> None:
    with pytest.raises(ValidationError, match="must define vec4 transition"):
        ShaderTransition("void main() {}")
    with pytest.raises(ComponentTypeError, match="GLSL text"):
        ShaderTransition(3)  # type: ignore[arg-type]
    with pytest.raises(ValidationError, match="declares no such uniform"):
        ShaderTransition(SPLIT, uniforms={"width": 1.0})
    with pytest.raises(ValidationError, match="declares float"):
        ShaderTransition(SPLIT, uniforms={"edge_width": (1.0, 2.0)})
    with pytest.raises(ValidationError, match="declared by kge"):
        ShaderTransition("uniform float progress;\n" + SPLIT)
    with pytest.raises(ValidationError, match="Iris.center"):
        Iris(center=(2.0, 0.5))
    with pytest.raises(ValidationError, match="Iris.duration"):
        Iris(duration=0.0)
    app = App(red_scene, headless=True)
    with pytest.raises(TypeError, match="Transition"):
        app.replace_scene(blue_scene, transition="iris")  # type: ignore[arg-type]
    app.close()
