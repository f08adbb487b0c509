"""Jointed bodies fall asleep as in Box2D: an island sleeps once all its bodies rested 0.5 s.

Box2D's island (bodies connected by contacts and joints) sleeps when every body
in it has been below 0.01 m/s and 2 deg/s for b2_timeToSleep. kge's joints solve
partly in Python, and every write restarted Chipmunk's own sleep timer, so bodies
held by prismatic, distance, pulley, weld, wheel or rope joints never slept.
Step counts measured with pybox2d 2.3.10 on the same scenes (8/3 iterations).
"""

from __future__ import annotations

import pytest

from kge.components import joints
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Circle

from .conftest import Sim


def _scene(kind: str) -> tuple[Sim, list[int]]:
    """A body or two held by one joint, starting at rest where they stay at rest."""
    sim = Sim()
    sim.ground()
    if kind == "distance":
        b = sim.dynamic(Circle(0.25), 0.0, 7.0)
        sim.spawn(joints.DistanceJoint(None, b, anchor_a=(0.0, 10.0), anchor_b=(0.0, 7.0)))
        bodies = [b]
    elif kind == "revolute":
        b = sim.dynamic(Circle(0.25), 0.0, 7.0)
        sim.spawn(joints.RevoluteJoint(None, b, anchor=(0.0, 10.0)))
        bodies = [b]
    elif kind == "prismatic":
        b = sim.dynamic(Box(0.5, 0.5), 0.0, 0.515)
        sim.spawn(joints.PrismaticJoint(None, b, anchor=(0.0, 0.515), local_axis_a=(1.0, 0.0)))
        bodies = [b]
    elif kind == "pulley":
        a = sim.dynamic(Box(0.5, 0.5), -2.0, 5.0)
        b = sim.dynamic(Box(0.5, 0.5), 2.0, 5.0)
        sim.spawn(joints.PulleyJoint(a, b, ground_anchor_a=(-2.0, 10.0), ground_anchor_b=(2.0, 10.0),
                              anchor_a=(-2.0, 5.5), anchor_b=(2.0, 5.5)))
        bodies = [a, b]
    elif kind == "weld":
        a = sim.dynamic(Box(0.5, 0.5), 0.0, 0.515)
        b = sim.dynamic(Box(0.5, 0.5), 1.0, 0.515)
        sim.spawn(joints.WeldJoint(a, b, anchor=(0.5, 0.515)))
        bodies = [a, b]
    elif kind == "wheel":
        car = sim.dynamic(Box(1.0, 0.25), 0.0, 1.2)
        wheel = sim.dynamic(Circle(0.4), 0.0, 0.41, friction=0.9)
        sim.spawn(joints.WheelJoint(car, wheel, anchor=(0.0, 0.41), local_axis_a=(0.0, 1.0)))
        bodies = [car, wheel]
    else:
        b = sim.dynamic(Circle(0.25), 0.0, 7.0)
        sim.spawn(joints.RopeJoint(None, b, anchor_a=(0.0, 10.0), anchor_b=(0.0, 7.0), max_length=3.0))
        bodies = [b]
    return sim, bodies


def _asleep_at(sim: Sim, bodies: list[int], limit: int) -> int | None:
    for k in range(1, limit + 1):
        sim.step()
        if not any(sim.rb(e).awake for e in bodies):
            return k
    return None


@pytest.mark.parametrize(
    ("kind", "box2d"),
    [("distance", 30), ("revolute", 30), ("prismatic", 30), ("pulley", 30), ("weld", 30),
     ("rope", 30), ("wheel", 113)],
)
def test_a_jointed_island_sleeps_after_half_a_second_at_rest(kind: str, box2d: int) -> None:
    sim, bodies = _scene(kind)
    step = _asleep_at(sim, bodies, 300)
    assert step is not None, f"{kind}: still awake after 5 s"
    # Box2D's step, give or take: the wheel's spring rings a little longer on pymunk
    assert abs(step - box2d) <= (3 if box2d == 30 else 25)
    sim.close()


@pytest.mark.parametrize("kind", ["distance", "prismatic", "pulley", "weld", "wheel", "rope"])
def test_a_sleeping_jointed_island_stays_put_and_wakes_when_hit(kind: str) -> None:
    sim, bodies = _scene(kind)
    assert _asleep_at(sim, bodies, 300) is not None
    poses = [(sim.t(e).x, sim.t(e).y, sim.t(e).angle) for e in bodies]
    sim.step(300)  # the joints' passes leave a sleeping island alone
    assert not any(sim.rb(e).awake for e in bodies)
    assert [(sim.t(e).x, sim.t(e).y, sim.t(e).angle) for e in bodies] == poses
    top = sim.t(bodies[0])
    sim.dynamic(Circle(0.2), top.x, top.y + 2.0)
    for _ in range(60):
        sim.step()
        if sim.rb(bodies[0]).awake:
            break
    assert all(sim.rb(e).awake for e in bodies)  # the whole island wakes
    sim.close()


def test_a_moving_neighbour_keeps_a_jointed_island_awake_until_it_rests() -> None:
    """Box2D's rule is per island: a welded pair under a box still sliding across it
    sleeps only once the box has rested 0.5 s too, and then together with it."""
    sim = Sim()
    sim.ground()
    a = sim.dynamic(Box(0.5, 0.5), 0.0, 0.515)
    b = sim.dynamic(Box(0.5, 0.5), 1.0, 0.515)
    sim.spawn(joints.WeldJoint(a, b, anchor=(0.5, 0.515)))
    rider = sim.dynamic(Box(0.25, 0.25), 0.25, 1.03 + 0.25 - 0.005,
                        body=RigidBody(velocity=(0.8, 0.0)))
    steps = {}
    for k in range(1, 400):
        sim.step()
        for e in (a, b, rider):
            if e not in steps and not sim.rb(e).awake:
                steps[e] = k
        if len(steps) == 3:
            break
    assert len(steps) == 3
    assert steps[a] == steps[b] == steps[rider] > 40  # one island, asleep together


def test_allow_sleep_false_keeps_the_island_awake() -> None:
    sim, bodies = _scene("weld")
    sim.rb(bodies[1]).allow_sleep = False
    assert _asleep_at(sim, bodies[:1], 120) is None
    sim.close()
