"""Flipbook frames and velocity-stretched particles on screen (headless EGL frames)."""

from __future__ import annotations

import math

import numpy as np

from kge import Transform
from kge.components.camera import Camera
from kge.components.particle_flipbook import ParticleFlipbook
from kge.components.particle_stretch import ParticleStretch
from kge.components.particles import ParticleEmitter
from kge.render.images import PixelImage

from .conftest import SIZE, bbox, mask, pixels

PPM = 20.0
RED, GREEN, BLUE, WHITE = (255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 255)


def _sheet() -> PixelImage:
    """2 x 2 cells of 4 x 4 pixels: red, green on top; blue, white below."""
    top = [RED] * 4 + [GREEN] * 4
    bottom = [BLUE] * 4 + [WHITE] * 4
    rows = [bottom] * 4 + [top] * 4  # PixelImage rows run bottom-up
    data = bytes(c for row in rows for px in row for c in (*px, 255))
    return PixelImage(8, 8, data)


def _centre(px: np.ndarray) -> tuple[int, int, int]:
    r, g, b = px[SIZE[1] // 2, SIZE[0] // 2, :3].astype(int)
    return (r, g, b)


def test_each_quarter_of_the_life_shows_the_next_cell_of_the_sheet(make_app) -> None:
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=PPM))
        world.spawn(Transform(), ParticleEmitter(burst=1, speed=0.0, lifetime=4.0, size=3.0,
                                                 texture=_sheet()), ParticleFlipbook(2, 2))

    app = make_app(scene)
    seen = []
    for steps in (31, 60, 60, 60):  # 0.5 s, then 1 s each: frames 0, 1, 2, 3
        app.step(steps)
        seen.append(_centre(pixels(app)))
    assert seen == [RED, GREEN, BLUE, WHITE], seen
    # the whole quad shows one cell: no neighbour's colour bleeds in
    app2 = make_app(scene)
    app2.step(1)
    px = pixels(app2)
    assert mask(px, GREEN, tol=10).sum() == 0 and mask(px, RED, tol=10).sum() > 0.8 * 60 * 60


def test_a_fast_particle_is_drawn_long_along_its_velocity(make_app) -> None:
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=PPM))
        world.spawn(Transform(-3.0, 0.0), ParticleEmitter(
            burst=1, speed=10.0, direction=0.0, lifetime=5.0, size=0.4, flat=True,
            color=(255, 255, 255)), ParticleStretch(speed_scale=0.2))  # fmt: skip
        world.spawn(Transform(0.0, -3.0), ParticleEmitter(
            burst=1, speed=10.0, direction=math.pi / 2, lifetime=5.0, size=0.4, flat=True,
            color=(255, 0, 0)), ParticleStretch(speed_scale=0.2, max_length=1.0))  # fmt: skip

    app = make_app(scene)
    app.step(1 + 18)  # 0.3 s: the white one at x = 0, the red one at y = 0
    px = pixels(app)
    x0, x1, y0, y1 = bbox(mask(px, WHITE, tol=30))
    # 0.4 m x 1 + 10 m/s x 0.2 s = 2.4 m long along x, 0.4 m across
    assert abs((x1 - x0 + 1) - 2.4 * PPM) <= 2 and abs((y1 - y0 + 1) - 0.4 * PPM) <= 2
    x0, x1, y0, y1 = bbox(mask(px, RED, tol=30))
    assert abs((y1 - y0 + 1) - 1.0 * PPM) <= 2 and abs((x1 - x0 + 1) - 0.4 * PPM) <= 2  # capped


def test_a_trail_is_a_band_behind_its_particle_and_a_ribbon_joins_them(make_app) -> None:
    from kge.components.particle_trail import ParticleTrail, TrailMode

    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=PPM))
        # moving +x at 5 m/s, a 0.4 s trail 0.5 m wide: a 2 m band behind the particle
        world.spawn(Transform(-4.0, 2.0), ParticleEmitter(
            burst=1, speed=5.0, direction=0.0, lifetime=5.0, size=0.0, color=(255, 255, 255)),
            ParticleTrail(duration=0.4, points=8, width=0.5, color=(0, 255, 0),
                          opacity=255))  # fmt: skip
        # one particle a frame rising at 1 m/s: the ribbon joins them into a column
        world.spawn(Transform(-3.0, -2.0), ParticleEmitter(
            rate=60.0, speed=1.0, lifetime=5.0, size=0.0, seed=2),
            ParticleTrail(mode=TrailMode.RIBBON, width=0.4, color=(255, 0, 0),
                          opacity=255))  # fmt: skip

    app = make_app(scene)
    app.step(1 + 36)  # the green particle at x = -4 + 5 x 0.6 = -1
    px = pixels(app)
    x0, x1, y0, y1 = bbox(mask(px, GREEN, tol=30))
    head = SIZE[0] / 2 + (-1.0) * PPM
    assert abs(x1 + 1 - head) <= 2 and abs((x1 - x0 + 1) - 2.0 * PPM) <= 0.2 * PPM + 2
    assert abs((y1 - y0 + 1) - 0.5 * PPM) <= 2
    x0, x1, y0, y1 = bbox(mask(px, RED, tol=30))
    assert abs((y1 - y0 + 1) - 0.6 * PPM) <= 2  # the oldest is 0.6 s old: 0.6 m up
    assert abs((x1 - x0 + 1) - 0.4 * PPM) <= 2 and abs(y0 - (SIZE[1] / 2 - 2.0 * PPM)) <= 1
