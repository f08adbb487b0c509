"""Shared tools of the reliability tests: a stepped physics world and invariant checks.

The checks read the physics system's own maps (``Simulation.bodies``,
``.colliders``, ``JointBridge.handles``, ``ContactRecorder.active``) and the
pymunk space, and compare them with the ECS, so a leaked or orphaned pymunk
object, a lost component or an unbalanced contact event is caught the step it
appears. ``tools/soak.py`` uses the same checks.
"""

from __future__ import annotations

import math
import os
import pickle
import sys
from typing import Any

import pymunk

from kge.components.collider import Collider
from kge.components.joints import Joint
from kge.components.rigidbody import RigidBody
from kge.components.transform import Transform
from kge.physics.cp import body_handle, ffi, lib, shape_handle
from kge.physics.events import PhysicsEvents
from kge.physics.resource import Physics
from kge.physics.settings import PhysicsSettings
from kge.physics.simulation import Simulation
from kge.schedule import Stage
from kge.systems.physics import PhysicsSystem
from kge.world import World

DT = 1.0 / 60.0


class PhysicsWorld:
    """A World with the physics system, stepped through the FIXED stage as the App does."""

    def __init__(self, settings: PhysicsSettings | None = None, name: str | None = None) -> None:
        self.world = World(name)
        if settings is not None:
            self.world.insert_resource(settings)
        self.system = PhysicsSystem()
        self.world.add_system(self.system)
        self.physics = self.world.resource(Physics)
        self.events = self.world.resource(PhysicsEvents)
        self.balance = EventBalance()

    @property
    def sim(self) -> Simulation:
        return self.system.sim

    def step(self, n: int = 1) -> None:
        for _ in range(n):
            self.world.clear_events()
            self.world.schedule.run(Stage.FIXED, DT)
            self.balance.record(self.events)

    def close(self) -> None:
        self.world.close()


class EventBalance:
    """Per collider pair and child pair (chain segments), begin and end events must
    alternate (and start with a begin).

    Begins and ends of one step come in separate lists, so a pair's order within
    the step is unknown: an open pair may end and begin again (E B ...), a closed
    one begin and end (B E ...), with substeps even several times. Both are legal
    exactly when the counts alternate from the pair's state before the step.
    """

    def __init__(self) -> None:
        self.open: set[tuple[str, int, int, int, int]] = set()
        self.begins = 0
        self.ends = 0

    def record(self, events: PhysicsEvents) -> None:
        step: dict[tuple[str, int, int, int, int], list[int]] = {}
        for kind, starts, stops in (
            ("contact", events.contact_begin, events.contact_end),
            ("sensor", events.sensor_begin, events.sensor_end),
        ):
            for ev in starts:
                step.setdefault(_pair(kind, ev), [0, 0])[0] += 1
                self.begins += 1
            for end in stops:
                step.setdefault(_pair(kind, end), [0, 0])[1] += 1
                self.ends += 1
        for key, (b, e) in step.items():
            if key in self.open:
                assert e - b in (0, 1), f"{key}: open pair got {b} begins and {e} ends"
                if e > b:
                    self.open.discard(key)
            else:
                assert b - e in (0, 1), f"{key}: closed pair got {b} begins and {e} ends"
                if b > e:
                    self.open.add(key)

    def live_pairs(self) -> set[tuple[str, int, int, int, int]]:
        return set(self.open)


def _pair(kind: str, ev: Any) -> tuple[str, int, int, int, int]:
    return (kind, ev.collider_a, ev.collider_b, ev.child_a, ev.child_b)


def space_counts(sim: Simulation) -> dict[str, int]:
    """pymunk objects in the space (the static body of the space is not counted)."""
    space = sim.space
    return {
        "bodies": len(space.bodies),
        "shapes": len(space.shapes),
        "constraints": len(space.constraints),
    }


def state_dump(world: World) -> bytes:
    """Every entity and component of ``world``, and its queued changes, as bytes.

    Like ``world.snapshot()`` but without flushing, so a pending despawn is part
    of the state instead of being applied by the act of looking.
    """
    entities = {e: world.components(e) for e in world.entities()}
    queued = [(e, op, repr(p)) for e, _, op, p in world._queue]
    return pickle.dumps((entities, sorted(world._dying), queued), protocol=5)


def _finite(values: Any, what: str) -> None:
    for v in values:
        assert math.isfinite(v), f"{what} is not finite: {values!r}"


def check_invariants(pw: PhysicsWorld | AppProbe) -> None:
    """Assert that pymunk mirrors the ECS exactly (call between steps, after a step)."""
    world, sim = pw.world, pw.sim
    # Changes flushed after the step (despawns made in contact hooks) reach pymunk at
    # the next sync-in; every query runs that sync first, so do the same here.
    world.resource(Physics)._synced()
    space = sim.space
    live = set(world.entities())
    # -- bodies ---------------------------------------------------------------------
    for e, rec in sim.bodies.items():
        assert e in live, f"pymunk body of dead entity {e}"
        rb = world.try_get(e, RigidBody)
        col = world.try_get(e, Collider)
        if rec.implicit:
            assert rb is None and col is not None and col.body is None, f"stale implicit {e}"
        else:
            assert rb is not None, f"body record of entity {e} without RigidBody"
            assert rec.in_space == rb.enabled, f"entity {e}: in_space != enabled"
    want_bodies = {id(r.body) for r in sim.bodies.values() if r.in_space}
    got_bodies = {id(b) for b in space.bodies}
    assert got_bodies == want_bodies, (
        f"space bodies {len(got_bodies)} != live body records {len(want_bodies)}"
    )
    rigid = {e for e, _ in world.query(RigidBody)}
    explicit = {e for e, r in sim.bodies.items() if not r.implicit}
    assert rigid == explicit, f"RigidBody entities {rigid ^ explicit} have no pymunk body"
    # -- colliders ------------------------------------------------------------------
    want_shapes: set[int] = set()
    for c, crec in sim.colliders.items():
        assert c in live, f"pymunk shapes of dead collider entity {c}"
        col = world.try_get(c, Collider)
        assert col is not None, f"shapes of entity {c} without Collider"
        owner = c if col.body is None else col.body
        assert crec.owner == owner, f"collider {c} on body {crec.owner}, wants {owner}"
        rec = sim.bodies[owner]
        assert c in rec.colliders
        if rec.in_space:
            want_shapes.update(id(s) for s in crec.shapes)
    got_shapes = {id(s) for s in space.shapes}
    assert got_shapes == want_shapes, (
        f"space shapes {len(got_shapes)} != live collider shapes {len(want_shapes)}"
    )
    for c, (col,) in world.query(Collider):
        owner = c if col.body is None else col.body
        if owner in sim.bodies:
            assert c in sim.colliders, f"collider {c} is not built although its body is"
    # -- joints ---------------------------------------------------------------------
    bridge = sim.joints
    joint_entities = {e for e in live if any(isinstance(x, Joint) for x in world.components(e))}
    for e in bridge.handles:
        assert e in joint_entities, f"pymunk joint of dead / non-joint entity {e}"
    owned = {id(c) for h in bridge.handles.values() for c in h.constraints}
    for constraint in space.constraints:
        assert id(constraint) in owned, "a constraint in the space belongs to no live joint"
    # -- contacts -------------------------------------------------------------------
    table = sim.shapes
    active = {
        ("sensor" if sensor else "contact", int(table.collider[a]), int(table.collider[b]),
         int(table.child[a]), int(table.child[b]))
        for (a, b), sensor in sim.recorder.active.items()
    }
    # ends produced by that sync are held for the next step's lists
    carried = world.resource(Physics)._carried
    ending = {_pair("contact", ev) for ev in carried.contact_end} | {
        _pair("sensor", ev) for ev in carried.sensor_end
    }
    opened = pw.balance.live_pairs()
    assert ending <= opened, f"end events {ending - opened} without a begin"
    assert opened - ending == active, (
        f"open begin events {(opened - ending) ^ active} do not match live contacts"
    )
    for key in active:
        assert key[1] in live and key[2] in live, f"live contact of a dead collider {key}"
    # -- numbers --------------------------------------------------------------------
    for e, (t,) in world.query(Transform):
        _finite((t.x, t.y, t.angle), f"entity {e} Transform")
    for e, (rb,) in world.query(RigidBody):
        _finite((*rb.velocity, rb.angular_velocity), f"entity {e} RigidBody velocity")
    for b in space.bodies:
        _finite((b.position.x, b.position.y, b.angle, b.velocity.x, b.velocity.y), "pymunk body")


class AppProbe:
    """The same checks for an :class:`~kge.app.App`'s current world (behaviours included)."""

    def __init__(self, app: Any) -> None:
        self.app = app
        self.balance = EventBalance()

    @property
    def world(self) -> World:
        world: World = self.app.world
        return world

    @property
    def sim(self) -> Simulation:
        system = self.world.get_system(PhysicsSystem)
        assert system is not None
        return system.sim

    def step(self, n: int = 1) -> None:
        for _ in range(n):
            self.app.step()
            self.balance.record(self.world.resource(PhysicsEvents))


def check_no_leftovers(pw: PhysicsWorld | AppProbe) -> None:
    """Every internal map of the physics system holds only live things (call after a step).

    Memory figures only show a leak after thousands of steps; these maps show it
    at once: a despawned body left in the CCD tracker, a joint component kept by
    the bridge, a contact cache entry of a removed shape...
    """
    world, sim = pw.world, pw.sim
    live = set(world.entities())
    body_ids = {r.body.id for r in sim.bodies.values()}  # CCD keys bodies by pymunk id
    joints = sim.joints
    assert set(joints.components) <= live, "joint bridge keeps dead joint components"
    assert set(joints.handles) <= live
    assert not (joints.removed or joints.dirty), "joint bridge has unprocessed changes"
    assert joints.pending <= live
    assert sim.pending <= live and sim.no_sleep <= set(sim.bodies)
    assert not sim.forces, "forces survived the step"
    for name in ("body_struct", "collider_struct", "rb_dirty", "col_dirty", "tf_dirty",
                 "mass_dirty", "ccd_dirty"):
        assert not getattr(sim, name), f"Simulation.{name} not empty after a step"
    assert set(sim.poses.slot) <= set(sim.bodies), "pose table keeps dead bodies"
    table = sim.shapes
    slots = {table.slot(s) for c in sim.colliders.values() for s in c.shapes}
    for key in sim.recorder.active:
        assert key[0] in slots and key[1] in slots, "live contact of a removed shape"
    assert len(table) == sum(len(c.shapes) for c in sim.colliders.values()), (
        "the shape table keeps rows of removed shapes"
    )
    assert len(sim.recorder._pre_cache) <= len(sim.recorder.active)
    ccd = sim.ccd
    if ccd is not None:
        for name in ("_tracked", "_bodies"):
            stale = [k for k in getattr(ccd, name) if k not in body_ids]
            assert not stale, f"CCD {name} keeps {len(stale)} removed bodies"
        assert len(ccd._movers) <= len(sim.bodies), "CCD keeps removed kinematic movers"


# -- the contact graph, read through Chipmunk's C API ------------------------------------
_seen: list[object] = []


@ffi.callback("void(cpBody *, cpArbiter *, void *)")
def _collect(body: object, arb: object, data: object) -> None:
    _seen.append(arb)
    if len(_seen) > 10_000:  # a list threaded into a cycle: iteration never ends
        sys.stderr.write("contact graph: cyclic arbiter list\n")
        sys.stderr.flush()
        os._exit(99)


def _addr(ptr: object) -> int:
    return int(ffi.cast("uintptr_t", ptr))


def contact_graph_problems(space: pymunk.Space) -> list[str]:
    """Arbiters threaded on the space's bodies that are duplicated or name dead objects.

    Only pointers are compared (never dereferenced through Python), so a dangling
    arbiter is reported instead of crashing.
    """
    shapes = {_addr(shape_handle(s)) for s in space.shapes}
    bodies = {_addr(body_handle(b)) for b in space.bodies} | {_addr(body_handle(space.static_body))}
    problems = []
    pa, pb = ffi.new("cpShape **"), ffi.new("cpShape **")
    ba, bb = ffi.new("cpBody **"), ffi.new("cpBody **")
    for body in list(space.bodies):
        _seen.clear()
        lib.cpBodyEachArbiter(body_handle(body), _collect, ffi.NULL)
        arbs = list(_seen)
        _seen.clear()
        if len({_addr(a) for a in arbs}) != len(arbs):
            problems.append(f"{body}: an arbiter is threaded twice")
        for arb in arbs:
            lib.cpArbiterGetShapes(arb, pa, pb)
            lib.cpArbiterGetBodies(arb, ba, bb)
            if _addr(pa[0]) not in shapes or _addr(pb[0]) not in shapes:
                problems.append(f"{body}: an arbiter names a shape outside the space")
            if _addr(ba[0]) not in bodies or _addr(bb[0]) not in bodies:
                problems.append(f"{body}: an arbiter names a body outside the space")
    return problems
