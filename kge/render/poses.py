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
* :meth:`PoseTable.blend` runs each frame. An entity whose Transform differs
  from the recorded ``current`` was moved outside the fixed step (by an
  ``on_update`` script, a teleport, scene setup): it is drawn where it is now,
  and its history restarts there.

>>> from kge.components.transform import Transform
>>> table = PoseTable()
>>> t = Transform(0.0, 0.0)
>>> row = table.acquire(7, t)
>>> t.x = 1.0; table.record()      # one fixed step moved it to x = 1
>>> table.blend(0.5)[row].tolist()
[0.5, 0.0, 0.0]
"""

from __future__ import annotations

import math
from itertools import chain
from operator import attrgetter

import numpy as np

from kge.components.transform import Transform

#: Box2D moves a body at most 2 m and pi/2 rad per step; more is a teleport.
MAX_STEP_TRANSLATION = 2.0
MAX_STEP_ROTATION = math.pi / 2

_IDENTITY = Transform()
_GET = attrgetter("x", "y", "angle")


class PoseTable:
    """Rows of (x, y, angle) for entities, with previous/current history."""

    def __init__(self, capacity: int = 64) -> None:
        self.row_of: dict[int, int] = {}
        self._refs: dict[int, int] = {}
        self._transforms: list[Transform] = []
        self._free: list[int] = []
        self.prev = np.zeros((capacity, 3))
        self.cur = np.zeros((capacity, 3))
        #: the Transform values read by the last :meth:`blend` (for camera-follow correction)
        self.last_live = np.zeros((0, 3))
        self._lut = np.full(64, -1, np.intp)  # entity id -> row, for bulk adoption

    def __len__(self) -> int:
        return len(self._transforms)

    # -- rows ------------------------------------------------------------------------
    def acquire(self, entity: int, transform: Transform | None) -> int:
        """The row of ``entity`` (created on first use; reference-counted)."""
        row = self.row_of.get(entity)
        if row is not None:
            self._refs[entity] += 1
            return row
        t = transform if transform is not None else _IDENTITY
        if self._free:
            row = self._free.pop()
            self._transforms[row] = t
        else:
            row = len(self._transforms)
            self._transforms.append(t)
            if row >= len(self.cur):
                self.prev = np.resize(self.prev, (2 * len(self.cur), 3))
                self.cur = np.resize(self.cur, (2 * len(self.cur), 3))
        self.row_of[entity] = row
        self._refs[entity] = 1
        if entity >= len(self._lut):
            grown = np.full(max(2 * len(self._lut), entity + 1), -1, np.intp)
            grown[: len(self._lut)] = self._lut
            self._lut = grown
        self._lut[entity] = row
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
            self._transforms[row] = _IDENTITY
            self.cur[row] = self.prev[row] = 0.0
            self._free.append(row)
            self._lut[entity] = -1

    def set_transform(self, entity: int, transform: Transform | None) -> None:
        """The entity gained or lost its Transform: read the new one, restart history."""
        row = self.row_of.get(entity)
        if row is None:
            return
        t = transform if transform is not None else _IDENTITY
        self._transforms[row] = t
        self.cur[row] = self.prev[row] = _GET(t)

    def snap(self, entity: int) -> None:
        """Forget the history of ``entity`` (draw it exactly at its Transform)."""
        row = self.row_of.get(entity)
        if row is not None:
            self.cur[row] = self.prev[row] = _GET(self._transforms[row])

    # -- per step / per frame -------------------------------------------------------------
    def live(self) -> np.ndarray:
        """Current Transform values of every row, (n, 3)."""
        n = len(self._transforms)
        if n == 0:
            return np.zeros((0, 3))
        return np.fromiter(chain.from_iterable(map(_GET, self._transforms)), float, 3 * n).reshape(
            n, 3
        )

    def record(self) -> None:
        """After a fixed step: previous = current, current = Transform (teleports snap)."""
        live = self.live()
        n = len(live)
        cur, prev = self.cur[:n], self.prev[:n]
        d = live - cur
        turn = (d[:, 2] + math.pi) % (2 * math.pi) - math.pi  # angles may be wrapped by users
        jump = (np.hypot(d[:, 0], d[:, 1]) > MAX_STEP_TRANSLATION + 1e-6) | (
            np.abs(turn) > MAX_STEP_ROTATION + 1e-6
        )
        prev[:] = np.where(jump[:, None], live, cur)
        cur[:] = live

    def adopt(self, entities: np.ndarray, prev: np.ndarray, cur: np.ndarray) -> None:
        """Take previous/current poses from physics for the entities it moves (bulk).

        Physics knows exactly which moves were teleports (it resets the history
        of a body whose Transform user code wrote), so its history replaces the
        heuristic one for its bodies. Entities without a row are ignored.
        """
        if len(entities) == 0:
            return
        ids = np.asarray(entities, np.intp)
        inside = (ids >= 0) & (ids < len(self._lut))
        rows = np.full(len(ids), -1, np.intp)
        rows[inside] = self._lut[ids[inside]]
        ok = rows >= 0
        self.prev[rows[ok]] = prev[ok]
        self.cur[rows[ok]] = cur[ok]

    def blend(self, alpha: float) -> np.ndarray:
        """Poses to draw, (n, 3): ``lerp(previous, current, alpha)``; moved rows snap."""
        live = self.last_live = self.live()
        n = len(live)
        cur, prev = self.cur[:n], self.prev[:n]
        moved = np.any(live != cur, axis=1)
        if moved.any():
            cur[moved] = live[moved]
            prev[moved] = live[moved]
        a = min(max(float(alpha), 0.0), 1.0)
        out = prev + (cur - prev) * a
        da = cur[:, 2] - prev[:, 2]
        da = (da + math.pi) % (2 * math.pi) - math.pi  # the short way round
        out[:, 2] = prev[:, 2] + da * a
        return out
