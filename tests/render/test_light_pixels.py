"""Lights on screen: ambient only, a lit pixel near a light, darkness behind a box, spots,
moving shadow casters, unlit layers and switching lighting off."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kge import Collider, RigidBody, Transform
from kge.components.camera import Camera
from kge.components.lights import DirectionalLight, Light, Lighting, ShadowCaster
from kge.components.shapes import Box
from kge.components.sprite import Sprite
from kge.errors import ValidationError
from kge.render.images import from_array, solid

from .conftest import SIZE, pixels

PPM = 20.0
TOL = 9  # the light map is half size, filtered: a few levels of slack


def px_at(px: np.ndarray, x: float, y: float) -> np.ndarray:
    sx, sy = SIZE[0] / 2 + x * PPM, SIZE[1] / 2 + y * PPM
    return px[int(sy), int(sx), :3].astype(int)


def lit_scene(*extra, ambient=(40, 40, 40), white=(255, 255, 255)):
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=PPM))
        world.insert_resource(Lighting(ambient=ambient))
        world.spawn(Transform(), Sprite(solid(2, 2, white), size=(12.0, 10.0)))
        for components in extra:
            world.spawn(*components)

    return scene


def test_ambient_only_scene_matches_the_ambient_colour(make_app) -> None:
    app = make_app(lit_scene(ambient=(96, 160, 200)))
    app.step(1)
    px = pixels(app)
    region = px[20:140, 20:180, :3].reshape(-1, 3).astype(int)
    assert np.all(np.abs(region - (96, 160, 200)) <= TOL)


def test_a_pixel_near_a_light_is_lit_and_light_falls_off(make_app) -> None:
    light = (Transform(-2.0, 0.0), Light(radius=4.0, color=(255, 128, 0), falloff=1.0))
    app = make_app(lit_scene(light))
    app.step(1)
    px = pixels(app)
    near, mid, far = px_at(px, -2.0, 0.1), px_at(px, 0.0, 0.0), px_at(px, 3.0, 0.0)
    assert near[0] >= 250 and abs(near[1] - (40 + 128)) <= TOL
    # linear falloff: half-way out the light adds half its colour to the ambient
    assert abs(mid[0] - (40 + 128)) <= TOL and abs(mid[1] - (40 + 64)) <= TOL
    assert np.all(np.abs(far - 40) <= TOL), "past its radius a light adds nothing"


def test_the_pixel_behind_a_box_is_dark(make_app) -> None:
    for shadows in (True, False):
        box = (Transform(0.0, 0.0), Collider(Box(0.5, 0.5)))  # one instance, one entity
        light = (Transform(-3.0, 0.0), Light(radius=8.0, falloff=0.0, shadows=shadows))
        app = make_app(lit_scene(box, light))
        app.step(1)
        px = pixels(app)
        behind, front, beside = px_at(px, 2.0, 0.0), px_at(px, -1.0, 0.0), px_at(px, 2.0, 2.5)
        assert np.all(front >= 250) and np.all(beside >= 250)
        if shadows:
            assert np.all(np.abs(behind - 40) <= TOL), f"behind the box: {behind}"
            assert np.all(px_at(px, 0.0, 0.0) >= 250), "the occluder itself is lit"
        else:
            assert np.all(behind >= 250)


def test_a_spot_light_lights_its_cone_only(make_app) -> None:
    spot = (Transform(0.0, 0.0, math.pi / 2), Light(radius=5.0, falloff=0.0, cone=1.0,
                                                    softness=0.0))  # fmt: skip
    app = make_app(lit_scene(spot, ambient=(0, 0, 0)))
    app.step(1)
    px = pixels(app)
    assert np.all(px_at(px, 0.0, 2.0) >= 250)  # straight up the cone
    assert np.all(px_at(px, 0.0, -2.0) <= TOL)  # behind it
    assert np.all(px_at(px, 2.0, 1.0) <= TOL)  # 63 degrees off axis, the cone is +-28.6
    assert np.all(px_at(px, 0.5, 2.0) >= 250)  # 14 degrees off axis


def test_a_moving_shadow_caster_moves_its_shadow(make_app) -> None:
    # a dynamic crate 4 m right of the light: its shadow at x = 3 is at 7/4 of its height
    crate = (Transform(0.0, 1.0), RigidBody(gravity_scale=0.0), Collider(Box(0.5, 0.5)),
             ShadowCaster())  # fmt: skip
    light = (Transform(-4.0, 0.0), Light(radius=9.0, falloff=0.0, shadows=True))
    app = make_app(lit_scene(crate, light))
    app.step(1)
    px = pixels(app)
    assert np.all(px_at(px, 3.0, 1.75) <= 40 + TOL)
    assert np.all(px_at(px, 3.0, -1.75) >= 250)
    body = next(e for e, _ in app.world.query(ShadowCaster))
    app.world.get(body, Transform).y = -1.0
    app.step(1)
    px = pixels(app)
    assert np.all(px_at(px, 3.0, 1.75) >= 250), "the old shadow is gone"
    assert np.all(px_at(px, 3.0, -1.75) <= 40 + TOL), "the shadow followed the crate"


def test_unlit_layers_and_switching_lighting_off(make_app) -> None:
    hud = (Transform(3.0, 3.0), Sprite(solid(2, 2, (0, 255, 0)), size=(1.0, 1.0), layer=100))
    app = make_app(lit_scene(hud, ambient=(0, 0, 0), white=(255, 0, 0)))
    app.step(1)
    px = pixels(app)
    assert tuple(px_at(px, 3.0, 3.0)) == (0, 255, 0), "layer 100 is drawn after the light map"
    assert tuple(px_at(px, -3.0, -3.0)) == (0, 0, 0), "layer 0 is dark under black ambient"
    app.world.resource(Lighting).enabled = False
    px = pixels(app)
    assert tuple(px_at(px, -3.0, -3.0)) == (255, 0, 0)
    app.world.resource(Lighting).enabled = True
    assert tuple(px_at(pixels(app), -3.0, -3.0)) == (0, 0, 0)


def test_shadow_softness_makes_a_smooth_penumbra(make_app) -> None:
    # a wall edge at y = 0 from x = 0 to 0.5 (a box); the light 3 m left of it. Along
    # x = 4 the hard shadow edge is a step one pixel wide (anti-aliased); a 0.8 m bulb
    # spreads it into a smooth gradient (no steps: the penumbra is computed per pixel).
    profiles = {}
    for soft in (0.0, 0.8):
        box = (Transform(0.25, -1.0), Collider(Box(0.25, 1.0)))  # one instance, one entity
        light = (Transform(-3.0, 0.0), Light(radius=12.0, falloff=0.0, shadows=True,
                                             shadow_softness=soft))  # fmt: skip
        app = make_app(lit_scene(box, light, ambient=(0, 0, 0)))
        app.step(1)
        px = pixels(app)
        sy = np.arange(SIZE[1] // 2 - 40, SIZE[1] // 2 + 40)  # every pixel row, y -2..2 m
        profiles[soft] = px[sy, int(SIZE[0] / 2 + 4.0 * PPM), 0].astype(int)
    hard, soft_profile = profiles[0.0], profiles[0.8]
    between = (hard > 10) & (hard < 245)
    # a light-map pixel of penumbra, filtered up to the screen (the map is half size)
    assert 1 <= between.sum() <= 5, f"the hard edge is an anti-aliased step: {hard}"
    assert hard[0] <= 8 and hard[-1] >= 247
    ramp = soft_profile[(soft_profile > 10) & (soft_profile < 245)]
    assert len(ramp) >= 12, f"a penumbra of many pixels: {soft_profile}"
    assert np.all(np.diff(soft_profile) >= -2), "it only brightens towards the light"
    assert np.abs(np.diff(soft_profile)).max() <= 40, f"no steps in it: {soft_profile}"
    assert soft_profile[0] <= 8 and soft_profile[-1] >= 247, "umbra and full light remain"


def test_a_directional_light_casts_parallel_shadows(make_app) -> None:
    sun = (DirectionalLight(angle=0.0, shadows=True),)  # travelling right
    box = (Transform(-2.0, 0.0), Collider(Box(0.5, 0.5)))
    app = make_app(lit_scene(sun, box, ambient=(0, 0, 0)))
    app.step(1)
    px = pixels(app)
    for x in (-1.0, 1.0, 3.5):  # the shadow goes on, the same width, to the view's edge
        assert np.all(px_at(px, x, 0.0) <= TOL), f"in the shadow at x = {x}"
        assert np.all(px_at(px, x, 0.8) >= 250) and np.all(px_at(px, x, -0.8) >= 250)
    assert np.all(px_at(px, -3.5, 0.0) >= 250), "before the box: lit"


def test_shadow_colour_tints_a_lights_shadow(make_app) -> None:
    box = (Transform(0.0, 0.0), Collider(Box(0.5, 0.5)))
    light = (Transform(-3.0, 0.0), Light(radius=8.0, falloff=0.0, shadows=True,
                                         shadow_color=(0, 0, 120)))  # fmt: skip
    app = make_app(lit_scene(box, light, ambient=(0, 0, 0)))
    app.step(1)
    behind = px_at(pixels(app), 2.0, 0.0)
    assert abs(behind[0]) <= TOL and abs(behind[2] - 120) <= TOL


def test_a_cookie_texture_patterns_the_light(make_app) -> None:
    cookie = np.zeros((2, 2, 4), np.uint8)
    cookie[:, 1] = 255  # the right half of the light passes, the left is blocked
    light = (Transform(0.0, 0.0), Light(radius=4.0, falloff=0.0, texture=from_array(cookie)))
    app = make_app(lit_scene(light, ambient=(0, 0, 0)))
    app.step(1)
    px = pixels(app)
    assert np.all(px_at(px, 2.0, 0.5) >= 250) and np.all(px_at(px, -2.0, 0.5) <= TOL)


def test_glow_draws_a_halo_over_the_lit_scene(make_app) -> None:
    light = (Transform(0.0, 0.0), Light(radius=4.0, color=(255, 200, 0), glow=1.0))
    app = make_app(lit_scene(light, ambient=(0, 0, 0), white=(0, 0, 0)))  # a black wall
    app.step(1)
    px = pixels(app)
    centre = px_at(px, 0.0, 0.0)
    assert centre[0] >= 200 and centre[2] <= TOL  # the halo, where the lit wall stays black
    assert np.all(px_at(px, 2.5, 0.0) <= TOL)  # half the radius: the halo has faded out


def _normal_map(nx: float) -> object:
    """A flat normal map tilted towards +x (nx > 0) or -x, 4 x 4 pixels."""
    n = np.array([nx, 0.0, np.sqrt(max(1.0 - nx * nx, 0.0))])
    arr = np.empty((4, 4, 4), np.uint8)
    arr[..., :3] = np.round((n * 0.5 + 0.5) * 255).astype(np.uint8)
    arr[..., 3] = 255
    return from_array(arr)


def test_normal_mapped_sprites_face_the_light_they_are_lit_by(make_app) -> None:
    def brightness(nx: float, angle: float = 0.0) -> int:
        crate = (Transform(0.0, 0.0, angle), Sprite(solid(4, 4, (255, 255, 255)), size=(2.0, 2.0),
                                                     normal_map=_normal_map(nx), layer=1))
        light = (Transform(-3.0, 0.0), Light(radius=8.0, falloff=0.0, height=1.0))
        app = make_app(lit_scene(crate, light, ambient=(0, 0, 0)))
        app.step(1)
        return int(px_at(pixels(app), 0.0, 0.0)[0])

    towards, away = brightness(-0.8), brightness(0.8)
    assert towards > away + 120  # facing the light (at the left) is brighter
    assert brightness(0.8, math.pi) > away + 120  # turned half round, it faces the light


def test_the_light_map_resolution_is_a_setting(make_app) -> None:
    with pytest.raises(ValidationError, match="resolution"):
        Lighting(resolution=0.0)
    light = (Transform(-3.0, 0.0), Light(radius=4.0, falloff=1.0))
    full = make_app(lit_scene(light))
    full.world.resource(Lighting).resolution = 1.0
    assert abs(int(px_at(pixels(full), -1.0, 0.0)[0]) - (40 + 128)) <= TOL


def test_the_shadows_of_one_light_never_darken_another(make_app) -> None:
    """Each light's shadows live in the map's alpha under its own square, which its
    draw resets: a light drawn later (here, moonlight over everything) is untouched."""
    def boxes_and_moon() -> list[tuple]:
        return [(Transform(x, y), Collider(Box(0.1, 2.0))) for x, y in ((-0.7, 0.0), (0.7, 0.0))
                ] + [(DirectionalLight(intensity=0.5, angle=-1.0, shadows=True),)]  # fmt: skip

    alone = make_app(lit_scene(*boxes_and_moon(), ambient=(0, 0, 0)))
    alone.step(1)
    only_moon = pixels(alone).astype(int)
    lamp = (Transform(0.0, 0.0), Light(radius=3.0, falloff=1.0, shadows=True))
    both = make_app(lit_scene(*boxes_and_moon(), lamp, ambient=(0, 0, 0)))
    both.step(1)
    px = pixels(both).astype(int)
    ys, xs = np.mgrid[0 : px.shape[0], 0 : px.shape[1]]
    outside = np.hypot(xs - SIZE[0] / 2, ys - SIZE[1] / 2) > 3.0 * PPM + 3  # past the lamp
    assert np.abs(px - only_moon)[outside].max() <= 2
