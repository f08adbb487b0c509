"""``Physics``: the imperative side of kge physics (Box2D's b2World and b2Body calls).

Components say *what* exists; this resource does what components cannot:
forces and impulses, mass data, coordinate helpers, queries, and the per-step
contact hooks. Get it with ``world.resource(Physics)``.

Forces follow Box2D: they act for the next fixed step only, at a world point
(or the centre of mass), wake the body unless ``wake=False``, and are ignored
for static and kinematic bodies. A sleeping body with ``wake=False`` ignores
them entirely. Impulses change the velocity at once (visible in
``RigidBody.velocity`` before the step).

Queries (``raycast``, ``query_aabb``, ``query_point``, ``query_shape``) are
implemented in :mod:`kge.physics.queries` and only forwarded here.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any, Literal, overload

import numpy as np
import pymunk

from kge.components.rigidbody import RigidBody
from kge.components.tracked import raw_set
from kge.deprecation import enum_value
from kge.errors import EntityNotFoundError, ValidationError, where
from kge.physics import impulses as impulses_mod
from kge.physics import states as states_mod
from kge.physics.bodies import DYNAMIC, BodyRecord
from kge.physics.contacts import ContactFilterFn, PostSolveFn, PreSolveFn
from kge.physics.cp import body_handle, lib
from kge.physics.events import PhysicsEvents
from kge.physics.mass import MassData
from kge.physics.queries import QueryFilter, QueryHit, RayHit, RayMode
from kge.physics.settings import PhysicsSettings
from kge.physics.tiny import TINY, flush
from kge.physics.writeback import set_all, slot_setter
from kge.validate import finite, vec2

if TYPE_CHECKING:
    from kge.physics.simulation import Simulation
    from kge.world import World

Vec2 = tuple[float, float]
Pose = tuple[float, float, float]

_set_velocity = lib.cpBodySetVelocity
_set_angular_velocity = lib.cpBodySetAngularVelocity
_get_type = lib.cpBodyGetType
_is_sleeping = lib.cpBodyIsSleeping
_CP_DYNAMIC = lib.CP_BODY_TYPE_DYNAMIC
_SET_VELOCITY = slot_setter(RigidBody, "velocity")
_SET_ANGULAR_VELOCITY = slot_setter(RigidBody, "angular_velocity")


class Physics:
    """Forces, mass data, coordinate helpers, queries and contact hooks of one world."""

    def __init__(self, world: World, sim: Simulation) -> None:
        self._world = world
        self._sim = sim
        self._carried = PhysicsEvents()  #: events of between-step syncs, for the next step
        self._state_slots = states_mod.SlotCache()
        self._rows = impulses_mod.RowReader()  # bodies' current rows for bulk impulses

    # -- configuration ------------------------------------------------------------------
    @property
    def settings(self) -> PhysicsSettings:
        return self._world.resource(PhysicsSettings)

    @property
    def step_count(self) -> int:
        return self._sim.steps

    # -- lookups -----------------------------------------------------------------------------
    def _synced(self) -> None:
        sim = self._sim
        if self._world.is_locked:
            return
        if (
            sim.body_struct or sim.collider_struct or sim.pending or sim.rb_dirty
            or sim.col_dirty or sim.tf_dirty or sim.mass_dirty
        ):
            # Events this early sync produces (contact ends of a removed collider,
            # joints destroyed with their body) belong to the *next* step: keep them
            # aside, or the next step's clear() would lose them and leave a begin
            # without its end.
            events = sim.events
            marks = [len(getattr(events, name)) for name, _ in PhysicsEvents.CHANNELS]
            sim.fresh_read = None  # the changes it applies are not in that read
            sim.sync_in()
            for (name, _), n in zip(PhysicsEvents.CHANNELS, marks, strict=True):
                lst = getattr(events, name)
                if len(lst) > n:
                    getattr(self._carried, name).extend(lst[n:])
                    del lst[n:]

    def _take_carried(self, events: PhysicsEvents) -> None:
        """Move events of between-step syncs into ``events`` (called as a step starts)."""
        carried = self._carried
        if len(carried):
            for name, _ in PhysicsEvents.CHANNELS:
                getattr(events, name).extend(getattr(carried, name))
            carried.clear()

    def _record(self, entity: int, op: str) -> BodyRecord:
        if isinstance(entity, bool) or not isinstance(entity, int):
            raise ValidationError(f"physics.{op}(): entity must be an int id, got {entity!r}")
        if not self._world.exists(entity):
            raise EntityNotFoundError(f"physics.{op}(): entity {entity} does not exist")
        self._synced()
        rec = self._sim.bodies.get(entity)
        if rec is None:
            raise ValidationError(
                f"physics.{op}(): entity {entity} has no body (add a RigidBody or a Collider)"
            )
        return rec

    # -- forces --------------------------------------------------------------------------------
    def _force_target(
        self, entity: int, op: str, wake: bool, rec: BodyRecord | None = None
    ) -> BodyRecord | None:
        """The body to push, or None (not dynamic, out of the space, asleep and
        ``wake`` False). ``rec``: the record the caller just looked up."""
        if rec is None:
            rec = self._record(entity, op)
        self._sim.touched = True
        self._sim.fresh_read = None  # (a wake-up or a velocity write follows)
        body = rec.body
        if body.body_type != DYNAMIC or not rec.in_space:
            return None
        if body.is_sleeping:
            if not wake:
                return None
            body.activate()
            self._mark_awake(entity)
        self._sim.rest.watch(entity)  # Box2D's clock, not Chipmunk's (kge.physics.rest)
        return rec

    def _mark_awake(self, entity: int) -> None:
        rb = self._world.try_get(entity, RigidBody)
        if rb is not None:
            self._sim._mark_awake(entity, rb)

    def apply_force(
        self, entity: int, force: Vec2, point: Vec2 | None = None, wake: bool = True
    ) -> None:
        """Apply ``force`` (N) at world ``point`` (default: the centre of mass) for one step."""
        owner = where(entity, "Physics.apply_force")
        fx, fy = vec2(force, owner, "force")
        at = None if point is None else vec2(point, owner, "point")  # before any change
        body = self._record(entity, "apply_force").body
        torque = 0.0
        if at is not None:
            px, py = at
            c = body.local_to_world(body.center_of_gravity)
            torque = (px - c.x) * fy - (py - c.y) * fx
        old = self._sim.forces.get(entity, (0.0, 0.0, 0.0))
        total = (old[0] + fx, old[1] + fy, old[2] + torque)
        _finite_result(owner, "the force or its torque", total)
        if self._force_target(entity, "apply_force", wake) is None:
            return
        self._sim.forces[entity] = list(total)

    def apply_torque(self, entity: int, torque: float, wake: bool = True) -> None:
        """Apply ``torque`` (N m) for one step."""
        owner = where(entity, "Physics.apply_torque")
        tq = finite(torque, owner, "torque")
        old = self._sim.forces.get(entity, (0.0, 0.0, 0.0))
        _finite_result(owner, "the total torque", (old[2] + tq,))
        rec = self._force_target(entity, "apply_torque", wake)
        if rec is None:
            return
        self._sim.forces.setdefault(entity, [0.0, 0.0, 0.0])[2] += tq

    def apply_linear_impulse(
        self, entity: int, impulse: Vec2, point: Vec2 | None = None, wake: bool = True
    ) -> None:
        """Change the velocity at once by ``impulse`` (N s) at world ``point`` (default centre).

        Called every step by controllers (an RL environment fires its thrusters
        this way), so it looks the body up once and reads it with Chipmunk's getters.
        """
        owner = where(entity, "Physics.apply_linear_impulse")
        jx, jy = vec2(impulse, owner, "impulse")
        at = None if point is None else vec2(point, owner, "point")  # before any change
        rec = self._record(entity, "apply_linear_impulse")
        cb = body_handle(rec.body)
        v = impulses_mod.velocity_of(cb)
        impulses_mod.push(cb, v, jx, jy, at)
        vx, vy, w = v
        if not (math.isfinite(vx) and math.isfinite(vy) and math.isfinite(w)):
            _finite_result(owner, "the resulting velocity", (vx, vy, w))
        if self._force_target(entity, "apply_linear_impulse", wake, rec) is None:
            return
        self._write_velocity(entity, cb, vx, vy, w)

    def apply_linear_impulses(
        self, entities: Any, impulses: Any, points: Any = None, wake: bool = True
    ) -> None:
        """Row k applies ``impulses[k]`` (N s) to ``entities[k]`` at world ``points[k]``.

        The same as calling :meth:`apply_linear_impulse` row by row (an entity may
        appear twice), for controllers that push many bodies every step: the rows
        are checked together and every one before any body changes, so a bad row
        raises naming its index and entity and applies nothing. ``points`` None
        pushes every body at its centre of mass.

        >>> # physics.apply_linear_impulses([ship, rock], [(0, 5), (1, 0)], [(0, -1), (2, 2)])
        """
        owner = "Physics.apply_linear_impulses"
        ents, jj, pp = impulses_mod.checked_rows(owner, entities, impulses, points)
        recs = self._records(ents, "apply_linear_impulses")
        if wake and self._push_distinct(owner, recs, ents, jj, pp):
            return
        new = impulses_mod.new_velocities(owner, recs, ents, jj, pp)
        self._sim.touched = True
        for rec, (vx, vy, w) in new.values():  # each body once, in order of first appearance
            cb = body_handle(rec.body)
            if not rec.in_space or _get_type(cb) != _CP_DYNAMIC:
                continue  # static and kinematic bodies ignore impulses
            if _is_sleeping(cb):
                if not wake:
                    continue
                rec.body.activate()
                self._mark_awake(rec.entity)
            self._sim.rest.watch(rec.entity)
            self._write_velocity(rec.entity, cb, vx, vy, w)

    def _push_distinct(
        self, owner: str, recs: list[BodyRecord], ents: list[int], jj: np.ndarray,
        pp: np.ndarray | None,
    ) -> bool:
        """The common case of :meth:`apply_linear_impulses` in bulk: every row a different
        awake dynamic body in the space (a batch of engines). False (nothing done) for
        anything else, which the row-by-row path handles."""
        sim = self._sim
        sim.fresh_read = None  # it views the buffer the read below refills
        table = sim.poses
        get = table.slot.get
        found = [get(e, -1) for e in ents]
        if sim.poses_stale or -1 in found or len(set(found)) != len(found):
            return False  # (a stale table: inside a callback, between flush and sync)
        slots = np.array(found, dtype=np.intp)
        if (
            not table.dynamic[slots].all()
            or table.asleep[slots].any()
            or not all([r.in_space for r in recs])
        ):
            return False
        # (a body Chipmunk put to sleep at the end of the last step while it still moved
        # is "awake" in the table: the velocity setter wakes it, as the other path does)
        state = self._rows.rows(sim.space, table.ids[slots])
        if state is None:
            return False
        v = impulses_mod.distinct_velocities(state, [r.mass for r in recs], jj, pp)
        if not np.isfinite(v).all():
            k = int(np.flatnonzero(~np.isfinite(v).all(axis=1))[0])
            raise ValidationError(
                f"{owner}: the velocity of entity {ents[k]} after impulses[{k}] would not "
                f"be finite ({tuple(v[k].tolist())!r}); the input is too large"
            )
        self._sim.touched = True
        v[np.abs(v) < TINY] = 0.0  # kge.physics.tiny.flush, every value at once
        vx, vy, w = v.T.tolist()
        cbs = [body_handle(r.body) for r in recs]  # Chipmunk's setters mapped over the bodies
        set_all(_set_velocity, cbs, zip(vx, vy, strict=True))
        set_all(_set_angular_velocity, cbs, w)
        push, watch = sim.contact_first.push, sim.rest.watch
        for rec in recs:
            push(rec.entity, rec.body)
            watch(rec.entity)
        # the read, with these velocities, is the space as it is: the step's continuous
        # collision and joints take it instead of reading again (Simulation.fresh_read)
        sim.fresh_read = self._rows.patch(v)
        every = sim._targets.rigidbodies[0]  # the RigidBody of each slot (re-slotted with it)
        rbs = [every[i] for i in found]
        if any(rb is None for rb in rbs):  # (``None in`` would call each dataclass's __eq__)
            keep = [k for k, rb in enumerate(rbs) if rb is not None]
            rbs = [rbs[k] for k in keep]
            vx, vy, w = [vx[k] for k in keep], [vy[k] for k in keep], [w[k] for k in keep]
        set_all(_SET_VELOCITY, rbs, zip(vx, vy, strict=True))
        set_all(_SET_ANGULAR_VELOCITY, rbs, w)
        return True

    def set_velocities(self, entities: Any, velocities: Any, angular: Any = None) -> None:
        """Row k gives ``entities[k]`` the velocity ``velocities[k]`` (and, unless
        ``angular`` is None, the spin ``angular[k]``): Box2D's ``SetLinearVelocity``
        in bulk, for controllers that drive many kinematic or dynamic bodies every
        step (:mod:`kge.physics.velocities`).

        The same as writing each ``RigidBody.velocity``, capped at
        ``settings.max_translation`` per step, waking sleepers, with one check of
        every row before anything changes; static bodies are skipped.

        >>> # physics.set_velocities([car, lift], [(4.0, 0.0), (0.0, 1.5)])
        """
        from kge.physics.velocities import set_velocities

        set_velocities(self, entities, velocities, angular)

    def _records(self, entities: list[int], op: str) -> list[BodyRecord]:
        """:meth:`_record` of every entity (ints), with one sync for them all."""
        missing = self._world.first_missing(entities)
        if missing is not None:
            raise EntityNotFoundError(f"physics.{op}(): entity {missing} does not exist")
        self._synced()
        get = self._sim.bodies.get
        recs = [get(e) for e in entities]
        if None in recs:
            bare = entities[recs.index(None)]
            raise ValidationError(
                f"physics.{op}(): entity {bare} has no body (add a RigidBody or a Collider)"
            )
        return recs  # type: ignore[return-value]

    def _write_velocity(self, entity: int, cb: Any, vx: float, vy: float, w: float) -> None:
        """Give Chipmunk's body ``cb`` and the entity's RigidBody this velocity (flushed)."""
        vx, vy, w = flush(vx), flush(vy), flush(w)  # see kge.physics.tiny
        _set_velocity(cb, (vx, vy))
        _set_angular_velocity(cb, w)
        self._sim.contact_first.push(entity, self._sim.bodies[entity].body)
        rb = self._world.try_get(entity, RigidBody)
        if rb is not None:
            raw_set(rb, "velocity", (vx, vy))
            raw_set(rb, "angular_velocity", w)

    def apply_angular_impulse(self, entity: int, impulse: float, wake: bool = True) -> None:
        """Change the angular velocity at once by ``impulse / inertia``."""
        owner = where(entity, "Physics.apply_angular_impulse")
        j = finite(impulse, owner, "impulse")
        body = self._record(entity, "apply_angular_impulse").body
        w = body.angular_velocity
        if math.isfinite(body.moment):
            w += j / body.moment
        _finite_result(owner, "the resulting angular velocity", (w,))
        if self._force_target(entity, "apply_angular_impulse", wake) is None:
            return
        body.angular_velocity = flush(w)
        self._sim.contact_first.push(entity, body)
        self._velocity_changed(entity, body)

    def _velocity_changed(self, entity: int, body: pymunk.Body) -> None:
        rb = self._world.try_get(entity, RigidBody)
        if rb is not None:
            v = body.velocity
            raw_set(rb, "velocity", (v.x, v.y))
            raw_set(rb, "angular_velocity", body.angular_velocity)

    # -- mass and helpers -------------------------------------------------------------------
    def mass_data(self, entity: int) -> MassData:
        """Mass (kg), inertia about the centre of mass (kg m^2) and local centre."""
        rec = self._record(entity, "mass_data")
        return rec.mass

    def world_point(self, entity: int, local_point: Vec2) -> Vec2:
        p = self._record(entity, "world_point").body.local_to_world(
            vec2(local_point, "world_point", "local_point")
        )
        return (p.x, p.y)

    def local_point(self, entity: int, world_point: Vec2) -> Vec2:
        p = self._record(entity, "local_point").body.world_to_local(
            vec2(world_point, "local_point", "world_point")
        )
        return (p.x, p.y)

    def world_vector(self, entity: int, local_vector: Vec2) -> Vec2:
        v = pymunk.Vec2d(*vec2(local_vector, "world_vector", "local_vector"))
        r = v.rotated(self._record(entity, "world_vector").body.angle)
        return (r.x, r.y)

    def local_vector(self, entity: int, world_vector: Vec2) -> Vec2:
        v = pymunk.Vec2d(*vec2(world_vector, "local_vector", "world_vector"))
        r = v.rotated(-self._record(entity, "local_vector").body.angle)
        return (r.x, r.y)

    def world_center(self, entity: int) -> Vec2:
        """The centre of mass in world coordinates."""
        body = self._record(entity, "world_center").body
        c = body.local_to_world(body.center_of_gravity)
        return (c.x, c.y)

    def local_center(self, entity: int) -> Vec2:
        return self.mass_data(entity).center

    def velocity_at_point(self, entity: int, world_point: Vec2) -> Vec2:
        """Velocity of the body's material point at ``world_point``.

        Box2D's GetLinearVelocityFromWorldPoint.
        """
        body = self._record(entity, "velocity_at_point").body
        v = body.velocity_at_world_point(vec2(world_point, "velocity_at_point", "world_point"))
        return (v.x, v.y)

    def is_awake(self, entity: int) -> bool:
        rec = self._record(entity, "is_awake")
        body = rec.body
        return rec.in_space and body.body_type != pymunk.Body.STATIC and not body.is_sleeping

    # -- joints -------------------------------------------------------------------------------
    def reset_joints(self, entities: Iterable[int]) -> None:
        """Let these joints start their next step from zero impulse, as new joints do.

        A solver warm-starts every joint with the impulse it applied in the last
        step (Box2D and pymunk alike), and teleporting the bodies keeps it: a
        ragdoll put back at a checkpoint, or a vehicle put back at its start,
        would begin with the push its legs last gave while standing. After this
        call the joints carry nothing over (for one substep they apply no impulse
        while pymunk's accumulator drains, then solve from zero). Joints not yet
        built are unaffected (they start cold anyway); an entity with no joint
        component is refused before any joint is touched.
        """
        ents = [int(e) for e in entities]
        joints = self._sim.joints
        for e in ents:
            if e not in joints.components:
                if not self._world.exists(e):
                    raise EntityNotFoundError(f"Physics.reset_joints: entity {e} does not exist")
                raise ValidationError(f"Physics.reset_joints: entity {e} has no joint component")
        joints.reset_impulses(ents)

    # -- interpolation ------------------------------------------------------------------------
    def previous_pose(self, entity: int) -> Pose | None:
        """Pose before the last step (x, y, angle), or None for non-moving entities."""
        poses = self._sim.poses
        i = poses.slot.get(entity)
        if i is None:
            return None
        x, y, a = poses.prev[i].tolist()
        return (x, y, a)

    def poses(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Bulk form: (entities, previous poses (n,3), current poses (n,3)) of moving bodies.

        The arrays are copies, safe to keep.
        """
        p = self._sim.poses
        return p.entities.copy(), p.prev.copy(), p.state[:, :3].copy()

    def states(self, entities: Any) -> tuple[np.ndarray, np.ndarray]:
        """Bulk form of reading Transform and RigidBody: ``(states, awake)`` of many bodies.

        ``states`` has one row ``(x, y, angle, vx, vy, w)`` per entity, ``awake`` one
        bool: the values the entity's Transform and RigidBody held when the last step
        ended (sync-out writes both from the same table), gathered with one numpy
        index instead of one component read per body. Changes made since that step
        (impulses, component writes) are not in it; read the components for those.
        A body spawned since the last step reads its pose at spawn. The arrays are
        fresh, safe to keep. For dynamic and kinematic bodies; others raise, naming
        the entity.

        >>> # states, awake = physics.states(vehicles); x, vy = states[:, 0], states[:, 4]
        """
        ents = np.asarray(entities)
        if ents.ndim != 1 or (len(ents) and ents.dtype.kind not in "iu"):
            raise ValidationError(
                f"Physics.states: entities must be a 1-D sequence of int ids, got {entities!r}"
            )
        ents = ents.astype(np.int64, copy=False)
        self._synced()  # bodies spawned since the last step get their slots
        table = self._sim.poses
        slots = self._state_slots.slots(table, ents)
        if slots is None:
            for e in ents.tolist():
                if e not in table.slot:
                    self._record(e, "states")  # raises for a missing or bodiless entity
                    raise ValidationError(
                        f"physics.states(): entity {e} has a static body (states are "
                        "kept for dynamic and kinematic bodies)"
                    )
        return states_mod.gather(table, slots)  # type: ignore[arg-type]

    # -- contact hooks -------------------------------------------------------------------------
    def on_pre_solve(self, fn: PreSolveFn) -> PreSolveFn:
        """Call ``fn(contact)`` once per step for each contact of a ``contact_hooks`` collider.

        ``contact`` is a :class:`kge.physics.contacts.PreSolve`: set ``enabled = False``
        to disable it for this step, or change ``friction``, ``restitution`` and
        ``tangent_speed`` (conveyor belts). The world is locked inside ``fn``.
        Usable as a decorator.
        """
        if not callable(fn):
            raise ValidationError(f"physics.on_pre_solve() needs a callable, got {fn!r}")
        self._sim.recorder.pre_solve.append(fn)
        return fn

    def on_post_solve(self, fn: PostSolveFn) -> PostSolveFn:
        """Call ``fn(impulses)`` after each step for each solved ``contact_hooks`` contact."""
        if not callable(fn):
            raise ValidationError(f"physics.on_post_solve() needs a callable, got {fn!r}")
        self._sim.recorder.post_solve.append(fn)
        return fn

    def remove_hook(self, fn: Callable[..., Any]) -> None:
        """Unregister a pre-solve or post-solve function."""
        rec = self._sim.recorder
        for lst in (rec.pre_solve, rec.post_solve):
            while fn in lst:
                lst.remove(fn)

    @property
    def contact_filter(self) -> ContactFilterFn | None:
        """Box2D's ShouldCollide: ``fn(collider_a, collider_b) -> bool``, once per new pair."""
        return self._sim.recorder.contact_filter

    @contact_filter.setter
    def contact_filter(self, fn: ContactFilterFn | None) -> None:
        if fn is not None and not callable(fn):
            raise ValidationError(f"physics.contact_filter must be callable or None, got {fn!r}")
        self._sim.recorder.contact_filter = fn
        ccd = self._sim.ccd
        if ccd is not None:  # sweeps must not stop a body at a pair the filter rejects
            ccd.pair_filter = None if fn is None else self._pair_filter

    def _pair_filter(self, a: pymunk.Shape, b: pymunk.Shape) -> bool:
        fn = self._sim.recorder.contact_filter
        if fn is None:
            return True
        with self._sim.world.locked():
            table = self._sim.shapes
            ca, cb = table.collider_of(a), table.collider_of(b)
            return ca is None or cb is None or bool(fn(ca, cb))  # (None: not kge's shape)

    # -- queries (kge.physics.queries) ---------------------------------------------------------
    def _query_space(self, op: str) -> pymunk.Space:
        self._synced()  # (skipped inside callbacks, where queries see the live step)
        return self._sim.space

    @overload
    def raycast(
        self,
        p1: Vec2,
        p2: Vec2,
        callback: Callable[[RayHit], float],
        mode: RayMode | str = ...,
        filter: QueryFilter = ...,
    ) -> None: ...
    @overload
    def raycast(
        self,
        p1: Vec2,
        p2: Vec2,
        callback: None = ...,
        mode: Literal[RayMode.CLOSEST, RayMode.ANY] = ...,
        filter: QueryFilter = ...,
    ) -> RayHit | None: ...
    @overload
    def raycast(
        self,
        p1: Vec2,
        p2: Vec2,
        callback: None = ...,
        *,
        mode: Literal[RayMode.ALL],
        filter: QueryFilter = ...,
    ) -> list[RayHit]: ...
    @overload
    def raycast(
        self,
        p1: Vec2,
        p2: Vec2,
        callback: Callable[[RayHit], float] | None = ...,
        mode: RayMode | str = ...,
        filter: QueryFilter = ...,
    ) -> RayHit | list[RayHit] | None: ...
    def raycast(
        self,
        p1: Vec2,
        p2: Vec2,
        callback: Callable[[RayHit], float] | None = None,
        mode: RayMode | str = RayMode.CLOSEST,
        filter: QueryFilter = None,
    ) -> RayHit | list[RayHit] | None:
        """Cast a ray from ``p1`` to ``p2`` (see :func:`kge.physics.queries.raycast`).

        With ``callback``, Box2D's protocol (returns None). Without one, ``mode``
        decides: ``RayMode.CLOSEST`` (the default) the nearest :class:`RayHit` or
        None, ``RayMode.ALL`` every hit by fraction, ``RayMode.ANY`` any hit or None.
        The strings ``"closest"``, ``"all"``, ``"any"`` still work for one release.
        """
        from kge.physics import queries

        ray_mode = enum_value(RayMode, mode, "Physics.raycast", "mode")
        space = self._query_space("raycast")
        return queries.raycast(space, p1, p2, callback, ray_mode, filter)

    def query_aabb(
        self,
        lower: Vec2,
        upper: Vec2,
        callback: Callable[[QueryHit], Any] | None = None,
        filter: QueryFilter = None,
    ) -> list[QueryHit]:
        """Colliders whose bounds overlap the box (with a callback returning False to stop
        early, the hits reported so far)."""
        from kge.physics import queries

        return queries.query_aabb(self._query_space("query_aabb"), lower, upper, callback, filter)

    def query_point(self, p: Vec2, filter: QueryFilter = None) -> list[QueryHit]:
        """Colliders containing the point ``p``."""
        from kge.physics import queries

        return queries.query_point(self._query_space("query_point"), p, filter)

    def query_shape(self, shape: Any, transform: Any, filter: QueryFilter = None) -> list[QueryHit]:
        """Colliders overlapping ``shape`` placed at ``transform`` (with contact points)."""
        from kge.physics import queries

        return queries.query_shape(self._query_space("query_shape"), shape, transform, filter)


def _finite_result(owner: str, what: str, values: tuple[float, ...]) -> None:
    """Refuse finite inputs whose product overflows (a 1e300 lever arm...), before any change."""
    if not all(math.isfinite(v) for v in values):
        raise ValidationError(
            f"{owner}: {what} would not be finite ({values!r}); the input is too large"
        )
