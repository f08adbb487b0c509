"""A world at rest skips the bulk reads, and still reacts to everything that wakes it."""

from __future__ import annotations

from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Circle
from kge.physics.simulation import Simulation

from .conftest import Sim


def _resting_row(sim: Sim, n: int = 5) -> list[int]:
    sim.ground()
    boxes = [sim.dynamic(Box(0.5, 0.5), 2.0 * i, 0.515) for i in range(n)]
    sim.step(90)
    assert not any(sim.rb(e).awake for e in boxes)
    return boxes


def _sim(sim: Sim) -> Simulation:
    return sim.physics._sim


def test_a_sleeping_world_takes_the_quiet_path_and_poses_stay_put(sim: Sim) -> None:
    boxes = _resting_row(sim)
    sim.step(2)
    assert _sim(sim).all_asleep
    before = [(sim.t(e).x, sim.t(e).y) for e in boxes]
    sim.step(30)
    assert [(sim.t(e).x, sim.t(e).y) for e in boxes] == before
    prev = sim.physics.previous_pose(boxes[0])
    assert prev is not None and prev[:2] == before[0]  # nothing to interpolate at rest


def test_an_impulse_wakes_a_body_out_of_the_quiet_path(sim: Sim) -> None:
    boxes = _resting_row(sim)
    sim.physics.apply_linear_impulse(boxes[2], (0.0, 5.0))
    sim.step(10)
    assert sim.t(boxes[2]).y > 1.0 and sim.rb(boxes[2]).awake


def test_a_dropped_ball_wakes_the_sleepers_it_hits(sim: Sim) -> None:
    boxes = _resting_row(sim)
    ball = sim.dynamic(Circle(0.3), 0.0, 3.0, density=5.0)
    sim.step(40)
    assert sim.t(ball).y < 1.5
    assert sim.rb(boxes[0]).awake or sim.t(boxes[0]).x != 0.0


def test_teleport_and_velocity_writes_reach_sleeping_bodies(sim: Sim) -> None:
    boxes = _resting_row(sim)
    sim.t(boxes[1]).x = 20.0
    sim.rb(boxes[3]).velocity = (3.0, 0.0)
    sim.step(5)
    assert sim.t(boxes[1]).x == 20.0
    assert sim.t(boxes[3]).x > 6.1


def test_a_moving_kinematic_body_keeps_the_world_awake(sim: Sim) -> None:
    _resting_row(sim)
    k = sim.dynamic(Box(1.0, 0.2), -10.0, 5.0,
                    body=RigidBody(type=BodyType.KINEMATIC, velocity=(1.0, 0.0)))
    sim.step(60)
    assert not _sim(sim).all_asleep
    assert abs(sim.t(k).x - (-9.0)) < 0.02
