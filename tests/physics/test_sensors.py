"""Sensors (box2d-reference: sensors)."""

from __future__ import annotations

import pytest

from kge.components.collider import Collider
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Circle
from kge.components.transform import Transform

from .conftest import Sim


def test_static_sensor_begin_end_and_no_response(sim: Sim) -> None:
    sensor = sim.spawn(Transform(0.0, 2.0), Collider(Box(1.0, 0.25), sensor=True))
    ball = sim.dynamic(Circle(0.25), 0.0, 5.0)
    begins, ends = [], []
    vys = {}
    for step in range(1, 71):
        sim.step()
        begins += [(step, e) for e in sim.events.sensor_begin]
        ends += [(step, e) for e in sim.events.sensor_end]
        vys[step] = sim.rb(ball).velocity[1]
        assert sim.events.contact_begin == []
    assert len(begins) == 1 and len(ends) == 1
    assert abs(begins[0][0] - 43) <= 1
    assert abs(ends[0][0] - 51) <= 1
    ev = begins[0][1]
    assert (ev.collider_a, ev.collider_b, ev.body_a, ev.body_b) == (sensor, ball, None, ball)
    for step, v in ((45, -7.5), (50, -25 / 3), (55, -55 / 6)):
        assert vys[step] == pytest.approx(v, abs=1e-6)


def _pair(sa: BodyType, sensor_a: bool, sb: BodyType, sensor_b: bool) -> int:
    s = Sim()
    s.spawn(Transform(0, 0), RigidBody(type=sa), Collider(Box(1, 1), sensor=sensor_a))
    s.spawn(Transform(0.5, 0), RigidBody(type=sb), Collider(Box(1, 1), sensor=sensor_b))
    s.step(3)
    n = len(s.system.sim.recorder.active)
    s.close()
    return n


D, K, S = BodyType.DYNAMIC, BodyType.KINEMATIC, BodyType.STATIC


@pytest.mark.parametrize(
    "a,sa,b,sb,fires",
    [
        (S, True, D, False, True),
        (D, True, S, False, True),
        (K, True, D, False, True),
        (D, True, D, True, True),
        (K, True, S, False, False),
        (K, True, K, False, False),
        (S, True, K, False, False),
        (S, False, K, False, False),
        (K, False, K, False, False),
    ],
)
def test_sensor_and_body_type_pair_matrix(
    a: BodyType, sa: bool, b: BodyType, sb: bool, fires: bool
) -> None:
    assert (_pair(a, sa, b, sb) == 1) == fires


def test_sensor_sensor_pair_reports_once(sim: Sim) -> None:
    a = sim.dynamic(Circle(0.5), 0.0, 0.0, body=RigidBody(gravity_scale=0.0), sensor=True)
    b = sim.dynamic(Circle(0.5), 0.6, 0.0, body=RigidBody(gravity_scale=0.0), sensor=True)
    sim.step()
    assert len(sim.events.sensor_begin) == 1
    ev = sim.events.sensor_begin[0]
    assert {ev.collider_a, ev.collider_b} == {a, b}
