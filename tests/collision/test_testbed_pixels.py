"""The Collision Module samples draw what kge.collision computed (headless EGL pixels)."""

from __future__ import annotations

import os

os.environ.setdefault("PYGLET_HEADLESS", "1")

import math

import numpy as np

from kge import App
from kge.components.behaviour import Behaviour
from kge.components.camera import Camera
from kge.components.drawables import Line
from kge.testbed import get_sample
from kge.testbed.samples.build import named
from kge.testbed.samples.collision_module import RED, SHAPE_A, SHAPE_B, YELLOW
from tests.render.conftest import mask, pixels

SIZE = (200, 160)
PPM = 16.0


def _app(slug: str) -> App:
    sample = get_sample(slug)

    def scene(world):
        sample.setup(world)
        world.insert_resource(Camera(center=(0.0, 5.0), pixels_per_meter=PPM))

    return App(scene, headless=True, size=SIZE, background=(0, 0, 0))


def _screen(p: tuple[float, float]) -> tuple[float, float]:
    return ((p[0] - 0.0) * PPM + SIZE[0] / 2, (p[1] - 5.0) * PPM + SIZE[1] / 2)


def test_distance_test_draws_the_closest_points_line_between_the_shapes() -> None:
    app = _app("distance-test")
    try:
        app.step(40)
        px = pixels(app)
        assert mask(px, SHAPE_A[:3]).any() and mask(px, SHAPE_B[:3]).any()
        line = app.world.get(named(app.world, "closest")[0], Line)
        yellow = mask(px, YELLOW[:3])
        ys, xs = np.nonzero(yellow)
        assert len(xs) > 5
        # the yellow pixels lie on the segment between the two closest points
        (ax, ay), (bx, by) = _screen(line.start), _screen(line.end)
        length = math.hypot(bx - ax, by - ay)
        off = np.abs((bx - ax) * (ys - ay) - (by - ay) * (xs - ax)) / length
        assert np.median(off) < 2.0
        assert abs((xs.max() - xs.min()) - abs(bx - ax)) <= 3
    finally:
        app.close()


def test_polygon_collision_draws_manifold_points_where_they_are() -> None:
    app = _app("polygon-collision")
    try:
        probe = app.world.get(named(app.world, "plank")[0], Behaviour).script
        for _ in range(200):
            app.step()
            if probe.manifold and probe.manifold.point_count == 2:
                break
        m = probe.manifold
        assert m and m.point_count == 2
        red = mask(pixels(app), RED[:3])
        for p in m.points:
            x, y = _screen(p)
            assert red[int(y) - 1:int(y) + 2, int(x) - 1:int(x) + 2].any(), p
    finally:
        app.close()
