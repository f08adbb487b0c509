"""Structural changes (spawn, despawn, replaced components) cost what they change.

Sync-in applies them without a pass over the world: the pose table re-slots only
the entities whose body or components changed, the joint bridge finds a body's
joints and a joint's dependents through its indexes, and refreshes the space
membership of the joints concerned only. These tests hold that bookkeeping to
what the full passes it replaced computed: the same joints destroyed in the same
order, every pose-table slot naming the right body and components, and the same
simulation bit for bit as with a full pass forced at every change.
"""

from __future__ import annotations

import random
from dataclasses import dataclass
from typing import Any

import numpy as np
import pymunk

from kge.components.joints import DistanceJoint, GearJoint, RevoluteJoint
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Circle
from kge.components.transform import Transform
from kge.physics import joint_api
from kge.physics.ccd.manager import Index
from kge.physics.joint_api import in_space
from kge.physics.settings import PhysicsSettings

from .conftest import Sim

STATIC = pymunk.Body.STATIC
DYNAMIC = pymunk.Body.DYNAMIC


def _old_destruction_order(handles: dict[int, Any], body: int) -> list[int]:
    """The joints a despawned ``body`` destroys, in the order of the full passes the
    indexes replaced: every live joint in entity order; a joint's dependents first."""
    live = {e: (h.body_a, h.body_b, tuple(h.depends_on)) for e, h in handles.items()}
    out: list[int] = []

    def destroy(e: int) -> None:
        if live.pop(e, None) is None:
            return
        for other in sorted(live):
            if other in live and e in live[other][2]:
                destroy(other)
        out.append(e)

    for e in sorted(live):
        if e in live and body in live[e][:2]:
            destroy(e)
    return out


def _geared_pair(sim: Sim, x: float, gear_first: bool) -> dict[str, int]:
    """Two wheels pinned to the ground, geared, and tied by a distance joint. With
    ``gear_first`` the gear's entity is older than the joints it depends on."""
    world = sim.world
    early = world.spawn() if gear_first else None
    w1 = sim.dynamic(Circle(0.5), x, 5.0, density=1.0)
    w2 = sim.dynamic(Circle(0.5), x + 2.0, 5.0, density=1.0)
    j1 = sim.spawn(RevoluteJoint(None, w1, anchor=(x, 5.0)))
    j2 = sim.spawn(RevoluteJoint(None, w2, anchor=(x + 2.0, 5.0)))
    d = sim.spawn(DistanceJoint(w1, w2))
    if early is not None:
        world.add(early, GearJoint(j1, j2, ratio=2.0))
        g = early
    else:
        g = sim.spawn(GearJoint(j1, j2, ratio=2.0))
    return {"w1": w1, "w2": w2, "j1": j1, "j2": j2, "d": d, "g": g}


def _crowd(sim: Sim, pairs: int) -> list[int]:
    """Many other jointed bodies (far from the pairs above)."""
    joints = []
    for k in range(pairs):
        a = sim.dynamic(Box(0.3, 0.3), 100.0 + 2.0 * k, 0.0, density=1.0)
        b = sim.dynamic(Box(0.3, 0.3), 100.6 + 2.0 * k, 0.0, density=1.0)
        joints.append(sim.spawn(RevoluteJoint(a, b, anchor=(100.3 + 2.0 * k, 0.0))))
        joints.append(sim.spawn(DistanceJoint(a, b)))
    return joints



def _record_destroys(bridge: Any) -> list[int]:
    """The joints ``bridge`` takes out, in the order they finish ``_destroy``."""
    done: list[int] = []
    destroy = bridge._destroy

    def recorded(entity: int, event: bool) -> None:
        known = entity in bridge.handles
        destroy(entity, event)
        if known:
            done.append(entity)

    bridge._destroy = recorded
    return done

def test_despawning_a_body_destroys_exactly_its_joints_and_dependents_in_order() -> None:
    sim = Sim(PhysicsSettings(gravity=(0.0, 0.0)))
    try:
        crowd = _crowd(sim, 60)
        late = _geared_pair(sim, 0.0, gear_first=False)
        early = _geared_pair(sim, 10.0, gear_first=True)
        # a second gear on the early pair's joints, and one joint on two pairs at once
        extra_gear = sim.spawn(GearJoint(early["j1"], early["j2"], ratio=-1.0))
        bridge = sim.system.sim.joints
        link = sim.spawn(DistanceJoint(late["w2"], early["w1"]))
        sim.step(2)
        assert len(bridge.handles) == len(crowd) + 2 * 4 + 2
        # the order joints are taken out (their constraints leave the space, their events
        # are made) is the order they finish _destroy; the event list is sorted later
        done = _record_destroys(bridge)
        for victim in (early["w1"], late["w1"]):
            want = _old_destruction_order(bridge.handles, victim)
            before = set(bridge.handles)
            done.clear()
            sim.world.despawn(victim)
            sim.step()
            assert done == want and done, f"despawning {victim}"
            assert sorted(ev.joint for ev in sim.events.joint_destroyed) == sorted(want)
            assert set(bridge.handles) == before - set(want)
            for j in want:
                assert not sim.world.exists(j)
            for j in bridge.handles:
                assert sim.world.exists(j)
        # the early pair: its gears went before the joint they depend on, the link too
        assert extra_gear not in bridge.handles and link not in bridge.handles
        assert all(j in bridge.handles for j in crowd)
    finally:
        sim.close()


def _pose_table_is_right(sim: Sim) -> None:
    """Every slot names its entity's body and current components; no body is missing."""
    physics = sim.system.sim
    poses, bodies, world = physics.poses, physics.bodies, sim.world
    moving = {e for e, r in bodies.items() if not r.implicit and r.body.body_type != STATIC}
    assert set(poses.slot) == moving
    n = len(moving)
    assert len(poses.ids) == len(poses.entities) == len(poses.bodies) == n
    assert poses.state.shape == (n, 6) and poses.prev.shape == (n, 3)
    assert len(poses.asleep) == len(poses.dynamic) == n
    tfs, has_tf = physics._targets.transforms
    rbs, has_rb = physics._targets.rigidbodies
    assert len(tfs) == len(rbs) == n
    for e, i in poses.slot.items():
        body = bodies[e].body
        assert int(poses.entities[i]) == e
        assert poses.bodies[i] is body
        assert int(poses.ids[i]) == body.id
        assert bool(poses.dynamic[i]) == (body.body_type == DYNAMIC)
        assert tfs[i] is world.try_get(e, Transform) and bool(has_tf[i])
        assert rbs[i] is world.try_get(e, RigidBody) and bool(has_rb[i])
        if not bodies[e].in_space:
            continue  # not read while disabled (a joint's position pass may nudge it: main too)
        p = body.position
        assert tuple(poses.state[i, :3]) == (p.x, p.y, body.angle), f"entity {e} row"
        t = world.get(e, Transform)
        assert (t.x, t.y, t.angle) == (p.x, p.y, body.angle), f"entity {e} Transform"
    ids, in_order = poses.by_id()
    assert ids.tolist() == sorted(poses.ids.tolist())
    assert [b.id for b in in_order] == ids.tolist()


def _waves(sim: Sim, rng: random.Random, steps: int, check: Any) -> list[int]:
    """Mixed spawn and despawn waves, replaced components, type changes, enabled flips."""
    sim.ground()
    live: list[int] = []
    for _ in range(steps):
        world = sim.world
        for _ in range(rng.randrange(0, 12)):
            shape = Circle(0.2) if rng.random() < 0.5 else Box(0.2, 0.3)
            live.append(sim.dynamic(shape, rng.uniform(-20, 20), rng.uniform(0, 10), density=1.0))
        rng.shuffle(live)
        for _ in range(rng.randrange(0, 8)):
            if live:
                world.despawn(live.pop())
        if live and rng.random() < 0.3:  # a teleport by a new Transform
            world.add(live[0], Transform(rng.uniform(-20, 20), 12.0))
        if len(live) > 1 and rng.random() < 0.3:  # a new RigidBody, kinematic or dynamic
            kind = BodyType.KINEMATIC if rng.random() < 0.5 else BodyType.DYNAMIC
            world.add(live[1], RigidBody(kind, velocity=(0.5, 0.0)))
        if len(live) > 2 and rng.random() < 0.2 and world.has(live[2], RigidBody):
            world.remove(live[2], RigidBody)  # an implicit static body now
        if len(live) > 3 and rng.random() < 0.3:
            rb = world.try_get(live[3], RigidBody)
            if rb is not None:
                rb.type = rng.choice([BodyType.STATIC, BodyType.KINEMATIC, BodyType.DYNAMIC])
        if len(live) > 4 and rng.random() < 0.3:
            rb = world.try_get(live[4], RigidBody)
            if rb is not None:
                rb.enabled = not rb.enabled
        if len(live) > 6 and rng.random() < 0.3:
            a, b = live[5], live[6]
            if world.has(a, RigidBody) and world.has(b, RigidBody):
                sim.spawn(RevoluteJoint(a, b, anchor=(0.0, 5.0)))
        sim.step()
        check(sim)
    return live


def test_pose_table_stays_right_through_mixed_waves() -> None:
    sim = Sim()
    try:
        live = _waves(sim, random.Random(5), 150, _pose_table_is_right)
        assert len(sim.system.sim.poses.slot) > 20 and live
    finally:
        sim.close()


def _membership_is_right(sim: Sim) -> None:
    bridge = sim.system.sim.joints
    space = bridge.space
    for h in bridge.handles.values():
        for c in h.constraints:
            a, b = c.a, c.b
            want = (a.space is space and b.space is space
                    and DYNAMIC in (a.body_type, b.body_type))
            assert in_space(space, c) == want, f"joint {h.entity}"


def test_membership_refresh_of_the_joints_concerned_matches_a_full_one() -> None:
    """Right after every refresh (new joints, type changes, enabled flips), every joint's
    constraints are in the space exactly when a full pass would put them there."""
    sim = Sim()
    bridge = sim.system.sim.joints
    inner = bridge.refresh_membership
    calls = [0]

    def checked() -> None:
        inner()
        calls[0] += 1
        _membership_is_right(sim)

    bridge.refresh_membership = checked  # type: ignore[method-assign]
    try:
        _waves(sim, random.Random(11), 150, lambda s: None)
        assert calls[0] > 30 and bridge.handles
    finally:
        sim.close()


def _run(full: bool) -> list[tuple[float, ...]]:
    """The waves and a geared pair, with the full passes forced (``full``) or not."""
    sim = Sim()
    physics = sim.system.sim
    bridge = physics.joints
    if full:
        refresh, rebuild = bridge.refresh_membership, physics._rebuild_poses

        def full_refresh() -> None:
            bridge.membership_dirty = True
            refresh()

        def full_rebuild() -> None:
            physics._pose_dirty |= set(physics.bodies) | set(physics.poses.slot)
            rebuild()

        bridge.refresh_membership = full_refresh  # type: ignore[method-assign]
        physics._rebuild_poses = full_rebuild  # type: ignore[method-assign]
    out: list[tuple[float, ...]] = []
    # a hub on four motorised, limited spokes: its joints leave and re-enter the space
    # together when it is disabled and enabled again, or changes type (their order is
    # the order of the space's constraints, and so of the solver)
    hub = sim.dynamic(Box(0.5, 0.5), -30.0, 3.0, density=1.0)
    for k, (dx, dy) in enumerate(((1, 0), (0, 1), (-1, 0), (0, -1))):
        spoke = sim.dynamic(Box(0.4, 0.1), -30.0 + dx, 3.0 + dy, density=1.0)
        sim.spawn(RevoluteJoint(hub, spoke, anchor=(-30.0 + 0.5 * dx, 3.0 + 0.5 * dy),
                                enable_motor=True, motor_speed=1.0 + k, max_motor_torque=5.0,
                                enable_limit=True, lower_angle=-0.5, upper_angle=0.5))

    def record(s: Sim) -> None:
        for e, (t,) in sorted(s.world.query(Transform)):
            out.append((e, t.x, t.y, t.angle))
        out.extend((ev.joint, ev.body_a, ev.body_b) for ev in s.events.joint_destroyed)
        rb = s.rb(hub)
        if s.steps % 7 == 0:
            rb.enabled = not rb.enabled
        if s.steps % 13 == 0:
            rb.type = BodyType.KINEMATIC if rb.type == BodyType.DYNAMIC else BodyType.DYNAMIC

    try:
        _geared_pair(sim, 30.0, gear_first=True)
        _waves(sim, random.Random(23), 120, record)
    finally:
        sim.close()
    return out


def test_incremental_bookkeeping_gives_the_full_passes_results_bit_for_bit() -> None:
    assert _run(full=False) == _run(full=True)



def _ccd_index_is_fresh(sim: Sim) -> None:
    """Continuous collision's index of tracked bodies, updated by the changes only,
    equals one made from scratch."""
    ccd = sim.system.sim.ccd
    index = ccd._lookup_index()
    fresh = Index(ccd._tracked)
    for name in ("ids", "core", "reach", "extent", "bullet"):
        assert np.array_equal(getattr(index, name), getattr(fresh, name)), name
    assert list(index.infos) == list(fresh.infos)
    assert (index.max_extent, index.max_reach, index.min_core, index.bullets) == (
        fresh.max_extent, fresh.max_reach, fresh.min_core, fresh.bullets)


def test_continuous_collision_index_follows_the_changes() -> None:
    sim = Sim()
    try:
        _waves(sim, random.Random(3), 100, _ccd_index_is_fresh)
        assert len(sim.system.sim.ccd._tracked) > 20
    finally:
        sim.close()


@dataclass(slots=True)
class Tether:
    """A joint of a user's own kind that depends on another joint (``after``) while its
    ends stay as built: the bridge finds it through its dependents index."""

    body_a: int | None
    body_b: int | None
    after: int


class _TetherHandle(joint_api.JointHandle):
    def __init__(self, ctx: Any, entity: int, t: Tether) -> None:
        self.entity = entity
        self.body_a, self.body_b = t.body_a, t.body_b  # type: ignore[assignment]
        self.depends_on = (t.after,)
        self.constraints = []

    def apply(self, component: Any) -> None:
        pass

    def read_back(self, component: Any, dt: float) -> None:
        pass


def test_a_joint_kind_with_fixed_ends_is_destroyed_with_the_joint_it_depends_on() -> None:
    joint_api.register(Tether, _TetherHandle)
    sim = Sim(PhysicsSettings(gravity=(0.0, 0.0)))
    try:
        crowd = _crowd(sim, 30)
        a = sim.dynamic(Circle(0.3), 0.0, 0.0, density=1.0)
        b = sim.dynamic(Circle(0.3), 2.0, 0.0, density=1.0)
        c = sim.dynamic(Circle(0.3), 4.0, 0.0, density=1.0)
        early = sim.world.spawn()  # older than the joint it will depend on
        hinge = sim.spawn(RevoluteJoint(a, b, anchor=(1.0, 0.0)))
        sim.world.add(early, Tether(b, c, after=hinge))
        late = sim.spawn(Tether(c, b, after=hinge))
        other = sim.spawn(Tether(b, c, after=crowd[0]))
        sim.step()
        bridge = sim.system.sim.joints
        assert {early, late, other, hinge} <= set(bridge.handles)
        done = _record_destroys(bridge)
        want = _old_destruction_order(bridge.handles, a)
        sim.world.despawn(a)
        sim.step()
        assert done == want == [early, late, hinge]
        assert other in bridge.handles and all(j in bridge.handles for j in crowd)
    finally:
        sim.close()
        del joint_api.BUILDERS[Tether]
