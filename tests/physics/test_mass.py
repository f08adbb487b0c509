"""Mass rules (box2d-reference: mass_rules)."""

from __future__ import annotations

import math

import pytest

from kge.components.collider import Collider
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Circle, Edge, Polygon
from kge.components.transform import Transform

from .conftest import Sim


def test_circle_and_box_mass(sim: Sim) -> None:
    c = sim.dynamic(Circle(0.5), density=1.0)
    b = sim.dynamic(Box(1.0, 0.5), 5.0, density=2.0)
    md = sim.physics.mass_data(c)
    assert md.mass == pytest.approx(0.785398, rel=1e-5)
    assert md.inertia == pytest.approx(0.098175, rel=1e-4)
    md = sim.physics.mass_data(b)
    assert md.mass == pytest.approx(4.0, rel=1e-5)
    assert md.inertia == pytest.approx(1.66667, rel=1e-4)
    assert md.center == pytest.approx((0.0, 0.0))


def test_triangle_centroid_and_inertia(sim: Sim) -> None:
    e = sim.dynamic(Polygon([(0, 0), (2, 0), (0, 1)]))
    md = sim.physics.mass_data(e)
    assert md.mass == pytest.approx(1.0, rel=1e-5)
    assert md.center == pytest.approx((2 / 3, 1 / 3), rel=1e-5)
    assert md.inertia == pytest.approx(0.27778, rel=1e-4)  # about the centroid
    # Box2D reports it about the origin: I_c + m |c|^2 = 0.83333
    assert md.inertia + md.mass * (md.center[0] ** 2 + md.center[1] ** 2) == pytest.approx(
        0.83333, rel=1e-4)
    assert sim.physics.world_center(e) == pytest.approx((2 / 3, 1 / 3))


def test_zero_density_dynamic_gets_one_kg_and_no_rotation(zero_g: Sim) -> None:
    e = zero_g.dynamic(Box(0.5, 0.5), density=0.0)
    md = zero_g.physics.mass_data(e)
    assert md.mass == 1.0
    assert math.isinf(md.inertia)
    zero_g.physics.apply_torque(e, 10.0)
    zero_g.physics.apply_force(e, (10.0, 0.0))
    zero_g.step()
    assert zero_g.rb(e).angular_velocity == 0.0
    assert zero_g.rb(e).velocity[0] == pytest.approx(10.0 / 60.0, rel=1e-4)


def test_body_without_colliders_and_edge_only_body_weigh_one_kg(sim: Sim) -> None:
    bare = sim.spawn(Transform(), RigidBody())
    edge = sim.dynamic(Edge((0, 0), (1, 0)), 0.0, 5.0)
    assert sim.physics.mass_data(bare).mass == 1.0
    assert sim.physics.mass_data(edge).mass == 1.0


def test_fixed_rotation_keeps_omega_zero(zero_g: Sim) -> None:
    e = zero_g.dynamic(Box(0.5, 0.5), body=RigidBody(fixed_rotation=True))
    assert math.isinf(zero_g.physics.mass_data(e).inertia)
    zero_g.physics.apply_torque(e, 100.0)
    zero_g.physics.apply_force(e, (0.0, 10.0), point=(0.5, 0.0))
    zero_g.step(10)
    assert zero_g.rb(e).angular_velocity == 0.0
    assert zero_g.t(e).angle == 0.0
    # re-applied after a mass change
    zero_g.world.get(e, Collider).density = 3.0
    zero_g.physics.apply_torque(e, 100.0)
    zero_g.step()
    assert zero_g.rb(e).angular_velocity == 0.0


def test_static_and_kinematic_mass_zero(sim: Sim) -> None:
    s = sim.dynamic(Box(0.5, 0.5), body=RigidBody(type=BodyType.STATIC))
    k = sim.dynamic(Box(0.5, 0.5), 3.0, body=RigidBody(type=BodyType.KINEMATIC))
    g = sim.spawn(Transform(0, -5), Collider(Box(1, 1)))
    for e in (s, k, g):
        assert sim.physics.mass_data(e).mass == 0.0


def test_mass_override_and_reset(sim: Sim) -> None:
    e = sim.dynamic(Box(0.5, 0.5))
    assert sim.physics.mass_data(e).mass == pytest.approx(1.0)
    sim.rb(e).mass = 5.0
    sim.step()
    md = sim.physics.mass_data(e)
    assert md.mass == 5.0
    assert md.inertia == pytest.approx(5.0 / 6.0)
    sim.rb(e).mass = None
    sim.step()
    assert sim.physics.mass_data(e).mass == pytest.approx(1.0)


def test_sensor_density_adds_mass_and_compound_centre(sim: Sim) -> None:
    body = sim.spawn(Transform(0, 5), RigidBody())
    sim.spawn(Collider(Box(0.5, 0.5, center=(0.0, 0.0)), density=1.0, body=body))
    sim.spawn(Collider(Box(0.5, 0.5, center=(2.0, 0.0)), density=3.0, body=body))
    md = sim.physics.mass_data(body)
    assert md.mass == pytest.approx(4.0)
    assert md.center == pytest.approx((1.5, 0.0))
    sensor = sim.dynamic(Box(0.5, 0.5), 10.0, density=1.0, sensor=True)
    assert sim.physics.mass_data(sensor).mass == pytest.approx(1.0)


def test_adding_a_collider_recomputes_mass(sim: Sim) -> None:
    body = sim.spawn(Transform(0, 5), RigidBody())
    assert sim.physics.mass_data(body).mass == 1.0
    sim.spawn(Collider(Circle(0.5), density=0.0, body=body))
    assert sim.physics.mass_data(body).mass == 1.0
    c2 = sim.spawn(Collider(Box(0.5, 0.5), density=1.0, body=body))
    assert sim.physics.mass_data(body).mass == pytest.approx(1.0)
    sim.world.despawn(c2)
    sim.world.flush()
    sim.step()
    assert sim.physics.mass_data(body).mass == 1.0


def test_static_to_dynamic_type_change_recomputes_mass(sim: Sim) -> None:
    e = sim.dynamic(Box(1.0, 0.5), 0.0, 5.0, body=RigidBody(type=BodyType.STATIC))
    sim.step(10)
    assert sim.t(e).y == 5.0
    assert sim.physics.mass_data(e).mass == 0.0
    sim.rb(e).type = BodyType.DYNAMIC
    sim.step(10)
    assert sim.physics.mass_data(e).mass == pytest.approx(2.0)
    assert sim.t(e).y < 5.0
    sim.rb(e).type = BodyType.KINEMATIC
    sim.step(2)
    assert sim.physics.mass_data(e).mass == 0.0
