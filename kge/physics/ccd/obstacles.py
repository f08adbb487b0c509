"""The static and kinematic shapes as numpy bounding boxes, screened in bulk.

A non-bullet body is only ever stopped by static or kinematic shapes, so the
question "could this fast body hit anything this step?" is answered for all
fast bodies at once against this index, without walking the dynamic shapes
around each of them.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from typing import Any

import numpy as np
import pymunk

from kge.gcpause import without_gc
from kge.physics.ccd.sorted_boxes import SortedBoxes
from kge.physics.cp import (
    body_handle,
    body_shapes,
    lib,
    shape_body,
    shape_handle,
    shape_hashid,
    shape_space,
)

_DYNAMIC = pymunk.Body.DYNAMIC
_KINEMATIC = pymunk.Body.KINEMATIC


def _pose(body: pymunk.Body) -> tuple[float, float, float]:
    """(x, y, angle) through Chipmunk's getters (no Vec2d)."""
    p = lib.cpBodyGetPosition(body_handle(body))
    return (p.x, p.y, lib.cpBodyGetAngle(body_handle(body)))



@dataclass(slots=True)
class Nearby:
    """The rows whose box overlapped a square, with their boxes as read then.

    Rows only leave the table (set to NaN) or get new boxes through the owner's
    upkeep, which does not run between the read and the questions asked of it
    (within one ``before_step``); a row dropped meanwhile is skipped by its
    shape's absence, as the full table would skip it.
    """

    left: float
    bottom: float
    right: float
    top: float
    rows: list[int]
    boxes: list[list[float]]
    kinematic: list[bool]

    def holds(self, left: float, bottom: float, right: float, top: float) -> bool:
        """Does the square contain this rectangle (so every row it meets is here)?"""
        return (
            left >= self.left and right <= self.right and bottom >= self.bottom and top <= self.top
        )

    def overlaps(self, x: float, y: float, r: float) -> bool:
        """Does any row's box overlap the square ``(x, y) ± r``? (The same sums as
        :meth:`Obstacles.near_any`.)"""
        right, left, top, bottom = x + r, x - r, y + r, y - r
        return any(
            b[0] <= right and b[2] >= left and b[1] <= top and b[3] >= bottom for b in self.boxes
        )

    def overlapping(self, box: pymunk.BB, still: float, moving: float) -> Iterator[int]:
        """Rows whose box overlaps ``box`` grown by ``still``, or ``moving`` for a
        kinematic row (the sums :meth:`Obstacles.candidates` makes), in row order."""
        bl, bb, br, bt = box.left, box.bottom, box.right, box.top
        for row, b, kinematic in zip(self.rows, self.boxes, self.kinematic, strict=True):
            g = moving if kinematic else still
            if b[0] <= br + g and b[2] >= bl - g and b[1] <= bt + g and b[3] >= bb - g:
                yield row


class Obstacles:
    """Bounding boxes of the space's static and kinematic shapes, in numpy.

    A non-bullet body can only be stopped by static or kinematic geometry, so
    "is anything within reach?" must not walk the (often many) dynamic shapes
    around it, as ``space.bb_query`` would. This index holds one row per
    static or kinematic shape: its cached bounding box and whether its body
    moves (kinematic). It is kept current at a cost proportional to what
    changed, never to the size of the space:

    * **new shapes**: Chipmunk gives every shape added to a space the next
      ``hashid``, and pymunk keeps ``space.shapes`` in insertion order, so the
      shapes added since the last look are the tail of that view whose hashid
      exceeds the newest one seen;
    * **removed shapes**: rows whose shape left the space are dropped when a
      query meets them, and swept out once removals outnumber the rows; dropped
      rows are reused by the next shapes, so the table never outgrows the most
      static and kinematic shapes the space held at once (a game that keeps
      spawning kinematic bodies must not grow it forever);
    * **moved bodies**: the owners' poses, read in bulk with the velocities,
      are compared with the last ones; the boxes of a body that moved (and of
      every moving kinematic body) are re-read, also on the next step, so a
      ``reindex`` that lags a move by one step is still seen;
    * **type changes**: :meth:`reclassify`, called by ``track``/``untrack``
      (the physics system calls one of them after every type change, and after
      a collider of the body is replaced: a new chain). A body still of the
      kind its rows were indexed as costs a scan and its own rows, never a walk
      of ``body.shapes`` (pymunk keeps removed shapes there: terrain rebuilt
      on every reset carries every chain it ever had).

    Queries: :meth:`nearby` finds the rows around many squares at once and
    returns them as :class:`Nearby`, which answers later questions about
    anything inside its square (:meth:`candidates` with ``near``) exactly as
    the table would; tables of thousands of rows are searched through
    :class:`~kge.physics.ccd.sorted_boxes.SortedBoxes`, smaller ones by a full
    numpy pass.

    Rows are candidates only: every hit is re-checked on the live shape.
    """

    def __init__(self, space: pymunk.Space) -> None:
        self.space = space
        self.shapes: list[pymunk.Shape | None] = []
        self.owner_of: list[int] = []  # row -> owner body id
        self.row_of: dict[pymunk.Shape, int] = {}
        self.box = np.full((16, 4), np.nan)  # left, bottom, right, top (nan: free row)
        self.kinematic = np.zeros(16, dtype=bool)
        #: False while no row was ever marked kinematic (since the last compaction)
        self.any_kinematic = False
        self.live = 0
        self._free: list[int] = []  # dropped rows, reused first
        self._count = 0  # len(space.shapes) at the last scan
        self._newest = -1  # largest hashid seen
        self._removed = 0  # removals seen since the last sweep of dead rows
        self._owners: dict[int, pymunk.Body] = {}  # body id -> body owning rows
        self._owner_rows: dict[int, list[int]] = {}
        self._owners_dirty = True
        self._oids = np.empty(0, dtype=np.int64)  # sorted owner ids
        self._opose = np.empty((0, 3))
        self._orow = np.empty(0, dtype=np.intp)  # owner -> row in the bulk read (-1: none)
        self._recent = np.empty(0, dtype=bool)
        self._recent_any = False  # self._recent.any()
        self._order = -1  # the bulk-read order _orow was computed for
        #: owners that got their first rows since the last refresh -> their pose then
        self._born: dict[int, tuple[float, float, float]] = {}
        #: rows whose box was read since the last scan (see :meth:`_scan`)
        self._read_rows: set[int] = set()
        #: the owners' rows in the bulk read, where every owner is in it (else None)
        self._gather: np.ndarray | None = None
        #: the rows sorted by left edge, for queries that test only a window of them
        self.sorted = SortedBoxes()

    # ----------------------------------------------------------------- upkeep

    def refresh(self, ids: np.ndarray, pose: np.ndarray, vel: np.ndarray, order: int) -> None:
        """Bring the rows up to date from this step's bulk read.

        ``order`` changes whenever the read's body order may have changed.
        """
        self._scan()
        fresh = order != self._order
        self._order = order
        if self._owners_dirty:
            old_ids, old_pose, old_recent = self._oids, self._opose, self._recent
            owners = self._owners
            self._oids = np.sort(np.fromiter(owners, dtype=np.int64, count=len(owners)))
            self._opose = np.full((len(self._oids), 3), np.nan)
            self._recent = np.zeros(len(self._oids), dtype=bool)
            if len(old_ids) and len(self._oids):
                # owners that stay keep their last pose: one new static collider
                # must not make every other owner re-read all its boxes (a tile
                # map's 100,000s) on this step and the next
                at = np.minimum(np.searchsorted(old_ids, self._oids), len(old_ids) - 1)
                same = old_ids[at] == self._oids
                self._opose[same] = old_pose[at[same]]
                self._recent[same] = old_recent[at[same]]
            if self._born:
                # new owners start from the pose their boxes were read at: one that has
                # not moved since is not re-read (a tile map's 100,000s of boxes would
                # be, twice, at the first step that looks for obstacles)
                born = np.array(list(self._born), dtype=np.int64)
                at = np.minimum(np.searchsorted(self._oids, born), len(self._oids) - 1)
                hit = self._oids[at] == born
                if hit.any():
                    self._opose[at[hit]] = np.array(list(self._born.values()))[hit]
                self._born.clear()
            self._owners_dirty = False
            self._recent_any = bool(self._recent.any())
            fresh = True
        k = len(self._oids)
        if k == 0:
            return
        if fresh:
            at = np.minimum(np.searchsorted(self._oids, ids), k - 1)
            hit = self._oids[at] == ids
            self._orow = np.full(k, -1, dtype=np.intp)
            self._orow[at[hit]] = np.flatnonzero(hit)
            self._gather = self._orow if hit.sum() == k else None
        gather = self._gather
        if gather is not None:  # every owner is in the read (the common case): no masks
            cur = pose[gather]
            if (
                not self._recent_any
                and (cur == self._opose).all()  # a nan (never read) is unequal: moved
                and not vel[gather].any()  # nan counts as moving, as != 0.0 does
            ):
                self._opose = cur  # nothing moved or turns, nothing re-read last step
                return
        present = self._orow >= 0
        rows = np.where(present, self._orow, 0)
        cur = np.where(present[:, None], pose[rows], np.nan)
        moved = ~(cur == self._opose).all(axis=1)  # nan (absent) counts as moved
        spinning = present & (vel[rows] != 0.0).any(axis=1)
        update = moved | spinning | self._recent
        self._recent = moved
        self._recent_any = bool(moved.any())
        self._opose = cur
        if update.any():
            self._update_owners(self._oids[update].tolist())

    @without_gc  # a tile map adds 100,000s of shapes at once (see kge.gcpause)
    def _scan(self) -> None:
        """Index the shapes added since the last scan (see the class docstring)."""
        shapes: Any = self.space.shapes  # a dict keys view: insertion order, reversible
        n = len(shapes)
        if n == self._count and (n == 0 or shape_hashid(next(reversed(shapes))) == self._newest):
            return
        added = 0
        newest = self._newest
        seen = []
        row_of, read, hashid = self.row_of, self._read_rows, lib.cpShapeGetHashID
        for shape in reversed(shapes):
            h = hashid(shape_handle(shape))  # what shape_hashid reads, without a Python call
            if h <= self._newest:
                break
            added += 1
            newest = max(newest, h)
            # a new shape that already has a row got it, and its box, after it joined
            # the space and since the last scan (``reclassify`` from the physics' sync
            # of its owner): reading it again would give the same box, as its owner's
            # moves since then are caught by refresh like any owner's
            row = row_of.get(shape)
            if row is None or row not in read:
                seen.append(shape)
        self._read_rows = set()
        if seen:
            self._classify_many(reversed(seen))  # skips new dynamic shapes, as before
        self._newest = newest
        self._removed += max(0, self._count + added - n)
        self._count = n
        if self._removed > max(32, self.live):
            self._removed = 0
            for shape in [s for s in self.shapes if s is not None]:
                if shape.space is not self.space:
                    self._drop(shape)

    def reclassify(self, body: pymunk.Body) -> None:
        """Re-read ``body``'s shapes after its type (or shape set) may have changed."""
        key = body.id
        rows = self._owner_rows.get(key)
        if rows is None:
            if body.body_type == _DYNAMIC:
                return  # the common case (a dynamic body tracked): nothing of it is indexed
            newest = self._newest
            if all(shape_hashid(s) > newest for s in body_shapes(body)):
                return  # a new body: the next scan indexes its shapes (they are the newest)
        elif self._same_kind(body, rows[0]):
            self._reread(body, key)
            return
        # only the shapes in the space: pymunk keeps a removed shape on its body, so a
        # static body whose chain is rebuilt on every reset carries all its old segments
        # (each would be looked at, then skipped, as in _classify_many)
        space = self.space
        own = [s for s in body_shapes(body) if shape_space(s) is space]
        self._classify_many(own)
        shapes, kept = self.shapes, set(own)
        gone = [shapes[row] for row in self._owner_rows.get(body.id, ())]
        self._classify_many([g for g in gone if g is not None and g not in kept])

    def _same_kind(self, body: pymunk.Body, row: int) -> bool:
        """Is ``body`` still of the kind (static or kinematic) its rows were indexed as?"""
        kind = body.body_type
        return kind != _DYNAMIC and bool(self.kinematic[row]) == (kind == _KINEMATIC)

    def _reread(self, body: pymunk.Body, key: int) -> None:
        """:meth:`reclassify` of an indexed body whose kind did not change (a replaced
        chain): what the full pass does, without walking every shape pymunk keeps on
        the body (it keeps removed ones: terrain rebuilt on every reset carries all its
        old chains). Its shapes in the space either have rows or joined the space
        since the last scan (a shape gets a new hashid whenever it is added), so a
        scan and its own rows cover them all."""
        self._scan()
        space, shapes, fresh = self.space, self.shapes, self._read_rows
        stay, moved, gone = [], [], []
        for row in self._owner_rows.get(key, ()):
            shape = shapes[row]
            if shape is None or row in fresh:
                continue  # just read by the scan
            if shape_space(shape) is not space:
                gone.append(shape)  # removed from the space: what _classify_many drops
            elif shape_body(shape) is body:
                stay.append(shape)
            else:
                moved.append(shape)
        if stay or moved:  # boxes re-read as the full pass does; moved: new owners
            self._classify_many(stay + moved)
        if gone:
            self._drop_many(gone)

    def _classify(self, shape: pymunk.Shape) -> None:
        body = shape.body
        if body is None or shape.space is not self.space or body.body_type == _DYNAMIC:
            self._drop(shape)
            return
        row = self.row_of.get(shape)
        if row is None:
            row = self._free_row()
            self.row_of[shape] = row
            self.shapes[row] = shape
            self.owner_of[row] = body.id
            self.live += 1
            rows = self._owner_rows.setdefault(body.id, [])
            if not rows:
                self._owners[body.id] = body
                self._owners_dirty = True
                self._born[body.id] = _pose(body)
            rows.append(row)
        bb = shape.bb
        self.box[row] = (bb.left, bb.bottom, bb.right, bb.top)
        self.sorted.touched((row,))
        moving = body.body_type == _KINEMATIC
        self.kinematic[row] = moving
        self.any_kinematic |= moving
        self._read_rows.add(row)

    def _classify_many(self, shapes: Iterable[pymunk.Shape]) -> None:
        """``_classify`` of each shape, boxes written in one numpy pass.

        A tile map's static outlines add 100,000s of segments at once; per shape
        this is a dict lookup, a row and a box read, nothing else. Dynamic
        shapes that have no row are skipped (they never need one).
        """
        space = self.space
        bodies: dict[int, tuple[int, int]] = {}  # id(body) -> (type, body.id), read once
        row_of = self.row_of
        get_bb = lib.cpShapeGetBB
        rows: list[int] = []  # known shapes' rows, then the new shapes' rows
        fresh: list[pymunk.Shape] = []
        fresh_key: list[int] = []
        owners: dict[int, pymunk.Body] = {}
        boxes: list[tuple[float, float, float, float]] = []  # known shapes, then new ones
        fresh_boxes: list[tuple[float, float, float, float]] = []
        moving: list[bool] = []
        fresh_moving: list[bool] = []
        gone: list[pymunk.Shape] = []  # rows to drop
        for shape in shapes:
            body = shape_body(shape)
            if body is None:
                kind, key = _DYNAMIC, 0
            else:
                known = bodies.get(id(body))
                if known is None:
                    known = bodies[id(body)] = (body.body_type, body.id)
                    owners[known[1]] = body
                kind, key = known
            row = row_of.get(shape)
            if body is None or kind == _DYNAMIC or shape_space(shape) is not space:
                if row is not None:
                    gone.append(shape)
                continue
            bb = get_bb(shape_handle(shape))  # what shape.bb reads, without building a BB
            if row is None:
                fresh.append(shape)
                fresh_key.append(key)
                fresh_boxes.append((bb.l, bb.b, bb.r, bb.t))
                fresh_moving.append(kind == _KINEMATIC)
            else:
                rows.append(row)
                boxes.append((bb.l, bb.b, bb.r, bb.t))
                moving.append(kind == _KINEMATIC)
        if fresh:
            rows += self._new_rows(fresh, fresh_key, owners)
            boxes += fresh_boxes
            moving += fresh_moving
        if rows:
            self.box[rows] = boxes
            self.sorted.touched(rows)
            self.kinematic[rows] = moving
            self.any_kinematic |= any(moving)
            self._read_rows.update(rows)
        if gone:
            # after the new rows: an owner whose shapes were all replaced (a replaced
            # chain) never runs out of rows, so the owner table is not rebuilt
            self._drop_many(gone)

    def _new_rows(
        self, fresh: list[pymunk.Shape], keys: list[int], owners: dict[int, pymunk.Body]
    ) -> list[int]:
        """Rows for shapes not indexed yet: dropped rows first, then a block at the end."""
        reuse = [self._free.pop() for _ in range(min(len(fresh), len(self._free)))]
        for shape, row, key in zip(fresh, reuse, keys, strict=False):
            self.shapes[row] = shape
            self.owner_of[row] = key
        start = len(self.shapes)
        self.shapes.extend(fresh[len(reuse) :])
        self.owner_of.extend(keys[len(reuse) :])
        end = len(self.shapes)
        if end > len(self.box):  # grow by doubling, as _free_row does
            grow = max(end, 2 * len(self.box)) - len(self.box)
            self.box = np.concatenate([self.box, np.full((grow, 4), np.nan)])
            self.kinematic = np.concatenate([self.kinematic, np.zeros(grow, dtype=bool)])
        new = reuse + list(range(start, end))
        self.row_of.update(zip(fresh, new, strict=True))
        self.live += len(fresh)
        for key, row in zip(keys, new, strict=True):
            owner_rows = self._owner_rows.setdefault(key, [])
            if not owner_rows:
                self._owners[key] = owners[key]
                self._owners_dirty = True
                self._born[key] = _pose(owners[key])
            owner_rows.append(row)
        return new

    def _free_row(self) -> int:
        if self._free:
            return self._free.pop()
        if len(self.shapes) == len(self.box):
            grow = len(self.box)
            self.box = np.concatenate([self.box, np.full((grow, 4), np.nan)])
            self.kinematic = np.concatenate([self.kinematic, np.zeros(grow, dtype=bool)])
        self.shapes.append(None)
        self.owner_of.append(0)
        return len(self.shapes) - 1

    def forget_owner(self, body_id: int) -> None:
        """Drop every row of a body leaving the space, in one pass (a chain's thousands)."""
        rows = self._owner_rows.pop(body_id, None)
        if not rows:
            return
        self._owners.pop(body_id, None)
        self._owners_dirty = True
        self._born.pop(body_id, None)
        for row in rows:
            shape = self.shapes[row]
            if shape is not None:
                self.row_of.pop(shape, None)
                self.shapes[row] = None
        self.box[rows] = np.nan
        self._free.extend(rows)
        self.live -= len(rows)
        if self.live == 0:  # compact, as _drop does
            self._drop_all()

    def _drop_many(self, shapes: list[pymunk.Shape]) -> None:
        """:meth:`_drop` of each shape, with one numpy write and one pass per owner (a
        replaced chain's old segments)."""
        row_of, table = self.row_of, self.shapes
        rows = []
        for shape in shapes:
            row = row_of.pop(shape, None)
            if row is not None:
                table[row] = None
                rows.append(row)
        if not rows:
            return
        self.box[rows] = np.nan
        self._free.extend(rows)
        self.live -= len(rows)
        by_owner: dict[int, set[int]] = {}
        for row in rows:
            by_owner.setdefault(self.owner_of[row], set()).add(row)
        for key, dropped in by_owner.items():
            kept = self._owner_rows.get(key)
            if kept is None:
                continue
            kept[:] = [r for r in kept if r not in dropped]
            if not kept:
                del self._owner_rows[key]
                self._owners.pop(key, None)
                self._owners_dirty = True
        if self.live == 0:  # compact: nothing left to keep
            self._drop_all()

    def _drop(self, shape: pymunk.Shape) -> None:
        self._drop_many([shape])

    def _drop_all(self) -> None:
        self.shapes.clear()
        self.owner_of.clear()
        self._free.clear()
        self.box[:] = np.nan
        self.sorted.clear()
        self.any_kinematic = False
        self._owner_rows.clear()
        self._owners.clear()
        self._owners_dirty = True

    @without_gc  # all of a tile map's owners on their first sighting
    def _update_owners(self, body_ids: list[int]) -> None:
        """Re-read the boxes of every shape of these owners, in one bulk pass."""
        shapes = self.shapes
        rows = [row for b in body_ids for row in self._owner_rows.get(b, ())]
        self._classify_many([s for s in (shapes[r] for r in rows) if s is not None])

    def body(self, body_id: int) -> pymunk.Body | None:
        """A static or kinematic body that owns indexed shapes, by id."""
        return self._owners.get(body_id)

    # ----------------------------------------------------------------- queries

    def near_any(self, x: np.ndarray, y: np.ndarray, r: np.ndarray) -> np.ndarray:
        """For each square ``(x, y) ± r``: does it overlap any row's box?"""
        out = np.zeros(len(x), dtype=bool)
        query, _ = self.overlapping(x, y, r)
        out[query] = True
        return out

    def overlapping(
        self, x: np.ndarray, y: np.ndarray, r: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray]:
        """(square, row) of every row whose box overlaps square ``(x, y) ± r``,
        sorted by square then row (see :class:`~kge.physics.ccd.sorted_boxes.SortedBoxes`)."""
        m = len(self.shapes) if self.live else 0
        return self.sorted.overlapping(self.box, m, x - r, y - r, x + r, y + r)

    def nearby(self, x: np.ndarray, y: np.ndarray, r: np.ndarray) -> list[Nearby]:
        """For each square ``(x, y) ± r``, its rows as a :class:`Nearby`: one bulk query
        for all squares, after which questions about anything inside a square cost a
        few Python comparisons instead of a pass over the table."""
        left, bottom, right, top = x - r, y - r, x + r, y + r
        m = len(self.shapes) if self.live else 0
        query, rows = self.sorted.overlapping(self.box, m, left, bottom, right, top)
        k = len(x)
        found = rows.tolist()
        boxes = self.box[rows].tolist()
        moving = self.kinematic[rows].tolist() if self.any_kinematic else [False] * len(found)
        # the pairs come sorted by square: each square's rows are one slice
        ends = [0, len(found)] if k == 1 else np.searchsorted(query, np.arange(k + 1)).tolist()
        return [
            Nearby(*edges, found[i:j], boxes[i:j], moving[i:j])
            for edges, i, j in zip(
                zip(left.tolist(), bottom.tolist(), right.tolist(), top.tolist(), strict=True),
                ends, ends[1:], strict=False,
            )
        ]

    def candidates(
        self, box: pymunk.BB, still: float, moving: float, near: Nearby | None = None
    ) -> list[pymunk.Shape]:
        """Shapes whose cached box overlaps ``box`` grown by ``still`` (static) or ``moving``.

        ``near``: rows found around ``box`` this step; when the grown box lies inside
        its square, only those rows are tested (any other row misses the square, so
        it misses the grown box too), else the whole table is.
        """
        return list(self.iter_candidates(box, still, moving, near))

    def iter_candidates(
        self, box: pymunk.BB, still: float, moving: float, near: Nearby | None = None
    ) -> Iterator[pymunk.Shape]:
        """:meth:`candidates` one at a time, in the same order: a caller that stops at
        the first real obstacle (most do: the ground is right there) tests no more."""
        m = len(self.shapes)
        if self.live == 0 or m == 0:
            return
        kinematic = self.any_kinematic and still != moving  # (a NaN differs)
        # a window wide enough for both growths (a NaN growth matches nothing, as in a
        # full pass)
        g = max((v for v in (still, moving) if v == v), default=still) if kinematic else still
        left, bottom, right, top = box.left - g, box.bottom - g, box.right + g, box.top + g
        if near is not None and near.holds(left, bottom, right, top):
            rows: Iterable[int] = near.overlapping(box, still, moving if kinematic else still)
        else:
            _, found = self.sorted.overlapping(
                self.box, m, np.array([left]), np.array([bottom]), np.array([right]),
                np.array([top]),
            )
            if kinematic and len(found):
                b = self.box[found]
                grow = np.where(self.kinematic[found], moving, still)
                hit = (
                    (b[:, 0] <= box.right + grow)
                    & (b[:, 2] >= box.left - grow)
                    & (b[:, 1] <= box.top + grow)
                    & (b[:, 3] >= box.bottom - grow)
                )
                found = found[hit]
            rows = found.tolist()
        for row in rows:
            if not self.live:
                return  # the last row was dropped (the table compacted): nothing left
            shape = self.shapes[row]
            if shape is None:
                continue
            if shape.space is not self.space:
                self._drop(shape)
                continue
            yield shape
