"""Previous/current poses of drawn entities, blended by the accumulator's alpha.

Physics runs at a fixed rate, the screen at another. Drawing the latest
physics pose makes motion stutter (some frames see two steps, some none), so
kge draws ``lerp(previous, current, alpha)`` where ``alpha`` is the leftover
fraction of a step, the classic "fix your timestep" blend. The picture is at
most one step behind, and smooth.

The table keeps one row per drawn entity in numpy arrays, so blending N
entities is a few vector operations:

* :meth:`PoseTable.record` runs after every fixed step: ``previous = current``,
  ``current = Transform``. A move larger than any physics step can make
  (Box2D's 2 m / quarter-turn per step limits) is a teleport: both poses jump,
  nothing is swept across the screen. For bodies the physics system moves,
  :meth:`PoseTable.adopt` then takes its exact history (``Physics.poses()``),
  which knows every teleport, however short.
* :meth:`PoseTable.blend` runs each frame. An entity whose Transform user code
  wrote since the last step or frame (an ``on_update`` script, a teleport,
  scene setup) is drawn where it is now, and its history restarts there.

Finding those entities must not cost a read of every Transform each frame or
step (that was most of the render sync). The table binds each Transform it
draws to its own dirty set, :attr:`PoseTable.written` (through
:mod:`kge.components.tracked`; physics' teleport set stays bound beside it),
so a user write marks the entity, and :meth:`PoseTable.record` and
:meth:`PoseTable.blend` read only marked rows; the rest is numpy over the
table. Nothing else changes a Transform unseen: the only unmarked writer is
physics' sync-out, and :meth:`PoseTable.adopt` takes physics' poses for every
body it moves (and re-reads a marked body whose Transform does not hold
physics' pose); a replaced or removed Transform comes through
:meth:`PoseTable.set_transform`. Hence ``cur`` holds every row's Transform
after each step and blend. (``raw_set`` on a Transform is for the physics
system only: another writer's moves would not be drawn.)

>>> from kge.components.transform import Transform
>>> table = PoseTable()
>>> t = Transform(0.0, 0.0)
>>> row = table.acquire(7, t)
>>> t.x = 1.0; table.record()      # one fixed step moved it to x = 1
>>> table.blend(0.5)[row].tolist()
[0.5, 0.0, 0.0]
"""

from __future__ import annotations

import heapq
import math
from operator import attrgetter

import numpy as np

from kge.components.tracked import bind, unbind
from kge.components.transform import Transform

#: Box2D moves a body at most 2 m and pi/2 rad per step; more is a teleport.
MAX_STEP_TRANSLATION = 2.0
MAX_STEP_ROTATION = math.pi / 2

_IDENTITY = Transform()  # shared by rows without a Transform; never bound
_GET = attrgetter("x", "y", "angle")
_COLUMNS = tuple(attrgetter(name) for name in ("x", "y", "angle"))


def read_poses(transforms: list[Transform]) -> np.ndarray:
    """(x, y, angle) of each Transform, as an (n, 3) array.

    One C-level pass per field (``map`` of a single-name attrgetter into
    ``np.fromiter``) is a third faster than building a tuple per Transform.
    """
    n = len(transforms)
    out = np.empty((n, 3))
    for column, get in enumerate(_COLUMNS):
        out[:, column] = np.fromiter(map(get, transforms), float, n)
    return out


class PoseTable:
    """Rows of (x, y, angle) for entities, with previous/current history."""

    def __init__(self, capacity: int = 64) -> None:
        self.row_of: dict[int, int] = {}
        self._refs: dict[int, int] = {}
        self._transforms: list[Transform] = []
        self._free: list[int] = []
        self.prev = np.zeros((capacity, 3))
        self.cur = np.zeros((capacity, 3))
        #: entities whose Transform user code wrote since the table last read every row
        #: (marked through the Transforms' bindings, which hold this very set: it is
        #: only ever cleared in place; see the module docstring)
        self.written: set[int] = set()
        #: (sorted entity ids, their rows) for bulk adoption; rebuilt after rows change.
        #: Sorted arrays rather than a table indexed by entity id: ids are never reused,
        #: so such a table grows with every entity a long game ever spawned.
        self._index: tuple[np.ndarray, np.ndarray] | None = None
        #: rows drawn without a Transform of their own (at the origin)
        self._bare = np.zeros(capacity, bool)
        #: rows the last :meth:`record` read (the written ones)
        self._recorded = np.empty(0, np.intp)

    def __len__(self) -> int:
        return len(self._transforms)

    @property
    def last_live(self) -> np.ndarray:
        """Each row's Transform as of the last :meth:`blend`, (n, 3) (camera-follow correction).

        No Transform is read for it: after a blend, ``cur`` is every Transform.
        """
        return self.cur[: len(self._transforms)].copy()

    # -- rows ------------------------------------------------------------------------
    def acquire(self, entity: int, transform: Transform | None) -> int:
        """The row of ``entity`` (created on first use; reference-counted)."""
        row = self.row_of.get(entity)
        if row is not None:
            self._refs[entity] += 1
            return row
        t = transform if transform is not None else _IDENTITY
        if self._free:  # the lowest free row: live rows stay packed at the bottom
            row = heapq.heappop(self._free)
            self._transforms[row] = t
        else:
            row = len(self._transforms)
            self._transforms.append(t)
            if row >= len(self.cur):
                self.prev = np.resize(self.prev, (2 * len(self.cur), 3))
                self.cur = np.resize(self.cur, (2 * len(self.cur), 3))
                self._bare = np.resize(self._bare, 2 * len(self._bare))
        self.row_of[entity] = row
        self._refs[entity] = 1
        self._index = None
        self._watch(entity, t)
        self.cur[row] = self.prev[row] = _GET(t)
        return row

    def release(self, entity: int) -> None:
        """Drop one reference; the row is freed with the last one."""
        n = self._refs.get(entity, 0) - 1
        if n > 0:
            self._refs[entity] = n
            return
        row = self.row_of.pop(entity, None)
        self._refs.pop(entity, None)
        if row is not None:
            self._unwatch(self._transforms[row])
            self.written.discard(entity)
            self._transforms[row] = _IDENTITY
            self.cur[row] = self.prev[row] = 0.0
            heapq.heappush(self._free, row)
            self._index = None
            if row == len(self._transforms) - 1:
                self._trim()

    def _trim(self) -> None:
        """Give back the free rows at the top (and halve the arrays once a quarter full),
        so a table that held many entities once is as small as what it holds now."""
        free = set(self._free)
        n = len(self._transforms)
        while n and n - 1 in free:
            n -= 1
        del self._transforms[n:]
        self._free = [r for r in self._free if r < n]
        heapq.heapify(self._free)
        cap = len(self.cur)
        while cap > 64 and n <= cap // 4:
            cap //= 2
        if cap < len(self.cur):
            self.prev, self.cur = self.prev[:cap].copy(), self.cur[:cap].copy()
            self._bare = self._bare[:cap].copy()

    def set_transform(self, entity: int, transform: Transform | None) -> None:
        """The entity gained or lost its Transform: read the new one, restart history."""
        row = self.row_of.get(entity)
        if row is None:
            return
        self._unwatch(self._transforms[row])
        t = transform if transform is not None else _IDENTITY
        self._transforms[row] = t
        self._watch(entity, t)
        self.cur[row] = self.prev[row] = _GET(t)

    def snap(self, entity: int) -> None:
        """Forget the history of ``entity`` (draw it exactly at its Transform)."""
        row = self.row_of.get(entity)
        if row is not None:
            self.cur[row] = self.prev[row] = _GET(self._transforms[row])

    def _watch(self, entity: int, t: Transform) -> None:
        """Have user writes to ``t`` mark ``entity`` in :attr:`written`."""
        self._bare[self.row_of[entity]] = t is _IDENTITY
        if t is not _IDENTITY:
            bind(t, entity, self.written)

    def _unwatch(self, t: Transform) -> None:
        if t is not _IDENTITY:
            unbind(t, self.written)

    # -- per step / per frame -------------------------------------------------------------
    def live(self) -> np.ndarray:
        """Current Transform values of every row, (n, 3)."""
        return read_poses(self._transforms)

    def record(self) -> None:
        """After a fixed step: previous = current, current = Transform (teleports snap).

        Only the Transforms user code wrote (:attr:`written`) are read. Every other
        row either did not move or is a body physics moved, whose exact history
        :meth:`adopt` takes right after this (physics' sync-out writes without marks).
        """
        n = len(self._transforms)
        cur, prev = self.cur[:n], self.prev[:n]
        rows = self._written_rows()
        prev[:] = cur
        if rows is None:
            rows = np.arange(n)
        self._recorded = rows
        if not len(rows):
            return
        ts = self._transforms
        live = read_poses([ts[r] for r in rows.tolist()])
        d = live - cur[rows]
        turn = (d[:, 2] + math.pi) % (2 * math.pi) - math.pi  # angles may be wrapped by users
        jump = (np.hypot(d[:, 0], d[:, 1]) > MAX_STEP_TRANSLATION + 1e-6) | (
            np.abs(turn) > MAX_STEP_ROTATION + 1e-6
        )
        prev[rows] = np.where(jump[:, None], live, cur[rows])
        cur[rows] = live

    def adopt(self, entities: np.ndarray, prev: np.ndarray, cur: np.ndarray) -> None:
        """Take previous/current poses from physics for the entities it moves (bulk).

        Physics knows exactly which moves were teleports (it resets the history
        of a body whose Transform user code wrote), so its history replaces the
        heuristic one for its bodies. Entities without a row are ignored.

        A row whose Transform does not hold physics' current pose was written
        after physics last synced (a teleport in a contact handler, say) or has
        no Transform: physics' history does not describe it, so it is drawn
        where its Transform is. Such a write marked the row, so :meth:`record`
        has just read it: only those rows (and rows without a Transform) are
        compared with physics.
        """
        if len(entities) == 0:
            return
        rows = self._rows_of(np.asarray(entities, np.intp))
        ok = rows >= 0
        rows, cur = rows[ok], cur[ok]
        suspect = self._bare[rows]
        if len(self._recorded):
            suspect |= np.isin(rows, self._recorded)
        unseen = rows[suspect & _differ(self.cur[rows], cur)]
        self.prev[rows] = prev[ok]
        self.cur[rows] = cur
        if len(unseen):
            self._resync(unseen)

    def _rows_of(self, entities: np.ndarray) -> np.ndarray:
        """Row of each entity, -1 for entities without one (one sorted search)."""
        if self._index is None:
            ids = np.fromiter(self.row_of.keys(), np.intp, len(self.row_of))
            rows = np.fromiter(self.row_of.values(), np.intp, len(self.row_of))
            order = np.argsort(ids)
            self._index = (ids[order], rows[order])
        ids, rows = self._index
        if not len(ids):
            return np.full(len(entities), -1, np.intp)
        pos = np.minimum(np.searchsorted(ids, entities), len(ids) - 1)
        return np.where(ids[pos] == entities, rows[pos], -1)

    def blend(self, alpha: float) -> np.ndarray:
        """Poses to draw, (n, 3): ``lerp(previous, current, alpha)``; rows written since snap.

        Only the Transforms marked in :attr:`written` are read; the blend
        itself is a few numpy passes over the table.
        """
        if self.written:
            self._resync(self._written_rows())
        n = len(self._transforms)
        cur, prev = self.cur[:n], self.prev[:n]
        a = min(max(float(alpha), 0.0), 1.0)
        out = np.subtract(cur, prev)
        turn = out[:, 2]
        turn += math.pi  # the short way round: wrap the angle step into [-pi, pi)
        np.remainder(turn, 2 * math.pi, out=turn)
        turn -= math.pi
        out *= a
        out += prev
        return out

    def _written_rows(self) -> np.ndarray | None:
        """Rows of the entities in :attr:`written` (which is emptied); None for every row.

        When most rows were written (a script moving everything each frame),
        reading all Transforms in row order is cheaper than looking each up.
        """
        written = self.written
        rows = None
        if 2 * len(written) < len(self.row_of):
            rows = np.array([r for r in map(self.row_of.get, written) if r is not None], np.intp)
        written.clear()
        return rows

    def _resync(self, rows: np.ndarray | None) -> None:
        """Read the Transforms of ``rows`` (None: all); a row that moved unseen restarts there.

        "Unseen" means its Transform differs from ``cur``: the history in the
        table does not lead there, so it is drawn at the Transform (a snap).
        """
        if rows is None:
            self._resync_all()
            return
        ts = self._transforms
        live = read_poses([ts[r] for r in rows.tolist()])
        moved = _differ(live, self.cur[rows])
        rows, live = rows[moved], live[moved]
        self.cur[rows] = live
        self.prev[rows] = live

    def _resync_all(self) -> None:
        """:meth:`_resync` of every row, in row order (masked copies, no gathers)."""
        live = self.live()
        n = len(live)
        moved = _differ(live, self.cur[:n])[:, None]
        np.copyto(self.cur[:n], live, where=moved)
        np.copyto(self.prev[:n], live, where=moved)


def _differ(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Which rows of two (n, 3) arrays differ (column ORs: ``np.any(axis=1)`` is 8x slower)."""
    ne = a != b
    return ne[:, 0] | ne[:, 1] | ne[:, 2]
