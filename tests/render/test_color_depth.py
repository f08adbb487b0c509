"""Headless frames keep 8 bits per channel, alpha and a stencil buffer.

Mesa's EGL defaults to a 16-bit RGB565 surface: greys come back tinted (green keeps
6 bits, red and blue 5) and gradients band. Every picture kge's tests and docs take
depends on the 8-bit surface, so losing it must fail here first.
"""

from __future__ import annotations

import numpy as np

from kge import Transform
from kge.components.camera import Camera
from kge.components.drawables import Rect

from .conftest import pixels


def test_window_has_8_bit_rgba_and_stencil(make_app):
    from kge.render.setup import ensure_renderer

    app = make_app(lambda world: None)
    app.render()
    cfg = ensure_renderer(app).window.config
    assert (cfg.red_size, cfg.green_size, cfg.blue_size, cfg.alpha_size) == (8, 8, 8, 8)
    assert cfg.stencil_size >= 8


def test_every_grey_level_reads_back_exactly(make_app):
    greys = [1, 2, 3, 5, 77, 127, 128, 129, 200, 254]

    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=10))
        for i, g in enumerate(greys):
            world.spawn(Transform(-9 + 2 * i, 0), Rect(1.5, 1.5, color=(g, g, g, 255)))

    px = pixels(make_app(scene))
    h, w = px.shape[:2]
    for i, g in enumerate(greys):
        x = round(w / 2 + (-9 + 2 * i) * 10)
        got = px[h // 2, x, :3]
        assert np.array_equal(got, [g, g, g]), f"grey {g} came back as {got.tolist()}"
