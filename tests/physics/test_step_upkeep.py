"""The per-step upkeep around pymunk's solver: bulk velocity reads, speed caps between
substeps, the CCD obstacle index after a re-laid chain, and the joint check of sweeps."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pymunk
import pymunk.batch as pb
import pytest

from kge.physics.ccd import ContinuousCollision
from kge.physics.ccd import sweep as sweep_module
from kge.physics.ccd.obstacles import Obstacles
from kge.physics.cp.bulk import BodyReader
from kge.physics.cp.static_bulk import add_shapes, chain_segments
from kge.physics.speed_cap import SpeedCap

_VELOCITIES = pb.BodyFields.VELOCITY | pb.BodyFields.ANGULAR_VELOCITY
DT = 1.0 / 60.0


def _balls(space: pymunk.Space, n: int, x0: float = 0.0) -> list[pymunk.Body]:
    bodies = []
    for k in range(n):
        body = pymunk.Body(1.0, 1.0)
        body.position = (x0 + k, 0.0)
        body.velocity = (k * 0.5, -k * 0.25)
        body.angular_velocity = k * 0.1
        space.add(body, pymunk.Circle(body, 0.2))
        bodies.append(body)
    return bodies


def _expected(bodies: list[pymunk.Body]) -> list[float]:
    return [x for b in bodies for x in (*b.velocity, b.angular_velocity)]


def test_the_flat_view_is_kept_while_the_space_is_steady_and_follows_growth() -> None:
    space = pymunk.Space()
    bodies = _balls(space, 5)
    reader = BodyReader(_VELOCITIES)
    assert reader.fill(space) == 15
    view = reader.flat()
    assert view.tolist() == _expected(bodies)
    assert list(reader.memory()) == view.tolist()
    bodies[2].velocity = (7.0, 8.0)
    assert reader.fill(space) == 15
    assert reader.flat() is view  # the same view, showing the new read
    assert view.tolist() == _expected(bodies)
    bodies += _balls(space, 300, x0=10.0)  # the C arrays grow (and move)
    assert reader.fill(space) == 3 * 305
    grown = reader.flat()
    assert grown is not view and grown.tolist() == _expected(bodies)
    assert list(reader.memory()) == grown.tolist()
    assert reader.fill(pymunk.Space()) == 0
    assert len(reader.flat()) == 0 and len(reader.memory()) == 0


@pytest.mark.parametrize("count", [3, 150])  # Python's max/min, then numpy's reductions
def test_speed_caps_between_substeps_write_only_the_bodies_over(count: int) -> None:
    space = pymunk.Space()
    bodies = _balls(space, count)
    static = pymunk.Body(body_type=pymunk.Body.STATIC)
    space.add(static, pymunk.Segment(static, (-5.0, -5.0), (5.0, -5.0), 0.1))
    ids = sorted((b.id, b) for b in bodies)
    known = (np.array([i for i, _ in ids], np.int64), [b for _, b in ids])
    vmax, wmax = 2.0 / DT, 0.5 * math.pi / DT
    cap = SpeedCap()
    before = _expected(bodies)
    assert cap.before_substep(space, known, vmax, wmax) == 0
    assert cap.before_substep(space, known, vmax, wmax) == 0  # the kept view, read again
    assert _expected(bodies) == before
    fast, spinning = bodies[1], bodies[-1]
    fast.velocity = (300.0, 400.0)
    spinning.angular_velocity = -200.0
    assert cap.before_substep(space, known, vmax, wmax) == 2
    assert fast.velocity.x == pytest.approx(0.6 * vmax) and fast.velocity.y == pytest.approx(
        0.8 * vmax
    )
    assert spinning.angular_velocity == -wmax
    untouched = [b for b in bodies if b is not fast and b is not spinning]
    assert _expected(untouched) == [
        x for b, x3 in zip(bodies, np.reshape(before, (-1, 3)), strict=True)
        if b is not fast and b is not spinning for x in x3.tolist()
    ]
    assert cap.before_substep(space, known, vmax, wmax) == 0


def _static_space() -> tuple[pymunk.Space, pymunk.Body]:
    space = pymunk.Space()
    body = pymunk.Body(body_type=pymunk.Body.STATIC)
    space.add(body)
    return space, body


def _read(space: pymunk.Space) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    bodies = list(space.bodies)
    ids = np.array([b.id for b in bodies], np.int64)
    pose = np.array([(b.position.x, b.position.y, b.angle) for b in bodies], float)
    return ids, pose, np.zeros((len(bodies), 3))


def _chain(body: pymunk.Body, y: float) -> list[pymunk.Segment]:
    points = [(float(i), y + 0.3 * (i % 2)) for i in range(12)]
    return chain_segments(body, points, False, 0.01, 0.0)


def test_a_relaid_chain_keeps_its_owner_and_is_read_once() -> None:
    """What a batched env's reset does to a moon: the chain's shapes are replaced."""
    space, body = _static_space()
    first = _chain(body, 0.0)
    add_shapes(space, first)
    obs = Obstacles(space)
    obs.reclassify(body)
    for _ in range(2):
        obs.refresh(*_read(space), 0)
    owners = obs._oids
    space.remove(*first)
    second = _chain(body, 5.0)
    add_shapes(space, second)
    read: list[pymunk.Shape] = []
    bulk = obs._classify_many

    def counting(shapes: Any) -> None:
        shapes = list(shapes)
        read.extend(shapes)
        bulk(shapes)

    obs._classify_many = counting  # type: ignore[method-assign]
    obs.reclassify(body)  # the physics' sync of the re-laid collider's owner
    assert not obs._owners_dirty  # the owner never ran out of rows: no table rebuild
    assert set(second) <= set(read)
    read.clear()
    obs.refresh(*_read(space), 0)
    assert read == []  # the scan did not read the new shapes' boxes again
    assert obs._oids is owners
    assert obs.live == len(second)
    for s in first:
        assert s not in obs.row_of
    for s in second:
        bb = s.bb
        assert tuple(obs.box[obs.row_of[s]]) == (bb.left, bb.bottom, bb.right, bb.top)
    new_place = pymunk.BB(0.0, 4.9, 11.0, 5.4)
    assert set(obs.candidates(new_place, 0.1, 0.1)) == set(second)
    assert obs.candidates(pymunk.BB(0.0, -0.2, 11.0, 0.5), 0.1, 0.1) == []
    # a chain added by other means (no reclassify) is still found by the scan
    other = pymunk.Body(body_type=pymunk.Body.STATIC)
    space.add(other)
    third = _chain(other, -10.0)
    add_shapes(space, third)
    obs.refresh(*_read(space), 0)
    assert set(third) <= set(read) and all(s in obs.row_of for s in third)


def _wall(space: pymunk.Space, x: float) -> pymunk.Body:
    body = pymunk.Body(body_type=pymunk.Body.STATIC)
    body.position = (x, 0.0)
    space.add(body, pymunk.Poly.create_box(body, (0.1, 4.0), radius=0.01))
    return body


def test_sweeps_walk_a_bodys_joints_only_for_obstacles_that_have_joints(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    walks: list[pymunk.Body] = []
    original = sweep_module.joint_free_bodies

    def counting(body: pymunk.Body) -> set[pymunk.Body]:
        walks.append(body)
        return original(body)

    monkeypatch.setattr(sweep_module, "joint_free_bodies", counting)
    for jointed in (False, True):
        walks.clear()
        space = pymunk.Space()
        wall = _wall(space, 3.0)
        ball = pymunk.Body()
        shape = pymunk.Circle(ball, 0.05)
        shape.density = 1.0
        space.add(ball, shape)
        if jointed:  # a joint that lets the ball pass through what it is joined to
            joint = pymunk.SlideJoint(wall, ball, (0, 0), (0, 0), 0, 100)
            joint.collide_bodies = False
            space.add(joint)
        ccd = ContinuousCollision(space)
        ccd.track(ball)
        ball.velocity = (100.0, 0.0)
        for _ in range(12):
            ccd.before_step(DT, 4)
            for _ in range(4):
                space.step(DT / 4)
            ccd.after_step(DT)
        if jointed:
            assert walks and ball.position.x > 3.0  # not an obstacle: passed through
        else:
            assert walks == [] and ball.position.x < 3.0  # stopped, no joint walk at all


def test_contact_events_look_for_hooks_only_while_some_entity_has_a_script(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    import kge
    from kge.components import Behaviour, Collider, RigidBody, Transform
    from kge.components.shapes import Box, Circle
    from kge.systems.behaviour import BehaviourRunner

    asked: list[int] = []
    original = BehaviourRunner.call_one

    def counting(self: BehaviourRunner, entity: int, hook: str, *args: Any) -> None:
        asked.append(entity)
        original(self, entity, hook, *args)

    monkeypatch.setattr(BehaviourRunner, "call_one", counting)
    seen: list[Any] = []

    def scene(world: kge.World) -> None:
        world.spawn(Transform(0, -10), Collider(Box(50, 10)))
        world.spawn(Transform(0, 1), RigidBody(), Collider(Circle(0.5), restitution=0.5))
        world.set_handler("contact_begin", seen.append)

    app = kge.App(scene, headless=True, plugins=[kge.BehaviourPlugin(), kge.PhysicsPlugin()])
    app.step(60)
    assert seen and asked == []  # events delivered to handlers; no script to look up

    class Script:
        def __init__(self) -> None:
            self.begins = 0

        def on_contact_begin(self, event: Any) -> None:
            self.begins += 1

    script = Script()
    ball = app.world.spawn(Transform(3, 1), RigidBody(), Collider(Circle(0.5)), Behaviour(script))
    app.step(60)
    assert ball in asked and script.begins >= 1


def test_the_kept_motion_limit_follows_threshold_and_substeps() -> None:
    space = pymunk.Space()
    _wall(space, 0.5)  # within the ball's step motion: armed whenever it is fast
    ball = pymunk.Body()
    shape = pymunk.Circle(ball, 0.1)
    shape.density = 1.0
    space.add(ball, shape)
    ccd = ContinuousCollision(space)
    ccd.track(ball)
    ball.velocity = (30.0, 0.0)  # 0.5 m per step: 0.125 m per substep of 4
    assert ccd.before_step(DT, 4) == 1  # over half the 0.1 m radius per substep
    assert ccd.before_step(DT, 16) == 0  # 0.03 m per substep: under it
    ccd.threshold = 2.0
    assert ccd.before_step(DT, 1) == 1  # 0.5 m per step > 2 * 0.1 m
    ccd.threshold = 10.0
    assert ccd.before_step(DT, 1) == 0
