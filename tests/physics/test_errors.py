"""Bad input raises a clear error at the call and leaves the world unchanged (DESIGN.md Errors)."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import pytest

from kge.components.collider import Collider
from kge.components.filter import Filter
from kge.components.joints import DistanceJoint, RevoluteJoint
from kge.components.platform import OneWayPlatform
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Chain, Circle, Edge, Polygon
from kge.components.transform import Transform
from kge.errors import ComponentTypeError, ValidationError
from kge.physics.settings import PhysicsSettings

from .conftest import Sim, snapshot

BAD_VALUES: list[tuple[Callable[[], Any], type[Exception], str]] = [
    (lambda: Polygon([(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)]), ValidationError, "convex"),
    (lambda: Polygon([(math.cos(a), math.sin(a)) for a in
                      [i * 2 * math.pi / 17 for i in range(17)]]), ValidationError, "3..16"),
    (lambda: Polygon([(0, 0), (1, 1), (2, 2)]), ValidationError, "zero area"),
    (lambda: Polygon([(0, 0), (1, 1), (1, 0)]), ValidationError, "counter-clockwise"),
    (lambda: Polygon([(0, 0), (1, 0)]), ValidationError, "3..16"),
    (lambda: Polygon([(0, 0), (1, 0), (1, 0), (0, 1)]), ValidationError, "coincide"),
    (lambda: Circle(-1.0), ValidationError, "Circle.radius"),
    (lambda: Circle(0.5, center=(math.nan, 0)), ValidationError, "Circle.center"),
    (lambda: Box(0.0, 1.0), ValidationError, "Box.half_width"),
    (lambda: Edge((0, 0), (0, 0)), ValidationError, "zero length"),
    (lambda: Chain([(0, 0)]), ValidationError, "at least 2"),
    (lambda: Chain([(0, 0), (1, 0)], loop=True), ValidationError, "loop"),
    # tuples of floats (the points' fast path) with a bad value take the checked path
    (lambda: Chain([(0.0, 0.0), (1.0, math.nan)]), ValidationError, "Chain.vertices"),
    (lambda: Chain([(0.0, 0.0), (math.inf, 1.0)]), ValidationError, "Chain.vertices"),
    (lambda: Chain(((0.0, 0.0), (2e6, 1.0))), ValidationError, "must lie within 1e"),
    (lambda: Chain([(0.0, 0.0), (1.0, 0.0), (1.0, 0.0)]), ValidationError, "coincide"),
    (lambda: Polygon([(0.0, 0.0), (1.0, 0.0, 2.0), (0.0, 1.0)]),  # type: ignore[list-item]
     ValidationError,
     "Polygon.vertices"),
    (lambda: Collider(Circle(1.0), density=-1.0), ValidationError, "Collider.density"),
    (lambda: Collider(Circle(1.0), friction=math.nan), ValidationError, "Collider.friction"),
    (lambda: Collider("circle"), ComponentTypeError, "Collider.shape"),  # type: ignore[arg-type]
    (lambda: Collider(Circle(1.0), filter=(1, 2, 3)), ComponentTypeError, "Filter"),  # type: ignore[arg-type]
    (lambda: Filter(category_bits=2**33), ValidationError, "category_bits"),
    (lambda: Filter(mask_bits=-1), ValidationError, "mask_bits"),
    (lambda: Transform(math.nan, 0.0), ValidationError, "Transform.x"),
    (lambda: RigidBody(type="wobbly"), ComponentTypeError, "RigidBody.type"),  # type: ignore[arg-type]
    (lambda: RigidBody(velocity=(math.inf, 0)), ValidationError, "RigidBody.velocity"),
    (lambda: RigidBody(mass=0.0), ValidationError, "RigidBody.mass"),
    (lambda: RigidBody(linear_damping=-0.5), ValidationError, "linear_damping"),
    (lambda: OneWayPlatform(up=(0, 0)), ValidationError, "OneWayPlatform.up"),
    (lambda: PhysicsSettings(iterations=0), ValidationError, "iterations"),
]


@pytest.mark.parametrize("make,exc,text", BAD_VALUES)
def test_bad_values_raise_clear_errors(make: Callable[[], Any], exc: type[Exception],
                                       text: str) -> None:
    with pytest.raises(exc, match=text.replace(".", r"\.").replace("(", r"\(")):
        make()


def test_bad_field_write_names_entity_and_leaves_value(sim: Sim) -> None:
    e = sim.dynamic(Circle(0.5), 0.0, 3.0)
    col = sim.world.get(e, Collider)
    with pytest.raises(ValidationError, match=f"entity {e}, Collider.density"):
        col.density = -2.0
    assert col.density == 1.0
    rb = sim.rb(e)
    with pytest.raises(ValidationError, match=f"entity {e}, RigidBody.angular_velocity"):
        rb.angular_velocity = math.nan
    with pytest.raises(ValidationError, match=f"entity {e}, Transform.y"):
        sim.t(e).y = math.inf
    sim.step(5)
    assert math.isfinite(sim.t(e).y)


def _refused(sim: Sim, op: Callable[[], Any], match: str) -> None:
    sim.step()
    before = snapshot(sim.world)
    n_bodies = len(sim.system.sim.bodies)
    with pytest.raises(ValueError, match=match):
        op()
    assert snapshot(sim.world) == before
    sim.step()
    assert len(sim.system.sim.bodies) == n_bodies
    assert snapshot(sim.world) == before


def test_collider_naming_missing_body_is_refused(sim: Sim) -> None:
    sim.ground()
    _refused(sim, lambda: sim.spawn(Collider(Circle(1.0), body=999)), "does not exist")


def test_collider_naming_entity_without_rigidbody_is_refused(sim: Sim) -> None:
    plain = sim.spawn(Transform())
    _refused(sim, lambda: sim.spawn(Collider(Circle(1.0), body=plain)), "no RigidBody")
    _refused(sim, lambda: sim.world.add(plain, Collider(Circle(1.0), body=plain)), "no RigidBody")


def test_joint_to_missing_entity_or_itself_is_refused(sim: Sim) -> None:
    a = sim.dynamic(Circle(0.5), 0.0, 3.0)
    plain = sim.spawn(Transform())
    _refused(sim, lambda: sim.spawn(RevoluteJoint(a, 12345, anchor=(0, 0))), "does not exist")
    _refused(sim, lambda: sim.spawn(DistanceJoint(a, a)), "two different bodies")
    _refused(sim, lambda: sim.spawn(DistanceJoint(a, plain)), "no RigidBody")


def test_despawned_body_reference_is_refused(sim: Sim) -> None:
    a = sim.dynamic(Circle(0.5), 0.0, 3.0)
    sim.world.despawn(a)
    _refused(sim, lambda: sim.spawn(Collider(Circle(1.0), body=a)), "does not exist")


def test_points_come_back_as_tuples_of_floats() -> None:
    """Any sequence of pairs in; a tuple of (float, float) tuples out, on either path."""
    given: Any
    for given in ([(0.0, 0.0), (1.5, 2.0)], ((0.0, 0.0), (1.5, 2.0)), [[0, 0], (1.5, 2)]):
        chain = Chain(given)
        assert chain.vertices == ((0.0, 0.0), (1.5, 2.0))
        assert all(type(v) is float for p in chain.vertices for v in p)
        assert type(chain.vertices) is tuple
