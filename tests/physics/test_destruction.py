"""Despawning bodies, colliders and joints (box2d-reference: destruction); locked world."""

from __future__ import annotations

import pytest

import kge
from kge.components.collider import Collider
from kge.components.joints import DistanceJoint, RevoluteJoint, RopeJoint
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Circle
from kge.components.transform import Transform
from kge.errors import WorldLockedError
from kge.physics.contacts import PreSolve

from .conftest import Sim


def test_despawn_body_removes_colliders_joints_and_reports(sim: Sim) -> None:
    ground = sim.ground()
    a = sim.spawn(Transform(0.0, 0.5), RigidBody())
    a_box = sim.spawn(Collider(Box(0.5, 0.5), body=a))
    a_circle = sim.spawn(Collider(Circle(0.3, center=(0.0, 1.0)), body=a))
    b = sim.dynamic(Circle(0.2), 2.0, 3.0)
    c = sim.dynamic(Circle(0.2), -2.0, 3.0)
    rev = sim.spawn(RevoluteJoint(a, b, anchor=(1.0, 1.0)))
    dist = sim.spawn(DistanceJoint(a, c))
    sim.step(5)
    space = sim.system.sim.space
    assert len(space.constraints) >= 2
    sim.world.despawn(a)
    sim.step()
    ends = sim.events.contact_end
    assert [(e.collider_a, e.collider_b) for e in ends] == [(ground, a_box)]
    assert sorted(j.joint for j in sim.events.joint_destroyed) == [rev, dist]
    assert len(space.constraints) == 0
    assert not sim.world.exists(rev) and not sim.world.exists(dist)
    assert a_box not in sim.system.sim.colliders and a_circle not in sim.system.sim.colliders
    sim.world.flush()
    sim.step(10)  # the orphan colliders stay inert
    assert b in sim.system.sim.bodies and c in sim.system.sim.bodies


def test_despawn_touching_collider_only_ends_its_contact(sim: Sim) -> None:
    sim.ground()
    body = sim.spawn(Transform(0.0, 0.515), RigidBody())
    box = sim.spawn(Collider(Box(0.5, 0.5), body=body))
    sim.spawn(Collider(Circle(0.3, center=(0.0, 1.0)), body=body))
    sim.step(5)
    sim.world.despawn(box)
    sim.step()
    assert len(sim.events.contact_end) == 1
    assert sim.events.joint_destroyed == []


def test_user_despawned_joint_gives_no_event(sim: Sim) -> None:
    a = sim.dynamic(Circle(0.2), 0.0, 3.0)
    j = sim.spawn(RopeJoint(None, a, anchor_a=(0.0, 5.0), max_length=3.0))
    sim.step(2)
    sim.world.despawn(j)
    sim.step()
    assert sim.events.joint_destroyed == []
    assert len(sim.system.sim.space.constraints) == 0


def test_collide_connected(sim: Sim) -> None:
    def run(collide: bool) -> float:
        s = Sim()
        s.ground()
        low = s.dynamic(Box(0.5, 0.5), 0.0, 0.515)
        high = s.dynamic(Box(0.5, 0.5), 0.0, 1.6)
        s.spawn(RopeJoint(low, high, max_length=3.0, collide_connected=collide))
        s.step(90)
        y = s.t(high).y
        s.close()
        return y

    assert run(False) == pytest.approx(0.515, abs=0.02)
    assert run(True) == pytest.approx(1.53, abs=0.02)


def test_structural_change_inside_pre_solve_raises_and_changes_nothing(sim: Sim) -> None:
    sim.ground()
    ball = sim.dynamic(Circle(0.5), 0.0, 0.51, contact_hooks=True)
    errors: list[Exception] = []
    before = sorted(sim.world.entities())

    def hook(c: PreSolve) -> None:
        for op in (lambda: sim.world.spawn(Transform()), lambda: sim.world.despawn(ball),
                   lambda: sim.world.add(ball, Transform(1, 1)),
                   lambda: sim.world.remove(ball, Collider)):
            try:
                op()
            except WorldLockedError as exc:
                errors.append(exc)

    sim.physics.on_pre_solve(hook)
    sim.step(3)
    assert len(errors) >= 4
    assert sorted(sim.world.entities()) == before
    assert sim.world.exists(ball)


def test_scene_close_with_contacts_and_joints() -> None:
    def scene(world: kge.World) -> None:
        world.spawn(Transform(0, -10), Collider(Box(50, 10)))
        a = world.spawn(Transform(0, 0.5), RigidBody(), Collider(Box(0.5, 0.5)))
        b = world.spawn(Transform(2, 0.5), RigidBody(), Collider(Box(0.5, 0.5)))
        world.spawn(DistanceJoint(a, b))

    app = kge.App(scene, headless=True)
    app.step(10)
    app.close()
