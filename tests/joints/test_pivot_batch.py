"""The bulk path for revolute joints (kge.physics.joints.pivots) against the per-joint one."""

from __future__ import annotations

import math
from typing import Any

import pytest

from kge.app import App
from kge.components import Transform
from kge.components.collider import Collider
from kge.components.joints import RevoluteJoint
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Circle
from kge.errors import EntityNotFoundError, ValidationError
from kge.physics.events import PhysicsEvents
from kge.physics.joint_bridge import JointBridge
from kge.physics.resource import Physics
from kge.physics.settings import PhysicsSettings
from kge.systems.physics import PhysicsSystem
from kge.world import World


@pytest.fixture(autouse=True)
def _batch_any_count(monkeypatch: pytest.MonkeyPatch) -> None:
    """These scenes have a few joints: take the bulk path anyway (kge waits for
    ``JointBridge.batch_from``, where it starts to pay)."""
    monkeypatch.setattr(JointBridge, "batch_from", 1)


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


# -- hinges with a motor and a limit, solved in pymunk's iterations (iterated_hinges) --------
def _legs(world: World, break_torque: float | None = None) -> None:
    """Lander-like: a hull dropped onto the ground on two legs whose motors push them
    outwards against their limits, so motors, limits and contacts all act."""
    from kge.components import Edge

    world.insert_resource(PhysicsSettings(substeps=4, iterations=20, iterated_hinges=True))
    world.spawn(Transform(0.0, 0.0), Collider(Edge((-10.0, 0.0), (10.0, 0.0)), friction=0.5))
    for k, x in enumerate((-3.0, 3.0)):
        hull = world.spawn(Transform(x, 2.0, 0.1 * k), RigidBody(),
                           Collider(Box(1.2, 0.6), density=5.0))
        for i in (-1, 1):
            leg = world.spawn(Transform(x + 0.7 * i, 1.4, 0.3 * i), RigidBody(),
                              Collider(Box(0.1, 0.5), density=1.0, friction=0.5))
            lower, upper = (0.4, 0.9) if i == 1 else (-0.9, -0.4)
            world.spawn(RevoluteJoint(hull, leg, anchor=(x + 0.5 * i, 1.8),
                                      enable_limit=True, lower_angle=lower, upper_angle=upper,
                                      enable_motor=True, motor_speed=0.3 * i,
                                      max_motor_torque=40.0, break_torque=break_torque))


def _bridge(app: App) -> JointBridge:
    system = app.world.get_system(PhysicsSystem)
    assert system is not None
    return system.sim.joints


def _run_legs(batch: bool, steps: int, scene: Any = _legs) -> tuple[list[Any], list[Any], Any]:
    old = JointBridge.batch_revolutes
    JointBridge.batch_revolutes = batch
    try:
        app = App(scene, headless=True)
        app.step(steps)
        poses = [(t.x, t.y, t.angle) for _, (t, _rb) in sorted(app.world.query(Transform,
                                                                                 RigidBody))]
        joints = [(j.angle, j.speed, j.motor_torque, j.reaction_torque)
                  for _, (j,) in sorted(app.world.query(RevoluteJoint))]
        bridge = _bridge(app)
        batched = set(bridge._batched)
        app.close()
        return poses, joints, batched
    finally:
        JointBridge.batch_revolutes = old


def test_motor_and_limit_hinges_join_the_batch_and_match_the_per_joint_path() -> None:
    bulk_poses, bulk_joints, batched = _run_legs(True, 90)
    one_poses, one_joints, none = _run_legs(False, 90)
    assert len(batched) == 4 and not none  # every leg hinge took the bulk path
    # standing on the ground: motors hold the legs on their limits in both
    for p, q in zip(bulk_poses, one_poses, strict=True):
        assert p == pytest.approx(q, abs=2e-3)
    for (a, _, m, r), (a1, _, m1, r1) in zip(bulk_joints, one_joints, strict=True):
        assert a == pytest.approx(a1, abs=2e-3)
        assert m == pytest.approx(m1, rel=0.05, abs=0.5)  # the motor's torque, N·m
        assert r == pytest.approx(r1, rel=0.05, abs=0.5)  # the limit's
    # the legs rest on their limits (within Box2D's 2° slop) and the motors push
    for (a, _, m, _), lower, upper in zip(bulk_joints, (-0.9, 0.4) * 2, (-0.4, 0.9) * 2,
                                          strict=True):
        assert lower - math.radians(2.5) <= a <= upper + math.radians(2.5)
        assert m != 0.0
    # a motor held off by its limit pushes with its whole max_motor_torque, in N·m (the
    # last substep's impulse over the substep's time, on both paths)
    for torques in (bulk_joints, one_joints):
        assert max(abs(m) for _, _, m, _ in torques) == pytest.approx(40.0, rel=1e-9)


def test_a_batched_limit_projects_a_hinge_back_within_its_slop() -> None:
    """Spawned 0.6 rad past its limit, a leg is turned back by Box2D's projection (8° per
    step), not only by the limit's slow velocity bias, as on the per-joint path."""

    def bent(world: World) -> None:
        world.insert_resource(PhysicsSettings(gravity=(0.0, 0.0), iterated_hinges=True))
        hull = world.spawn(Transform(0.0, 2.0), RigidBody(), Collider(Box(1.2, 0.6), density=5.0))
        leg = world.spawn(Transform(0.5, 1.8, 1.5), RigidBody(),
                          Collider(Box(0.1, 0.5), density=1.0))
        world.spawn(RevoluteJoint(hull, leg, anchor=(0.5, 1.8), reference_angle=0.0,
                                  enable_limit=True, lower_angle=0.4, upper_angle=0.9))

    for batch in (True, False):
        _, joints, batched = _run_legs(batch, 10, bent)
        assert bool(batched) == batch
        # 0.6 rad at 8° (0.14 rad) a step: back within the slop after five steps
        assert joints[0][0] <= 0.9 + math.radians(2.0) + 1e-9


def test_a_batched_limit_breaks_at_its_break_torque() -> None:
    def scene(world: World) -> None:
        _legs(world, break_torque=1.0)  # far less than the landing's limit torque

    app = App(scene, headless=True)
    broken = []
    for _ in range(90):
        app.step(1)
        broken += app.world.resource(PhysicsEvents).joint_broken
    assert broken and all(abs(ev.reaction_torque) > 1.0 for ev in broken)
    app.close()


def test_a_hinge_whose_bodies_cannot_turn_leaves_the_batch() -> None:
    """fixed_rotation on both sides takes the motor and limit out (nothing to turn):
    the joint leaves the batch, whose torque read-back assumes they are in the space."""

    def scene(world: World) -> None:
        world.insert_resource(PhysicsSettings(iterated_hinges=True))
        bob = world.spawn(Transform(1.0, 5.0), RigidBody(), Collider(Circle(0.2), density=1.0))
        world.spawn(RevoluteJoint(None, bob, anchor=(0.0, 5.0), enable_motor=True,
                                  motor_speed=1.0, max_motor_torque=5.0, enable_limit=True,
                                  lower_angle=-0.5, upper_angle=0.5))

    app = App(scene, headless=True)
    app.step(5)
    bridge = _bridge(app)
    assert len(bridge._batched) == 1
    (_, (rb,)), = app.world.query(RigidBody)
    rb.fixed_rotation = True
    app.step(5)
    assert not bridge._batched
    (_, (j,)), = app.world.query(RevoluteJoint)
    assert j.motor_torque == 0.0 and math.isfinite(j.angle)
    rb.fixed_rotation = False  # it can turn again: back in the batch
    app.step(5)
    assert len(bridge._batched) == 1
    app.close()


def test_reset_joints_drops_the_warm_start() -> None:
    """A pendulum hanging at rest: its hinge carries m·g every step. After
    Physics.reset_joints the hinge starts from nothing: for one (sub)step it applies
    no impulse while pymunk's accumulator drains, then holds the bob again."""

    def pendulum(world: World) -> None:
        world.insert_resource(PhysicsSettings(substeps=1))
        # awake throughout: a sleeping joint is not solved (its warm start waits)
        bob = world.spawn(Transform(0.0, 4.0), RigidBody(allow_sleep=False),
                          Collider(Circle(0.2), density=1.0))
        world.spawn(RevoluteJoint(None, bob, anchor=(0.0, 5.0)))

    app = App(pendulum, headless=True)
    app.step(30)
    (j_e, (j,)), = app.world.query(RevoluteJoint)
    held = math.hypot(*j.reaction_force)
    assert held > 1.0
    physics = app.world.resource(Physics)
    with pytest.raises(ValidationError, match="entity 1 has no joint component"):
        physics.reset_joints([j_e, 1])  # the bob: refused before any joint is touched
    app.step(1)
    assert math.hypot(*j.reaction_force) == pytest.approx(held, rel=0.01)
    physics.reset_joints([j_e])
    app.step(1)
    assert math.hypot(*j.reaction_force) < 0.01 * held
    app.step(2)
    assert math.hypot(*j.reaction_force) > 0.5 * held
    with pytest.raises(EntityNotFoundError, match="entity 99 does not exist"):
        physics.reset_joints([99])
    app.close()


def test_few_joints_stay_on_the_per_joint_path(monkeypatch: pytest.MonkeyPatch) -> None:
    """Below ``batch_from`` batchable joints the bulk path costs more than it saves."""

    def chains(count: int) -> Any:
        def scene(world: World) -> None:
            for c in range(count):
                prev = None
                for i in range(4):
                    link = world.spawn(Transform(3.0 * c + 0.5 + i, 5.0), RigidBody(),
                                       Collider(Circle(0.2), density=1.0))
                    world.spawn(RevoluteJoint(prev, link, anchor=(3.0 * c + i, 5.0)))
                    prev = link
        return scene

    monkeypatch.setattr(JointBridge, "batch_from", 24)
    for count, batched in ((5, 0), (6, 24)):  # 20 joints, then 24
        app = App(chains(count), headless=True)
        app.step(2)
        assert len(_bridge(app)._batched) == batched
        app.close()


@pytest.mark.parametrize("bystanders", [0, 60])
def test_the_position_pass_leaves_chipmunks_own_poses(bystanders: int) -> None:
    """After the bulk position pass, every Transform is its body's pose in Chipmunk
    to the last bit (off-centre discs: the origin is recomputed from the centre of
    gravity). Alone, the chain's moves are read back by one read of the whole space;
    among many still bodies, body by body."""

    def scene(world: World) -> None:
        _chain(world)
        for i in range(bystanders):  # resting far away: moved by nothing
            world.spawn(Transform(100.0 + 3 * i, 0.0), RigidBody(type=BodyType.STATIC),
                        Collider(Box(1.0, 0.1)))
            world.spawn(Transform(100.0 + 3 * i, 0.35, 0.2), RigidBody(),
                        Collider(Circle(0.25, (0.05, 0.02))))

    app = App(scene, headless=True)
    system = app.world.get_system(PhysicsSystem)
    assert system is not None
    sim = system.sim
    for _ in range(40):
        app.step()
        for e, (t, _rb) in app.world.query(Transform, RigidBody):
            body = sim.bodies[e].body
            assert (t.x, t.y, t.angle) == (body.position.x, body.position.y, body.angle), e
    app.close()
