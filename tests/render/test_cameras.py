"""Several cameras: rotation, viewports (split screen, minimap), layers, render textures."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kge import Text, Transform
from kge.components.camera import Camera
from kge.components.drawables import Rect
from kge.components.sprite import Sprite
from kge.errors import ValidationError
from kge.render.images import RenderTexture

from .conftest import SIZE, bbox, mask, pixels

RED, BLUE, GREEN, GREY = (255, 0, 0), (0, 0, 255), (0, 255, 0), (90, 90, 90)


def test_a_turned_camera_turns_the_world_the_other_way(make_app):
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=20, rotation=math.pi / 2))
        world.spawn(Transform(2.0, 0.0), Rect(0.5, 0.5, color=RED))

    app = make_app(scene)
    x0, x1, y0, y1 = bbox(mask(pixels(app), RED))
    cam = app.world.resource(Camera)
    sx, sy = cam.world_to_screen((2.0, 0.0), SIZE)
    assert (sx, sy) == pytest.approx((SIZE[0] / 2, SIZE[1] / 2 - 40))  # +x points down
    assert x0 <= sx <= x1 + 1 and y0 <= sy <= y1 + 1
    assert cam.screen_to_world((sx, sy), SIZE) == pytest.approx((2.0, 0.0))


def _split(world):
    world.spawn(Transform(-10.0, 0.0), Rect(2.0, 2.0, color=RED))
    world.spawn(Transform(10.0, 0.0), Rect(2.0, 2.0, color=BLUE))
    world.spawn(Camera(center=(-10.0, 0.0), pixels_per_meter=20, viewport=(0.0, 0.0, 0.5, 1.0)))
    world.spawn(Camera(center=(10.0, 0.0), pixels_per_meter=20, viewport=(0.5, 0.0, 0.5, 1.0)))


def test_split_screen_shows_each_camera_in_its_half(make_app):
    app = make_app(_split)
    px = pixels(app)
    half = SIZE[0] // 2
    rx0, rx1, _, _ = bbox(mask(px, RED))
    bx0, bx1, _, _ = bbox(mask(px, BLUE))
    assert rx1 < half <= bx0  # each in its own half, nothing crosses the line
    assert (rx0 + rx1) / 2 == pytest.approx(half / 2, abs=1)  # centred in its viewport
    assert (bx0 + bx1) / 2 == pytest.approx(half + half / 2, abs=1)
    # the mouse maps through the camera under it
    assert app.screen_to_world((half / 2, SIZE[1] / 2)) == pytest.approx((-10.0, 0.0))
    assert app.screen_to_world((half * 1.5, SIZE[1] / 2)) == pytest.approx((10.0, 0.0))


def test_screen_text_is_drawn_once_over_every_camera(make_app):
    def scene(world):
        _split(world)
        world.spawn(Text("HUD", size=20, color=(0, 255, 0, 255), screen_space=True,
                         offset=(10, 150), anchor=(0, 1)))  # fmt: skip

    px = pixels(make_app(scene))
    green = mask(px, GREEN, 60)
    assert green.any() and not green[:, SIZE[0] // 2 :].any()  # only where it was put


def test_a_minimap_draws_over_the_main_view_with_its_background(make_app):
    def scene(world):
        world.spawn(Transform(0.0, 0.0), Rect(40.0, 40.0, color=GREY))
        world.spawn(Transform(0.0, 0.0), Rect(1.0, 1.0, color=RED))
        world.spawn(Camera(pixels_per_meter=20))
        world.spawn(Camera(pixels_per_meter=2, viewport=(0.7, 0.7, 0.25, 0.25),
                           background=(0, 0, 80), order=1, layers={1}))  # fmt: skip

    px = pixels(make_app(scene))
    corner = px[int(SIZE[1] * 0.8), int(SIZE[0] * 0.8), :3]
    assert tuple(corner) == (0, 0, 80)  # the minimap's own background, its layers empty
    assert tuple(px[10, 10, :3]) == GREY


def test_cameras_draw_only_their_layers(make_app):
    def scene(world):
        world.spawn(Transform(-1.0, 0.0), Rect(1.0, 1.0, color=RED, layer=0))
        world.spawn(Transform(1.0, 0.0), Rect(1.0, 1.0, color=BLUE, layer=1))
        world.spawn(Camera(pixels_per_meter=20, viewport=(0.0, 0.0, 0.5, 1.0), layers={0}))
        world.spawn(Camera(pixels_per_meter=20, viewport=(0.5, 0.0, 0.5, 1.0), layers={1}))

    px = pixels(make_app(scene))
    half = SIZE[0] // 2
    assert mask(px[:, :half], RED).any() and not mask(px[:, :half], BLUE).any()
    assert mask(px[:, half:], BLUE).any() and not mask(px[:, half:], RED).any()


def test_a_camera_draws_into_a_texture_a_sprite_shows(make_app):
    def scene(world):
        world.spawn(Transform(50.0, 0.0), Rect(2.0, 2.0, color=GREEN, layer=3))
        world.spawn(Camera(center=(50.0, 0.0), pixels_per_meter=10, target="cam",
                           target_size=(64, 64), layers={3}, background=(40, 0, 0)))
        world.spawn(Camera(pixels_per_meter=20, layers={0}))
        world.spawn(Transform(0.0, 0.0), Sprite(RenderTexture("cam"), size=(4.0, 4.0)))

    px = pixels(make_app(scene))
    # the sprite (80 x 80 pixels) shows the texture: a green square on dark red
    gx0, gx1, _, _ = bbox(mask(px, GREEN, 30))
    assert gx1 - gx0 + 1 == pytest.approx(25, abs=2)  # 2 m at 10 px/m = 20 of 64 texels
    assert (gx0 + gx1) / 2 == pytest.approx(SIZE[0] / 2, abs=1.5)
    assert mask(px, (40, 0, 0), 8).sum() > 3000


def test_a_sprite_of_a_texture_no_camera_draws_is_refused(make_app):
    def scene(world):
        world.spawn(Transform(), Sprite(RenderTexture("nowhere")))

    app = make_app(scene)
    with pytest.raises(ValidationError, match="nowhere"):
        pixels(app)


@pytest.mark.parametrize("viewport", [(0.5, 0.0, 0.6, 1.0), (-0.1, 0.0, 0.5, 1.0),
                                      (0.0, 0.0, 0.0, 1.0), (0.0, 0.5, 1.0, float("nan"))])
def test_viewports_outside_the_window_are_refused_at_the_call(viewport):
    with pytest.raises(ValidationError, match="viewport"):
        Camera(viewport=viewport)
    cam = Camera()
    with pytest.raises(ValidationError, match="viewport"):
        cam.viewport = viewport
    assert cam.viewport == (0.0, 0.0, 1.0, 1.0)


def test_bad_camera_targets_and_post_stacks_are_refused():
    with pytest.raises(ValidationError, match="target_size"):
        Camera(target="t", target_size=(0, 64))
    with pytest.raises(Exception, match="post"):
        Camera(post=("bloom",))


def test_the_view_rect_of_a_turned_camera_holds_what_it_sees():
    cam = Camera(pixels_per_meter=10, rotation=math.pi / 4)
    x0, y0, x1, y1 = cam.view_rect((100, 100))
    corners = [cam.screen_to_world(p, (100, 100)) for p in ((0, 0), (100, 0), (0, 100), (100, 100))]
    xs, ys = np.array(corners).T
    assert x0 <= xs.min() + 1e-9 and xs.max() <= x1 + 1e-9
    assert y0 <= ys.min() + 1e-9 and ys.max() <= y1 + 1e-9
