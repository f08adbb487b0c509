"""The physics side of :mod:`kge.physics.joint_api`: joint lifecycle in the space.

Joint components are entities of their own naming two body entities. The
bridge builds a joint (through the builder its module registered) once both
bodies exist, pushes component changes with ``apply``, runs ``before_step``
and ``read_back`` around the step, breaks joints whose reaction exceeds their
limits (JointBroken) and destroys joints whose body or prerequisite joint goes
away (JointDestroyed). A joint's constraints are in the space only while both
of its bodies are (a disabled body takes its joints out, as in Box2D).

Revolute joints, the ones scenes have by the hundred (chains, bridges, grids,
a batch of vehicles' legs), skip the per-joint path in the steady state once
there are ``batch_from`` of them: a
:class:`~kge.physics.joints.pivots.PivotBatch` does their position pass and
read-back over all of them at once. A joint leaves the batch (and takes the
per-joint path) while it is inert, suspended or has a body out of the space;
the batch is rebuilt whenever joints come or go, are changed, or a body's type
or membership changes (``refresh_membership``, which every type change calls).
"""

from __future__ import annotations

import contextlib
import importlib
import itertools
from typing import TYPE_CHECKING, Any

import pymunk

from kge.components.tracked import Tracked, bind, unbind
from kge.physics import joint_api
from kge.physics.cp import body_handle
from kge.physics.cp import lib as _lib
from kge.physics.drain import Drain
from kge.physics.events import JointBroken, JointDestroyed

_DYNAMIC = _lib.CP_BODY_TYPE_DYNAMIC


def _awake(h: joint_api.JointHandle) -> bool:
    """:meth:`JointBridge.asleep` when no body sleeps."""
    return False

if TYPE_CHECKING:
    from kge.physics.joints.revolute import Revolute
    from kge.physics.simulation import Simulation


def load_joint_modules() -> None:
    """Import the joint implementations so they register their builders (optional)."""
    for name in ("kge.components.joints", "kge.physics.joints"):
        with contextlib.suppress(ImportError):
            importlib.import_module(name)


_SETTLE: tuple[Any, Any] | None = None
_REVOLUTE: Any = None


def _revolute() -> type[Revolute]:
    """The revolute handle class, imported on first use (the joint modules are optional)."""
    global _REVOLUTE
    if _REVOLUTE is None:
        from kge.physics.joints.revolute import Revolute

        _REVOLUTE = Revolute
    return _REVOLUTE


def _settle_api() -> tuple[Any, Any]:
    """(Composite, position_loop), imported on first use (the joint modules are optional)."""
    global _SETTLE
    if _SETTLE is None:
        from kge.physics.joints.base import Composite
        from kge.physics.joints.settle import position_loop

        _SETTLE = (Composite, position_loop)
    return _SETTLE


def body_fields(component: Any) -> tuple[int | None, int | None]:
    return getattr(component, "body_a", None), getattr(component, "body_b", None)


def moved_ends(handle: joint_api.JointHandle, component: Any) -> bool:
    """Whether ``component`` names other bodies than ``handle`` was built on.

    (A handle stores the ground as -1. A gear writes its own ``body_a`` /
    ``body_b``, so they agree with its handle unless the user overwrote them.)
    """
    a, b = body_fields(component)
    return (-1 if a is None else a, -1 if b is None else b) != (handle.body_a, handle.body_b)


class JointBridge:
    """Implements :class:`~kge.physics.joint_api.JointContext` for the builders."""

    #: handle revolute joints in bulk (False: every joint on the per-joint path)
    batch_revolutes = True
    #: fewest batchable joints for the bulk path: its few hundred numpy calls per step
    #: cost more than that many joints one by one (measured on batched two-legged
    #: vehicles' motor-and-limit legs: 16 joints 98 µs per env step one by one against 105 in
    #: bulk, 32 joints 78 against 72; a single env's two legs 355 against 465 µs)
    batch_from = 24
    #: most position passes per step over the per-joint path (Box2D's
    #: ``positionIterations``). kge's own physics makes one; ``kge.box2d`` sets
    #: Step's count, and above 1 the joints take turns with the contacts of their
    #: bodies until all are within Box2D's slops (kge.physics.joints.settle).
    position_iterations = 1

    def __init__(self, sim: Simulation) -> None:
        self.sim = sim
        self.space: pymunk.Space = sim.space
        self.dt = sim.dt
        self.errors = sim.errors
        self.handles: dict[int, joint_api.JointHandle] = {}
        self.components: dict[int, Any] = {}
        #: constraints to start from zero impulse at the next step (the simulation
        #: brackets its first substep with ``drain.start`` / ``drain.end``)
        self.drain = Drain()
        self.pending: set[int] = set()
        self.dirty: set[int] = set()
        self.removed: set[int] = set()
        #: every joint's membership must be checked at the next refresh (the
        #: targeted marks below cover the changes the bridge and the simulation make)
        self.membership_dirty = False
        self._check_joints: set[int] = set()  # new joints: their membership is checked
        self._check_bodies: set[int] = set()  # bodies in or out of the space, or retyped
        #: bumped by every membership refresh (body types or enabled flags changed)
        self.types_epoch = 0
        # indexes of the live handles, so a structural change costs what it touches:
        self._rank: dict[int, int] = {}  # joint -> place in ``handles``' order
        self._ranks = itertools.count()
        self._by_body: dict[int, set[int]] = {}  # body entity -> joints on it
        self._dependents: dict[int, set[int]] = {}  # joint -> joints depending on it
        self._indexed: dict[int, tuple[tuple[int, ...], tuple[int, ...]]] = {}
        self._loose: set[int] = set()  # handles whose ends may change: always looked at
        self._batch_epoch = -1
        self._ordered: list[tuple[int, joint_api.JointHandle]] | None = None
        self._batch: Any = None  # PivotBatch, created on first use
        self._batched: set[int] = set()
        self._checked: list[tuple[int, joint_api.JointHandle]] = []
        self._others: list[tuple[int, joint_api.JointHandle]] = []
        self._batch_live = False
        self._others_epoch = -1
        #: bumped whenever the set of bodies held by per-joint handles may change
        #: (kge.physics.rest watches them: their passes restart Chipmunk's sleep timer)
        self.restless_epoch = 0

    # -- JointContext ----------------------------------------------------------------
    @property
    def substep(self) -> float:
        return self.dt / max(1, self.sim.substeps)

    @property
    def iterated_hinges(self) -> bool:
        return bool(self.sim.settings.iterated_hinges)

    @property
    def hinge_limit_push(self) -> float:
        return float(self.sim.settings.hinge_limit_push)

    @property
    def epoch(self) -> tuple[int, int]:
        """Changes whenever a body's type, membership or mass data may have changed:
        joints re-check their bodies then (Composite.before_step), not every step."""
        return self.types_epoch, self.sim.mass_epoch

    def body(self, entity: int) -> pymunk.Body:
        rec = self.sim.bodies.get(entity)
        if rec is None:
            return self.space.static_body
        return rec.body

    def joint(self, entity: int) -> joint_api.JointHandle | None:
        return self.handles.get(entity)

    # -- world hooks -----------------------------------------------------------------
    def added(self, entity: int, component: Any) -> None:
        if isinstance(component, Tracked):
            bind(component, entity, self.dirty, self.sim.world.validate)
        self.components[entity] = component
        if entity in self.handles:  # replaced: rebuild
            self.removed.add(entity)
        self.pending.add(entity)

    def removed_hook(self, entity: int, component: Any) -> None:
        if isinstance(component, Tracked):
            unbind(component)
        if self.components.get(entity) is component:
            del self.components[entity]
            if entity in self.handles:  # a handle the bridge has not destroyed itself
                self.removed.add(entity)
            self.pending.discard(entity)

    # -- per step -----------------------------------------------------------------------
    def sync(self) -> None:
        # a joint despawned (or replaced) by the user: no event, as Box2D's DestroyJoint
        for e in sorted(self.removed):
            if e not in self.components or e in self.pending:
                self._destroy(e, event=False)
        self.removed.clear()
        if self.pending:
            for e in sorted(self.pending):
                self._try_build(e)
        if self.dirty:
            for e in sorted(self.dirty):
                h = self.handles.get(e)
                comp = self.components.get(e)
                if h is None or comp is None:
                    continue
                if moved_ends(h, comp):
                    self._rebuild(e)
                    continue
                h.apply(comp)
                if e in self._batched or self._batchable(e, h):
                    self._batch_epoch = -1  # anchors, reference or motor changed
            self.dirty.clear()
        if self.membership_dirty or self._check_joints or self._check_bodies:
            self.refresh_membership()

    def _try_build(self, entity: int) -> None:
        comp = self.components.get(entity)
        if comp is None:
            self.pending.discard(entity)
            return
        a, b = body_fields(comp)
        bodies = self.sim.bodies
        if (a is not None and a not in bodies) or (b is not None and b not in bodies):
            return  # waits for its bodies
        builder = joint_api.BUILDERS.get(type(comp))
        if builder is None:
            return
        handle = builder(self, entity, comp)
        handle.apply(comp)
        self.handles[entity] = handle
        self._index(entity, handle)
        self._ordered = None
        self._check_joints.add(entity)
        self.pending.discard(entity)
        self.dirty.discard(entity)

    def _rebuild(self, entity: int) -> None:
        """Build a joint anew on the bodies its component now names.

        A handle is made for one pair of bodies, so a write of ``body_a`` or
        ``body_b`` rebuilds it (anchors stay as resolved, in each body's frame). No
        event, and gears on it are kept: they notice the new handle and rebuild
        themselves. If a named body does not exist (yet), the joint waits for it,
        as at spawn.
        """
        h = self.handles.pop(entity)
        self._unindex(entity)
        h.remove(self.space)
        self._ordered = None
        self._batch_epoch = -1
        self.pending.add(entity)
        self._try_build(entity)

    # -- indexes: which joints a body or a joint concerns ---------------------------------
    def _index(self, entity: int, h: joint_api.JointHandle) -> None:
        """Record a new handle under its bodies and the joints it depends on.

        A handle whose ends may change after it is built (``fixed_ends`` False: a
        gear takes its joints' bodies once they exist) is kept apart and looked at
        by every query instead; every query re-checks the live handle anyway.
        """
        self._rank[entity] = next(self._ranks)
        self.restless_epoch += 1
        if not h.fixed_ends:
            self._loose.add(entity)
            return
        ends = tuple({h.body_a, h.body_b} - {-1})
        deps = tuple(set(h.depends_on))
        self._indexed[entity] = (ends, deps)
        for b in ends:
            self._by_body.setdefault(b, set()).add(entity)
        for d in deps:
            self._dependents.setdefault(d, set()).add(entity)

    def _unindex(self, entity: int) -> None:
        self.restless_epoch += 1
        self._rank.pop(entity, None)
        self._loose.discard(entity)
        ends, deps = self._indexed.pop(entity, ((), ()))
        for key in ends:
            _discard(self._by_body, key, entity)
        for key in deps:
            _discard(self._dependents, key, entity)

    def on_body(self, body: int) -> list[int]:
        """The joints that may be built on ``body``, sorted (re-check each handle's ends)."""
        return sorted(self._by_body.get(body, set()) | self._loose)

    def depending_on(self, joint: int) -> list[int]:
        """The joints that may depend on ``joint``, sorted (re-check ``depends_on``)."""
        return sorted(self._dependents.get(joint, set()) | self._loose)

    def body_changed(self, body: int) -> None:
        """A body entered or left the space or changed type: its joints' constraints
        are checked at the next :meth:`refresh_membership`."""
        self._check_bodies.add(body)

    def refresh_membership(self) -> None:
        """Constraints are in the space exactly while both bodies are (one dynamic).

        Only the joints that may have changed are looked at: new ones, those on
        the bodies marked with :meth:`body_changed`, and those whose ends may
        move; all of them when :attr:`membership_dirty` asks. They are visited in
        the order of :attr:`handles` (the order of the space's constraint array,
        and so of the solver, follows these adds and removes).
        """
        full = self.membership_dirty
        self.membership_dirty = False
        self.types_epoch += 1
        joints, bodies = self._check_joints, self._check_bodies
        self._check_joints, self._check_bodies = set(), set()
        if full:
            chosen: Any = self.handles.values()
        else:
            for b in bodies:
                joints |= self._by_body.get(b, set())
            joints |= self._loose
            rank = self._rank
            chosen = [self.handles[e] for e in sorted(
                (e for e in joints if e in self.handles), key=rank.__getitem__)]
        space = self.space
        for h in chosen:
            for c in h.constraints:
                a, b = c.a, c.b
                want = (
                    a.space is space
                    and b.space is space
                    and (a.body_type == pymunk.Body.DYNAMIC or b.body_type == pymunk.Body.DYNAMIC)
                )
                present = joint_api.in_space(space, c)
                if want and not present:
                    space.add(c)
                elif not want and present:
                    space.remove(c)

    def ordered(self) -> list[tuple[int, joint_api.JointHandle]]:
        """The live handles in entity order (cached until joints come or go)."""
        if self._ordered is None:
            self._ordered = sorted(self.handles.items())
        return self._ordered

    def _batchable(self, e: int, h: joint_api.JointHandle) -> bool:
        """A live hinge that needs no Python between substeps: a revolute joint with
        no motor and no limit, or with pymunk solving them (``iterated_hinges``).

        kge's own motor and limit rows run in Python every substep, which dwarfs
        their after-step work; keeping them on the per-joint path also keeps their
        position pass in entity order, which a tumbling ragdoll is sensitive to.
        Box2D's position iterations (``position_iterations`` above 1, kge.box2d)
        take motors and limits per joint with the contacts, as Box2D does.
        """
        if not (self.batch_revolutes and type(h) is _revolute()):
            return False
        j = h.settings
        if (j.enable_motor or j.enable_limit) and (
            h.rotation_off or not (self.iterated_hinges and self.position_iterations == 1)
        ):
            return False
        return (
            h.active
            and h.suspended is None
            and h.pivot is not None
            and self.components.get(e) is h.component
        )

    def _rebuild_batch(self) -> None:
        from kge.physics.joints.pivots import PivotBatch

        if self._batch is None:
            self._batch = PivotBatch(self.space, self.sim.bodies)
        space, inside = self.space, joint_api.in_space
        chosen = [
            (e, h)
            for e, h in self.ordered()
            if self._batchable(e, h) and inside(space, h.pivot)  # type: ignore[attr-defined]
        ]
        if len(chosen) < self.batch_from:
            chosen = []
        self._batch.rebuild([h for _, h in chosen], self._pivot_tolerance())
        self._batched = {e for e, _ in chosen}
        # the break check skips batched joints that have no break limit
        unbreakable = {
            e for e, _ in chosen
            if self.components[e].break_force is None and self.components[e].break_torque is None
        }
        self._checked = [(e, h) for e, h in self.ordered() if e not in unbreakable]
        self._others = [(e, h) for e, h in self.ordered() if e not in self._batched]
        self._batch_epoch = self.types_epoch
        self.restless_epoch += 1

    def restless_bodies(self) -> list[int]:
        """The body entities of the joints solved one by one (not in the pivot batch):
        their Python passes write to the bodies every step (kge.physics.rest)."""
        batched = self._batched
        return [
            b for e, h in self.handles.items() if e not in batched for b in (h.body_a, h.body_b)
        ]

    def _some_asleep(self) -> bool:
        """Might any body be asleep? (No: no joint needs looking at; one numpy call.)"""
        poses = self.sim.poses
        return bool(poses.asleep.any()) or self.sim.poses_stale

    def asleep(self, h: joint_api.JointHandle) -> bool:
        """Are the dynamic bodies of ``h`` (at least one) all asleep? Box2D does not
        solve a sleeping island, and a pass that wrote to its bodies would wake them."""
        bodies = self.sim.bodies
        found = False
        for e in (h.body_a, h.body_b):
            rec = bodies.get(e)
            if rec is None:
                continue
            cb = body_handle(rec.body)
            if _lib.cpBodyGetType(cb) == _DYNAMIC:
                if not _lib.cpBodyIsSleeping(cb):
                    return False
                found = True
        return found

    def _pivot_tolerance(self) -> float:
        """Pivot gaps the position pass leaves alone, m (see ``Revolute.project``)."""
        if not self.iterated_hinges:
            return 0.0
        from kge.physics.joints.positions import ITERATED_PIVOT_TOLERANCE

        return ITERATED_PIVOT_TOLERANCE

    def before_step(self, dt: float, raw: Any = None) -> None:
        """``raw``: sync-out's bulk read when nothing touched a body since (or None)."""
        ordered = self.ordered()
        asleep = self.asleep if self._some_asleep() else _awake
        if self._batch_epoch != self.types_epoch:
            for _, h in ordered:
                if not asleep(h):
                    h.before_step(dt)
            self._rebuild_batch()
        else:
            for _, h in self._others:
                if not asleep(h):
                    h.before_step(dt)
            if (
                self._batched or len(self._others) >= self.batch_from
            ) and self.sim.mass_epoch != self._others_epoch:
                # a mass update can let a body turn again (fixed_rotation off): a
                # motor or limit hinge that left the batch for it may come back
                self._others_epoch = self.sim.mass_epoch
                if any(self._batchable(e, h) for e, h in self._others):
                    self._rebuild_batch()
            if self._batched and self._batch.mass_changed(self.sim.mass_epoch):
                # a body that can no longer turn takes a motor or limit out
                # (Composite.track_rotation): such a joint leaves the batch
                torqued = [self._batch.handles[k] for k in self._batch.torqued]
                for h in torqued:
                    h.before_step(dt)
                if any(h.rotation_off for h in torqued):
                    self._rebuild_batch()
                else:
                    self._batch.refresh_mass()
        self._batch_live = bool(self._batched) and self._batch.before_step(raw)
        if self._batched and not self._batch_live:  # a body left the space: per joint
            for e, h in ordered:
                if e in self._batched:
                    h.before_step(dt)
            self._batch_epoch = -1

    def after_step(self, dt: float) -> None:
        events = self.sim.events
        ordered = self.ordered()
        batch = self._batch
        live = self._batch_live
        state = batch.read() if live else None
        if live and state is None:  # cannot happen between before and after step
            live = False
            self._batch_epoch = -1
        jolted: list[joint_api.JointHandle] = []
        box2d = self.position_iterations > 1
        unsettled: list[tuple[int, joint_api.JointHandle]] = []
        if state is not None:
            far = [batch.handles[k] for k in batch.project(state)]
            jolted += far
            if box2d and far:
                # a plain hinge far apart (built apart, a body moved away): Box2D's
                # further iterations, with the contacts, per joint. Everyday drift
                # keeps the one bulk pass: iterating a 200-link chain to the slop
                # cost 10x the step (and left it tighter than Box2D's 3 passes do)
                unsettled = [(e, h) for e, h in ordered if e in self._batched]
        others = False
        loop = self._others if state is not None else ordered
        if box2d and (loop or unsettled):
            others = self._box2d_positions(loop, dt, unsettled)
            jolted += [h for _, h in loop + unsettled if h.jolted]
        else:
            asleep = self.asleep if self._some_asleep() else _awake
            for e, h in loop:
                comp = self.components.get(e)
                if comp is None or asleep(h):
                    continue  # a sleeping joint keeps what it last read
                h.read_back(comp, dt)
                if h.jolted:
                    jolted.append(h)
                others = True
        if jolted:
            self.forget_impulses(jolted)
        if state is not None:
            if others:  # their position passes may have moved shared bodies
                state = batch.read()
            if state is not None:
                h0 = self.space.current_time_step
                batch.read_back(state, dt, h0 if h0 > 0 else 1.0 / 60.0, self.space.gravity)
                # nothing moves a body from here to sync-out: it reuses this read
                self.sim.out_read = batch.raw
        for e, h in self._checked if live else ordered:
            if e not in self.handles:
                continue  # destroyed with a joint it depended on
            comp = self.components.get(e)
            if comp is None:
                continue
            if h.exceeds_break_limits(comp):
                fx, fy = getattr(comp, "reaction_force", (0.0, 0.0))
                torque = float(getattr(comp, "reaction_torque", 0.0))
                events.joint_broken.append(
                    JointBroken(e, h.body_a, h.body_b, (float(fx), float(fy)), torque)
                )
                self._destroy(e, event=False)
                if self.sim.world.exists(e):
                    self.sim.world.despawn(e)

    def _box2d_positions(self, handles: list[tuple[int, joint_api.JointHandle]], dt: float,
                         batched: list[tuple[int, joint_api.JointHandle]]) -> bool:
        """Box2D's position iterations over the per-joint handles (and the batched
        ones still apart after the batch's pass) and the contacts of their bodies
        (:mod:`kge.physics.joints.settle`), then the read-back of the per-joint
        handles from the final poses (the batch reads its own back). Returns
        whether any body may have moved."""
        composite, position_loop = _settle_api()
        live: list[tuple[Any, Any]] = []
        rest: list[tuple[joint_api.JointHandle, Any]] = []
        for e, h in handles:
            comp = self.components.get(e)
            if comp is None or self.asleep(h):
                continue
            if isinstance(h, composite) and h.active and h.suspended is None:
                live.append((h, comp))
            else:
                rest.append((h, comp))
        extra = [h for _, h in batched if isinstance(h, composite)]
        position_loop([h for h, _ in live] + extra, self.position_iterations)
        for h, comp in live:
            h.read_live(comp, dt)
        for other, comp in rest:
            other.read_back(comp, dt)
        return bool(live or rest or extra)

    def forget_impulses(self, jolted: list[joint_api.JointHandle]) -> None:
        """Joints found far off their constraint start the next step from zero impulse.

        So does every other joint on the same bodies: far-off joints are usually
        fighting another joint about where a body belongs, and a warm start that
        one of them forgot would leave the other's pushing alone (see
        :class:`~kge.physics.drain.Drain`).
        """
        moved = {e for h in jolted for e in (h.body_a, h.body_b) if e >= 0}
        for h in jolted:
            self.drain.add(h.forget_impulses())
        for body in sorted(moved):  # the joints on those bodies only (the index)
            for e in self.on_body(body):
                other = self.handles.get(e)
                if other is not None and body in (other.body_a, other.body_b):
                    self.drain.add(other.forget_impulses())

    def reset_impulses(self, entities: list[int]) -> None:
        """The live joints among ``entities`` start the next step from zero impulse."""
        for e in entities:
            h = self.handles.get(e)
            if h is not None:
                self.drain.add(h.forget_impulses())

    def body_removed(self, body_entity: int) -> None:
        """A body left: destroy every joint on it (and joints depending on those)."""
        for e in self.on_body(body_entity):
            h = self.handles.get(e)
            if h is not None and body_entity in (h.body_a, h.body_b):
                self._destroy(e, event=True)
                if self.sim.world.exists(e):
                    self.sim.world.despawn(e)

    def _destroy(self, entity: int, event: bool) -> None:
        h = self.handles.pop(entity, None)
        if h is None:
            return
        self._unindex(entity)
        self._ordered = None
        self._batch_epoch = -1
        for other in self.depending_on(entity):
            oh = self.handles.get(other)
            if oh is not None and entity in oh.depends_on:
                self._destroy(other, event=True)
                if self.sim.world.exists(other):
                    self.sim.world.despawn(other)
        h.remove(self.space)
        self.drain.discard(getattr(h, "parts", h.constraints))
        if event:
            self.sim.events.joint_destroyed.append(JointDestroyed(entity, h.body_a, h.body_b))


def _discard(table: dict[int, set[int]], key: int, entity: int) -> None:
    members = table.get(key)
    if members is not None:
        members.discard(entity)
        if not members:
            del table[key]
