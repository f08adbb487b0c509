"""Contact events: sides, normals, points, bounce sequence, delivery (box2d-reference)."""

from __future__ import annotations

from typing import Any

import pytest

import kge
from kge.components.behaviour import Behaviour
from kge.components.collider import Collider
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Circle, Edge
from kge.components.transform import Transform
from kge.physics.events import ContactBegin, PhysicsEvents

from .conftest import Sim


def _first_begin(sim: Sim, steps: int = 3) -> ContactBegin:
    for _ in range(steps):
        sim.step()
        if sim.events.contact_begin:
            return sim.events.contact_begin[0]
    raise AssertionError("no contact")


def test_ground_first_then_box(sim: Sim) -> None:
    g = sim.ground()
    box = sim.dynamic(Box(0.5, 0.5), 0.0, 0.51)
    ev = _first_begin(sim)
    assert (ev.collider_a, ev.collider_b) == (g, box)
    assert (ev.body_a, ev.body_b) == (None, box)
    assert ev.normal == pytest.approx((0.0, 1.0))
    assert len(ev.points) == 2
    assert all(abs(p[1]) < 0.02 for p in ev.points)


def test_box_first_then_ground_normal_flips(sim: Sim) -> None:
    box = sim.dynamic(Box(0.5, 0.5), 0.0, 0.51)
    g = sim.ground()
    ev = _first_begin(sim)
    assert (ev.collider_a, ev.collider_b) == (box, g)
    assert ev.normal == pytest.approx((0.0, -1.0))


def test_circle_vs_polygon_polygon_is_a(sim: Sim) -> None:
    ball = sim.dynamic(Circle(0.5), 0.0, 0.505)
    g = sim.ground()
    ev = _first_begin(sim)
    assert (ev.collider_a, ev.collider_b) == (g, ball)
    assert ev.normal == pytest.approx((0.0, 1.0))
    assert len(ev.points) == 1


def test_static_circle_first_vs_dynamic_circle(sim: Sim) -> None:
    s = sim.spawn(Transform(0.0, 0.0), Collider(Circle(0.5)))
    d = sim.dynamic(Circle(0.5), 0.0, 0.99)
    ev = _first_begin(sim)
    assert (ev.collider_a, ev.collider_b) == (s, d)
    assert ev.normal == pytest.approx((0.0, 1.0), abs=1e-6)


@pytest.mark.parametrize("shape,points", [(Box(0.5, 0.5), 2), (Circle(0.5), 1)])
def test_anything_vs_edge_edge_is_a(sim: Sim, shape: Any, points: int) -> None:
    body = sim.dynamic(shape, 0.0, 0.51)
    edge = sim.spawn(Transform(), Collider(Edge((-5.0, 0.0), (5.0, 0.0))))
    ev = _first_begin(sim)
    assert (ev.collider_a, ev.collider_b) == (edge, body)
    assert ev.normal == pytest.approx((0.0, 1.0))
    assert len(ev.points) == points


def test_rotated_box_touches_with_one_point(sim: Sim) -> None:
    sim.ground()
    sim.dynamic(Box(0.5, 0.5), 0.0, 0.72, 0.785398)
    ev = _first_begin(sim, 10)
    assert len(ev.points) == 1


def test_bounce_sequence_and_no_events_while_asleep(sim: Sim) -> None:
    sim.ground()
    ball = sim.dynamic(Circle(0.5), 0.0, 3.0, restitution=0.5)
    begins, ends = [], []
    asleep_at = None
    for step in range(1, 400):
        sim.step()
        begins += [step] * len(sim.events.contact_begin)
        ends += [step] * len(sim.events.contact_end)
        if asleep_at is None and not sim.rb(ball).awake:
            asleep_at = step
    assert abs(begins[0] - 42) <= 1
    assert abs(len(begins) - 5) <= 1
    assert len(ends) == len(begins) - 1  # resting contact stays open
    assert asleep_at is not None
    assert all(s <= asleep_at for s in begins + ends)


def test_events_balanced_on_despawn(sim: Sim) -> None:
    g = sim.ground()
    box = sim.dynamic(Box(0.5, 0.5), 0.0, 0.51)
    sim.step(5)
    assert len(sim.system.sim.recorder.active) == 1
    sim.world.despawn(box)
    sim.step()
    assert len(sim.events.contact_end) == 1
    end = sim.events.contact_end[0]
    assert (end.collider_a, end.collider_b) == (g, box)
    assert sim.system.sim.recorder.active == {}


def test_hit_events_above_threshold(sim: Sim) -> None:
    sim.ground()
    fast = sim.dynamic(Circle(0.5), 0.0, 5.0, hit_threshold=5.0)
    slow = sim.dynamic(Circle(0.5), 3.0, 0.6, hit_threshold=5.0)
    quiet = sim.dynamic(Circle(0.5), 6.0, 5.0)
    hits = []
    for _ in range(90):
        sim.step()
        hits += sim.events.hits
    assert [h.collider_b for h in hits] == [fast]
    assert hits[0].approach_speed > 5.0
    assert slow not in [h.collider_b for h in hits] and quiet not in [h.collider_b for h in hits]


class Listener:
    def __init__(self) -> None:
        self.log: list[tuple[str, Any]] = []

    def on_contact_begin(self, event: Any) -> None:
        self.log.append(("begin", event))

    def on_contact_end(self, event: Any) -> None:
        self.log.append(("end", event))

    def on_sensor_begin(self, event: Any) -> None:
        self.log.append(("sensor", event))


def test_delivery_to_behaviours_and_esper_handlers() -> None:
    ball_script = Listener()
    ground_script = Listener()
    seen: list[Any] = []

    def scene(world: kge.World) -> None:
        world.spawn(Transform(0, -10), Collider(Box(50, 10)), Behaviour(ground_script))
        world.spawn(Transform(0, 1), RigidBody(), Collider(Circle(0.5), restitution=0.5),
                    Behaviour(ball_script))
        world.set_handler("contact_begin", seen.append)

    app = kge.App(scene, headless=True)
    app.step(90)
    kinds = [k for k, _ in ball_script.log]
    assert kinds[:2] == ["begin", "end"]
    assert [k for k, _ in ground_script.log][:2] == ["begin", "end"]
    assert len(seen) == kinds.count("begin")
    assert isinstance(app.world.resource(PhysicsEvents), PhysicsEvents)
    app.close()


def test_behaviour_on_body_entity_gets_compound_child_events() -> None:
    body_script = Listener()

    def scene(world: kge.World) -> None:
        world.spawn(Transform(0, -10), Collider(Box(50, 10)))
        body = world.spawn(Transform(0, 1), RigidBody(), Behaviour(body_script))
        world.spawn(Collider(Box(0.5, 0.5), body=body))
        world.spawn(Collider(Box(0.5, 0.5, center=(3, 0)), body=body))

    app = kge.App(scene, headless=True)
    app.step(60)
    assert [k for k, _ in body_script.log].count("begin") == 2
    app.close()


def test_kinematic_pusher_moves_dynamic_box(sim: Sim) -> None:
    sim.ground()
    pusher = sim.dynamic(Box(0.5, 0.5), -2.0, 0.515,
                         body=RigidBody(type=BodyType.KINEMATIC, velocity=(2.0, 0.0)))
    box = sim.dynamic(Box(0.5, 0.5), 0.0, 0.515, friction=0.0)
    sim.step(120)
    assert sim.rb(box).velocity[0] == pytest.approx(2.0, abs=0.05)
    assert sim.rb(pusher).velocity == (2.0, 0.0)
