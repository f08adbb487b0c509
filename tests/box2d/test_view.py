"""KgeDraw: a pybox2d program's debug drawing as kge drawables, checked in pixels."""

from __future__ import annotations

import os

os.environ.setdefault("PYGLET_HEADLESS", "1")

from typing import Any

import numpy as np

from kge import App
from kge.box2d.view import KgeDraw
from kge.components.camera import Camera
from kge.components.drawables import Circle, Line, Polygon
from kge.testbed.samples.box2d_api import Program, hello_world

SIZE = (200, 160)
PPM = 20.0
CENTER = (0.0, 1.0)


def _px(px: np.ndarray, x: float, y: float) -> tuple[int, ...]:
    sx = int(SIZE[0] / 2 + (x - CENTER[0]) * PPM)
    sy = int(SIZE[1] / 2 + (y - CENTER[1]) * PPM)
    return tuple(int(c) for c in px[sy, sx, :3])


def test_hello_world_is_drawn_where_the_box_lies() -> None:
    from kge.render.setup import frame_pixels

    programs: list[Program] = []

    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=CENTER, pixels_per_meter=PPM))
        from kge.components import Behaviour, Transform

        program = Program(hello_world)
        programs.append(program)
        world.spawn(Transform(), Behaviour(program))

    app = App(setup, headless=True, size=SIZE, background=(0, 0, 0))
    try:
        app.step(150)  # the box has landed and fallen asleep
        draw = programs[0].b2world.renderer
        assert isinstance(draw, KgeDraw)
        pools = {k: len(v) for k, v in draw._pools.items()}
        app.step(30)
        assert {k: len(v) for k, v in draw._pools.items()} == pools  # reused, none spawned
        assert pools[Polygon] == 2 and pools[Circle] == 0 and pools[Line] == 0
        app.render()
        px = frame_pixels(app)
        box, ground, sky = _px(px, 0.0, 1.0), _px(px, 0.0, -1.0), _px(px, 0.0, 3.0)
        # Box2D's colours at half alpha over black: asleep grey (153) and static green
        assert all(abs(c - 76) <= 12 for c in box), box
        assert abs(ground[0] - 63) <= 12 and abs(ground[1] - 114) <= 12, ground
        assert sky == (0, 0, 0)
        # the box's edges: 1 m either side of x = 0, at 20 px per metre
        row = px[int(SIZE[1] / 2), :, 0].astype(int)
        lit = np.nonzero(row > 30)[0]
        assert abs(lit.min() - (SIZE[0] / 2 - PPM)) <= 2 and abs(lit.max() - (SIZE[0] / 2 + PPM)) <= 2
    finally:
        app.close()
