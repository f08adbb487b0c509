"""DistanceJoint and RopeJoint against box2d-reference.md's joint table."""

from __future__ import annotations

import math

import pymunk
import pytest

from kge.components.joints import DistanceJoint, RopeJoint
from tests.joints.conftest import Sim, period_of, turning_points


def test_rigid_distance_keeps_its_length_while_swinging(sim: Sim) -> None:
    ball = sim.add_body((3.0, 10.0), circle=0.25)
    sim.add_joint(DistanceJoint(None, ball, anchor_a=(0.0, 10.0), anchor_b=(3.0, 10.0)))
    worst = 0.0
    for _ in range(300):  # 5 s
        sim.step()
        worst = max(worst, abs(abs(sim.pos(ball) - (0.0, 10.0)) - 3.0))
    assert worst < 0.01  # Box2D < 1e-6; band 0.01 m


def soft_stretch(freq: float, zeta: float, density: float = 10.0) -> tuple[float, list[float]]:
    """g = 0; ball r=0.1 stretched 0.5 past length 2: (period, stretch samples)."""
    sim = Sim(gravity=(0.0, 0.0))
    ball = sim.add_body((2.5, 0.0), circle=0.1, density=density)
    sim.add_joint(
        DistanceJoint(None, ball, length=2.0, frequency_hz=freq, damping_ratio=zeta)
    )
    stretch = []
    for _ in range(240):
        sim.step()
        stretch.append(abs(sim.pos(ball)) - 2.0)
    return period_of(stretch, sim.dt), stretch


@pytest.mark.parametrize("freq", [1.0, 2.0])
def test_soft_distance_period_is_one_over_f(freq: float) -> None:
    period, _ = soft_stretch(freq, 0.0)
    assert period == pytest.approx(1.0 / freq, rel=0.03)  # Box2D 1.004 / 0.507


def test_soft_distance_period_does_not_depend_on_mass() -> None:
    light, _ = soft_stretch(2.0, 0.0, density=1.0)
    heavy, _ = soft_stretch(2.0, 0.0, density=1000.0)
    assert light == pytest.approx(heavy, rel=0.01)


@pytest.mark.parametrize(("zeta", "box2d", "analytic"), [(0.0, 0.52, 1.0), (0.1, 0.28, 0.53)])
def test_soft_distance_decay_between_box2d_and_analytic(
    zeta: float, box2d: float, analytic: float
) -> None:
    _, stretch = soft_stretch(2.0, zeta)
    peaks = turning_points(stretch)
    ratio = peaks[1] / peaks[0]
    assert box2d * 0.9 <= ratio <= analytic * 1.02


def test_soft_distance_hanging_sag_and_reaction(sim: Sim) -> None:
    ball = sim.add_body((0.0, 8.0), circle=0.1, density=10.0)
    j = DistanceJoint(None, ball, anchor_a=(0.0, 10.0), anchor_b=(0.0, 8.0),
                      frequency_hz=2.0, damping_ratio=1.0)
    sim.add_joint(j)
    sim.step(180)
    sag = abs(sim.pos(ball) - (0.0, 10.0)) - 2.0
    assert sag == pytest.approx(10.0 / (2 * math.pi * 2.0) ** 2, rel=0.10)  # Box2D 0.06332
    m = sim.bodies[ball].mass
    assert j.reaction_force[1] == pytest.approx(m * 10.0, rel=0.02)  # Box2D 3.1418 = m·g
    assert abs(j.reaction_force[0]) < 1e-3 * m * 10.0


def test_distance_min_max_range_bounds_a_spring(sim: Sim) -> None:
    ball = sim.add_body((0.0, 8.0), circle=0.1, density=10.0)
    sim.add_joint(DistanceJoint(None, ball, anchor_a=(0.0, 10.0), anchor_b=(0.0, 8.0),
                                frequency_hz=0.2, damping_ratio=0.0, max_length=2.5))
    longest = 0.0
    for _ in range(180):
        sim.step()
        longest = max(longest, abs(sim.pos(ball) - (0.0, 10.0)))
    assert 2.4 < longest <= 2.53  # a 0.2 Hz spring alone would stretch ~6 m


def free_fall_y(steps: int, y0: float, vy0: float = 0.0) -> float:
    sim = Sim()
    ball = sim.add_body((10.0, y0), circle=0.1)
    sim.bodies[ball].velocity = (0.0, vy0)
    sim.step(steps)
    return float(sim.pos(ball).y)


def test_rope_slack_is_free_fall_and_taut_length_is_capped(sim: Sim) -> None:
    ball = sim.add_body((0.0, 8.0), circle=0.1)
    j = RopeJoint(None, ball, anchor_a=(0.0, 10.0), anchor_b=(0.0, 8.0), max_length=3.0)
    sim.add_joint(j)
    ys, longest = [], 0.0
    for _ in range(240):
        sim.step()
        ys.append(sim.pos(ball).y)
        longest = max(longest, abs(sim.pos(ball) - (0.0, 10.0)))
    assert ys[9] == pytest.approx(free_fall_y(10, 8.0), abs=1e-6)
    assert ys[19] == pytest.approx(free_fall_y(20, 8.0), abs=1e-6)
    assert longest <= 3.02  # Box2D 3.000
    assert abs(sim.pos(ball) - (0.0, 10.0)) == pytest.approx(3.0, abs=0.01)
    assert j.reaction_force[1] > 0  # the rope pulls the ball up


def test_rope_launched_up_flies_freely(sim: Sim) -> None:
    ball = sim.add_body((0.0, 8.0), circle=0.1)
    sim.bodies[ball].velocity = (0.0, 8.0)
    sim.add_joint(RopeJoint(None, ball, anchor_a=(0.0, 10.0), anchor_b=(0.0, 8.0), max_length=3.0))
    top = 0.0
    for _ in range(120):
        sim.step()
        top = max(top, sim.pos(ball).y)
    free = Sim()
    b = free.add_body((0.0, 8.0), circle=0.1)
    free.bodies[b].velocity = (0.0, 8.0)
    free_top = 0.0
    for _ in range(120):
        free.step()
        free_top = max(free_top, free.pos(b).y)
    assert top == pytest.approx(free_top, abs=1e-6)  # Box2D 11.1333 (free flight)


def test_joint_between_two_non_dynamic_bodies_is_inert(sim: Sim) -> None:
    a = sim.add_body((0.0, 0.0), kind=pymunk.Body.STATIC)
    b = sim.add_body((1.0, 0.0), kind=pymunk.Body.KINEMATIC)
    sim.bodies[b].velocity = (1.0, 0.0)
    j = DistanceJoint(a, b)
    sim.add_joint(j)
    sim.step(60)
    assert sim.pos(b).x == pytest.approx(2.0)
    assert j.reaction_force == (0.0, 0.0)
    assert not sim.handles[2 + 1].constraints


def test_distance_range_without_spring_is_slack_between_bounds(sim: Sim) -> None:
    ball = sim.add_body((0.0, 8.5), circle=0.1)
    sim.add_joint(DistanceJoint(None, ball, anchor_a=(0.0, 10.0), anchor_b=(0.0, 8.5),
                                min_length=1.0, max_length=2.0))
    sim.step(10)
    assert sim.bodies[ball].velocity.y == pytest.approx(-10.0 * 10 / 60, rel=1e-6)  # free
    sim.step(110)
    assert abs(sim.pos(ball) - (0.0, 10.0)) == pytest.approx(2.0, abs=0.01)
