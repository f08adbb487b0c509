"""Sync-out: reading every body's pose in bulk after a step.

``pymunk.batch.get_space_bodies`` copies id, position, angle and velocities of
all bodies into one buffer (~100x faster than a property loop). Its row order
is unstable (removals swap rows, sleeping reorders them), so rows are mapped
to kge slots by BODY_ID with ``np.searchsorted`` over the sorted ids of the
bodies kge tracks (:meth:`PoseTable.by_id`). Only rows whose values changed since the last step are
written to components, so sleeping bodies cost nothing in Python.

The table also keeps the previous step's pose of every tracked body, for
render interpolation.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import pymunk
import pymunk.batch as pb

from kge.physics.cp import body_handle
from kge.physics.cp import lib as _lib
from kge.physics.cp.bulk import BodyReader

FIELDS = (
    pb.BodyFields.BODY_ID
    | pb.BodyFields.POSITION
    | pb.BodyFields.ANGLE
    | pb.BodyFields.VELOCITY
    | pb.BodyFields.ANGULAR_VELOCITY
)

_DYNAMIC = pymunk.Body.DYNAMIC


class _InOrder(Sequence[pymunk.Body]):
    """``bodies`` seen in the order ``slots`` (no copy: indexed a few at a time)."""

    __slots__ = ("_bodies", "_slots")

    def __init__(self, bodies: list[pymunk.Body], slots: np.ndarray) -> None:
        self._bodies = bodies
        self._slots = slots

    def __len__(self) -> int:
        return len(self._slots)

    def __getitem__(self, k: Any) -> Any:
        if isinstance(k, slice):
            return [self._bodies[i] for i in self._slots[k].tolist()]
        return self._bodies[int(self._slots[k])]


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


@dataclass(slots=True)
class Reslot:
    """How :meth:`PoseTable.update` moved the slots, for tables kept beside it.

    Slots ``movers`` moved into ``holes`` (the slots of removed entities), the
    table was cut to ``kept`` slots, then the new entities were appended; the
    entities re-slotted in place kept their slot. ``placed`` is the slot of each
    of the update's items, in their order.
    """

    holes: list[int]
    movers: list[int]
    kept: int
    placed: list[int]
    size: int


class PoseTable:
    """Slots for the moving (dynamic and kinematic) bodies kge tracks.

    A slot is an entity's for as long as its body moves: a removed entity's slot
    is filled by the last one, and new entities are appended, so a structural
    change costs what it changes (plus a few array copies), however many bodies
    the world holds. Slots are therefore in no particular order; :meth:`by_id`
    gives the id-sorted view that maps a bulk read (a binary search).
    """

    def __init__(self) -> None:
        self.ids = np.empty(0, dtype=np.int64)  # pymunk body ids, by slot
        self.entities = np.empty(0, dtype=np.int64)
        self.state = np.empty((0, 6))  # x, y, angle, vx, vy, w after the last step
        self.prev = np.empty((0, 3))  # pose one step earlier
        self.asleep = np.empty(0, dtype=bool)
        self.dynamic = np.empty(0, dtype=bool)  # kinematic bodies never sleep in pymunk
        #: seconds each body has been below Box2D's sleep tolerances (kge.physics.rest)
        self.rest = np.empty(0)
        #: bumped whenever slots move, come or go
        self.epoch = 0
        self.slot: dict[int, int] = {}
        self.bodies: list[pymunk.Body] = []
        self._reader = BodyReader(FIELDS)
        # the last row-to-slot mapping: pymunk keeps its row order from step to step
        # unless bodies are added, removed, or fall asleep, so it is usually reused
        self._row_ids = b""
        self._mapping: tuple[np.ndarray, np.ndarray] | None = None
        self._sorted: tuple[np.ndarray, np.ndarray] | None = None  # (sorted ids, their slots)
        #: the last read returned every slot, in slot order (``slots`` is an arange)
        self.full = False
        #: (ids, rows) of the last bulk read, every body of the space (views of the
        #: buffer, valid until the next read); continuous collision reuses them when
        #: nothing changed the bodies between the end of a step and the next one
        self.raw: tuple[np.ndarray, np.ndarray] | None = None

    def rebuild(self, items: Sequence[tuple[int, pymunk.Body]]) -> Reslot:
        """Reset the slots to ``items`` (entity, body), keeping known states."""
        return self.update([*self.slot, *(e for e, _ in items)], items)

    def update(
        self, changed: Iterable[int], items: Sequence[tuple[int, pymunk.Body]]
    ) -> Reslot:
        """Re-slot the ``changed`` entities to ``items`` (entity, body).

        ``items`` are the pairs among ``changed`` that belong in the table now
        (moving bodies); changed entities without an item leave it. An entity that
        had a slot keeps it, with its state, previous pose and sleep flag (also on
        a new body: a RigidBody replaced, as a full rebuild always did); only
        entities new to the table are read through pymunk. Every other slot keeps
        its contents, though the last ones may move into the slots freed.
        """
        slot = self.slot
        self._mapping = None
        self._sorted = None
        self.raw = None
        self.epoch += 1
        wanted = {e for e, _ in items}
        n = len(self.ids)
        gone = sorted(slot[e] for e in set(changed) if e in slot and e not in wanted)
        kept = n - len(gone)
        holes = [i for i in gone if i < kept]
        dropped = set(gone)
        movers = [i for i in range(kept, n) if i not in dropped]
        ids, ents, bodies = self.ids, self.entities, self.bodies
        for i in gone:
            del slot[int(ents[i])]
        if holes:
            for arr in (ids, ents, self.state, self.prev, self.asleep, self.dynamic, self.rest):
                arr[holes] = arr[movers]
            for h, m in zip(holes, movers, strict=True):
                bodies[h] = bodies[m]
                slot[int(ents[h])] = h
        if gone:
            del bodies[kept:]
            self.ids, self.entities = ids[:kept], ents[:kept]
            self.state, self.prev = self.state[:kept], self.prev[:kept]
            self.asleep, self.dynamic = self.asleep[:kept], self.dynamic[:kept]
            self.rest = self.rest[:kept]
        placed: list[int] = []
        fresh: list[tuple[int, pymunk.Body]] = []
        for e, body in items:
            known = slot.get(e)
            if known is None:
                i = slot[e] = kept + len(fresh)
                fresh.append((e, body))
            else:  # known: a new body perhaps, keeping its row
                i = known
                self.ids[i] = body.id
                bodies[i] = body
                self.dynamic[i] = body.body_type == _DYNAMIC
            placed.append(i)
        if fresh:
            self._append(fresh)
        return Reslot(holes, movers, kept, placed, len(self.ids))

    def _append(self, fresh: list[tuple[int, pymunk.Body]]) -> None:
        """New slots at the end, read through Chipmunk's getters (no Vec2d per read)."""
        m = len(fresh)
        new = [b for _, b in fresh]
        self.bodies.extend(new)
        rows = []
        asleep = []
        lib = _lib
        for body in new:
            cp = body_handle(body)
            p, v = lib.cpBodyGetPosition(cp), lib.cpBodyGetVelocity(cp)
            w = lib.cpBodyGetAngularVelocity(cp)
            rows.append((p.x, p.y, lib.cpBodyGetAngle(cp), v.x, v.y, w))
            asleep.append(bool(lib.cpBodyIsSleeping(cp)))
        state = np.array(rows, dtype=np.float64).reshape(m, 6)
        self.ids = np.concatenate(
            [self.ids, np.fromiter([b.id for b in new], dtype=np.int64, count=m)]
        )
        self.entities = np.concatenate(
            [self.entities, np.fromiter([e for e, _ in fresh], dtype=np.int64, count=m)]
        )
        self.state = np.concatenate([self.state, state])
        self.prev = np.concatenate([self.prev, state[:, :3]])
        self.asleep = np.concatenate([self.asleep, np.array(asleep, dtype=bool)])
        self.rest = np.concatenate([self.rest, np.zeros(m)])
        self.dynamic = np.concatenate(
            [self.dynamic, np.array([b.body_type == _DYNAMIC for b in new], dtype=bool)]
        )

    def by_id(self) -> tuple[np.ndarray, Sequence[pymunk.Body]]:
        """(the tracked bodies' ids sorted, the bodies in that order): binary searches."""
        ids, slots = self._by_id()
        return ids, _InOrder(self.bodies, slots)

    def _by_id(self) -> tuple[np.ndarray, np.ndarray]:
        if self._sorted is None:
            order = np.argsort(self.ids, kind="stable")  # unique ids: the one order
            self._sorted = (self.ids[order], order)
        return self._sorted

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
            known, order = self._by_id()
            idx = np.searchsorted(known, ids)
            idx[idx >= len(known)] = 0
            hit = known[idx] == ids
            slots = order[idx[hit]]
            order = np.argsort(slots, kind="stable")
            self._mapping = (np.flatnonzero(hit)[order], slots[order])
            self._row_ids = key
            self.full = len(slots) == len(self.ids)  # sorted, unique: every slot once
        rows_of_slots, slots = self._mapping  # slots is shared: callers must not write to it
        return slots, rows[rows_of_slots]
