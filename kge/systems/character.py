"""``CharacterSystem``: moves every :class:`~kge.components.character.CharacterBody`.

It runs in the fixed step's ``"characters"`` set (:data:`CHARACTERS`, which the plugin
adds): after the behaviours' ``on_fixed_update`` (``SCRIPTS``, where a game sets
``velocity`` and ``jump``) and ``PRE_PHYSICS`` (where tweens and game systems set the
velocities of platforms and lifts), before the physics step (``PHYSICS``). It moves each
character with collide-and-slide (:mod:`kge.character`), hands the move to the
character's kinematic body as a velocity (``Physics.set_velocities``, one call for
all), writes the contact flags back into the components and pushes the dynamic
bodies it walked into. Physics then moves the kinematic bodies exactly there, so
dynamic bodies, sensors, ray casts and drawing (interpolated) see the character as a
body. ``CharacterSensorSystem`` (``PHYSICS``, after the step, before events are
delivered in ``PHYSICS_EVENTS``) reports the static and kinematic sensors characters
enter and leave, which physics does not (Box2D's bodies of those kinds do not meet
sensors).

The plugin gives a new character what it lacks: a kinematic ``RigidBody`` and a
``Collider`` of its shape (a capsule's is a 14-sided polygon). It refuses a character
on a body that is static or dynamic, at the call that makes it.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from kge.character.batch import read
from kge.character.bodies import Bodies
from kge.character.contacts import collides
from kge.character.grid import Grid
from kge.character.narrowphase import signed_distance
from kge.character.obstacles import CELL, DYNAMIC, WATCHED, Obstacles, Pieces
from kge.character.step import Stepper
from kge.components.character import CharacterBody, CharacterShape
from kge.components.collider import Collider
from kge.components.filter import Filter
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import LINEAR_SLOP, Box, Circle, Polygon
from kge.components.tracked import NoMarks, bind
from kge.components.transform import Transform
from kge.errors import ValidationError, where
from kge.physics.events import PhysicsEvents, SensorBegin, SensorEnd
from kge.physics.resource import Physics
from kge.physics.settings import PhysicsSettings
from kge.physics.writeback import set_all, slot_setter
from kge.plugin import Plugin
from kge.schedule import Stage, System, SystemSet
from kge.systems.physics import PhysicsPlugin, PhysicsSystem
from kge.world import World, stored_resource

#: the fixed step's set of the character system: after ``PRE_PHYSICS`` (where tweens and
#: game systems set the velocities of platforms and lifts), before the physics step
CHARACTERS = "characters"
_DEFAULT_BITS = (Filter().category_bits, Filter().mask_bits, Filter().group_index)
#: the read-back fields and their column in a step's result
_WRITES = {
    name: slot_setter(CharacterBody, name)
    for name in ("velocity", "on_floor", "on_wall", "on_ceiling", "floor_normal", "wall_normal",
                 "ceiling_normal", "floor_collider", "wall_collider", "floor_velocity",
                 "jumped", "landed",
                 "hard_landing", "landing_speed")
}
_SET_X = slot_setter(Transform, "x")
_SET_Y = slot_setter(Transform, "y")
#: sides of each half disc of a capsule's collider polygon
_CAPSULE_SIDES = 6


def collider_shape(shape: CharacterShape, skin: float = 0.01) -> Circle | Box | Polygon:
    """The collider shape physics gives a character: its own shape, for a capsule a
    polygon through its outline (14 vertices; Box2D's polygons allow 16), polygons
    drawn in by ``skin`` (``PhysicsSettings.polygon_radius``) so that with the skin
    physics puts round them they are the character's shape. The collider never reaches
    past the shape, so what the character stops against, physics never sees it
    overlap (only the character system pushes what it walks into).

    >>> from kge import Box, Capsule
    >>> len(collider_shape(Capsule(0.3, 0.9)).vertices)
    14
    >>> collider_shape(Box(0.4, 0.9))
    Box(half_width=0.39, half_height=0.89, center=(0.0, 0.0), angle=0.0)
    """
    if isinstance(shape, Circle):
        return shape
    if isinstance(shape, Box):
        return Box(max(shape.half_width - skin, LINEAR_SLOP),
                   max(shape.half_height - skin, LINEAR_SLOP), shape.center, shape.angle)
    (_, a0), (_, a1) = shape.segment
    r = shape.radius
    if a1 - a0 < 1e-6:
        return Circle(r)
    r = max(r - skin, LINEAR_SLOP)
    pts = []
    for k in range(_CAPSULE_SIDES + 1):  # bottom half disc, left to right
        t = math.pi + math.pi * k / _CAPSULE_SIDES
        pts.append((r * math.cos(t), a0 + r * math.sin(t)))
    for k in range(_CAPSULE_SIDES + 1):  # top half disc, right to left
        t = math.pi * k / _CAPSULE_SIDES
        pts.append((r * math.cos(t), a1 + r * math.sin(t)))
    return Polygon([(round(x, 12) + 0.0, round(y, 12) + 0.0) for x, y in pts])


def _sibling(world: World, entity: int | None, ctype: type) -> Any:
    """The ``ctype`` component the entity has, or is being spawned with."""
    if entity is not None:
        return world.try_get(entity, ctype)
    return next((c for c in world.spawning if type(c) is ctype), None)


class CharacterSystem(System):
    """Moves the characters (fixed stage, between the behaviours and physics)."""

    stage = Stage.FIXED
    in_set = CHARACTERS

    def attach(self, world: World) -> None:
        super().attach(world)
        #: what characters collide with; made at the first step that has a character, so a
        #: world without any pays nothing for tracking its colliders
        self._obstacles: Obstacles | None = None
        #: bindings that only run the world's validators on RigidBody.type writes
        self._marks = NoMarks()
        self.stepper = Stepper()
        world.insert_resource(self.stepper.state)  # (snapshots carry it)
        #: characters whose collider the plugin added: (collider, the shape it was made for)
        self.auto: dict[int, tuple[Collider, CharacterShape]] = {}
        #: the characters (entity, body, transform, rigid body, collider) by entity, made
        #: again when one of those components comes or goes on a character (hooks below)
        self._roster: list[tuple[int, CharacterBody, Transform, Any, Any]] | None = None
        self._members: set[int] = set()
        #: collision bits by Filter object (filters are frozen; assigning one replaces it)
        self._bits: dict[int, tuple[Any, tuple[int, int, int]]] = {}
        world.on_add(CharacterBody, self._character_added)
        world.on_add(CharacterBody, self._forget_roster)
        world.on_remove(CharacterBody, self._character_removed)
        for ctype in WATCHED:  # (registered here, with the system, even before obstacles)
            world.on_add(ctype, self._obstacle_added)
            world.on_remove(ctype, self._obstacle_removed)
        world.on_add(RigidBody, self._rigidbody_added)
        for ctype in (RigidBody, Collider, Transform):
            world.on_add(ctype, self._part_changed)
            world.on_remove(ctype, self._part_changed)
        world.validator(CharacterBody, self._check_character)
        world.validator(RigidBody, self._check_rigidbody)

    # -- the entity of a character --------------------------------------------------------------
    def _check_character(self, entity: int | None, body: CharacterBody) -> None:
        rb = _sibling(self.world, entity, RigidBody)
        if rb is not None and rb.type is not BodyType.KINEMATIC:
            raise ValidationError(
                f"{where(entity, 'CharacterBody')}: a character moves a kinematic body, but "
                f"this entity's RigidBody is {rb.type.name} (use "
                "RigidBody(type=BodyType.KINEMATIC), or leave the RigidBody out: one is added)"
            )

    def _check_rigidbody(self, entity: int | None, rb: RigidBody) -> None:
        if rb.type is BodyType.KINEMATIC:
            return
        if _sibling(self.world, entity, CharacterBody) is not None:
            raise ValidationError(
                f"{where(entity, 'RigidBody.type')}: this entity is a character "
                f"(CharacterBody), whose body must stay KINEMATIC, not {rb.type.name} "
                "(remove the CharacterBody first to make it a simulated body)"
            )

    def _character_added(self, entity: int, body: CharacterBody) -> None:
        world = self.world
        # inside the spawn that brings the character, the components still to come count
        coming = world.spawning if any(c is body for c in world.spawning) else ()
        if world.try_get(entity, RigidBody) is None and not any(
            type(c) is RigidBody for c in coming
        ):
            world.add(entity, RigidBody(type=BodyType.KINEMATIC))
        if world.try_get(entity, Collider) is None and not any(type(c) is Collider for c in coming):
            col = Collider(collider_shape(body.shape, self._skin()), friction=0.0)
            world.add(entity, col)
            self.auto[entity] = (col, body.shape)
        rb = world.try_get(entity, RigidBody)
        if rb is not None:
            bind(rb, entity, self._marks, world.validate)

    @property
    def obstacles(self) -> Obstacles:
        if self._obstacles is None:
            self._obstacles = Obstacles(self.world, self._skin())
        return self._obstacles

    def _skin(self) -> float:
        settings = self.world.try_resource(PhysicsSettings)
        return (settings or PhysicsSettings()).polygon_radius

    def _forget_roster(self, entity: int, body: CharacterBody) -> None:
        self._roster = None

    def _obstacle_added(self, entity: int, component: Any) -> None:
        if self._obstacles is not None:
            self._obstacles.added(entity, component)

    def _obstacle_removed(self, entity: int, component: Any) -> None:
        if self._obstacles is not None:
            self._obstacles.removed(entity, component)

    def _character_removed(self, entity: int, body: CharacterBody) -> None:
        self.auto.pop(entity, None)
        self._roster = None

    def _part_changed(self, entity: int, component: Any) -> None:
        if entity in self._members or self.world.try_get(entity, CharacterBody) is not None:
            self._roster = None
            made = self.auto.get(entity)
            if made is not None and made[0] is component:  # the game gave it another
                del self.auto[entity]

    def _characters(self) -> list[tuple[int, CharacterBody, Transform, Any, Any]]:
        roster = self._roster
        if roster is None:
            world = self.world
            roster = sorted(
                ((e, body, t, world.try_get(e, RigidBody), world.try_get(e, Collider))
                 for e, (body, t) in world.query(CharacterBody, Transform)),
                key=lambda row: row[0],
            )
            self._roster = roster
            self._members = {row[0] for row in roster}
        return roster

    def _bits_of(self, col: Collider | None) -> tuple[int, int, int]:
        if col is None:
            return _DEFAULT_BITS
        f = col.filter
        found = self._bits.get(id(f))
        if found is None or found[0] is not f:
            if len(self._bits) > 1024:
                self._bits.clear()
            found = self._bits[id(f)] = (f, (f.category_bits, f.mask_bits, f.group_index))
        return found[1]

    def _rigidbody_added(self, entity: int, rb: RigidBody) -> None:
        if self.world.try_get(entity, CharacterBody) is not None:
            bind(rb, entity, self._marks, self.world.validate)
            self._roster = None

    # -- the step -------------------------------------------------------------------------------
    def process(self, dt: float) -> None:
        world = self.world
        physics = world.try_resource(Physics)
        if physics is None:
            return
        settings = world.resource(PhysicsSettings)
        roster = self._characters()
        if not roster:
            return
        movers = [row for row in roster if row[3] is None or row[3].enabled]
        bits = [self._bits_of(row[4]) for row in movers]
        auto = self.auto
        for e, body, *_ in movers:
            made = auto.get(e)
            if made is not None and body.shape is not made[1] and body.shape != made[1]:
                # a new shape: a new collider
                made[0].shape = collider_shape(body.shape, settings.polygon_radius)
                auto[e] = (made[0], body.shape)
        if not movers:
            return
        if self.obstacles.skin != settings.polygon_radius:
            self.obstacles.reskin(settings.polygon_radius)
        self.obstacles.refresh()
        ents = [m[0] for m in movers]
        batch = read(ents, [m[1] for m in movers], [(m[2].x, m[2].y) for m in movers], bits)
        moving = self.obstacles.moving
        bodies = Bodies(physics, world, moving.owners, moving.owner_kind, dt)
        self.obstacles.place(bodies.end)
        result = self.stepper.advance(
            batch, batch.entity, self.obstacles, bodies, settings.gravity, dt,
            settings.max_translation, physics,
        )
        pos = result.pos
        bad = ~np.isfinite(pos).all(axis=1)
        if bad.any():  # (never expected) keep such a character where it was
            pos[bad] = batch.pos[bad]
            result.velocity[bad] = 0.0
        motion = (pos - batch.pos) / dt
        # the kinematic bodies whose velocity changes (one walking steadily keeps its own)
        now = [(0.0, 0.0) if m[3] is None else m[3].velocity for m in movers]
        held = np.array(now, dtype=np.float64).reshape(-1, 2)
        change = [k for k in np.flatnonzero((held != motion).any(axis=1)).tolist()
                  if movers[k][3] is not None]
        if change:
            physics.set_velocities([ents[k] for k in change], motion[change])
        for k, m in enumerate(movers):
            if m[3] is None:  # no body (removed by the game): the character is moved directly
                _SET_X(m[2], float(pos[k, 0]))
                _SET_Y(m[2], float(pos[k, 1]))
        self._write(batch, result)
        ents_i, imps, pts = result.impulses
        if len(ents_i):
            physics.apply_linear_impulses(ents_i.tolist(), imps, pts)

    def _write(self, batch: Any, r: Any) -> None:
        """The read-back fields, row by row only where they changed since they were last
        written (most characters' flags stay the same from one step to the next)."""
        bodies = batch.bodies
        state = self.stepper.state
        slots = self.stepper.slots  # (the rows advance() just used)
        ids = np.fromiter(map(id, bodies), np.int64, len(bodies))
        fresh = state["component"][slots] != ids  # a component never written to
        state["component"][slots] = ids
        moved = fresh | (r.velocity != batch.velocity).any(axis=1)
        _write_changed(bodies, "velocity", r.velocity, moved)
        flags = (r.on_floor.astype(np.int64) | r.on_wall << 1 | r.on_ceiling << 2
                 | r.jumped << 3 | r.landed << 4 | r.hard_landing << 5)
        old = state["shown_flags"][slots]
        changed = (old != flags) | fresh
        for bit, name in enumerate(("on_floor", "on_wall", "on_ceiling", "jumped", "landed",
                                    "hard_landing")):
            mask = changed & (((old ^ flags) >> bit) & 1 | fresh).astype(bool)
            rows = np.flatnonzero(mask)
            if len(rows):
                values = ((flags[rows] >> bit) & 1).astype(bool).tolist()
                set_all(_WRITES[name], [bodies[k] for k in rows.tolist()], values)
        state["shown_flags"][slots] = flags
        for name, column, values in (("floor_collider", "shown_collider", r.floor_collider),
                                     ("wall_collider", "shown_wall_collider", r.wall_collider)):
            mask = fresh | (state[column][slots] != values)
            changed_rows = np.flatnonzero(mask).tolist()
            if changed_rows:
                entities = [None if e < 0 else e for e in values[changed_rows].tolist()]
                set_all(_WRITES[name], [bodies[k] for k in changed_rows], entities)
            state[column][slots] = values
        mask = fresh | (state["shown_landing"][slots] != r.landing_speed)
        changed_rows = np.flatnonzero(mask).tolist()
        if changed_rows:
            set_all(_WRITES["landing_speed"], [bodies[k] for k in changed_rows],
                    r.landing_speed[changed_rows].tolist())
        state["shown_landing"][slots] = r.landing_speed
        for name, column, values in (("floor_normal", "shown_floor_n", r.floor_normal),
                                     ("wall_normal", "shown_wall_n", r.wall_normal),
                                     ("ceiling_normal", "shown_ceiling_n", r.ceiling_normal),
                                     ("floor_velocity", "shown_floor_v", r.floor_velocity)):
            x, y = state[column], state[column + "_y"]
            mask = fresh | (x[slots] != values[:, 0]) | (y[slots] != values[:, 1])
            _write_changed(bodies, name, values, mask)
            x[slots] = values[:, 0]
            y[slots] = values[:, 1]

    def detach(self) -> None:
        if self._obstacles is not None:
            self._obstacles.close()


def _write_changed(bodies: list[CharacterBody], name: str, values: np.ndarray,
                   mask: np.ndarray) -> None:
    """``body.<name> = values[k]`` (an (x, y) pair) for the rows ``mask`` selects."""
    rows = np.flatnonzero(mask).tolist()
    if rows:
        v = values[rows]
        set_all(_WRITES[name], [bodies[k] for k in rows],
                list(zip(v[:, 0].tolist(), v[:, 1].tolist(), strict=True)))


class CharacterSensorSystem(System):
    """Reports the static and kinematic sensors characters enter and leave, as
    ``SensorBegin`` / ``SensorEnd`` events of the step (``world.events(SensorBegin)``,
    ``on_sensor_begin`` / ``on_sensor_end``), delivered with the physics events."""

    stage = Stage.FIXED
    in_set = SystemSet.PHYSICS
    after = (PhysicsSystem,)

    def process(self, dt: float) -> None:
        world = self.world
        mover = world.get_system(CharacterSystem)
        events = stored_resource(world, PhysicsEvents)
        physics = world.try_resource(Physics)
        if mover is None or events is None or physics is None:
            return
        known = mover.stepper.state.sensors
        found = world.query(CharacterBody, Transform)
        if not found and not known:
            return
        found.sort(key=lambda item: item[0])
        now: dict[int, set[tuple[int, int]]] = {}
        bodies_of: dict[tuple[int, int], int | None] = {}
        if found:
            obstacles = mover.obstacles
            obstacles.refresh()
            if obstacles.static.sensor.any() or obstacles.moving.sensor.any():
                now = self._overlaps(found, obstacles, physics, dt, bodies_of)
        begins: list[SensorBegin] = []
        ends: list[SensorEnd] = []
        for e in sorted(set(known) | set(now)):
            before = known.get(e, set())
            after = now.get(e, set())
            for col, child in sorted(after - before):
                body = bodies_of.get((col, child))
                begins.append(SensorBegin(col, e, body, e, child, 0))
            for col, child in sorted(before - after):
                body = self._body_of(col)
                ends.append(SensorEnd(col, e, body, e, child, 0))
        known.clear()
        known.update({e: s for e, s in now.items() if s})
        if begins or ends:
            events.sensor_begin.extend(begins)
            events.sensor_end.extend(ends)
            events.sort()

    def _body_of(self, collider: int) -> int | None:
        col = self.world.try_get(collider, Collider)
        if col is None:
            return None
        if col.body is not None:
            return col.body
        return collider if self.world.try_get(collider, RigidBody) is not None else None

    def _overlaps(self, found: list[Any], obstacles: Obstacles, physics: Any, dt: float,
                  bodies_of: dict[tuple[int, int], int | None]
                  ) -> dict[int, set[tuple[int, int]]]:
        world = self.world
        ents = [e for e, _ in found]
        bits = []
        for e in ents:
            col = world.try_get(e, Collider)
            f = None if col is None else col.filter
            bits.append(_DEFAULT_BITS if f is None else (f.category_bits, f.mask_bits,
                                                         f.group_index))
        batch = read(ents, [b for _, (b, _) in found], [(t.x, t.y) for _, (_, t) in found], bits)
        moving = obstacles.moving
        if len(moving) and moving.sensor.any():
            states = Bodies(physics, world, moving.owners, moving.owner_kind, dt)
            obstacles.place(states.pose)  # where the step left them
        qlo, qhi = batch.pos + batch.lo, batch.pos + batch.hi
        out: dict[int, set[tuple[int, int]]] = {}
        for pieces, grid in ((obstacles.static, obstacles.static.grid), (moving, None)):
            if len(pieces) == 0 or not pieces.sensor.any():
                continue
            if grid is None:
                lo, hi = pieces.bounds()
                grid = Grid(lo, hi, CELL)
            c, p = grid.pairs(qlo, qhi)
            keep = pieces.sensor[p] & (pieces.kind[p] != DYNAMIC) & collides(
                batch.bits[c], pieces.bits[p]
            )
            c, p = c[keep], p[keep]
            if len(c) == 0:
                continue
            sd = _distances(batch, c, pieces, p)
            inside = sd < 0.0
            for ci, pi in zip(c[inside].tolist(), p[inside].tolist(), strict=True):
                key = (int(pieces.collider[pi]), int(pieces.child[pi]))
                body = int(pieces.body[pi])
                bodies_of[key] = None if body < 0 else body
                out.setdefault(int(batch.entity[ci]), set()).add(key)
        return out


def _distances(batch: Any, c: np.ndarray, pieces: Pieces, p: np.ndarray) -> np.ndarray:
    a = batch.vertices(c, batch.pos[c])
    simple = (pieces.count[p] <= 2) & batch.small[c]
    return signed_distance(a, batch.radius[c], pieces.gather(p), pieces.radius[p], simple)[0]


class CharacterPlugin(Plugin):
    """Characters that collide and slide (:class:`~kge.components.character.CharacterBody`):
    :class:`CharacterSystem` and :class:`CharacterSensorSystem`, in the fixed step."""

    requires = (PhysicsPlugin,)

    def build(self, world: World) -> None:
        if CHARACTERS not in world.schedule.sets(Stage.FIXED):
            world.schedule.add_set(CHARACTERS, Stage.FIXED, after=[SystemSet.PRE_PHYSICS],
                                   before=[SystemSet.PHYSICS])
        world.add_system(CharacterSystem())
        world.add_system(CharacterSensorSystem())
