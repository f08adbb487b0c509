"""Characters on screen: drawn standing on the floor and against the wall they walk
into (no pixel inside either), and drawn between fixed steps like any body."""

from __future__ import annotations

import numpy as np

from kge import Behaviour, Box, Capsule, CharacterBody, Collider, Script, Transform
from kge.components import drawables as draw
from kge.components.camera import Camera

from .conftest import SIZE, bbox, mask, pixels

RED = (255, 0, 0)
GREEN = (0, 255, 0)
BLUE = (0, 0, 255)
PPM = 20  # pixels per metre: the 15 mm skin is under a pixel


class Walker(Script):
    """Walks right at ``speed`` m/s, keeping its fall."""

    def __init__(self, speed: float) -> None:
        self.speed = speed

    def on_fixed_update(self, dt: float) -> None:
        body = self.get(CharacterBody)
        body.velocity = (self.speed, body.velocity[1])


def _scene(speed: float, wall: bool, x: float = -2.0):
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=PPM, center=(0.0, 0.0)))
        # floor: top face at y = -2 m; wall: left face at x = 2 m
        world.spawn(Transform(0.0, -2.5), Collider(Box(20.0, 0.5)),
                    draw.Rect(40.0, 1.0, color=(*BLUE, 255)))
        if wall:
            world.spawn(Transform(3.0, 0.0), Collider(Box(1.0, 3.0)),
                        draw.Rect(2.0, 6.0, color=(*GREEN, 255)))
        world.spawn(Transform(x, -2.0 + 1.0 + 0.015), CharacterBody(Capsule(0.4, 1.0)),
                    draw.Rect(0.8, 2.0, color=(*RED, 255), layer=1),
                    Behaviour(Walker(speed)))

    return scene


def test_a_character_is_drawn_on_the_floor_and_against_the_wall(make_app) -> None:
    app = make_app(_scene(6.0, wall=True))
    app.step(120)  # walked 4 m into a wall 3.6 m away, at 6 m/s
    px = pixels(app)
    red, green, blue = mask(px, RED), mask(px, GREEN), mask(px, BLUE)
    rx0, rx1, ry0, ry1 = bbox(red)
    gx0, _, _, _ = bbox(green)
    _, _, _, by1 = bbox(blue)
    cx, cy = SIZE[0] / 2, SIZE[1] / 2
    assert gx0 == round(cx + 2.0 * PPM) and by1 == round(cy - 2.0 * PPM) - 1
    # touching both (within a pixel), overlapping neither
    assert gx0 - 2 <= rx1 < gx0
    assert by1 < ry0 <= by1 + 2
    assert ry1 - ry0 + 1 == 2 * PPM and rx1 - rx0 + 1 == round(0.8 * PPM)
    assert not np.any(red & (green | blue))


def test_a_walking_character_is_drawn_between_fixed_steps(make_app) -> None:
    app = make_app(_scene(30.0, wall=False, x=-4.5))
    app.render()  # the renderer, and its pose recorder, start with the first frame
    app.step(8)  # standing, walking at 30 m/s: 0.5 m (10 px) a step
    centres = []
    for alpha in (0.0, 0.5, 1.0):
        app.timestep.accumulator = alpha * app.fixed_dt
        x0, x1, _, _ = bbox(mask(pixels(app), RED))
        centres.append((x0 + x1 + 1) / 2 - SIZE[0] / 2)
    # alpha 0 draws the previous step's pose, alpha 1 this step's, 0.5 halfway
    [(_, (_, t))] = app.world.query(CharacterBody, Transform)
    x = t.x
    assert abs(centres[2] - x * PPM) <= 1 and abs(centres[0] - (x - 0.5) * PPM) <= 1
    assert abs(centres[1] - (x - 0.25) * PPM) <= 1
