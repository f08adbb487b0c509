"""Drawn poses blend the last two fixed steps by alpha; teleports and update-moves snap."""

from __future__ import annotations

import math

import numpy as np

from kge import Behaviour, Script, Transform
from kge.components.camera import Camera
from kge.components.collider import Collider
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box
from kge.components.sprite import Sprite
from kge.render.images import solid
from kge.render.poses import PoseTable

from .conftest import SIZE, bbox, mask, pixels

RED = (255, 0, 0)


class Mover(Script):
    """Moves its entity by ``step`` metres along x every fixed step."""

    def __init__(self, step: float) -> None:
        self.step = step

    def on_fixed_update(self, dt):
        self.get(Transform).x += self.step


def _scene(step):
    def scene(world):
        world.insert_resource(Camera(pixels_per_meter=20))
        world.spawn(
            Transform(0.0, 0.0), Sprite(solid(2, 2, RED), size=(1, 1)), Behaviour(Mover(step))
        )

    return scene


def _center_x(app):
    x0, x1, _, _ = bbox(mask(pixels(app), RED))
    return (x0 + x1 + 1) / 2 - SIZE[0] / 2  # pixels right of the window centre


def test_alpha_half_draws_halfway_between_steps(make_app):
    app = make_app(_scene(2.0))
    app.render()  # the renderer, and its pose recorder, start with the first frame
    app.step(1)  # previous x = 0, current x = 2
    app.timestep.accumulator = 0.5 * app.fixed_dt
    assert abs(_center_x(app) - 1.0 * 20) <= 1  # halfway: x = 1 m
    app.timestep.accumulator = 0.0
    assert abs(_center_x(app) - 0.0) <= 1  # alpha 0: the previous step's pose


def test_a_teleport_is_not_swept_across(make_app):
    app = make_app(_scene(0.0))
    app.render()
    app.step(1)
    ((e, (_t,)),) = app.world.query(Transform)
    mover = app.world.get(e, Behaviour)
    mover.script.step = 3.0  # 3 m in one step: more than physics can move, so a teleport
    app.step(1)
    app.timestep.accumulator = 0.5 * app.fixed_dt
    assert abs(_center_x(app) - 3.0 * 20) <= 1


def test_a_move_outside_the_fixed_step_is_drawn_at_once(make_app):
    app = make_app(_scene(0.0))
    app.render()
    app.step(1)
    ((_e, (t,)),) = app.world.query(Transform)
    t.x = -1.5  # e.g. an on_update script or the test itself
    app.timestep.accumulator = 0.5 * app.fixed_dt
    assert abs(_center_x(app) + 1.5 * 20) <= 1


def test_pose_table_blends_angles_the_short_way():
    table = PoseTable()
    t = Transform(0.0, 0.0, math.pi - 0.1)
    row = table.acquire(1, t)
    t.angle = -math.pi + 0.1  # 0.2 rad further CCW, across the +-pi seam
    table.record()
    a = table.blend(0.5)[row, 2]
    assert math.isclose(math.remainder(a - math.pi, 2 * math.pi), 0.0, abs_tol=1e-9)


def test_pose_table_rows_are_reused_and_refcounted():
    table = PoseTable()
    a, b = Transform(1, 0), Transform(2, 0)
    ra = table.acquire(10, a)
    assert table.acquire(10, a) == ra  # a second store drawing the same entity
    table.release(10)
    assert 10 in table.row_of
    table.release(10)
    assert 10 not in table.row_of
    assert table.acquire(11, b) == ra  # freed row reused
    np.testing.assert_allclose(table.blend(0.3)[ra], (2, 0, 0))


def _sliding(world):
    world.insert_resource(Camera(pixels_per_meter=20))
    world.spawn(
        Transform(0.0, 0.0),
        Sprite(solid(2, 2, RED), size=(1, 1)),
        RigidBody(velocity=(30.0, 0.0), gravity_scale=0.0),
        Collider(Box(0.5, 0.5)),
    )


def test_physics_bodies_blend_from_the_physics_history(make_app):
    app = make_app(_sliding)
    app.render()
    app.step(1)  # 30 m/s: 0.5 m per step
    app.timestep.accumulator = 0.5 * app.fixed_dt
    assert abs(_center_x(app) - 0.25 * 20) <= 1
    ((e, _),) = app.world.query(RigidBody)
    app.world.get(e, Transform).x = 1.0  # a short teleport (under 2 m)
    app.step(1)  # physics restarts the history at 1.0, then moves to 1.5
    app.timestep.accumulator = 0.5 * app.fixed_dt
    # halfway between 1.0 and 1.5; a history that ignored the teleport would sweep 0.5 -> 1.5
    assert abs(_center_x(app) - 1.25 * 20) <= 1
