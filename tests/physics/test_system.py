"""PhysicsSystem wiring: resources, settings at run time, CCD through the system."""

from __future__ import annotations

import pytest

import kge
from kge.components.collider import Collider
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Circle
from kge.components.transform import Transform
from kge.physics.events import PhysicsEvents
from kge.physics.resource import Physics
from kge.physics.settings import PhysicsSettings

from .conftest import Sim


def test_scene_settings_replace_the_defaults() -> None:
    def scene(world: kge.World) -> None:
        world.insert_resource(PhysicsSettings(gravity=(0.0, 0.0)))
        world.spawn(Transform(0, 5), RigidBody(), Collider(Circle(0.5)))

    app = kge.App(scene, headless=True)
    e = app.world.query(RigidBody)[0][0]
    app.step(30)
    assert app.world.get(e, Transform).y == 5.0
    assert app.world.resource(Physics).settings.gravity == (0.0, 0.0)
    app.world.resource(PhysicsSettings).gravity = (0.0, -10.0)
    app.step(30)
    assert app.world.get(e, Transform).y < 4.0
    assert isinstance(app.world.resource(PhysicsEvents), PhysicsEvents)
    app.close()


@pytest.mark.parametrize("speed", [30.0, 200.0, 500.0])
def test_no_tunnelling_through_a_thin_static_wall(zero_g: Sim, speed: float) -> None:
    zero_g.spawn(Transform(11.11, 0.0), Collider(Box(0.05, 2.0)))
    shot = zero_g.dynamic(Circle(0.05), 0.0, 0.0, body=RigidBody(velocity=(speed, 0.0)))
    zero_g.step(60)
    assert zero_g.t(shot).x < 11.11


def test_bullet_does_not_tunnel_through_dynamic_plank(zero_g: Sim) -> None:
    plank = zero_g.dynamic(Box(0.05, 2.0), 11.11, 0.0, density=100.0)
    shot = zero_g.dynamic(Circle(0.05), 0.0, 0.0,
                          body=RigidBody(velocity=(200.0, 0.0), bullet=True))
    zero_g.step(30)
    assert zero_g.t(shot).x < zero_g.t(plank).x


def test_hundreds_of_sleeping_bodies_write_nothing(sim: Sim) -> None:
    sim.ground()
    boxes = [sim.dynamic(Box(0.4, 0.4), -40.0 + i, 0.415) for i in range(80)]
    sim.step(90)
    assert not any(sim.rb(e).awake for e in boxes)
    t = sim.t(boxes[0])
    x = t.x
    sim.step(5)
    assert t.x == x


def test_events_clear_and_len_cover_every_channel() -> None:
    """``clear`` and ``len`` spell the lists out for speed; they must not miss one."""
    from kge.physics.events import PhysicsEvents

    events = PhysicsEvents()
    for name, _ in PhysicsEvents.CHANNELS:
        getattr(events, name).append(object())
    assert len(events) == len(PhysicsEvents.CHANNELS)
    events.clear()
    assert len(events) == 0
    assert all(not getattr(events, name) for name, _ in PhysicsEvents.CHANNELS)
