"""Queries and CCD end to end: components in a headless App, answers from ``Physics``.

The same box2d-reference rows as test_queries.py / test_ccd.py, but built from
RigidBody / Collider components and stepped by the App's fixed loop, so they
check the physics system's shape attributes, sync and CCD wiring too.
"""

from __future__ import annotations

import math

import pytest

import kge
from kge.components.collider import Collider
from kge.components.filter import Filter
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Circle, Edge
from kge.components.transform import Transform
from kge.physics.queries import QueryHit, RayHit, RayMode
from kge.physics.resource import Physics
from kge.physics.settings import PhysicsSettings
from kge.world import World


def _reference(world: World) -> None:
    """QueryAABB / RayCast scene: static boxes at 0, 3, 6; circle at 9; sensor at (0, 5)."""
    world.insert_resource(PhysicsSettings(gravity=(0.0, 0.0)))
    for x in (0.0, 3.0, 6.0):
        world.spawn(Transform(x, 0.0), Collider(Box(0.5, 0.5)))
    world.spawn(Transform(9.0, 0.0), RigidBody(), Collider(Circle(0.5)))
    world.spawn(Transform(0.0, 5.0), Collider(Box(0.5, 0.5), sensor=True))


@pytest.fixture
def app() -> kge.App:
    a = kge.App(_reference, headless=True)
    a.step()
    return a


def _colliders(world: World) -> list[int]:
    return sorted(e for e, _ in world.query(Collider))


def test_raycast_through_the_physics_resource(app: kge.App) -> None:
    physics = app.world.resource(Physics)
    box0, box3, box6, circle, sensor = _colliders(app.world)
    hit = physics.raycast((-2, 0), (12, 0))
    assert isinstance(hit, RayHit)
    assert (hit.collider, hit.body) == (box0, None)
    assert hit.fraction == pytest.approx(0.10714, abs=1e-4)
    assert hit.point == pytest.approx((-0.5, 0.0), abs=1e-9)
    assert hit.normal == pytest.approx((-1.0, 0.0))

    every = physics.raycast((-2, 0), (12, 0), mode=RayMode.ALL)
    assert [h.collider for h in every] == [box0, box3, box6, circle]
    assert every[-1].body == circle

    clipped: list[RayHit] = []

    def skip_box0(h: RayHit) -> float:
        if h.collider == box0:
            return -1.0
        clipped.append(h)
        return h.fraction

    physics.raycast((-2, 0), (12, 0), skip_box0)
    assert clipped[-1].collider == box3
    assert clipped[-1].fraction == pytest.approx(0.32143, abs=1e-4)
    inside = physics.raycast((0, 0), (12, 0))  # starts inside box0
    assert inside is not None and inside.collider == box3
    above = physics.raycast((-2, 5), (2, 5))
    assert above is not None and above.collider == sensor
    with pytest.raises(kge.ValidationError):
        physics.raycast((1, 1), (1, 1))


def test_aabb_point_and_shape_queries_through_the_resource(app: kge.App) -> None:
    physics = app.world.resource(Physics)
    box0, box3, box6, circle, sensor = _colliders(app.world)
    assert [h.collider for h in physics.query_aabb((-10, -10), (20, 20))] == [
        box0,
        box3,
        box6,
        circle,
        sensor,
    ]
    calls: list[QueryHit] = []

    def stop(hit: QueryHit) -> bool:
        calls.append(hit)
        return False

    physics.query_aabb((-10, -10), (20, 20), stop)
    assert len(calls) == 1
    assert [h.collider for h in physics.query_point((0.5, 0.0))] == [box0]
    assert physics.query_point((0.505, 0.0)) == []
    hits = physics.query_shape(Circle(0.3), Transform(8.3, 0.0))
    assert [h.collider for h in hits] == [circle]
    assert hits[0].body == circle
    assert physics.query_shape(Circle(0.3), (1.5, 0.0, 0.0)) == []


def test_queries_follow_moving_bodies_and_filters() -> None:
    def scene(world: World) -> None:
        world.insert_resource(PhysicsSettings(gravity=(0.0, 0.0)))
        world.spawn(
            Transform(0.0, 0.0),
            RigidBody(velocity=(1.0, 0.0)),
            Collider(Box(0.5, 0.5), filter=Filter(category_bits=0x2)),
        )

    app = kge.App(scene, headless=True)
    app.step(60)  # one second at 1 m/s
    physics = app.world.resource(Physics)
    (mover,) = _colliders(app.world)
    hit = physics.raycast((-2, 0), (5, 0))
    assert hit is not None and hit.collider == mover
    assert hit.point[0] == pytest.approx(0.5, abs=1e-6)
    assert [h.collider for h in physics.query_point((1.45, 0.0))] == [mover]
    assert physics.raycast((-2, 0), (5, 0), filter=Filter(mask_bits=0x4)) is None
    assert physics.raycast((-2, 0), (5, 0), filter=lambda c: c != mover) is None


# ------------------------------------------------------------------------------ CCD


def _shoot(speed: float, phase: int, wall: BodyType | None, bullet: bool) -> tuple[float, float]:
    """box2d-reference ccd: circle r=0.05 at ``speed`` at a wall half (0.05, 2) at x=11.11."""
    per_step = min(speed, 120.0) / 60.0
    ids: dict[str, int] = {}

    def scene(world: World) -> None:
        world.insert_resource(PhysicsSettings(gravity=(0.0, 0.0)))
        wall_parts: list[object] = [Transform(11.11, 0.0), Collider(Box(0.05, 2.0))]
        if wall is not None:
            wall_parts.append(RigidBody(type=wall))
        ids["wall"] = world.spawn(*wall_parts)
        ids["ball"] = world.spawn(
            Transform(phase * per_step / 8, 0.0),
            RigidBody(velocity=(speed, 0.0), bullet=bullet),
            Collider(Circle(0.05)),
        )

    app = kge.App(scene, headless=True)
    app.step(int(11.6 / min(speed, 120.0) * 60) + 20)
    world = app.world
    return world.get(ids["ball"], Transform).x, world.get(ids["wall"], Transform).x


@pytest.mark.parametrize("wall", [None, BodyType.KINEMATIC], ids=["static", "kinematic"])
@pytest.mark.parametrize("speed", [30.0, 500.0])
def test_app_walls_never_tunnel(wall: BodyType | None, speed: float) -> None:
    for phase in range(8):
        x, wall_x = _shoot(speed, phase, wall, bullet=False)
        assert x < wall_x, f"tunnelled at phase {phase}"
        assert x == pytest.approx(11.005, abs=0.02)  # stopped at the face


@pytest.mark.parametrize("speed", [30.0, 500.0])
def test_app_bullets_never_tunnel_through_a_dynamic_plank(speed: float) -> None:
    for phase in range(8):
        x, plank_x = _shoot(speed, phase, BodyType.DYNAMIC, bullet=True)
        assert x < plank_x, f"tunnelled at phase {phase}"


def test_app_speed_caps() -> None:
    ids: dict[str, int] = {}

    def scene(world: World) -> None:
        world.insert_resource(PhysicsSettings(gravity=(0.0, 0.0)))
        ids["fast"] = world.spawn(
            Transform(0.0, 0.0), RigidBody(velocity=(500.0, 0.0)), Collider(Circle(0.1))
        )
        ids["spin"] = world.spawn(
            Transform(0.0, 5.0), RigidBody(angular_velocity=200.0), Collider(Circle(0.1))
        )

    app = kge.App(scene, headless=True)
    app.step()
    world = app.world
    assert world.get(ids["fast"], Transform).x == pytest.approx(2.0, abs=1e-3)
    assert world.get(ids["fast"], RigidBody).velocity[0] == pytest.approx(120.0, abs=1e-3)
    assert world.get(ids["spin"], RigidBody).angular_velocity == pytest.approx(94.248, abs=1e-3)
    assert world.get(ids["spin"], Transform).angle == pytest.approx(math.pi / 2, abs=1e-3)


def test_app_fast_fall_onto_an_edge_rests_on_it() -> None:
    ids: dict[str, int] = {}

    def scene(world: World) -> None:
        world.spawn(Transform(0.0, 0.0), Collider(Edge((-5.0, 0.0), (5.0, 0.0))))
        ids["ball"] = world.spawn(
            Transform(0.0, 8.0), RigidBody(velocity=(0.0, -200.0)), Collider(Circle(0.1))
        )

    app = kge.App(scene, headless=True)
    app.step(60)
    y = app.world.get(ids["ball"], Transform).y
    assert y == pytest.approx(0.105, abs=0.01)  # Box2D: circle rests 0.005 above the skin
