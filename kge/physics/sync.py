"""Sync-out: reading every body's pose in bulk after a step.

``pymunk.batch.get_space_bodies`` copies id, position, angle and velocities of
all bodies into one buffer (~100x faster than a property loop). Its row order
is unstable (removals swap rows, sleeping reorders them), so rows are mapped
to kge slots by BODY_ID with ``np.searchsorted`` over the sorted ids of the
bodies kge tracks. Only rows whose values changed since the last step are
written to components, so sleeping bodies cost nothing in Python.

The table also keeps the previous step's pose of every tracked body, for
render interpolation.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pymunk
import pymunk.batch as pb
from pymunk._chipmunk import lib as _lib

from kge.physics.bulk import BodyReader

FIELDS = (
    pb.BodyFields.BODY_ID
    | pb.BodyFields.POSITION
    | pb.BodyFields.ANGLE
    | pb.BodyFields.VELOCITY
    | pb.BodyFields.ANGULAR_VELOCITY
)

_DYNAMIC = pymunk.Body.DYNAMIC


def _first(item: tuple[int, int, pymunk.Body]) -> int:
    return item[0]


# columns of the float rows
X, Y, A, VX, VY, W = range(6)


def rows_differ(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Which rows of two C-contiguous float arrays of one shape differ, bit for bit.

    Each row is compared as one opaque block of bytes: ten times faster than
    ``np.any(a != b, axis=1)``, whose reduction along a short axis is slow.
    Bitwise, so -0.0 vs 0.0 counts as a change and a NaN that stays NaN does not.

    >>> a = np.zeros((3, 2)); b = a.copy(); b[1, 1] = 5.0
    >>> rows_differ(a, b).tolist()
    [False, True, False]
    """
    block = np.dtype((np.void, a.shape[1] * a.itemsize))
    rows_a = np.ascontiguousarray(a).view(block).ravel()
    return rows_a != np.ascontiguousarray(b).view(block).ravel()


def columns_differ(a: np.ndarray, b: np.ndarray, start: int, stop: int) -> np.ndarray:
    """Which rows differ in columns ``start:stop`` (one vector compare per column).

    >>> a = np.zeros((2, 6)); b = a.copy(); b[0, 4] = 1.0
    >>> columns_differ(a, b, 0, 3).tolist(), columns_differ(a, b, 3, 6).tolist()
    ([False, False], [True, False])
    """
    out = a[:, start] != b[:, start]
    for k in range(start + 1, stop):
        out |= a[:, k] != b[:, k]
    return out


class PoseTable:
    """Slots for the moving (dynamic and kinematic) bodies kge tracks."""

    def __init__(self) -> None:
        self.ids = np.empty(0, dtype=np.int64)  # sorted pymunk body ids
        self.entities = np.empty(0, dtype=np.int64)
        self.state = np.empty((0, 6))  # x, y, angle, vx, vy, w after the last step
        self.prev = np.empty((0, 3))  # pose one step earlier
        self.asleep = np.empty(0, dtype=bool)
        self.dynamic = np.empty(0, dtype=bool)  # kinematic bodies never sleep in pymunk
        self.slot: dict[int, int] = {}
        self.bodies: list[pymunk.Body] = []
        self._reader = BodyReader(FIELDS)
        # the last row-to-slot mapping: pymunk keeps its row order from step to step
        # unless bodies are added, removed, or fall asleep, so it is usually reused
        self._row_ids = b""
        self._mapping: tuple[np.ndarray, np.ndarray] | None = None
        #: the last read returned every slot, in slot order (``slots`` is an arange)
        self.full = False
        #: (ids, rows) of the last bulk read, every body of the space (views of the
        #: buffer, valid until the next read); continuous collision reuses them when
        #: nothing changed the bodies between the end of a step and the next one
        self.raw: tuple[np.ndarray, np.ndarray] | None = None

    def rebuild(self, items: Sequence[tuple[int, pymunk.Body]]) -> None:
        """Reset the slots to ``items`` (entity, body), keeping known states.

        Runs once per sync-in that added or removed bodies, so it is written for
        a wave of new bodies among many known ones: known rows are copied with
        one numpy gather, and only new bodies are read through pymunk.
        """
        old_slot, old_state, old_prev, old_sleep = self.slot, self.state, self.prev, self.asleep
        self._mapping = None
        self.raw = None
        keyed = sorted([(b.id, e, b) for e, b in items], key=_first)  # ids are unique
        n = len(keyed)
        self.ids = np.fromiter([k[0] for k in keyed], dtype=np.int64, count=n)
        ents = [k[1] for k in keyed]
        self.entities = np.fromiter(ents, dtype=np.int64, count=n)
        self.bodies = bodies = [k[2] for k in keyed]
        self.slot = dict(zip(ents, range(n), strict=True))
        self.dynamic = np.fromiter(
            [b.body_type == _DYNAMIC for b in bodies], dtype=bool, count=n
        )
        old = np.fromiter([old_slot.get(e, -1) for e in ents], dtype=np.int64, count=n)
        known = old >= 0
        self.state = np.empty((n, 6))
        self.prev = np.empty((n, 3))
        self.asleep = np.zeros(n, dtype=bool)
        if known.any():
            src = old[known]
            self.state[known] = old_state[src]
            self.prev[known] = old_prev[src]
            self.asleep[known] = old_sleep[src]
        fresh = np.flatnonzero(~known).tolist()
        if fresh:
            rows = []
            lib = _lib
            for i in fresh:
                cp = bodies[i]._body  # Chipmunk's getters: no Vec2d per read
                p, v = lib.cpBodyGetPosition(cp), lib.cpBodyGetVelocity(cp)
                rows.append(
                    (p.x, p.y, lib.cpBodyGetAngle(cp), v.x, v.y, lib.cpBodyGetAngularVelocity(cp))
                )
                if lib.cpBodyIsSleeping(cp):
                    self.asleep[i] = True
            self.state[fresh] = rows
            self.prev[fresh] = self.state[fresh, :3]

    def teleported(self, entity: int, x: float, y: float, angle: float) -> None:
        """A user moved the body: no interpolation across the jump."""
        i = self.slot.get(entity)
        if i is not None:
            self.state[i, :3] = (x, y, angle)
            self.prev[i] = (x, y, angle)

    def read(
        self, space: pymunk.Space, raw: tuple[np.ndarray, np.ndarray] | None = None
    ) -> tuple[np.ndarray, np.ndarray]:
        """Fetch all rows; returns (slots, rows) of the tracked bodies, in slot order.

        ``rows`` is a fresh array (a gather), owned by the caller. :attr:`full`
        tells whether ``slots`` is every slot, i.e. ``arange(len(ids))``. ``raw``:
        the (ids, rows) of a current bulk read of ``space`` to use instead of one.
        """
        ids, rows = self._reader.read(space) if raw is None else raw
        self.raw = (ids, rows)
        if len(self.ids) == 0 or len(ids) == 0:
            self.full = False
            return np.empty(0, dtype=np.int64), np.empty((0, 6))
        key = ids.tobytes()  # one memcmp: cheaper than np.array_equal for any size
        if self._mapping is None or key != self._row_ids:
            idx = np.searchsorted(self.ids, ids)
            idx[idx >= len(self.ids)] = 0
            hit = self.ids[idx] == ids
            slots = idx[hit]
            order = np.argsort(slots, kind="stable")
            self._mapping = (np.flatnonzero(hit)[order], slots[order])
            self._row_ids = key
            self.full = len(slots) == len(self.ids)  # sorted, unique: every slot once
        rows_of_slots, slots = self._mapping  # slots is shared: callers must not write to it
        return slots, rows[rows_of_slots]
