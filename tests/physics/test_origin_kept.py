"""A body's origin is where its Transform says, whatever its centre of mass does.

Chipmunk keeps a body's centre of mass fixed when the centre moves within the body
(a new shape or density) and turns a body about its centre; Box2D keeps the origin
(``ResetMassData``) and ``SetTransform`` places the origin. kge follows Box2D: before,
a body spawned at rest with an off-centre shape jumped by its centre's offset on its
first step, and teleporting a turned body set its origin and then turned it away.
"""

from __future__ import annotations

import math

import pytest

from kge.app import App
from kge.components import Collider, RigidBody, Transform
from kge.components.shapes import Circle, Polygon
from kge.physics.resource import Physics
from kge.physics.settings import PhysicsSettings
from kge.world import World

OFF_CENTRE = Circle(0.3, (0.4, 0.1))


def _weightless(world: World) -> None:
    world.insert_resource(PhysicsSettings(gravity=(0.0, 0.0)))


def test_a_body_spawned_at_rest_stays_where_it_was_spawned() -> None:
    def scene(world: World) -> None:
        _weightless(world)
        world.spawn(Transform(1.0, 2.0, 0.5), RigidBody(), Collider(OFF_CENTRE, density=1.0))
        # a lander-like hull: its polygon's centre is 0.1 m above the origin
        world.spawn(Transform(5.0, 2.0, -1.0), RigidBody(),
                    Collider(Polygon([(-0.5, -0.3), (0.5, -0.3), (0.4, 0.6), (-0.4, 0.6)])))

    app = App(scene, headless=True)
    app.step(5)
    poses = sorted((t.x, t.y, t.angle) for _, (t, _rb) in app.world.query(Transform, RigidBody))
    assert poses == [(1.0, 2.0, 0.5), (5.0, 2.0, -1.0)]
    app.close()


def test_a_teleport_puts_a_turned_body_exactly_at_the_pose() -> None:
    def scene(world: World) -> None:
        _weightless(world)
        world.spawn(Transform(0.0, 0.0, 3.0), RigidBody(), Collider(OFF_CENTRE, density=1.0))

    app = App(scene, headless=True)
    app.step(1)
    (e, (t, _rb)), = app.world.query(Transform, RigidBody)
    t.x, t.y, t.angle = 10.0, 13.0, 0.0  # turned by 3 rad on the way
    app.step(1)
    assert (t.x, t.y, t.angle) == (10.0, 13.0, 0.0)
    assert app.world.resource(Physics).world_point(e, (0.0, 0.0)) == pytest.approx((10.0, 13.0))
    app.close()


def test_a_new_centre_keeps_the_origin_and_its_velocity() -> None:
    """A spinning body whose centre moves (a new shape): its origin stays put and moves
    on with the velocity it had (Box2D: the centre takes ``v + ω × Δc``)."""

    def scene(world: World) -> None:
        _weightless(world)
        world.spawn(Transform(0.0, 0.0), RigidBody(velocity=(1.0, 0.0), angular_velocity=2.0),
                    Collider(Circle(0.3), density=1.0))

    app = App(scene, headless=True)
    app.step(3)
    physics = app.world.resource(Physics)
    (e, (t, _rb, col)), = app.world.query(Transform, RigidBody, Collider)
    before = (t.x, t.y, t.angle)
    origin_v = physics.velocity_at_point(e, (t.x, t.y))
    col.shape = OFF_CENTRE  # the centre of mass moves 0.41 m within the body
    dt = 1.0 / 60.0
    app.step(1)
    # the origin moved on as before: by its own velocity, not jumped by the offset
    assert math.dist((t.x, t.y), before[:2]) < 1.5 * math.hypot(*origin_v) * dt
    assert physics.mass_data(e).center == pytest.approx((0.4, 0.1))
    app.close()
