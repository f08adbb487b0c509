"""What characters collide with: every collider's pieces, kept in numpy arrays.

The world's colliders are read from their components (no pymunk), one
:class:`Record` per collider entity, rebuilt only when something about that
collider changed: the world's add/remove hooks and the write tracking of
``Collider``, ``OneWayPlatform``, ``RigidBody`` and ``Transform`` name the entities
touched (:mod:`kge.components.tracked`). Pieces of static colliders are kept in world
coordinates with a grid over them (:class:`~kge.character.grid.Grid`), rebuilt only
when a static collider changes; pieces of kinematic and dynamic bodies are kept in
their body's frame and placed every step from the bodies' poses, read in bulk
(``Physics.states``). Kinematic bodies are placed where the step will leave them
(their velocity is all that moves them), so a character meets a moving platform
where it will be.

Colliders of character bodies are left out: characters meet each other through
their :class:`~kge.components.character.CharacterBody` shapes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from kge.character.grid import Grid
from kge.character.shapes import collider_pieces
from kge.components.character import CharacterBody
from kge.components.collider import Collider
from kge.components.platform import OneWayPlatform
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.tracked import bind, unbind
from kge.components.transform import Transform
from kge.world import World

STATIC, KINEMATIC, DYNAMIC = 0, 1, 2
_KIND = {BodyType.STATIC: STATIC, BodyType.KINEMATIC: KINEMATIC, BodyType.DYNAMIC: DYNAMIC}
#: grid cell, metres: about a character's size
CELL = 2.0
#: components whose writes can change what characters meet (tracked for writes; the
#: Transforms of static colliders' owners too, bound while they own one)
_TRACKED = (Collider, OneWayPlatform, RigidBody)
#: components whose arrival or departure can change what characters meet
WATCHED = (*_TRACKED, Transform, CharacterBody)


@dataclass(slots=True)
class Record:
    """One collider's pieces and what decides how characters meet them."""

    collider: int
    owner: int  #: the entity whose pose places the pieces (the body, or the collider)
    body: int  #: the body entity, -1 for the implicit static body
    kind: int
    shape: Any
    skin: float
    sensor: bool
    bits: tuple[int, int, int]  #: (category, mask, group)
    oneway: tuple[float, float, float] | None  #: (up x, up y, min cos)
    pose: tuple[float, float, float]  #: static pieces: where they were placed


@dataclass(slots=True)
class Pieces:
    """Many colliders' convex pieces, flat: piece i owns ``count[i]`` vertices of
    ``local`` (and of ``world``, where they are now) from ``start[i]``."""

    local: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))
    start: np.ndarray = field(default_factory=lambda: np.zeros(0, np.int64))
    count: np.ndarray = field(default_factory=lambda: np.zeros(0, np.int64))
    radius: np.ndarray = field(default_factory=lambda: np.zeros(0))
    collider: np.ndarray = field(default_factory=lambda: np.zeros(0, np.int64))
    body: np.ndarray = field(default_factory=lambda: np.zeros(0, np.int64))
    child: np.ndarray = field(default_factory=lambda: np.zeros(0, np.int64))
    kind: np.ndarray = field(default_factory=lambda: np.zeros(0, np.int8))
    sensor: np.ndarray = field(default_factory=lambda: np.zeros(0, bool))
    bits: np.ndarray = field(default_factory=lambda: np.zeros((0, 3), np.int64))
    oneway: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))  #: NaN: not one-way
    #: per vertex: the row of its owner in ``owners`` (moving pieces)
    vertex_owner: np.ndarray = field(default_factory=lambda: np.zeros(0, np.int64))
    owners: np.ndarray = field(default_factory=lambda: np.zeros(0, np.int64))
    owner_kind: np.ndarray = field(default_factory=lambda: np.zeros(0, np.int8))
    world: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))
    grid: Grid | None = None

    def __len__(self) -> int:
        return len(self.start)

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Each piece's bounding box (lo, hi), radius included, from ``world``."""
        if len(self) == 0:
            return np.zeros((0, 2)), np.zeros((0, 2))
        lo = np.minimum.reduceat(self.world, self.start, axis=0) - self.radius[:, None]
        hi = np.maximum.reduceat(self.world, self.start, axis=0) + self.radius[:, None]
        return lo, hi

    def gather(self, rows: np.ndarray) -> np.ndarray:
        """World vertices of pieces ``rows`` as (P, n, 2), short lists padded by repeating
        their last vertex (which adds zero-length sides only)."""
        if len(rows) == 0:
            return np.zeros((0, 1, 2))
        count = self.count[rows]
        n = int(count.max())
        idx = self.start[rows][:, None] + np.minimum(np.arange(n), count[:, None] - 1)
        return self.world[idx]


def _concat(records: list[Record], moving: bool) -> Pieces:
    """The pieces of ``records`` in one :class:`Pieces` (in the order given)."""
    if not records:
        return Pieces()
    flats, counts, radii, children, per_piece = [], [], [], [], []
    owners: list[int] = []
    owner_kinds: list[int] = []
    owner_row: dict[int, int] = {}
    vertex_owner = []
    for rec in records:
        flat, count, radius, child = collider_pieces(rec.shape, rec.skin)
        if not moving:
            flat = _place(flat, rec.pose)
        flats.append(flat)
        counts.append(count)
        radii.append(radius)
        children.append(child)
        per_piece.append(len(count))
        if moving:
            row = owner_row.get(rec.owner)
            if row is None:
                row = owner_row[rec.owner] = len(owners)
                owners.append(rec.owner)
                owner_kinds.append(rec.kind)
            vertex_owner.append(np.full(len(flat), row, np.int64))
    n = np.array(per_piece)
    count = np.concatenate(counts)
    start = np.cumsum(count) - count
    oneway = np.array([r.oneway if r.oneway is not None else (math.nan,) * 3 for r in records])
    local = np.concatenate(flats)
    out = Pieces(
        local=local,
        start=start,
        count=count,
        radius=np.concatenate(radii),
        collider=np.repeat(np.array([r.collider for r in records], np.int64), n),
        body=np.repeat(np.array([r.body for r in records], np.int64), n),
        child=np.concatenate(children),
        kind=np.repeat(np.array([r.kind for r in records], np.int8), n),
        sensor=np.repeat(np.array([r.sensor for r in records]), n),
        bits=np.repeat(np.array([r.bits for r in records], np.int64), n, axis=0),
        oneway=np.repeat(oneway, n, axis=0),
    )
    if moving:
        out.vertex_owner = np.concatenate(vertex_owner)
        out.owners = np.array(owners, np.int64)
        out.owner_kind = np.array(owner_kinds, np.int8)
    else:
        out.world = local
        lo, hi = out.bounds()
        out.grid = Grid(lo, hi, CELL)
    return out


def _place(local: np.ndarray, pose: tuple[float, float, float]) -> np.ndarray:
    x, y, a = pose
    c, s = math.cos(a), math.sin(a)
    out = np.empty_like(local)
    out[:, 0] = x + c * local[:, 0] - s * local[:, 1]
    out[:, 1] = y + s * local[:, 0] + c * local[:, 1]
    return out


def place_many(local: np.ndarray, owner: np.ndarray, poses: np.ndarray) -> np.ndarray:
    """``local`` vertices (V, 2) placed by their owners' poses ``poses[owner]`` (x, y, angle)."""
    p = poses[owner]
    c, s = np.cos(p[:, 2]), np.sin(p[:, 2])
    out = np.empty_like(local)
    out[:, 0] = p[:, 0] + c * local[:, 0] - s * local[:, 1]
    out[:, 1] = p[:, 1] + s * local[:, 0] + c * local[:, 1]
    return out


class Obstacles:
    """The colliders of one world as static and moving :class:`Pieces`."""

    def __init__(self, world: World, skin: float) -> None:
        self.world = world
        self.skin = skin
        self.records: dict[int, Record] = {}
        #: body entity -> collider entities it carries (``Collider.body`` or its own)
        self.carried: dict[int, set[int]] = {}
        self.dirty: set[int] = set()
        #: owners of static pieces whose Transform writes are tracked
        self._posed: set[int] = set()
        self.static = Pieces()
        self.moving = Pieces()
        self._static_stale = True
        self._moving_stale = True
        for ctype in WATCHED:  # what the world holds already
            for e, (comp,) in world.query(ctype):
                self.added(e, comp)

    # -- change tracking (the owner calls these from its world's on_add / on_remove hooks
    # -- of the WATCHED types) -------------------------------------------------------------
    def added(self, entity: int, component: Any) -> None:
        self.dirty.add(entity)
        if isinstance(component, _TRACKED):
            bind(component, entity, self.dirty)

    def removed(self, entity: int, component: Any) -> None:
        self.dirty.add(entity)
        if isinstance(component, _TRACKED):
            unbind(component, self.dirty)
        elif isinstance(component, Transform) and entity in self._posed:
            unbind(component, self.dirty)
            self._posed.discard(entity)

    def close(self) -> None:
        """Stop tracking the world's components (the plugin's world closed)."""
        for ctype in _TRACKED:
            for _e, (comp,) in self.world.query(ctype):
                unbind(comp, self.dirty)
        for e in self._posed:
            t = self.world.try_get(e, Transform)
            if t is not None:
                unbind(t, self.dirty)

    def reskin(self, skin: float) -> None:
        """Use a new polygon skin (``PhysicsSettings.polygon_radius``) for every piece."""
        self.skin = skin
        self.dirty.update(self.records)

    def refresh(self) -> None:
        """Bring the records and arrays up to date with the changes since the last call."""
        if self.dirty:
            touched: set[int] = set()
            for e in self.dirty:
                touched.add(e)
                touched.update(self.carried.get(e, ()))
            self.dirty.clear()
            for c in sorted(touched):
                self._update(c)
        if self._static_stale:
            recs = [r for _, r in sorted(self.records.items()) if r.kind == STATIC]
            self.static = _concat(recs, moving=False)
            self._static_stale = False
        if self._moving_stale:
            recs = [r for _, r in sorted(self.records.items()) if r.kind != STATIC]
            self.moving = _concat(recs, moving=True)
            self._moving_stale = False

    def _update(self, c: int) -> None:
        old = self.records.get(c)
        new = self._record(c)
        if old != new:
            if old is not None:
                self.carried.get(old.owner, set()).discard(c)
                self._stale(old.kind)
                del self.records[c]
            if new is not None:
                self.carried.setdefault(new.owner, set()).add(c)
                self.records[c] = new
                self._stale(new.kind)
        for rec in (old, new):
            if rec is not None and rec.kind == STATIC:
                self._watch_pose(rec.owner)

    def _watch_pose(self, owner: int) -> None:
        """Track writes of ``owner``'s Transform while it places static pieces (a moving
        body's pose is read every step; everything else's is none of our business)."""
        t = self.world.try_get(owner, Transform)
        if t is None:
            return
        static = any(self.records[c].kind == STATIC for c in self.carried.get(owner, ()))
        if static and owner not in self._posed:
            bind(t, owner, self.dirty)
            self._posed.add(owner)
        elif not static and owner in self._posed:
            unbind(t, self.dirty)
            self._posed.discard(owner)

    def _stale(self, kind: int) -> None:
        if kind == STATIC:
            self._static_stale = True
        else:
            self._moving_stale = True

    def _record(self, c: int) -> Record | None:
        world = self.world
        if not world.exists(c):
            return None
        col = world.try_get(c, Collider)
        if col is None:
            return None
        owner = c if col.body is None else col.body
        if not world.exists(owner):
            return None
        rb = world.try_get(owner, RigidBody)
        if col.body is not None and rb is None:
            return None
        if rb is not None and not rb.enabled:
            return None
        if world.try_get(owner, CharacterBody) is not None:
            return None  # a character's own colliders: characters meet its shape
        kind = STATIC if rb is None else _KIND[rb.type]
        pose = (0.0, 0.0, 0.0)
        if kind == STATIC:
            t = world.try_get(owner, Transform)
            if t is not None:
                pose = (t.x, t.y, t.angle)
        platform = world.try_get(c, OneWayPlatform)
        f = col.filter
        return Record(
            collider=c,
            owner=owner,
            body=-1 if rb is None else owner,
            kind=kind,
            shape=col.shape,
            skin=self.skin,
            sensor=col.sensor,
            bits=(f.category_bits, f.mask_bits, f.group_index),
            oneway=None if platform is None else (*platform.up, platform.min_cos),
            pose=pose,
        )

    # -- placing the moving pieces --------------------------------------------------------
    def place(self, poses: np.ndarray) -> None:
        """Put the moving pieces where ``poses`` (one (x, y, angle) row per owner) say."""
        m = self.moving
        if len(m):
            m.world = place_many(m.local, m.vertex_owner, poses)
