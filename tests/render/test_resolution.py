"""A design resolution fitted to the window: letterbox, stretch, integer scaling, snapping."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from kge import Text, Transform
from kge.components.camera import Camera
from kge.components.drawables import Rect
from kge.components.resolution import Resolution, ScaleMode
from kge.components.sprite import Sprite, TextureFilter
from kge.errors import ValidationError
from kge.render.images import checker

from .conftest import bbox, mask, pixels

WINDOW = (400, 300)
RED, BARS = (255, 0, 0), (30, 0, 40)


def _design(mode: Any, **kw):
    def scene(world):
        world.insert_resource(Resolution(200, 100, mode=mode, bars=BARS, **kw))
        world.insert_resource(Camera(pixels_per_meter=10))
        world.spawn(Transform(0.0, 0.0), Rect(2.0, 2.0, color=RED))  # 20 x 20 design pixels

    return scene


def test_letterbox_scales_uniformly_with_bars(make_app):
    app = make_app(_design(ScaleMode.LETTERBOX), size=WINDOW, background=(0, 60, 0))
    px = pixels(app)
    # 200 x 100 at 2x is 400 x 200: 50-pixel bars above and below
    assert tuple(px[10, 200, :3]) == BARS and tuple(px[290, 200, :3]) == BARS
    assert tuple(px[60, 10, :3]) == (0, 60, 0)
    x0, x1, y0, y1 = bbox(mask(px, RED))
    assert (x1 - x0 + 1, y1 - y0 + 1) == (40, 40)  # 20 design pixels, 2 window pixels each
    assert ((x0 + x1) / 2, (y0 + y1) / 2) == pytest.approx((199.5, 149.5), abs=1)


def test_stretch_fills_the_window(make_app):
    px = pixels(make_app(_design(ScaleMode.STRETCH), size=WINDOW))
    x0, x1, y0, y1 = bbox(mask(px, RED))
    assert (x1 - x0 + 1, y1 - y0 + 1) == (40, 60)  # 2x across, 3x up
    assert not mask(px, BARS, 2).any()


def test_integer_scaling_keeps_pixels_square_and_whole(make_app):
    def scene(world):
        _design(ScaleMode.INTEGER)(world)
        world.spawn(Transform(-5.0, 0.0), Sprite(checker(8, 8, 1, (0, 0, 0), (255, 255, 255)),
                                                 size=(0.8, 0.8)))  # fmt: skip

    px = pixels(make_app(scene, size=(450, 320)))  # 2x fits (400 x 200), centred
    x0, x1, y0, y1 = bbox(mask(px, RED))
    assert (x1 - x0 + 1, y1 - y0 + 1) == (40, 40)
    assert tuple(px[5, 5, :3]) == BARS
    # the checker's design pixels are exact 2 x 2 blocks of one colour (nearest, whole scale)
    white = mask(px, (255, 255, 255), 0)
    wx0, _, wy0, _ = bbox(white)
    block = px[wy0 : wy0 + 16, wx0 : wx0 + 16, 0].reshape(8, 2, 8, 2)
    assert np.all(block.min(axis=(1, 3)) == block.max(axis=(1, 3)))


def test_screen_coordinates_are_design_pixels(make_app):
    app = make_app(_design(ScaleMode.LETTERBOX), size=WINDOW)
    assert app.screen_to_world((100.0, 50.0)) == pytest.approx((0.0, 0.0))
    assert app.screen_to_world((110.0, 50.0)) == pytest.approx((1.0, 0.0))
    res = app.world.resource(Resolution)
    assert res.to_design((200.0, 150.0), WINDOW) == (100.0, 50.0)


def test_hud_text_is_placed_in_design_pixels_and_baked_at_window_size(make_app):
    def scene(world):
        _design(ScaleMode.LETTERBOX)(world)
        world.spawn(Text("HI", size=12, color=(0, 255, 0, 255), screen_space=True,
                         offset=(10, 90), anchor=(0, 1)))  # fmt: skip

    app = make_app(scene, size=WINDOW)
    px = pixels(app)
    x0, _, _, y1 = bbox(mask(px, (0, 255, 0), 80))
    # the box's top-left at design (10, 90): window (20, 230); the ink a little inside it
    assert x0 == pytest.approx(20 + 2, abs=3) and 230 - 14 <= y1 <= 230
    from kge.systems.render import RenderSystem

    (label,) = app.world.get_system(RenderSystem).view.labels.labels.values()
    assert label.scale == pytest.approx(2.0)  # rasterised at the window's pixel size


@pytest.mark.parametrize(("w", "h"), [(0, 100), (100, -5), (20000, 100), (100, 10**9)])
def test_zero_or_huge_resolutions_are_refused(w, h):
    with pytest.raises(ValidationError, match="Resolution"):
        Resolution(w, h)
    with pytest.raises(ValidationError, match="mode"):
        Resolution(100, 100, mode="zoom")  # type: ignore[arg-type]


def test_snapping_puts_sprites_and_the_camera_on_whole_design_pixels(make_app):
    def frame(x: float, snap: bool) -> np.ndarray:
        def scene(world):
            world.insert_resource(Resolution(200, 100, mode=ScaleMode.INTEGER, snap=snap))
            world.insert_resource(Camera(pixels_per_meter=10, center=(0.031, 0.0)))
            world.spawn(Transform(x, 0.0), Sprite(checker(4, 4, 1, (0, 0, 0), (255, 255, 255)),
                                                  size=(0.4, 0.4), filter=TextureFilter.LINEAR))  # fmt: skip

        return pixels(make_app(scene, size=WINDOW))

    snapped = [frame(x, True) for x in (0.0, 0.02, 0.04)]
    assert all(np.array_equal(snapped[0], other) for other in snapped[1:])
    loose = [frame(x, False) for x in (0.0, 0.04)]
    assert not np.array_equal(loose[0], loose[1])  # a fifth of a pixel, filtered in between
