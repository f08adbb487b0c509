"""Particles on screen: at the expected pixel and colour at time t, blending, layers."""

from __future__ import annotations

import numpy as np

from kge import Transform
from kge.components.camera import Camera
from kge.components.particles import Blend, ParticleEmitter
from kge.components.sprite import Sprite
from kge.particles import Particles
from kge.render.images import solid

from .conftest import SIZE, bbox, mask, pixels

PPM = 20.0


def _screen(x: float, y: float) -> tuple[float, float]:
    return (SIZE[0] / 2 + x * PPM, SIZE[1] / 2 + y * PPM)


def test_a_particle_is_at_its_expected_position_and_colour_at_time_t(make_app) -> None:
    # born at (-2, 0) moving +x at 1.5 m/s; colour fades red -> blue over its 4 s life
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=PPM))
        world.spawn(Transform(-2.0, 0.0), ParticleEmitter(
            burst=1, speed=1.5, direction=0.0, lifetime=4.0, size=0.5, flat=True,
            color=((255, 0, 0), (0, 0, 255))))  # fmt: skip

    app = make_app(scene)
    app.step(1 + 120)  # born on the first frame, then 2 s
    px = pixels(app)
    seen = np.any(px[..., :3] > 30, axis=-1)
    x0, x1, y0, y1 = bbox(seen)
    cx, cy = _screen(-2.0 + 1.5 * 2.0, 0.0)
    assert abs((x0 + x1 + 1) / 2 - cx) <= 1 and abs((y0 + y1 + 1) / 2 - cy) <= 1
    assert abs((x1 - x0 + 1) - 0.5 * PPM) <= 1  # 0.5 m wide
    r, g, b = px[int(cy), int(cx), :3].astype(int)
    # half-way through its life; the headless pbuffer keeps 5 bits of red and blue (RGB565)
    assert abs(r - 128) <= 8 and g == 0 and abs(b - 127) <= 8
    assert abs(r - b) <= 10


def test_additive_particles_add_up_alpha_ones_cover(make_app) -> None:
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=PPM))
        world.spawn(
            Transform(-2.0, 0.0),
            ParticleEmitter(
                burst=2, speed=0.0, size=1.0, flat=True, color=(100, 0, 0), blend=Blend.ADDITIVE
            ),
        )
        world.spawn(Transform(2.0, 0.0), ParticleEmitter(
            burst=2, speed=0.0, size=1.0, flat=True, color=(100, 0, 0), opacity=127.5))  # fmt: skip

    app = make_app(scene)
    app.step(1)
    px = pixels(app)
    add = px[int(_screen(-2, 0)[1]), int(_screen(-2, 0)[0]), 0]
    over = px[int(_screen(2, 0)[1]), int(_screen(2, 0)[0]), 0]
    assert abs(int(add) - 200) <= 8  # 100 + 100 (RGB565: steps of 8)
    assert abs(int(over) - 75) <= 8  # 50 then 50 + 50 * 0.5


def test_particles_sort_with_sprites_by_layer(make_app) -> None:
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=PPM))
        world.spawn(
            Transform(-1.0, 0.0), Sprite(solid(2, 2, (0, 255, 0)), size=(1.5, 1.5), layer=0)
        )
        world.spawn(Transform(1.0, 0.0), Sprite(solid(2, 2, (0, 255, 0)), size=(1.5, 1.5), layer=2))
        for x in (-1.0, 1.0):
            world.spawn(Transform(x, 0.0), ParticleEmitter(
                burst=1, speed=0.0, size=1.0, flat=True, color=(255, 0, 0), layer=1))  # fmt: skip

    app = make_app(scene)
    app.step(1)
    px = pixels(app)
    left, right = _screen(-1, 0), _screen(1, 0)
    assert tuple(px[int(left[1]), int(left[0]), :3]) == (255, 0, 0)  # over layer 0
    assert tuple(px[int(right[1]), int(right[0]), :3]) == (0, 255, 0)  # under layer 2


def test_dead_particles_leave_no_pixels_and_the_soft_dot_is_round(make_app) -> None:
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=PPM))
        world.spawn(
            Transform(),
            ParticleEmitter(burst=1, speed=0.0, size=3.0, lifetime=0.5, color=(255, 255, 255)),
        )

    app = make_app(scene)
    app.step(1)
    px = pixels(app)
    c = _screen(0, 0)
    assert px[int(c[1]), int(c[0]), 0] > 200  # bright centre
    corner = (int(c[1] + 1.4 * PPM), int(c[0] + 1.4 * PPM))  # inside the quad, outside the disc
    assert px[corner][0] == 0
    assert mask(px, (255, 255, 255), tol=60).sum() > 0
    app.step(40)
    assert app.world.resource(Particles).total() == 0
    assert int(pixels(app)[..., :3].max()) == 0


def test_a_texture_renamed_after_spawn_is_refused_at_the_write_and_drawing_goes_on(
    make_app,
) -> None:
    import pytest

    from kge.errors import ValidationError

    def scene(world):
        world.spawn(Transform(), ParticleEmitter(burst=3))

    app = make_app(scene)
    app.step(1)
    with pytest.raises(ValidationError, match="entity 1, ParticleEmitter.texture"):
        app.world.get(1, ParticleEmitter).texture = "missing.png"
    assert app.world.get(1, ParticleEmitter).texture is None
    pixels(app)  # the emitter keeps its generated soft dot and draws
