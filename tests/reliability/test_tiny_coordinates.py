"""Coordinates below 1e-100 m are zero to Chipmunk, so they never make a NaN pose.

Found by the long fuzz (shrunk): a 1 kg circle at the origin and a triangle
whose corner sat at x = 1.3e-167 m; Chipmunk normalised their 1.3e-167 m
offset into a normal 1e140 long and both poses were NaN after one step. See
kge/physics/tiny.py. Each case below, on the old code, ends in NaN.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

import pytest

from kge.components.collider import Collider
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Circle, Polygon, Shape
from kge.components.transform import Transform
from kge.physics.resource import Physics
from kge.world import World
from tests.reliability.harness import PhysicsWorld, check_invariants

TINY = 1.3073197514429995e-167
TRIANGLE = [(0.0, 0.0), (0.6, 0.0), (0.0, 0.4)]


def _dynamic(world: World, x: float, shape: Shape, density: float = 0.0) -> int:
    return world.spawn(
        Transform(x, 0.0), RigidBody(type=BodyType.DYNAMIC), Collider(shape, density=density)
    )


def _tiny_body_position(world: World) -> None:  # the fuzz's own sequence
    _dynamic(world, 0.0, Circle(1.0))
    _dynamic(world, TINY, Polygon(TRIANGLE))


def _tiny_vertex(world: World) -> None:
    _dynamic(world, 0.0, Circle(1.0))
    _dynamic(world, 0.0, Polygon([(TINY, 0.0), (0.6, 0.0), (0.0, 0.4)]))


def _tiny_offset_from_a_static_circle(world: World) -> None:
    world.spawn(Transform(0.0, 0.0), Collider(Circle(1.0)))
    _dynamic(world, TINY, Polygon(TRIANGLE))


CASES: dict[str, Callable[[World], None]] = {
    "body position": _tiny_body_position,
    "polygon vertex": _tiny_vertex,
    "offset from a static circle": _tiny_offset_from_a_static_circle,
}


@pytest.fixture
def pw() -> Iterator[PhysicsWorld]:
    pw = PhysicsWorld()
    pw.world.spawn(Transform(0.0, -1.0), Collider(Box(10.0, 1.0)))
    yield pw
    pw.close()


@pytest.mark.parametrize("case", list(CASES))
def test_a_feature_a_hair_from_another_never_makes_nan(pw: PhysicsWorld, case: str) -> None:
    CASES[case](pw.world)
    for _ in range(30):
        pw.step()
        check_invariants(pw)  # no NaN anywhere, pymunk and the ECS agree


def test_a_tiny_impulse_never_makes_nan(pw: PhysicsWorld) -> None:
    """A body exactly at a static circle's centre, nudged by 1e-200 N s: zero to Chipmunk."""
    pw.world.spawn(Transform(0.0, 0.0), Collider(Circle(1.0)))
    tri = _dynamic(pw.world, 0.0, Polygon(TRIANGLE))
    pw.world.resource(Physics).apply_linear_impulse(tri, (1e-200, 0.0))
    for _ in range(10):
        pw.step()
        check_invariants(pw)
