"""The simulation: one pymunk Space per World, kept in step with the components.

Each fixed step runs three phases (DESIGN.md "Frame order"):

1. **sync-in**, in sorted entity order and O(changes): bodies and colliders that
   appeared or disappeared (recorded by world hooks), then component fields
   that user code wrote (recorded by :mod:`kge.components.tracked` bindings):
   body type, enabled, velocities, damping, mass, collider material and filter,
   teleports (a user write to Transform). Everything that pymunk forbids inside
   a step (body type changes, sleeping) happens here, between steps.
2. **step**: ``substeps`` pymunk steps of ``dt / substeps``, with joints'
   ``before_step`` before and ``read_back`` after.
3. **sync-out** with :class:`~kge.physics.sync.PoseTable`: only changed bodies
   are written back (with ``raw_set``, so they do not look like user writes);
   ``RigidBody.awake`` follows pymunk's sleeping; Box2D's speed caps are applied.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
import pymunk

from kge.components.collider import Collider
from kge.components.platform import OneWayPlatform
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.tracked import bind, raw_set, unbind
from kge.components.transform import Transform
from kge.errors import ValidationError
from kge.gcpause import without_gc
from kge.physics.bodies import (
    DYNAMIC,
    PYMUNK_TYPE,
    STATIC,
    BodyRecord,
    ColliderRecord,
    configure_dynamics,
    make_body,
    set_body_type,
    set_mass,
    sleep_island,
    take_out,
    wake_neighbours,
    woken_with,
)
from kge.physics.callback_errors import CallbackErrors
from kge.physics.contact_first import ContactFirst
from kge.physics.contacts import HOOKED, ContactRecorder
from kge.physics.cp import body_handle, shape_handle
from kge.physics.cp import lib as _cp
from kge.physics.cp.static_bulk import add_shapes, remove_shapes
from kge.physics.events import PhysicsEvents
from kge.physics.joint_bridge import JointBridge
from kge.physics.mass import MassData, combine, dynamic_mass, shape_mass
from kge.physics.rest import RestClock
from kge.physics.settings import PhysicsSettings
from kge.physics.shape_table import ShapeTable
from kge.physics.shapes import (
    apply_material,
    build_shapes,
    rebuild_in_place,
    same_segments,
    spread,
)
from kge.physics.speed_cap import SpeedCap, clamp, clamp_one, maybe_over
from kge.physics.sync import PoseTable, columns_differ, rows_differ
from kge.physics.tiny import flush
from kge.physics.writeback import Targets, write_poses, write_velocities
from kge.world import World

#: up to this many rows (every slot moved), all velocities are written without a mask
_FEW = 32
#: bodies changed in one sync-in above which the cyclic collector waits until they are done
_BULK = 64


class Simulation:
    """pymunk mirror of one World's physics components."""

    def __init__(
        self,
        world: World,
        settings: Callable[[], PhysicsSettings],
        events: PhysicsEvents,
        dt: float,
    ) -> None:
        self.world = world
        self._settings = settings
        self.events = events
        self.dt = dt
        self.space = pymunk.Space()
        self._threads = 1
        self._hash_cell: float | None = None
        self._hash_count = 0
        #: exceptions raised inside pymunk callbacks during a step, raised after it
        self.errors = CallbackErrors()
        #: kge's data about every shape of the space, by slot (kge.physics.shape_table)
        self.shapes = ShapeTable()
        self.shapes.adopt(self.space)
        self.recorder = ContactRecorder(world, self.space, events, self.errors, self.shapes)
        self.bodies: dict[int, BodyRecord] = {}
        #: the entity of each pymunk body (islands of bodies map back to entities)
        self.body_entities: dict[pymunk.Body, int] = {}
        self.colliders: dict[int, ColliderRecord] = {}
        self.pending: set[int] = set()  # colliders waiting for their body
        #: pending colliders whose reshaped segments wait to go back into the space
        self._reshaped: dict[int, ColliderRecord] = {}
        self.body_struct: set[int] = set()
        self.collider_struct: set[int] = set()
        self.rb_dirty: set[int] = set()
        self.col_dirty: set[int] = set()
        self.tf_dirty: set[int] = set()
        self.mass_dirty: set[int] = set()
        self.no_sleep: set[int] = set()
        self.poses = PoseTable()
        self.poses_stale = True
        #: entities whose pose-table slot (membership, body, components) may have changed
        self._pose_dirty: set[int] = set()
        self._targets = Targets([], [])
        #: bumped whenever a body's mass data is recomputed (joint batches watch it)
        self.mass_epoch = 0
        self.joints = JointBridge(self)
        self._applied: tuple[Any, ...] = ()
        self.skin = 0.01
        self.substeps = 1
        self.steps = 0
        #: body entity -> [fx, fy, torque about the centre of mass] for this step
        self.forces: dict[int, list[float]] = {}
        self.ccd = _make_ccd(self.space, self.errors, self.shapes)
        self.ccd_dirty: set[int] = set()
        #: bodies whose velocity came from outside the solver: their first move of the
        #: next step respects their contacts first (kge.physics.contact_first)
        self.contact_first = ContactFirst()
        #: the Chipmunk bodies of bullets (a time of impact against dynamic bodies too)
        self.bullets: set[Any] = set()
        #: Box2D's sleep clock for jointed islands (kge.physics.rest)
        self.rest = RestClock()
        #: bodies that kept a jointed island awake: their clock is watched too
        self._rest_blockers: set[int] = set()
        self._rest_epoch = 0
        self._speed_cap = SpeedCap()
        #: every tracked body was asleep after the last step (and none is kinematic)
        self.all_asleep = False
        #: something outside the dirty sets (an impulse, a wake-up) touched a body
        self.touched = False
        #: (ids, rows) of every body as it is now, left by the last thing that changed
        #: bodies between steps when it could keep its own bulk read current (the bulk
        #: impulses); anything else that changes a body clears it (Physics does)
        self.fresh_read: tuple[np.ndarray, np.ndarray] | None = None
        #: a bulk read the joints' after-step work left current (its moves patched in),
        #: for sync-out instead of reading every body again (JointBridge.after_step)
        self.out_read: tuple[np.ndarray, np.ndarray] | None = None
        #: ``poses.prev`` equals the current poses (set by a quiet step)
        self._prev_is_current = False

    @property
    def settings(self) -> PhysicsSettings:
        return self._settings()

    # -- world hooks (record only; the work happens in sync-in) ----------------------------
    def on_rigidbody_added(self, entity: int, rb: RigidBody) -> None:
        bind(rb, entity, self.rb_dirty)
        self.body_struct.add(entity)
        self.rb_dirty.add(entity)
        self._restale(entity)

    def on_rigidbody_removed(self, entity: int, rb: RigidBody) -> None:
        unbind(rb)
        self.body_struct.add(entity)
        if not self.world.exists(entity):  # despawned, not just a removed RigidBody
            self._despawn_attached(entity)

    def _despawn_attached(self, body: int) -> None:
        """Despawn the colliders on other entities that name ``body`` (``Collider(body=e)``).

        Box2D's DestroyBody destroys the body's fixtures; kge's fixtures on other
        entities go with it instead of staying alive attached to nothing. Runs from
        the flush that applies the despawn, so they are despawned in that same flush.
        """
        world = self.world
        rec = self.bodies.get(body)
        found = set() if rec is None else set(rec.colliders)
        for c in self.pending:
            col = world.try_get(c, Collider)
            if col is not None and col.body == body:
                found.add(c)
        for c in sorted(found):
            if c != body and world.exists(c):
                world.despawn(c)

    def on_collider_added(self, entity: int, col: Collider) -> None:
        bind(col, entity, self.col_dirty, self.world.validate)
        self.collider_struct.add(entity)
        self.body_struct.add(entity)
        body = col.body
        if body is not None and not self.world.exists(body) and self.world.exists(entity):
            # queued in the flush that despawned its body (validated while it lived)
            self.world.despawn(entity)

    def on_collider_removed(self, entity: int, col: Collider) -> None:
        unbind(col)
        self.collider_struct.add(entity)
        self.body_struct.add(entity)

    def on_transform_added(self, entity: int, t: Transform) -> None:
        bind(t, entity, self.tf_dirty)
        self.tf_dirty.add(entity)
        self._restale(entity)

    def on_transform_removed(self, entity: int, t: Transform) -> None:
        unbind(t)
        self._restale(entity)

    def _restale(self, entity: int) -> None:
        """The pose-table slot of ``entity`` is re-read at the next sync-in."""
        self.poses_stale = True
        self._pose_dirty.add(entity)

    def on_platform_changed(self, entity: int, p: OneWayPlatform) -> None:
        if self.world.exists(entity) and self.world.try_get(entity, OneWayPlatform) is p:
            bind(p, entity, self.col_dirty)
        else:
            unbind(p)
        self.col_dirty.add(entity)

    # -- sync-in --------------------------------------------------------------------------
    def _apply_settings(self) -> None:
        s = self.settings
        key = (
            s.gravity, s.iterations, s.collision_slop, s.sleep, s.time_to_sleep,
            s.sleep_speed, s.substeps, s.velocity_threshold, s.polygon_radius,
            s.threads, s.spatial_hash,
        )
        if key == self._applied:
            return
        if (s.threads, s.spatial_hash) != (self._threads, self._hash_cell):
            try:
                self._choose_space(s.threads, s.spatial_hash)
            except ValidationError:
                # the settings keep what the space is, so the world stays as it was
                object.__setattr__(s, "threads", self._threads)
                object.__setattr__(s, "spatial_hash", self._hash_cell)
                raise
        space = self.space
        if self._applied and s.gravity != self._applied[0]:
            for e in sorted(self.bodies):  # a new gravity concerns resting bodies too
                rec = self.bodies[e]
                if rec.in_space and rec.body.body_type == DYNAMIC:
                    rec.body.activate()  # also restarts the idle timer
        space.gravity = s.gravity
        space.iterations = s.iterations
        space.collision_slop = s.collision_slop
        if not s.sleep and math.isfinite(space.sleep_time_threshold):
            for rec in self.bodies.values():
                if rec.body.is_sleeping:
                    rec.body.activate()
        space.sleep_time_threshold = s.time_to_sleep if s.sleep else math.inf
        space.idle_speed_threshold = s.sleep_speed
        self.recorder.velocity_threshold = s.velocity_threshold
        self.recorder.slop = s.collision_slop
        if self.ccd is not None:
            self.ccd.max_translation = s.max_translation
            self.ccd.max_rotation = s.max_rotation
        if s.substeps != self.substeps:
            self.substeps = s.substeps
            self.rb_dirty.update(e for e, r in self.bodies.items() if not r.implicit)
        if s.polygon_radius != self.skin:
            self.skin = s.polygon_radius
            for c in self.colliders:
                self.collider_struct.add(c)
        self._applied = key

    def _choose_space(self, threads: int, cell: float | None) -> None:
        """Apply ``PhysicsSettings.threads`` and ``spatial_hash`` (see there).

        A threaded space is another kind of pymunk Space, so it replaces the
        empty one this simulation started with: everything that registered on it
        (contact handlers, continuous collision, joints) moves to the new one.
        Both choices are made before the first body arrives, which is when a
        scene inserts its settings; later they raise instead of changing a
        running simulation's results.
        """
        space = self.space
        if threads != self._threads:
            if self.steps or space.bodies or space.shapes or space.constraints:
                raise ValidationError(
                    f"PhysicsSettings.threads: set it before the first step (it was "
                    f"{self._threads}, now {threads}); pymunk's threaded space is a "
                    "different kind of space"
                )
            space = pymunk.Space(threaded=threads > 1)
            if threads > 1:
                space.threads = threads
            self.space = space
            self.shapes.adopt(space)
            self.recorder.bind(space)
            self.ccd = _make_ccd(space, self.errors, self.shapes)
            self.joints.space = space
            self._threads = threads
            self._hash_cell = None  # a fresh space has the tree again
        if cell != self._hash_cell:
            if cell is None:
                raise ValidationError(
                    "PhysicsSettings.spatial_hash: Chipmunk cannot go back from its "
                    "spatial hash to its tree; choose the broad phase before the first step"
                )
            self._use_hash(cell)

    def _use_hash(self, cell: float) -> None:
        """Chipmunk's spatial hash of ``cell`` metres, with about ten cells per shape."""
        shapes = len(self.space.shapes) + len(self.pending) + len(self.collider_struct)
        self._hash_count = max(1024, 10 * shapes)
        self.space.use_spatial_hash(cell, self._hash_count)
        self._hash_cell = cell

    def sync_in(self) -> None:
        self._apply_settings()
        if self.body_struct:
            ents = sorted(self.body_struct)
            self.body_struct.clear()
            if len(ents) > _BULK:
                self._restructure_bodies(ents)
            else:
                for e in ents:
                    self._restructure_body(e)
        if self.collider_struct:
            ents = sorted(self.collider_struct)
            self.collider_struct.clear()
            for e in ents:
                crec = self.colliders.pop(e, None)
                if crec is not None:
                    self._detach(crec)
                if self.world.try_get(e, Collider) is not None:
                    self.pending.add(e)
                else:
                    self.pending.discard(e)
                rec = self.bodies.get(e)
                if rec is not None and rec.implicit:
                    # its collider may have moved onto a body meanwhile (a field write
                    # this sync-in applies too late for a collider rebuilt here)
                    self._restructure_body(e)
        if self.pending:
            self._attach_pending()
        if self.rb_dirty:
            ents = sorted(self.rb_dirty)
            self.rb_dirty.clear()
            for e in ents:
                self._apply_rigidbody(e)
        if self.col_dirty:
            ents = sorted(self.col_dirty)
            self.col_dirty.clear()
            for e in ents:
                self._apply_collider(e)
            if self.pending:
                self._attach_pending()
        if self.tf_dirty:
            ents = sorted(self.tf_dirty)
            self.tf_dirty.clear()
            for e in ents:
                self._teleport(e)
        if self.mass_dirty:
            ents = sorted(self.mass_dirty)
            self.mass_dirty.clear()
            for e in ents:
                self._update_mass(e)
        self.joints.sync()
        if self.ccd_dirty:
            self._sync_ccd()
        if self.poses_stale:
            self._rebuild_poses()
        for e in sorted(self.no_sleep):
            rec = self.bodies.get(e)
            if rec is not None and rec.in_space:
                # Box2D's allowSleep=False: the body's time at rest stays 0, so neither it
                # nor its island sleeps; Chipmunk's clock restarts with each activation
                # (waking it only once it slept let it doze off every 0.5 s)
                rec.body.activate()

    @without_gc  # a tile map's 100,000s of new static shapes (see kge.gcpause)
    def _sync_ccd(self) -> None:
        """(Re)register bodies with continuous collision after shape or type changes."""
        ccd = self.ccd
        ents = sorted(self.ccd_dirty)
        self.ccd_dirty.clear()
        if ccd is None:
            return
        for e in ents:
            rec = self.bodies.get(e)
            if rec is None:
                continue
            body = rec.body
            if rec.in_space and body.body_type == DYNAMIC and rec.colliders:
                ccd.track(body, bullet=rec.bullet)
            else:
                ccd.untrack(body)

    @without_gc  # a wave of new bodies: pymunk objects, records, bindings (kge.gcpause)
    def _restructure_bodies(self, ents: list[int]) -> None:
        for e in ents:
            self._restructure_body(e)

    def _restructure_body(self, e: int) -> None:
        world = self.world
        rb = world.try_get(e, RigidBody)
        col = world.try_get(e, Collider)
        implicit = rb is None and col is not None and col.body is None
        rec = self.bodies.get(e)
        if rec is not None:
            if (rb is not None and not rec.implicit) or (implicit and rec.implicit):
                if rb is not None:
                    self.rb_dirty.add(e)
                return
            self._destroy_body(rec)
        if rb is not None or implicit:
            self._create_body(e, rb)

    def _create_body(self, e: int, rb: RigidBody | None) -> None:
        t = self.world.try_get(e, Transform)
        if t is None:
            t = Transform()
            self.world.add(e, t)
        kind = BodyType.STATIC if rb is None else rb.type
        body = make_body(kind, t.x, t.y, t.angle)
        self.tf_dirty.discard(e)  # the body starts at the Transform: no teleport to apply
        rec = BodyRecord(e, body, implicit=rb is None)
        self.bodies[e] = rec
        self.body_entities[body] = e
        if rb is not None:
            self.rb_dirty.add(e)
        if rb is None or rb.enabled:
            self.space.add(body)
            rec.in_space = True
        else:
            rec.enabled = False
        self.mass_dirty.add(e)
        self._restale(e)

    def _destroy_body(self, rec: BodyRecord) -> None:
        self.joints.body_removed(rec.entity)
        if self.ccd is not None:
            self.ccd.untrack(rec.body, removed=True)
        if rec.in_space:
            wake_neighbours(rec.body)
        for c in sorted(rec.colliders):
            crec = self.colliders.pop(c, None)
            if crec is not None:
                self._remove_shapes(crec)
            if self.world.try_get(c, Collider) is not None:
                self.pending.add(c)
        rec.colliders.clear()
        if rec.in_space:
            self.space.remove(rec.body)
            rec.in_space = False
        del self.bodies[rec.entity]
        self.body_entities.pop(rec.body, None)
        self.no_sleep.discard(rec.entity)
        self.bullets.discard(body_handle(rec.body))
        self._restale(rec.entity)

    def _remove_shapes(self, crec: ColliderRecord, keep: bool = False) -> None:
        """Take the collider's shapes out of the space (``keep``: they come back, reshaped,
        keeping their slots in the shape table)."""
        remove_shapes(self.space, crec.shapes)  # one call: a chain's thousands of segments
        self.recorder.forget_shapes(crec.shapes)
        if not keep:
            self.shapes.drop(crec.shapes)

    def _detach(self, crec: ColliderRecord) -> None:
        rec = self.bodies.get(crec.owner)
        if rec is not None:
            if rec.in_space and crec.shapes:
                wake_neighbours(rec.body)  # the body and all it touches (see bodies.take_out)
            rec.colliders.discard(crec.entity)
            self.mass_dirty.add(crec.owner)
            self.ccd_dirty.add(crec.owner)
        self._remove_shapes(crec)

    @without_gc  # a tile map attaches 100,000s of shapes here (see kge.gcpause)
    def _attach_pending(self) -> None:
        world = self.world
        space = self.space
        to_add: list[pymunk.Shape] = []
        attached: list[int] = []
        reshaped = self._reshaped
        for c in sorted(self.pending):
            if c in reshaped:  # its own segments, new again (see _reshape)
                crec = reshaped.pop(c)
                if self.bodies[crec.owner].in_space:
                    shapes = crec.shapes
                    to_add.extend(shapes if len(shapes) < 64 else spread(shapes))
                attached.append(c)
                continue
            col = world.try_get(c, Collider)
            if col is None:
                attached.append(c)
                continue
            owner = c if col.body is None else col.body
            rec = self.bodies.get(owner)
            if rec is None:
                continue
            shapes = build_shapes(rec.body, col, c, rec.event_body, self.skin, self.shapes)
            self._configure_shapes(c, col, shapes, fresh=True)
            if rec.in_space:
                to_add.extend(shapes if len(shapes) < 64 else spread(shapes))
            self.colliders[c] = ColliderRecord(c, owner, shapes, col.shape)
            rec.colliders.add(c)
            self.mass_dirty.add(owner)
            self.ccd_dirty.add(owner)
            attached.append(c)
        if to_add:
            add_shapes(space, to_add)  # one call, same order as shape by shape
        self.pending.difference_update(attached)
        if self._hash_cell is not None and 5 * len(space.shapes) > self._hash_count:
            self._use_hash(self._hash_cell)  # grown: a larger table (fewer false pairs)

    def _configure_shapes(
        self, c: int, col: Collider, shapes: list[pymunk.Shape], fresh: bool = False
    ) -> None:
        """One-way platform and hook flag; ``fresh`` shapes have neither yet."""
        plat = self.world.try_get(c, OneWayPlatform)
        oneway = None if plat is None else (plat.up, plat.min_cos)
        ctype = HOOKED if col.contact_hooks else 0
        if fresh and oneway is None and ctype == 0:
            return
        table = self.shapes
        for s in shapes:
            table.set_oneway(s, oneway)
            table.set_hooked(s, ctype == HOOKED)
            if s.collision_type != ctype:
                s.collision_type = ctype

    def _apply_collider(self, e: int) -> None:
        crec = self.colliders.get(e)
        col = self.world.try_get(e, Collider)
        if col is None:
            return
        if crec is None:
            # waiting to be (re)built this sync-in (a new skin rebuilds every collider):
            # its shapes follow ``col.body`` when they are attached, but an implicit
            # static body of this entity must still go (moved onto a body) or come
            rec = self.bodies.get(e)
            if rec is None or rec.implicit:
                self._restructure_body(e)  # (nothing to do when it already fits)
            return
        owner = e if col.body is None else col.body
        if owner != crec.owner or crec.geometry is not col.shape:
            if owner == crec.owner and self._reshape(crec, col):
                return
            self.colliders.pop(e)
            self._detach(crec)
            self.pending.add(e)
            if owner != crec.owner:
                # an implicit static body of this entity goes (moved onto a body) or
                # comes (moved back to body=None)
                self._restructure_body(e)
            return
        rec = self.bodies.get(owner)
        refilter = False
        table = self.shapes
        for s in crec.shapes:
            was = table.filters[table.index[shape_handle(s)]]
            refilter = refilter or was != col.filter or s.sensor != col.sensor
            apply_material(s, col, table)
        self._configure_shapes(e, col, crec.shapes)
        if rec is not None:
            self.mass_dirty.add(owner)
            if refilter and rec.body.body_type == DYNAMIC and rec.in_space:
                rec.body.activate()  # Box2D: assigning a filter wakes the body

    def _reshape(self, crec: ColliderRecord, col: Collider) -> bool:
        """A new shape of the same segments (:func:`same_segments`) for a collider on
        the same body: reuse its pymunk segments instead of building new ones.

        Everything a rebuild (:meth:`_detach`, then :meth:`_attach_pending`) does
        happens, in the same order: what touches the body wakes, the segments
        leave the space (Chipmunk ends their contacts, with separate callbacks,
        and wakes what touched them), the contact recorder forgets them; they are
        then initialised as new segments of the new shape
        (:func:`rebuild_in_place`) and go back into the space with the colliders
        that :meth:`_attach_pending` adds, in entity order, getting new hash ids as
        new shapes would (so the space's index, pair order and results are those
        of a rebuild). What a rebuild would redo for nothing is skipped for a static
        body: an edge's or chain's mass is zero, so its mass data stays, and it has
        no continuous collision to re-register (a dynamic or kinematic body's are
        redone as before). False: rebuild instead.
        """
        rec = self.bodies.get(crec.owner)
        if rec is None or not same_segments(crec.geometry, col.shape):
            return False
        e = crec.entity
        if rec.in_space and crec.shapes:
            wake_neighbours(rec.body)  # as _detach
        self._remove_shapes(crec, keep=True)
        rebuild_in_place(crec.shapes, rec.body, col, e, rec.event_body, self.skin, self.shapes)
        self._configure_shapes(e, col, crec.shapes, fresh=True)  # new again
        crec.geometry = col.shape
        if rec.body.body_type != STATIC:
            self.mass_dirty.add(crec.owner)
            self.ccd_dirty.add(crec.owner)
        # else continuous collision's obstacle index needs no word: the segments come
        # back with new hash ids, which is how it tells the shapes it must (re-)read
        # at its next look (kge.physics.ccd.obstacles), as it reads any new shape
        self._reshaped[e] = crec
        self.pending.add(e)
        return True

    def _apply_rigidbody(self, e: int) -> None:
        rec = self.bodies.get(e)
        rb = self.world.try_get(e, RigidBody)
        if rec is None or rec.implicit or rb is None:
            return
        body = rec.body
        ptype = PYMUNK_TYPE[rb.type]
        if body.body_type != ptype:
            # the body leaves the space and comes back with the new type (its contacts
            # end, as Box2D's SetType destroys them); joints come out of the space and
            # the bridge puts back the ones that still act
            if self.ccd is not None:
                self.ccd.untrack(body)
            set_body_type(body, ptype)  # safe: sync-in runs between steps
            self.joints.body_changed(e)
            self.joints.refresh_membership()
            self.mass_dirty.add(e)
            self._restale(e)
        if rb.enabled != rec.enabled:
            self._set_enabled(rec, rb.enabled)
        if ptype == STATIC:
            if rb.velocity != (0.0, 0.0) or rb.angular_velocity != 0.0:
                raw_set(rb, "velocity", (0.0, 0.0))
                raw_set(rb, "angular_velocity", 0.0)
        else:
            s = self.settings
            (vx, vy), w = rb.velocity, rb.angular_velocity
            nv, nw = clamp_one(vx, vy, w, s.max_translation / self.dt, s.max_rotation / self.dt)
            if nv is not None:
                vx, vy = nv
                raw_set(rb, "velocity", nv)
            if nw is not None:
                w = nw
                raw_set(rb, "angular_velocity", nw)
            if ptype == DYNAMIC and rb.fixed_rotation:
                w = 0.0
                raw_set(rb, "angular_velocity", 0.0)
            vx, vy, w = flush(vx), flush(vy), flush(w)
            # Chipmunk's setters directly: pymunk's properties go through a
            # __setattr__ of its own (a reset writes several bodies' velocities)
            cp = body_handle(body)
            v = _cp.cpBodyGetVelocity(cp)
            pushed = False
            if (v.x, v.y) != (vx, vy):
                _cp.cpBodySetVelocity(cp, (vx, vy))
                pushed = True
            if _cp.cpBodyGetAngularVelocity(cp) != w:
                _cp.cpBodySetAngularVelocity(cp, w)
                pushed = True
            if pushed and ptype == DYNAMIC:
                self.contact_first.push(e, body)
            i = self.poses.slot.get(e)
            if i is not None and not self.poses_stale:
                # sync-out writes what changed since this: the component now holds it
                self.poses.state[i, 3:6] = (vx, vy, w)
        configure_dynamics(body, rb, self.dt, self.substeps)
        rec.bullet = rb.bullet
        if rb.bullet and ptype == DYNAMIC:
            self.bullets.add(body_handle(body))
        else:
            self.bullets.discard(body_handle(body))
        # a velocity write (a player controller's, every frame) leaves the mass data
        # and continuous collision as they were: rebuilt only when what they are
        # made of changed
        applied = (rb.type, rb.enabled, rb.mass, rb.fixed_rotation, rb.bullet)
        if applied != rec.applied:
            rec.applied = applied
            self.mass_dirty.add(e)
            self.ccd_dirty.add(e)
        if rb.allow_sleep:
            self.no_sleep.discard(e)
        else:
            self.no_sleep.add(e)
        if not rec.in_space:
            return
        if rb.awake != rec.awake:  # the user wrote awake
            if rb.awake and body.is_sleeping:
                body.activate()
                self._mark_awake(e, rb)
            elif not rb.awake and not body.is_sleeping and rb.allow_sleep:
                self._put_to_sleep(rec, rb)
        elif not body.is_sleeping and not rb.awake:
            self._mark_awake(e, rb)  # a velocity write woke it

    def _mark_awake(self, e: int, rb: RigidBody) -> None:
        rec = self.bodies[e]
        was_asleep = not rec.awake
        self._awake_now(e, rb)
        body = rec.body
        if was_asleep and body.space is self.space:
            # its sleeping island woke with it, moving or not (see bodies.woken_with)
            for other in woken_with(self.space, body, self._seen_awake):
                other_rec = self.bodies.get(self.body_entities.get(other, -1))
                if other_rec is None or other_rec.body is not other:
                    continue
                other_rb = self.world.try_get(other_rec.entity, RigidBody)
                if other_rb is not None:
                    self._awake_now(other_rec.entity, other_rb)

    def _seen_awake(self, body: pymunk.Body) -> bool:
        """kge's record of ``body`` says awake (a body kge does not own counts as awake)."""
        rec = self.bodies.get(self.body_entities.get(body, -1))
        return rec is None or rec.body is not body or rec.awake

    def _awake_now(self, e: int, rb: RigidBody) -> None:
        raw_set(rb, "awake", True)
        self.bodies[e].awake = True
        i = self.poses.slot.get(e)
        if i is not None and not self.poses_stale:
            self.poses.asleep[i] = False

    def _put_to_sleep(self, rec: BodyRecord, rb: RigidBody) -> None:
        """``RigidBody.awake = False``: Box2D's SetAwake(false), made safe for Chipmunk.

        The velocities are zeroed either way. The body sleeps now together with
        the awake bodies connected to it when all of those were asked to sleep too
        (a whole stack put to sleep at once), or alone next to static bodies and
        sleeping ones (:func:`~kge.physics.bodies.sleep_island`). Next to any
        other awake body it stays awake, as Box2D's island solver would wake it at
        the next step, and falls asleep by itself once at rest.
        """
        body = rec.body
        body.velocity = (0.0, 0.0)
        body.angular_velocity = 0.0
        raw_set(rb, "velocity", (0.0, 0.0))
        raw_set(rb, "angular_velocity", 0.0)
        self._flush_mass(rec.entity)  # sleep with the final mass
        island = sleep_island(self.space, body, self._wants_sleep)
        for member in island:
            self._mark_asleep(self.body_entities[member])
        if not island:
            raw_set(rb, "awake", True)
            rec.awake = True

    def _wants_sleep(self, body: pymunk.Body) -> bool:
        """Has the user asked this (awake) body to sleep, and may it?

        Its own ``_apply_rigidbody`` may not have run yet in this sync-in: the
        request is the ``awake`` field differing from what kge last saw.
        """
        e = self.body_entities.get(body)
        rec = None if e is None else self.bodies.get(e)
        if e is None or rec is None or rec.body is not body:
            return False
        rb = self.world.try_get(e, RigidBody)
        if rb is None:
            return False
        if rb.awake or not rec.awake or not rb.allow_sleep or not rec.in_space:
            return False
        self._flush_mass(e)  # it may sleep now: with its final mass (harmless if it does not)
        return True

    def _mark_asleep(self, e: int) -> None:
        """Record that the body of ``e`` was put to sleep during sync-in."""
        rec = self.bodies[e]
        rec.awake = False
        rb = self.world.try_get(e, RigidBody)
        if rb is not None:
            raw_set(rb, "awake", False)
            raw_set(rb, "velocity", (0.0, 0.0))
            raw_set(rb, "angular_velocity", 0.0)
        i = self.poses.slot.get(e)
        if i is not None and not self.poses_stale:
            self.poses.asleep[i] = True
            self.poses.state[i, 3:] = 0.0
            self.poses.rest[i] = 0.0  # Box2D: a woken body's clock starts from zero
        self.rest.slept(e)

    def _flush_mass(self, e: int) -> None:
        """Apply a pending mass change now (it wakes the body, so before it sleeps)."""
        if e in self.mass_dirty:
            self.mass_dirty.discard(e)
            self._update_mass(e)

    def _set_enabled(self, rec: BodyRecord, on: bool) -> None:
        space = self.space
        if on and not rec.in_space:
            shapes = [s for c in sorted(rec.colliders) for s in self.colliders[c].shapes]
            space.add(rec.body, *shapes)
            rec.in_space = True
        elif not on and rec.in_space:
            if self.ccd is not None:
                self.ccd.untrack(rec.body)
            take_out(space, rec.body)  # wakes its neighbours first (see bodies.take_out)
            rec.in_space = False
        rec.enabled = on
        self._restale(rec.entity)
        self.joints.body_changed(rec.entity)

    def _teleport(self, e: int) -> None:
        rec = self.bodies.get(e)
        t = self.world.try_get(e, Transform)
        if rec is None or t is None:
            return
        body = rec.body
        cp = body_handle(body)  # Chipmunk's getters and setters directly (see _apply_rigidbody)
        p = _cp.cpBodyGetPosition(cp)
        x, y, angle = flush(t.x), flush(t.y), flush(t.angle)
        if (p.x, p.y, _cp.cpBodyGetAngle(cp)) == (x, y, angle):
            return
        # angle first: Chipmunk turns a body about its centre of gravity, so setting
        # the origin and then the angle would move the origin off the pose again
        _cp.cpBodySetAngle(cp, angle)
        _cp.cpBodySetPosition(cp, (x, y))
        if body.body_type == STATIC and rec.in_space:
            self.space.reindex_shapes_for_body(body)
        self.poses.teleported(e, t.x, t.y, t.angle)

    def _update_mass(self, e: int) -> None:
        rec = self.bodies.get(e)
        if rec is None:
            return
        body = rec.body
        world = self.world
        parts = []
        for c in sorted(rec.colliders):
            col = world.try_get(c, Collider)
            if col is not None:
                parts.append(shape_mass(col.shape, col.density))
        computed = combine(parts)
        rb = None if rec.implicit else world.try_get(e, RigidBody)
        if rb is None or body.body_type != DYNAMIC:
            rec.mass = MassData(0.0, 0.0, computed.center)
            self.mass_epoch += 1
            return
        md = dynamic_mass(computed, rb.mass, rb.fixed_rotation)
        rec.mass = md
        self.mass_epoch += 1
        set_mass(body, md)

    def _rebuild_poses(self) -> None:
        """Re-slot the entities whose body or components came, went or changed type.

        Only those are looked at (:meth:`PoseTable.update`), so a few bodies spawned
        or despawned in a world of thousands cost a few numpy copies of the table
        instead of a pass over every body. Every other slot keeps its components:
        each Transform or RigidBody that comes or goes (a replacement too) passes
        the world hooks above, which mark its entity here.
        """
        changed = self._pose_dirty
        self._pose_dirty = set()
        bodies = self.bodies
        items = []
        for e in changed:
            r = bodies.get(e)
            if r is not None and not r.implicit and r.body.body_type != STATIC:
                items.append((e, r.body))
        reslot = self.poses.update(changed, items)
        world = self.world
        tfs = [world.try_get(e, Transform) for e, _ in items]
        rbs = [world.try_get(e, RigidBody) for e, _ in items]
        self._targets.reslot(reslot, tfs, rbs)
        self.poses_stale = False

    # -- step ------------------------------------------------------------------------------
    def _busy(self) -> bool:
        """Is any change waiting to be applied (anything that could wake a body)?"""
        return bool(self.touched or self.forces or self._pending_changes())

    def _pending_changes(self) -> bool:
        """Will sync-in change a body (the dirty sets, the pose table, no-sleep bodies)?"""
        return bool(
            self.poses_stale or self.no_sleep or self.body_struct or self.collider_struct
            or self.pending or self.rb_dirty or self.col_dirty or self.tf_dirty
            or self.mass_dirty or self.ccd_dirty
        )

    def step(self) -> None:
        """sync-in, substeps, joints read-back, sync-out (events are recorded meanwhile).

        When every body was asleep after the last step and nothing has touched the
        world since, no body can move during this one: sleeping islands only wake
        through an awake body or a change made from outside. The step then skips the
        bulk reads of continuous collision and sync-out, so a world at rest costs
        almost nothing however many bodies it holds.
        """
        applied = self._applied
        idle = not self._busy()
        quiet = self.all_asleep and idle and not self.joints.handles
        fresh, self.fresh_read = self.fresh_read, None
        if fresh is not None and self._pending_changes():
            fresh = None  # sync-in is about to change bodies
        self.sync_in()
        unchanged = self._applied is applied
        quiet = quiet and unchanged
        self.touched = False
        self.events_step_started()
        n = self.substeps
        h = self.dt / n
        # nothing touched a body since the last sync-out: its bulk read is current; or
        # only bulk impulses did, and they kept theirs current
        last = self.poses.raw if idle and unchanged else (fresh if unchanged else None)
        first = self.contact_first
        # velocities set from outside meet their contacts first (Box2D's order)
        if first.pushed and first.solve(self.space, h):
            last = None
        rec = self.recorder
        toi = rec.toi
        toi.clear()
        toi.update(first.current)
        if self.bullets:
            toi.update(self.bullets)
        self.joints.before_step(self.dt, last)
        if self.ccd is not None and not quiet:
            self.ccd.before_step(self.dt, n, last)
        forces = self.forces
        # Box2D's speed caps before every substep (see kge.physics.speed_cap); the
        # first one's velocities were capped by sync-in, sync-out and the CCD's read
        cap = None if quiet else self._speed_cap
        s = self.settings
        vmax, wmax = s.max_translation / self.dt, s.max_rotation / self.dt
        known = self.poses.by_id()
        drain = self.joints.drain
        drained = drain.start(self.space)  # joints starting from zero impulse
        for i in range(n):
            rec.begin_substep(i, h)
            if cap is not None and i:
                cap.before_substep(self.space, known, vmax, wmax)
            if forces:
                self._apply_forces()
            self.space.step(h)
            if drained:
                drain.end(drained)
                drained = []
        forces.clear()
        rec.substep = 0
        first.end_step()
        self.steps += 1
        self.out_read = None
        self.joints.after_step(self.dt)
        out, self.out_read = self.out_read, None
        if quiet:
            if not self._prev_is_current:  # at rest: no interpolation (copied once)
                self.poses.prev[:] = self.poses.state[:, :3]
                self._prev_is_current = True
        else:
            self._prev_is_current = False
            self.sync_out(out)
        self.events.sort()  # Chipmunk's order follows addresses (kge.physics.events)
        self.errors.raise_pending()
        rec.deliver_post_solve()

    def _apply_forces(self) -> None:
        """Box2D forces act for the whole step; pymunk clears them every substep."""
        for e in sorted(self.forces):
            rec = self.bodies.get(e)
            if rec is None or not rec.in_space or rec.body.body_type != DYNAMIC:
                continue
            fx, fy, tq = self.forces[e]
            rec.body.force = (fx, fy)
            rec.body.torque = tq

    def events_step_started(self) -> None:
        self.recorder.begin_step()

    # -- sync-out -------------------------------------------------------------------------
    def sync_out(self, raw: tuple[np.ndarray, np.ndarray] | None = None) -> None:
        """Read every moving body once and write the ones that changed to their
        components (:meth:`_write_out`); then Box2D's sleep rule for jointed islands."""
        self._write_out(raw)
        if self.joints.handles or self.rest.pushed:
            self._rest_check()

    def _rest_check(self) -> None:
        """Put to sleep the jointed or pushed islands whose bodies all rested for
        time_to_sleep (kge.physics.rest: the joints' passes, forces and impulses restart
        Chipmunk's own timer)."""
        s = self.settings
        if not s.sleep or self.poses_stale:
            return
        blockers = self._rest_blockers
        joints = self.joints

        def watched() -> list[int]:
            return [*joints.restless_bodies(), *blockers]

        poses = self.poses
        due = self.rest.tick(poses, self.dt, s.sleep_speed, s.time_to_sleep, watched,
                             joints.restless_epoch + self._rest_epoch)
        if not due:
            return
        looked: set[pymunk.Body] = set()  # searched already this step
        threshold = s.time_to_sleep - 1e-9
        blocker: list[pymunk.Body] = []

        def rested(body: pymunk.Body) -> bool:
            e = self.body_entities.get(body)
            i = None if e is None else poses.slot.get(e)
            ok = (
                i is not None and e not in self.no_sleep and poses.bodies[i] is body
                and bool(poses.rest[i] >= threshold)
            )
            if not ok:
                blocker.append(body)
            return ok

        for i in due:
            body = poses.bodies[i]
            e = int(poses.entities[i])
            blockers.discard(e)
            rec = self.bodies.get(e)
            if body in looked or e in self.no_sleep or rec is None or not rec.awake:
                continue
            blocker.clear()
            island = sleep_island(self.space, body, rested, looked)
            for member in island:
                self._mark_asleep(self.body_entities[member])
            if not island:
                # wait for what kept it awake to rest as long (its clock is watched)
                for other in blocker:
                    other_e = self.body_entities.get(other)
                    if other_e is not None and other_e not in blockers:
                        blockers.add(other_e)
                        self._rest_epoch += 1

    def _write_out(self, raw: tuple[np.ndarray, np.ndarray] | None = None) -> None:
        """Read every moving body once and write the ones that changed to their components.

        ``raw``: a bulk read of the whole space that is still current (the joints'
        after-step read, their position pass's moves patched in), instead of a new one.

        Its fixed cost is a few dozen numpy calls, which is what a small world (a
        few bodies) pays per step, so the common cases take the short way:
        the exact speed cap only after a cheap bound says a body may be over it,
        and when every tracked body moved (an awake world) no mask and no gather.
        """
        if self.poses_stale:
            self._rebuild_poses()
        poses = self.poses
        slots, rows = poses.read(self.space, raw)
        if len(slots) == 0:
            self.all_asleep = len(poses.dynamic) == 0
            return
        s = self.settings
        vmax = s.max_translation / self.dt
        wmax = s.max_rotation / self.dt
        if maybe_over(rows[:, 3:6], vmax, wmax):
            self._cap_rows(slots, rows, vmax, wmax)
        state = poses.state
        poses.prev[:] = state[:, :3]
        if poses.full:  # ``rows`` is a fresh gather in slot order: it becomes the state
            old = state
            poses.state = rows
        else:
            old = state[slots]
            state[slots] = rows
        changed = rows_differ(rows, old)
        targets = self._targets
        if poses.full and changed.all():  # everything moved (rain, a small world): no gathers
            write_poses(targets, None, rows)
            self._write_velocities(None, rows, old)
            if poses.asleep.any():
                self._woke(slots)
            self.all_asleep = False
            return
        if changed.any():
            # (rewriting every Transform when most moved, with the unchanged ones' own
            # values, measured slower and far noisier than this gather: 7.0-7.7 vs
            # 7.5-12.5 ms on sparse-20000, five processes each)
            write_poses(targets, slots[changed], rows[changed])
            self._write_velocities(slots, rows, old)
            if poses.asleep.any():
                self._woke(slots[changed])
        still = slots[~changed & ~poses.asleep[slots] & poses.dynamic[slots]]
        if len(still):
            for i in still.tolist():
                body = poses.bodies[i]
                if body.is_sleeping:
                    poses.asleep[i] = True
                    self.bodies[int(poses.entities[i])].awake = False
                    rb = self._targets.rigidbodies[0][i]
                    if rb is not None:
                        raw_set(rb, "awake", False)
                        raw_set(rb, "velocity", (0.0, 0.0))
                        raw_set(rb, "angular_velocity", 0.0)
        self.all_asleep = bool(poses.dynamic.all() and poses.asleep.all())

    def _write_velocities(
        self, slots: np.ndarray | None, rows: np.ndarray, old: np.ndarray
    ) -> None:
        """The RigidBodies whose velocities changed since the last step (``slots`` None:
        ``rows`` is every slot in order).

        A crowd drifting without gravity keeps its velocities and writes none; a few
        collisions in it write a few (one compare first; -0.0 == 0.0 is the only change
        it ignores). Only rows that changed are written: a sleeper's RigidBody holds
        zero while its row keeps the speed it fell asleep at.
        """
        if (rows[:, 3:6] == old[:, 3:6]).all():
            return
        if slots is not None or len(rows) > _FEW:
            vel = columns_differ(rows, old, 3, 6)
            if not vel.all():
                moved = np.flatnonzero(vel) if slots is None else slots[vel]
                write_velocities(self._targets, moved, rows[vel])
                return
        write_velocities(self._targets, slots, rows)

    def _cap_rows(self, slots: np.ndarray, rows: np.ndarray, vmax: float, wmax: float) -> None:
        """Box2D's speed caps on the rows read (a gathered copy) and on their bodies."""
        capped = clamp(rows[:, 3:6], vmax, wmax).tolist()
        if capped:  # the bulk read no longer holds these bodies' velocities
            self.poses.raw = None
        for k in capped:
            body = self.poses.bodies[int(slots[k])]
            vx, vy, w = rows[k, 3:6].tolist()
            body.velocity = (vx, vy)
            body.angular_velocity = w

    def _woke(self, moved: np.ndarray) -> None:
        """The RigidBodies of sleepers that moved are awake again."""
        poses = self.poses
        rbs, has_rb = self._targets.rigidbodies
        for i in moved[has_rb[moved] & poses.asleep[moved]].tolist():
            poses.asleep[i] = False
            raw_set(rbs[i], "awake", True)
            self.bodies[int(poses.entities[i])].awake = True

    # -- teardown ---------------------------------------------------------------------------
    def close(self) -> None:
        for rec in list(self.bodies.values()):
            if rec.in_space:
                rec.in_space = False
        self.bodies.clear()
        self.body_entities.clear()
        self.colliders.clear()
        self.pending.clear()


def _make_ccd(space: pymunk.Space, errors: CallbackErrors, shapes: ShapeTable) -> Any:
    """Continuous collision (kge.physics.ccd) when available; None otherwise."""
    try:
        from kge.physics.ccd import ContinuousCollision
    except ImportError:  # pragma: no cover - the module ships with kge
        return None
    return ContinuousCollision(space, errors=errors, shapes=shapes)
