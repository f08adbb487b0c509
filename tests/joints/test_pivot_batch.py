"""The bulk path for plain revolute joints (kge.physics.joints.pivots) against the per-joint one."""

from __future__ import annotations

import math

import pytest

from kge.app import App
from kge.components import Transform
from kge.components.collider import Collider
from kge.components.joints import RevoluteJoint
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Circle
from kge.physics.joint_bridge import JointBridge
from kge.physics.resource import Physics
from kge.world import World


def _chain(world: World) -> None:
    prev = None
    for i in range(6):
        # off-centre discs: the centre of gravity is not the origin
        link = world.spawn(Transform(0.5 + i, 5.0, 0.1 * i), RigidBody(),
                           Collider(Circle(0.2, (0.1, -0.05)), density=2.0 + i))
        world.spawn(RevoluteJoint(prev, link, anchor=(float(i), 5.0)))
        prev = link
    box = world.spawn(Transform(6.5, 5.0), RigidBody(), Collider(Box(0.5, 0.1), density=5.0))
    world.spawn(RevoluteJoint(prev, box, anchor=(6.0, 5.0)))


def _run(batch: bool, steps: int = 90) -> tuple[list[tuple[float, ...]], list[tuple[float, ...]]]:
    old = JointBridge.batch_revolutes
    JointBridge.batch_revolutes = batch
    try:
        app = App(_chain, headless=True)
        app.step(steps)
        poses: list[tuple[float, ...]] = [
            (t.x, t.y, t.angle) for _, (t,) in sorted(app.world.query(Transform))
        ]
        joints: list[tuple[float, ...]] = [
            (j.angle, j.speed, *j.reaction_force)
            for _, (j,) in sorted(app.world.query(RevoluteJoint))
        ]
        gaps = []
        physics = app.world.resource(Physics)
        for _, (j,) in app.world.query(RevoluteJoint):
            pa = j.local_anchor_a if j.body_a is None else physics.world_point(
                j.body_a, j.local_anchor_a)
            assert j.body_b is not None  # every joint of the chain hangs a body
            pb = physics.world_point(j.body_b, j.local_anchor_b)
            gaps.append(math.dist(pa, pb))
        assert max(gaps) < 0.05  # the testbed chains' band
        app.close()
        return poses, joints
    finally:
        JointBridge.batch_revolutes = old


def test_bulk_path_keeps_the_chain_together() -> None:
    _run(True, steps=180)


def test_bulk_path_matches_the_per_joint_path() -> None:
    bulk_poses, bulk_joints = _run(True, steps=20)
    one_poses, one_joints = _run(False, steps=20)
    # the same solver swept in another order: within a centimetre over a third of a
    # second (a swinging chain is chaotic: later the two drift apart)
    for p, q in zip(bulk_poses, one_poses, strict=True):
        assert p == pytest.approx(q, abs=1e-2)
    for p, q in zip(bulk_joints, one_joints, strict=True):
        assert p[0] == pytest.approx(q[0], abs=3e-2)  # angle
        # speeds and reactions are as order-sensitive as in any Gauss-Seidel pass
        # (running the per-joint pass in reverse entity order flips some signs)


def test_one_joint_is_the_per_joint_path_to_rounding() -> None:
    """With one joint per body pair there is no order to differ: same numbers."""

    def pendulum(world: World) -> None:
        bob = world.spawn(Transform(2.0, 8.0, 0.3), RigidBody(),
                          Collider(Circle(0.3, (0.4, 0.1)), density=10.0))
        world.spawn(RevoluteJoint(None, bob, anchor=(1.6, 8.0)))

    results = []
    for batch in (True, False):
        old = JointBridge.batch_revolutes
        JointBridge.batch_revolutes = batch
        try:
            app = App(pendulum, headless=True)
            app.step(120)
            (_, (j,)), = app.world.query(RevoluteJoint)
            (_, (t, _rb)), = app.world.query(Transform, RigidBody)
            results.append((t.x, t.y, t.angle, j.angle, j.speed, *j.reaction_force))
            app.close()
        finally:
            JointBridge.batch_revolutes = old
    assert results[0] == pytest.approx(results[1], rel=1e-9, abs=1e-9)


def test_bulk_read_back_agrees_with_the_poses() -> None:
    """The angle read back is the final relative angle of the bodies."""
    app = App(_chain, headless=True)
    app.step(30)
    for _, (j,) in app.world.query(RevoluteJoint):
        ta = 0.0 if j.body_a is None else app.world.get(j.body_a, Transform).angle
        assert j.body_b is not None and j.reference_angle is not None  # resolved when built
        tb = app.world.get(j.body_b, Transform).angle
        assert j.angle == pytest.approx(tb - ta - j.reference_angle, abs=1e-9)
        assert j.motor_torque == 0.0 and j.reaction_torque == 0.0
    app.close()


def test_bulk_path_follows_a_mass_change() -> None:
    """The batch caches masses and centres of gravity; a changed collider reloads them
    (checked only when the physics system recomputed a mass: ``Simulation.mass_epoch``)."""

    def pendulum(world: World) -> None:
        bob = world.spawn(Transform(2.0, 8.0, 0.3), RigidBody(),
                          Collider(Circle(0.3, (0.4, 0.1)), density=10.0))
        world.spawn(RevoluteJoint(None, bob, anchor=(1.6, 8.0)))

    results = []
    for batch in (True, False):
        old = JointBridge.batch_revolutes
        JointBridge.batch_revolutes = batch
        try:
            app = App(pendulum, headless=True)
            app.step(30)
            (_, (col,)), = app.world.query(Collider)
            col.density = 40.0
            col.shape = Circle(0.3, (-0.2, 0.3))  # the centre of gravity moves too
            app.step(90)
            (_, (j,)), = app.world.query(RevoluteJoint)
            (_, (t, _rb)), = app.world.query(Transform, RigidBody)
            results.append((t.x, t.y, t.angle, j.angle, j.speed, *j.reaction_force))
            app.close()
        finally:
            JointBridge.batch_revolutes = old
    assert results[0] == pytest.approx(results[1], rel=1e-9, abs=1e-9)
