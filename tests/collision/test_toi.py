"""Time of impact against b2TimeOfImpact, and the guarantees it gives."""

from __future__ import annotations

import math
from collections import Counter

import pytest

from kge.collision import Sweep, distance, time_of_impact
from kge.components.shapes import LINEAR_SLOP, Box, Circle, Edge, Polygon
from kge.errors import ValidationError
from tests.collision.reference import data, shapes, sweep

#: time tolerance (a fraction of the sweep): both stop within 0.25 * linear slop of the
#: target gap along the same iteration path; float32 moves t by far less than this
T_TOL = 1e-4


def test_time_of_impact_matches_box2d() -> None:
    states: Counter[str] = Counter()
    for c in data()["toi"]:
        out = time_of_impact(shapes()[c["a"]], sweep(c["sweep_a"]), shapes()[c["b"]],
                             sweep(c["sweep_b"]), c["t_max"], child_a=c["child_a"],
                             child_b=c["child_b"])
        assert out.state == c["state"], c
        assert out.t == pytest.approx(c["t"], abs=T_TOL), c
        states[out.state] += 1
    assert states["touching"] > 20 and states["separated"] > 20 and states["overlapped"] > 3


def test_a_fast_ball_does_not_tunnel_through_a_thin_wall() -> None:
    ball, wall = Circle(0.1), Box(0.01, 2.0)
    moving = Sweep.between((-10.0, 0.0, 0.0), (10.0, 0.0, 0.0))  # 20 m in one step
    still = Sweep.between((0.0, 0.0, 0.0), (0.0, 0.0, 0.0))
    out = time_of_impact(ball, moving, wall, still)
    assert out.state == "touching"
    at = moving.transform(out.t)
    core = distance(ball, (at.x, at.y, at.angle), wall, (0.0, 0.0, 0.0), use_radii=False)
    # Box2D's target: the rounded shapes overlap by 3 linear slop, within 0.25 slop
    target = 0.1 + 0.01 - 3 * LINEAR_SLOP
    assert core.distance == pytest.approx(target, abs=0.25 * LINEAR_SLOP)
    assert at.x < 0.0  # stopped on the near side


def test_a_spinning_bar_hits_a_post() -> None:
    bar = Polygon([(2.0, -0.05), (2.0, 0.05), (-2.0, 0.05), (-2.0, -0.05)])
    spin = Sweep((0.0, 0.0), (0.0, 0.0), (0.0, 0.0), 0.0, math.pi / 2)
    post = Sweep.between((0.0, 1.5, 0.0), (0.0, 1.5, 0.0))
    out = time_of_impact(bar, spin, Circle(0.1), post)
    assert out.state == "touching"
    # the bar's top face (y = 0.05 in its frame) reaches the post when the post's
    # centre, at (1.5 sin a, 1.5 cos a) in the bar's frame, is the target gap above it
    target = 0.1 + 0.01 - 3 * LINEAR_SLOP
    angle = math.acos((0.05 + target) / 1.5)
    assert out.t == pytest.approx(angle / (math.pi / 2), abs=1e-3)


def test_separated_and_overlapped_states() -> None:
    still = Sweep.between((0.0, 0.0, 0.0), (0.0, 0.0, 0.0))
    away = Sweep.between((3.0, 0.0, 0.0), (6.0, 0.0, 0.0))
    assert time_of_impact(Circle(0.5), still, Circle(0.5), away).state == "separated"
    assert time_of_impact(Circle(0.5), still, Circle(0.5), away, 0.5).t == 0.5
    # circles' cores are points: only polygons' cores can overlap
    inside = Sweep.between((0.2, 0.0, 0.0), (3.0, 0.0, 0.0))
    assert time_of_impact(Circle(0.5), still, Circle(0.5), inside).state == "touching"
    assert time_of_impact(Box(0.5, 0.5), still, Box(0.5, 0.5), inside).state == "overlapped"
    over = time_of_impact(Edge((-1, 0), (1, 0)), still, Box(0.5, 0.5),
                          Sweep.between((0.0, 2.0, 0.0), (0.0, -2.0, 0.0)))
    assert over.state == "touching" and 0.3 < over.t < 0.4


def test_advance_restarts_the_sweep_where_it_was() -> None:
    s = Sweep((0.5, 0.0), (0.0, 0.0), (4.0, 2.0), 0.0, 1.0)
    later = s.advance(0.25)
    assert later.alpha0 == 0.25 and later.c0 == pytest.approx((1.0, 0.5))
    assert later.a0 == pytest.approx(0.25)
    # the pose at the restart is the pose the old sweep had there
    old, new = s.transform(0.25), later.transform(0.0)
    assert (new.x, new.y, new.angle) == pytest.approx((old.x, old.y, old.angle))
    again = later.advance(0.625)  # halfway through what remained
    assert again.c0 == pytest.approx((2.5, 1.25))
    with pytest.raises(ValidationError, match="alpha must be in"):
        later.advance(0.1)


def test_sweep_transform_places_the_local_centre_on_the_path() -> None:
    s = Sweep((1.0, 0.0), (0.0, 0.0), (4.0, 0.0), 0.0, math.pi)
    mid = s.transform(0.5)
    assert mid.apply((1.0, 0.0)) == pytest.approx((2.0, 0.0))
    assert mid.angle == pytest.approx(math.pi / 2)
    assert s.normalized().a0 == 0.0
    assert Sweep((0, 0), (0, 0), (0, 0), 7.0, 8.0).normalized().a0 == pytest.approx(7 - 2 * math.pi)
