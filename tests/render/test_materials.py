"""Materials (custom GLSL per drawable, uniforms tweens animate) and blend modes."""

from __future__ import annotations

import warnings

import pytest

from kge import Blend, ParticleEmitter, Transform, Tween, Tweens
from kge.components.camera import Camera
from kge.components.drawables import Rect
from kge.components.material import Material, Shader, ShaderWarning
from kge.components.sprite import Sprite
from kge.errors import ValidationError
from kge.render.images import solid

from .conftest import SIZE, mask, pixels

CENTER = (SIZE[1] // 2, SIZE[0] // 2)

TINT = Shader("""
uniform float level;
vec4 effect(vec4 color, sampler2D tex, vec2 uv, vec2 world)
{
    return vec4(level, 1.0 - level, 0.0, texture(tex, uv).a * color.a);
}
""", name="tint")


def _one(make_app, *components, background=(0, 0, 0)):
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=20))
        world.spawn(Transform(), *components)

    return make_app(scene, background=background)


def test_a_material_draws_a_sprite_with_its_shader(make_app):
    app = _one(make_app, Sprite(solid(4, 4, (0, 0, 255)), size=(2.0, 2.0)),
               Material(TINT, {"level": 1.0}))  # fmt: skip
    px = pixels(app)
    assert tuple(px[CENTER][:3]) == (255, 0, 0)
    material = app.world.get(1, Material)
    material.set("level", 0.0)  # read at draw time: no rebuild
    assert tuple(pixels(app)[CENTER][:3]) == (0, 255, 0)


def test_tweens_animate_a_uniform(make_app):
    app = _one(make_app, Sprite(solid(4, 4, (0, 0, 255)), size=(2.0, 2.0)),
               Material(TINT, {"level": 0.0}))  # fmt: skip
    app.world.resource(Tweens).start(1, Tween(Material, "uniforms.level", 1.0, 0.5))
    app.step(15)  # half way
    red = int(pixels(app)[CENTER][0])
    assert 110 <= red <= 145
    app.step(30)
    assert app.world.get(1, Material).uniforms["level"] == 1.0


def test_shapes_and_particles_take_materials(make_app):
    app = _one(make_app, Rect(2.0, 2.0, color=(0, 0, 255)), Material(TINT, {"level": 1.0}))
    assert tuple(pixels(app)[CENTER][:3]) == (255, 0, 0)

    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=20))
        world.spawn(Transform(), ParticleEmitter(burst=50, rate=0.0, speed=0.0, lifetime=5.0,
                                                 size=1.0, flat=True, color=(0, 0, 255)),
                    Material(TINT, {"level": 1.0}))  # fmt: skip

    app = make_app(scene)
    app.step(2)
    px = pixels(app)
    assert mask(px, (255, 0, 0), 10).sum() > 100 and not mask(px, (0, 0, 255), 10).any()


def test_a_shader_that_does_not_compile_warns_with_its_line_and_draws_plain(make_app):
    broken = Shader("""uniform float level;
vec4 effect(vec4 color, sampler2D tex, vec2 uv, vec2 world)
{
    return vec4(level, 0.0, 0.0) * color;
}
""", name="broken")
    app = _one(make_app, Sprite(solid(4, 4, (0, 0, 255)), size=(2.0, 2.0)),
               Material(broken, {"level": 1.0}))  # fmt: skip
    with pytest.warns(ShaderWarning, match=r"shader 'broken' did not compile \(line 4"):
        px = pixels(app)
    assert tuple(px[CENTER][:3]) == (0, 0, 255)  # the plain material meanwhile
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # reported once, not every frame
        pixels(app)


def test_uniforms_of_the_wrong_type_are_refused_at_the_call():
    with pytest.raises(ValidationError, match=r"uniforms\['level'\]: the shader declares float"):
        Material(TINT, {"level": (1.0, 2.0)})
    with pytest.raises(ValidationError, match="declares no such uniform"):
        Material(TINT, {"lvl": 1.0})
    m = Material(TINT, {"level": 0.5})
    with pytest.raises(ValidationError, match="float"):
        m.set("level", "bright")
    with pytest.raises(ValidationError):
        m.uniforms = {"level": float("nan")}
    assert m.uniforms == {"level": 0.5}
    with pytest.raises(ValidationError, match="effect"):
        Shader("void main() {}")
    with pytest.raises(ValidationError, match="declared by kge"):
        Shader("uniform float time;\nvec4 effect(vec4 c, sampler2D t, vec2 u, vec2 w) { return c; }")


BACK = (200, 100, 50)


@pytest.mark.parametrize(("blend", "color", "expected"), [
    (Blend.ALPHA, (255, 0, 0, 128), (228, 50, 25)),
    (Blend.ADDITIVE, (0, 100, 200, 255), (200, 200, 250)),
    (Blend.MULTIPLY, (128, 128, 128, 255), (100, 50, 25)),
    (Blend.SCREEN, (128, 128, 128, 255), (228, 178, 153)),
])  # fmt: skip
def test_blend_modes_combine_with_what_is_below(make_app, blend, color, expected):
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=20))
        world.spawn(Transform(), Rect(4.0, 4.0, color=BACK))
        world.spawn(Transform(), Rect(2.0, 2.0, color=color, blend=blend, layer=1))
        world.spawn(Transform(0.0, 1.5), Sprite(solid(2, 2, color[:3]), size=(2.0, 0.5),
                                                opacity=color[3], blend=blend, layer=1))

    px = pixels(make_app(scene))
    for y in (CENTER[0], CENTER[0] + 30):  # the shape, then the sprite
        got = px[y, CENTER[1], :3].astype(int)
        assert max(abs(got - expected)) <= 2, f"{blend}: {got.tolist()} != {expected}"


def test_alike_materials_share_one_draw_and_a_changed_one_leaves(make_app):
    """Sprites whose materials are equal share one group (one draw call); a material
    changed later (set, tween) is drawn alone with its own values, the others unchanged."""
    from kge.systems.render import RenderSystem

    xs = [-3.6 + 1.2 * i for i in range(7)]

    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=20))
        for x in xs:
            world.spawn(Transform(x, 0.0), Sprite(solid(4, 4, (0, 0, 255)), size=(0.8, 0.8)),
                        Material(TINT, {"level": 1.0}))  # fmt: skip

    app = make_app(scene)
    px = pixels(app)
    at = [(CENTER[0], int(SIZE[0] / 2 + x * 20)) for x in xs]
    assert all(tuple(px[p][:3]) == (255, 0, 0) for p in at)
    shared = app.world.get_system(RenderSystem).view.sprites.shared
    assert len(shared) == 1 and not shared.alone  # seven sprites, one group
    entities = [e for e, _ in app.world.query(Material)]
    app.world.get(entities[3], Material).set("level", 0.0)  # no tracked write: still seen
    px = pixels(app)
    assert tuple(px[at[3]][:3]) == (0, 255, 0)
    assert all(tuple(px[p][:3]) == (255, 0, 0) for i, p in enumerate(at) if i != 3)
    assert shared.alone == {entities[3]} and len(shared) == 1
    app.world.get(entities[3], Material).set("level", 1.0)  # alone for good: reads its own
    app.world.get(entities[3], Material).set("level", 0.5)
    assert 110 <= int(pixels(app)[at[3]][0]) <= 145
    for e in entities:
        app.world.despawn(e)
    app.step(1)
    pixels(app)
    assert len(shared) == 0 and not shared.alone  # nothing kept for gone sprites
