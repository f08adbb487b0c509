"""The particle collision grid follows static geometry only: bodies spawning and
despawning over a large map do not re-rasterise it, while a static collider that comes
or goes (or a body attached to by colliders that becomes static) does."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from kge import App, Collider, RigidBody, Transform, World
from kge.components.particles import EmitBox, ParticleCollision, ParticleEmitter
from kge.components.rigidbody import BodyType
from kge.components.shapes import Box, Circle
from kge.particles import Particles
from kge.particles.grid import StaticGrid


@pytest.fixture
def builds(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """Counts the grid's rasterisations."""
    calls: list[int] = []
    real = StaticGrid.from_geometry

    def counted(*args: Any, **kwargs: Any) -> StaticGrid | None:
        calls.append(1)
        return real(*args, **kwargs)

    monkeypatch.setattr(StaticGrid, "from_geometry", staticmethod(counted))
    return calls


def map_with_rain(world: World) -> None:
    for i in range(200):  # a long floor of tiles
        world.spawn(Transform(-100.0 + i + 0.5, -0.5), Collider(Box(0.5, 0.5)))
    world.spawn(Transform(0.0, 3.0), ParticleEmitter(
        rate=200, speed=0.0, acceleration=(0.0, -10.0), collide=ParticleCollision.BOUNCE, lifetime=2.0,
        shape=EmitBox(20.0, 0.1)))  # fmt: skip


def test_spawning_and_despawning_balls_does_not_rebuild_the_grid(builds: list[int]) -> None:
    app = App(map_with_rain, headless=True)
    balls: list[int] = []
    for k in range(120):
        balls.append(app.world.spawn(Transform(-50.0 + k % 100, 5.0), RigidBody(),
                                     Collider(Circle(0.2))))
        if len(balls) > 20:
            app.world.despawn(balls.pop(0))
        app.step()
    assert len(builds) == 1


def _lowest(app: App) -> float:
    e = next(e for e, _ in app.world.query(ParticleEmitter))
    return float(app.world.resource(Particles).positions(e)[:, 1].min())


def test_a_static_collider_that_comes_or_goes_rebuilds_it(builds: list[int]) -> None:
    app = App(map_with_rain, headless=True)
    app.step(60)
    assert _lowest(app) > -0.11 and len(builds) == 1
    shelf = app.world.spawn(Transform(0.0, 1.5), Collider(Box(15.0, 0.1)))  # static
    app.step(120)
    assert len(builds) == 2
    assert _lowest(app) > 1.3, "particles rest on the new shelf"
    app.world.despawn(shelf)
    app.step(120)
    assert len(builds) == 3
    assert _lowest(app) < 0.1, "the shelf is gone: they fall to the floor"


def test_a_body_that_becomes_static_under_attached_colliders_rebuilds_it(
        builds: list[int]) -> None:
    app = App(map_with_rain, headless=True)
    app.step(2)
    body = app.world.spawn(Transform(0.0, 1.5), RigidBody(type=BodyType.KINEMATIC))
    app.world.spawn(Transform(0.0, 1.5), Collider(Box(15.0, 0.1), body=body))
    app.step(30)
    assert len(builds) == 1  # a kinematic shelf is not static geometry
    app.world.remove(body, RigidBody)  # now an implicit static body
    app.step(120)
    assert len(builds) == 2
    positions = app.world.resource(Particles).positions(
        next(e for e, _ in app.world.query(ParticleEmitter)))
    assert np.count_nonzero(positions[:, 1] > 1.3) > 50


def test_changes_do_not_pile_up_while_no_emitter_collides() -> None:
    from kge.systems.particles import ParticleSystem

    def scene(world: World) -> None:
        world.spawn(Transform(0.0, -1.0), Collider(Box(10.0, 0.5)))
        world.spawn(Transform(0.0, 3.0), ParticleEmitter(
            rate=50, collide=ParticleCollision.BOUNCE, lifetime=0.2))

    app = App(scene, headless=True)
    app.step()  # the grid is built for the colliding emitter
    for e, _ in app.world.query(ParticleEmitter):
        app.world.despawn(e)
    system = app.world.get_system(ParticleSystem)
    assert system is not None
    balls: list[int] = []
    for k in range(300):  # long play with no colliding emitter: bodies come and go
        balls.append(app.world.spawn(Transform(k % 10, 5.0), RigidBody(), Collider(Circle(0.2))))
        if len(balls) > 10:
            app.world.despawn(balls.pop(0))
        app.step()
        assert len(system._pending) <= 2, "changes of past frames kept"
    # a colliding emitter coming back still sees the floor (the grid was kept right)
    e = app.world.spawn(Transform(0.0, 3.0), ParticleEmitter(
        rate=200, speed=0.0, acceleration=(0.0, -10.0), collide=ParticleCollision.BOUNCE,
        lifetime=2.0))
    app.step(90)
    assert float(app.world.resource(Particles).positions(e)[:, 1].min()) > -1.0
