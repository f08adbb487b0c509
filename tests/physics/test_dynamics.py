"""Body types, damping, forces and impulses (box2d-reference: body types, damping, forces)."""

from __future__ import annotations

import math

import pytest

from kge.components.collider import Collider
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Circle
from kge.components.transform import Transform
from kge.errors import ValidationError

from .conftest import Sim


def test_kinematic_moves_by_velocity_and_ignores_forces(sim: Sim) -> None:
    k = sim.dynamic(Box(0.5, 0.5), body=RigidBody(type=BodyType.KINEMATIC, velocity=(1.0, 0.0),
                                                  angular_velocity=1.0))
    for _ in range(60):
        sim.physics.apply_force(k, (100.0, 100.0))
        sim.physics.apply_torque(k, 50.0)
        sim.physics.apply_linear_impulse(k, (5.0, 5.0))
        sim.physics.apply_angular_impulse(k, 5.0)
        sim.step()
    assert sim.t(k).x == pytest.approx(1.0, abs=1e-4)
    assert sim.t(k).y == pytest.approx(0.0, abs=1e-4)
    assert sim.t(k).angle == pytest.approx(1.0, abs=1e-4)
    assert sim.rb(k).velocity == (1.0, 0.0)
    assert sim.rb(k).angular_velocity == 1.0


def test_static_body_ignores_velocity_and_forces(sim: Sim) -> None:
    s = sim.dynamic(Box(0.5, 0.5), body=RigidBody(type=BodyType.STATIC, velocity=(5.0, 0.0)))
    sim.physics.apply_force(s, (10.0, 0.0))
    sim.step(30)
    assert (sim.t(s).x, sim.t(s).y) == (0.0, 0.0)
    assert sim.rb(s).velocity == (0.0, 0.0)


@pytest.mark.parametrize("c", [0.0, 0.1, 0.5, 1.0, 2.0, 5.0, 10.0])
def test_damping_formula(zero_g: Sim, c: float) -> None:
    e = zero_g.dynamic(Box(0.5, 0.5), body=RigidBody(velocity=(10.0, 0.0), angular_velocity=10.0,
                                                     linear_damping=c, angular_damping=c))
    zero_g.step(60)
    ratio = zero_g.rb(e).velocity[0] / 10.0
    ang = zero_g.rb(e).angular_velocity / 10.0
    box2d = (1 - c / 60) ** 60
    if c <= 2:
        assert ratio == pytest.approx(box2d, abs=0.01)
        assert ang == pytest.approx(box2d, abs=0.01)
    else:
        assert min(box2d, math.exp(-c)) - 1e-9 <= ratio <= max(box2d, math.exp(-c)) + 1e-9


def test_damped_fall_terminal_velocity(sim: Sim) -> None:
    e = sim.dynamic(Circle(0.5), body=RigidBody(linear_damping=1.0))
    sim.step(600)
    assert sim.rb(e).velocity[1] == pytest.approx(-9.833, abs=0.2)


@pytest.mark.parametrize("scale,vy", [(0.0, 0.0), (0.5, -5.0), (2.0, -20.0), (-1.0, 10.0)])
def test_gravity_scale(sim: Sim, scale: float, vy: float) -> None:
    e = sim.dynamic(Circle(0.5), body=RigidBody(gravity_scale=scale))
    sim.step(60)
    assert sim.rb(e).velocity[1] == pytest.approx(vy, abs=1e-4)


def _box(zero_g: Sim) -> int:
    return zero_g.dynamic(Box(0.5, 0.5), density=1.0)


def test_force_at_point_lasts_one_step(zero_g: Sim) -> None:
    e = _box(zero_g)
    zero_g.physics.apply_force(e, (0.0, 10.0), point=(0.5, 0.0))
    zero_g.step()
    assert zero_g.rb(e).velocity[1] == pytest.approx(1 / 6, abs=1e-4)
    assert zero_g.rb(e).angular_velocity == pytest.approx(0.5, abs=1e-4)
    zero_g.step()
    assert zero_g.rb(e).velocity[1] == pytest.approx(1 / 6, abs=1e-4)
    assert zero_g.rb(e).angular_velocity == pytest.approx(0.5, abs=1e-4)


def test_impulses_change_velocity_before_the_step(zero_g: Sim) -> None:
    e = _box(zero_g)
    zero_g.physics.apply_linear_impulse(e, (2.0, 0.0))
    assert zero_g.rb(e).velocity == pytest.approx((2.0, 0.0))
    f = zero_g.dynamic(Box(0.5, 0.5), 5.0, 0.0)
    zero_g.physics.apply_linear_impulse(f, (2.0, 0.0), point=(5.0, 0.5))
    assert zero_g.rb(f).angular_velocity == pytest.approx(-6.0)
    g = zero_g.dynamic(Box(0.5, 0.5), 10.0, 0.0)
    zero_g.physics.apply_angular_impulse(g, 1.0)
    assert zero_g.rb(g).angular_velocity == pytest.approx(6.0)
    zero_g.step()
    assert zero_g.rb(e).velocity == pytest.approx((2.0, 0.0))
    assert zero_g.t(e).x == pytest.approx(2.0 / 60.0)


def test_torque_and_centre_force_for_one_second(zero_g: Sim) -> None:
    e = _box(zero_g)
    f = zero_g.dynamic(Box(0.5, 0.5), 0.0, 5.0)
    for _ in range(60):
        zero_g.physics.apply_torque(e, 1.0)
        zero_g.physics.apply_force(f, (10.0, 0.0))
        zero_g.step()
    assert zero_g.rb(e).angular_velocity == pytest.approx(6.0, abs=1e-4)
    assert zero_g.t(e).angle == pytest.approx(3.05, abs=0.11)  # pymunk integrates position first
    assert zero_g.rb(f).velocity[0] == pytest.approx(10.0, abs=1e-4)
    assert zero_g.t(f).x == pytest.approx(5.0833, abs=0.17)


def test_sleeping_body_ignores_input_without_wake(sim: Sim) -> None:
    sim.ground()
    e = sim.dynamic(Box(0.5, 0.5), 0.0, 0.515)
    sim.step(60)
    assert not sim.rb(e).awake
    sim.physics.apply_force(e, (100.0, 0.0), wake=False)
    sim.physics.apply_linear_impulse(e, (5.0, 0.0), wake=False)
    sim.physics.apply_torque(e, 5.0, wake=False)
    sim.step()
    assert not sim.rb(e).awake
    assert sim.rb(e).velocity == (0.0, 0.0)
    sim.physics.apply_force(e, (100.0, 0.0))
    assert sim.rb(e).awake
    sim.step()
    assert sim.rb(e).velocity[0] > 0.5


def test_helpers(zero_g: Sim) -> None:
    e = zero_g.dynamic(Box(0.5, 0.5), 1.0, 2.0, math.pi / 2,
                       body=RigidBody(angular_velocity=2.0))
    p = zero_g.physics
    assert p.world_point(e, (1.0, 0.0)) == pytest.approx((1.0, 3.0))
    assert p.local_point(e, (1.0, 3.0)) == pytest.approx((1.0, 0.0))
    assert p.world_vector(e, (1.0, 0.0)) == pytest.approx((0.0, 1.0))
    assert p.local_vector(e, (0.0, 1.0)) == pytest.approx((1.0, 0.0))
    assert p.world_center(e) == pytest.approx((1.0, 2.0))
    assert p.local_center(e) == pytest.approx((0.0, 0.0))
    assert p.velocity_at_point(e, (2.0, 2.0)) == pytest.approx((0.0, 2.0))


def test_helpers_refuse_bad_entities(sim: Sim) -> None:
    plain = sim.spawn(Transform())
    with pytest.raises(ValidationError, match="has no body"):
        sim.physics.apply_force(plain, (1.0, 0.0))
    with pytest.raises(KeyError, match="does not exist"):
        sim.physics.mass_data(999)
    e = sim.dynamic(Circle(0.5))
    with pytest.raises(ValueError, match="finite"):
        sim.physics.apply_force(e, (math.nan, 0.0))


def test_velocity_write_is_honoured_and_wakes(sim: Sim) -> None:
    sim.ground()
    e = sim.dynamic(Box(0.5, 0.5), 0.0, 0.515)
    sim.step(60)
    assert not sim.rb(e).awake
    sim.rb(e).velocity = (3.0, 0.0)
    sim.step()
    assert sim.rb(e).awake
    assert sim.t(e).x > 0.03


def test_teleport_keeps_velocity_and_resets_interpolation(zero_g: Sim) -> None:
    e = zero_g.dynamic(Circle(0.5), body=RigidBody(velocity=(1.0, 0.0)))
    zero_g.step(10)
    t = zero_g.t(e)
    t.x, t.y = 20.0, 5.0
    zero_g.step()
    assert t.x == pytest.approx(20.0 + 1 / 60)
    assert t.y == pytest.approx(5.0)
    prev = zero_g.physics.previous_pose(e)
    assert prev is not None and prev[0] == pytest.approx(20.0)
    ents, before, now = zero_g.physics.poses()
    i = list(ents).index(e)
    assert now[i][0] == pytest.approx(t.x) and before[i][0] == pytest.approx(20.0)


def test_teleported_static_collider_is_reindexed(sim: Sim) -> None:
    plat = sim.spawn(Transform(0.0, 0.0), Collider(Box(1.0, 0.25)))
    sim.step()
    sim.world.get(plat, Transform).x = 10.0
    ball = sim.dynamic(Circle(0.25), 10.0, 2.0)
    sim.step(90)
    assert sim.t(ball).y == pytest.approx(0.25 + 0.25 + 0.005, abs=0.01)


def test_disabled_body_leaves_simulation_and_keeps_state(sim: Sim) -> None:
    sim.ground()
    e = sim.dynamic(Circle(0.5), 0.0, 5.0)
    sim.step(10)
    y, v = sim.t(e).y, sim.rb(e).velocity
    sim.rb(e).enabled = False
    sim.step(30)
    assert sim.t(e).y == y and sim.rb(e).velocity == v
    sim.rb(e).enabled = True
    sim.step(1)
    assert sim.t(e).y < y


def test_body_type_change_at_run_time(sim: Sim) -> None:
    sim.ground()
    e = sim.dynamic(Box(0.5, 0.5), 0.0, 3.0)
    sim.step(10)
    sim.rb(e).type = BodyType.KINEMATIC
    sim.rb(e).velocity = (0.0, 0.0)
    sim.step(10)
    y = sim.t(e).y
    sim.step(10)
    assert sim.t(e).y == y
    sim.rb(e).type = BodyType.DYNAMIC
    sim.step(120)
    assert sim.t(e).y == pytest.approx(0.515, abs=0.01)
