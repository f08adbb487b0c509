"""PrismaticJoint and PulleyJoint against box2d-reference.md's joint table."""

from __future__ import annotations

import math

import pytest

from kge.components.joints import PrismaticJoint, PulleyJoint
from tests.joints.conftest import Sim


@pytest.mark.parametrize("iterated", [False, True], ids=["custom-limit", "iterated-limit"])
def test_motor_limit_and_no_drift(iterated: bool) -> None:
    sim = Sim(gravity=(0.0, 0.0))
    sim.iterated_hinges = iterated
    box = sim.add_body((0.0, 0.0), box=(0.5, 0.5))
    j = PrismaticJoint(None, box, anchor=(0.0, 0.0), local_axis_a=(2.0, 0.0), enable_motor=True,
                       motor_speed=1.0, max_motor_force=100.0, enable_limit=True,
                       lower_translation=-1.0, upper_translation=2.0)
    sim.add_joint(j)
    assert j.local_axis_a == (1.0, 0.0)
    longest = 0.0
    for step in range(1, 181):
        if step == 30:
            sim.bodies[box].apply_force_at_local_point((0.0, 50.0))  # off-axis push
        sim.step()
        longest = max(longest, j.translation)
        if step == 60:
            assert j.translation == pytest.approx(1.0, abs=0.02)  # Box2D 1.000
            assert j.speed == pytest.approx(1.0, abs=1e-3)
    assert j.translation == pytest.approx(2.0, abs=0.01)  # Box2D stops at 2.005
    assert longest <= 2.01
    assert j.motor_force == pytest.approx(100.0, rel=1e-3)  # pushing into the limit
    assert abs(sim.pos(box).y) < 1e-3
    assert abs(sim.angle(box)) < 1e-3


@pytest.mark.parametrize(("fmax", "speed", "force"), [(5.0, -5.0, 5.0), (20.0, 1.0, 10.0)])
def test_vertical_motor_against_gravity(fmax: float, speed: float, force: float) -> None:
    sim = Sim()
    box = sim.add_body((0.0, 0.0), box=(0.5, 0.5))  # m = 1
    j = PrismaticJoint(None, box, anchor=(0.0, 0.0), local_axis_a=(0.0, 1.0), enable_motor=True,
                       motor_speed=1.0, max_motor_force=fmax)
    sim.add_joint(j)
    sim.step(60)
    assert j.speed == pytest.approx(speed, rel=0.01)  # Box2D a = -5 (5 N) / 1.0 m/s (20 N)
    assert j.motor_force == pytest.approx(force, rel=0.01)  # Box2D 5.0 / 10.0
    # Box2D -2.5417 / +0.9583 at 1 s; pymunk moves positions before velocities (one step)
    assert j.translation == pytest.approx(-2.5417 if fmax == 5.0 else 0.9583, abs=0.1)


def test_free_slider_on_a_45_degree_axis() -> None:
    sim = Sim()
    box = sim.add_body((0.0, 0.0), box=(0.5, 0.5))
    j = PrismaticJoint(None, box, anchor=(0.0, 0.0), local_axis_a=(1.0, 1.0))
    sim.add_joint(j)
    sim.step(60)
    assert j.speed == pytest.approx(-7.071, rel=0.01)  # Box2D -7.071
    assert j.translation == pytest.approx(-3.536, abs=0.1)  # Box2D -3.594, analytic -3.536


def test_lower_limit_catches_a_falling_slider() -> None:
    sim = Sim()
    box = sim.add_body((0.0, 0.0), box=(0.5, 0.5))
    j = PrismaticJoint(None, box, anchor=(0.0, 0.0), local_axis_a=(0.0, 1.0), enable_limit=True,
                       lower_translation=-1.0, upper_translation=1.0)
    sim.add_joint(j)
    lowest = 0.0
    for _ in range(90):
        sim.step()
        lowest = min(lowest, j.translation)
    assert lowest >= -1.01  # Box2D -1.005; pymunk's groove end alone reaches -1.04
    assert j.translation == pytest.approx(-1.0, abs=0.01)
    assert j.reaction_force[1] == pytest.approx(10.0, rel=0.02)


def pulley(ratio: float, mass_a: float, mass_b: float) -> tuple[Sim, PulleyJoint, int, int]:
    sim = Sim()
    a = sim.add_body((-2.0, 5.0), box=(0.5, 0.5), density=mass_a)
    b = sim.add_body((2.0, 5.0), box=(0.5, 0.5), density=mass_b)
    j = PulleyJoint(a, b, ground_anchor_a=(-2.0, 10.0), ground_anchor_b=(2.0, 10.0),
                    anchor_a=(-2.0, 5.0), anchor_b=(2.0, 5.0), ratio=ratio)
    sim.add_joint(j)
    return sim, j, a, b


@pytest.mark.parametrize(
    ("ratio", "ma", "mb", "accel"), [(1.0, 2.0, 1.0, 10 / 3), (2.0, 2.0, 1.0, 20 / 3)]
)
def test_pulley_invariant_and_motion(ratio: float, ma: float, mb: float, accel: float) -> None:
    sim, j, a, b = pulley(ratio, ma, mb)
    worst = 0.0
    for _ in range(60):
        sim.step()
        worst = max(worst, abs(j.length_a + ratio * j.length_b - 5.0 * (1 + ratio)))
    assert worst < 0.01  # Box2D 1e-6; band 0.01 m
    assert sim.bodies[a].velocity.y == pytest.approx(-accel, rel=0.01)  # a = 3.333 / 6.667
    assert sim.bodies[b].velocity.y == pytest.approx(accel / ratio, rel=0.01)
    # Box2D A -1.694 / -3.389 (analytic -1.667 / -3.333); pymunk lags one step of motion
    assert sim.pos(a).y - 5.0 == pytest.approx(-accel / 2, rel=0.03)
    assert sim.pos(b).y - 5.0 == pytest.approx(accel / 2 / ratio, rel=0.03)
    tension = ma * (10.0 - accel)  # rope tension on A; B feels ratio·tension
    assert j.reaction_force[1] == pytest.approx(ratio * tension, rel=0.02)


def test_pulley_ratio_two_balances_one_against_two_kilograms() -> None:
    sim, _j, a, b = pulley(2.0, 1.0, 2.0)
    sim.step(60)
    assert abs(sim.pos(a).y - 5.0) < 1e-3  # Box2D 0.000
    assert abs(sim.pos(b).y - 5.0) < 1e-3


def test_pulley_invariant_holds_without_substeps() -> None:
    sim = Sim(substeps=1)
    a = sim.add_body((-2.0, 5.0), box=(0.5, 0.5), density=2.0)
    b = sim.add_body((2.0, 5.0), box=(0.5, 0.5), density=1.0)
    j = PulleyJoint(a, b, ground_anchor_a=(-2.0, 10.0), ground_anchor_b=(2.0, 10.0),
                    anchor_a=(-2.0, 5.0), anchor_b=(2.0, 5.0))
    sim.add_joint(j)
    sim.step(60)
    assert abs(j.length_a + j.length_b - 10.0) < 0.01
    assert sim.bodies[a].velocity.y == pytest.approx(-10 / 3, rel=0.01)


def test_pulley_max_length_stops_a_side() -> None:
    sim = Sim()
    a = sim.add_body((-2.0, 5.0), box=(0.5, 0.5), density=2.0)
    b = sim.add_body((2.0, 5.0), box=(0.5, 0.5), density=1.0)
    j = PulleyJoint(a, b, ground_anchor_a=(-2.0, 10.0), ground_anchor_b=(2.0, 10.0),
                    anchor_a=(-2.0, 5.0), anchor_b=(2.0, 5.0), max_length_a=6.0)
    sim.add_joint(j)
    sim.step(120)
    assert j.length_a == pytest.approx(6.0, abs=0.05)
    assert abs(sim.bodies[a].velocity.y) < 0.1
    assert math.isfinite(j.length_b)
