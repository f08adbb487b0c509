"""Friction and restitution mixing, the 1 m/s threshold (box2d-reference: materials)."""

from __future__ import annotations

import math

import pytest

from kge.components.collider import Collider
from kge.components.shapes import Box, Circle

from .conftest import Sim


def _drop(restitution_ball: float, restitution_ground: float, gap: float) -> tuple[float, float,
                                                                                 float]:
    """Drop a ball r=0.5 with its bottom ``gap`` above the ground.

    Returns (approach speed of the first contact, rebound speed, bounce height ratio).
    """
    s = Sim()
    s.ground(restitution=restitution_ground)
    ball = s.dynamic(Circle(0.5), 0.0, 0.5 + gap + 0.005, friction=0.3,
                     restitution=restitution_ball)
    approach = rebound = 0.0
    top = -1.0
    hit = False
    for _ in range(400):
        s.step()
        if not hit and s.events.contact_begin:
            hit = True
            approach = s.events.contact_begin[0].approach_speed
        vy = s.rb(ball).velocity[1]
        if hit:
            rebound = max(rebound, vy)
            if vy <= 0 and rebound > 0:
                top = max(top, s.t(ball).y - 0.505)
                break
    s.close()
    return approach, rebound, max(top, 0.0) / gap


@pytest.mark.parametrize("e", [0.5, 0.8, 0.9, 1.0])
def test_restitution_rebound_and_height_ratio(e: float) -> None:
    approach, rebound, ratio = _drop(e, 0.0, 5.0)
    assert approach == pytest.approx(10.0, abs=0.3)
    assert rebound == pytest.approx(e * approach, rel=0.03)
    assert ratio == pytest.approx(e * e, abs=0.06)


def test_restitution_mixes_by_max() -> None:
    _, rebound_a, _ = _drop(0.0, 0.5, 5.0)  # ground bouncy, ball not
    _, rebound_b, _ = _drop(0.5, 0.2, 5.0)
    assert rebound_a == pytest.approx(5.0, rel=0.05)
    assert rebound_b == pytest.approx(5.0, rel=0.05)
    _, rebound_0, _ = _drop(0.0, 0.0, 5.0)
    assert rebound_0 < 0.05


def test_no_bounce_at_or_below_one_metre_per_second() -> None:
    approach, rebound, _ = _drop(1.0, 0.0, 0.03)
    assert approach <= 1.0
    assert rebound < 0.05
    approach, rebound, _ = _drop(1.0, 0.0, 0.1)
    assert approach > 1.0
    # the bounce happens in a substep; gravity of the rest of the step is then applied
    assert approach - 10.0 / 60.0 <= rebound <= 1.03 * approach


def _slide(mu: float) -> tuple[float, float]:
    """Box half 0.5 released on a static 30 degree slope; (distance down-slope, tilt) after 2 s."""
    s = Sim()
    a = math.radians(30)
    s.spawn(*_slope(a, mu))
    ux, uy = math.cos(a), math.sin(a)
    nx, ny = -math.sin(a), math.cos(a)
    d0 = 10.0
    h = 0.5 + 0.5 + 0.015
    box = s.dynamic(Box(0.5, 0.5), d0 * ux + h * nx, d0 * uy + h * ny, a, friction=mu)
    x0, y0 = s.t(box).x, s.t(box).y
    s.step(120)
    dx, dy = s.t(box).x - x0, s.t(box).y - y0
    dist = -(dx * ux + dy * uy)
    tilt = abs(s.t(box).angle - a)
    s.close()
    return dist, tilt


def _slope(a: float, mu: float) -> tuple[object, ...]:
    from kge.components.transform import Transform

    return (Transform(0.0, 0.0, a), Collider(Box(30.0, 0.5), friction=mu))


@pytest.mark.parametrize("mu,expected", [(0.0, 10.083), (0.3, 4.844), (0.5, 1.351)])
def test_friction_slide_distance(mu: float, expected: float) -> None:
    dist, tilt = _slide(mu)
    assert abs(dist - expected) <= max(0.05 * expected, 0.1) + 0.17  # + pymunk's 1-step lag
    assert tilt < 0.01


@pytest.mark.parametrize("mu", [0.6, 1.0])
def test_friction_sticks_above_tan30(mu: float) -> None:
    dist, _ = _slide(mu)
    assert abs(dist) < 0.01


def test_friction_mixing_is_sqrt_of_product() -> None:
    """Box friction 0.09 on a slope of friction 1.0 mixes to 0.3 (not 0.09 nor 1.0)."""
    s = Sim()
    a = math.radians(30)
    s.spawn(*_slope(a, 1.0))
    ux, uy = math.cos(a), math.sin(a)
    nx, ny = -math.sin(a), math.cos(a)
    box = s.dynamic(Box(0.5, 0.5), 10 * ux + 1.015 * nx, 10 * uy + 1.015 * ny, a, friction=0.09)
    x0, y0 = s.t(box).x, s.t(box).y
    s.step(120)
    dist = -((s.t(box).x - x0) * ux + (s.t(box).y - y0) * uy)
    shape = s.system.sim.colliders[box].shapes[0]
    assert shape.friction == pytest.approx(0.3)  # sqrt(0.09): pymunk multiplies to sqrt(a*b)
    s.close()
    assert abs(dist - 4.844) < 0.3
