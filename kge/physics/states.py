"""Bulk reads of many bodies' states from the pose table: ``Physics.states``.

After a step, sync-out holds every moving body's (x, y, angle, vx, vy, w) in
one numpy table (:class:`~kge.physics.sync.PoseTable`) and writes the same
numbers into the Transforms and RigidBodies. A controller that reads the same
64 bodies every step (64 RL environments in one world) would walk 64 components
for what the table already holds in rows: this gathers them with one numpy
index instead.

The entities' slots in the table are resolved once and reused while the same
entities are asked for and the table still holds them there (checked on each
call with one compare of the entity column, so a table rebuilt by spawns and
despawns is noticed whatever way it was rebuilt).
"""

from __future__ import annotations

import numpy as np

from kge.physics.sync import PoseTable


class SlotCache:
    """The pose-table slots of the last entities asked for."""

    __slots__ = ("_key", "_slots", "_top")

    def __init__(self) -> None:
        self._key = b""
        self._slots = np.empty(0, dtype=np.int64)
        self._top = -1  # the largest slot, so a shrunken table is noticed before indexing

    def slots(self, table: PoseTable, entities: np.ndarray) -> np.ndarray | None:
        """Each entity's slot, or None when one of them has none (not a moving body)."""
        key = entities.tobytes()
        slots = self._slots
        if (
            key == self._key
            and self._top < len(table.entities)
            and np.array_equal(table.entities[slots], entities)
        ):
            return slots
        get = table.slot.get
        found = [get(e, -1) for e in entities.tolist()]
        if -1 in found:
            return None
        slots = np.array(found, dtype=np.int64)
        self._key, self._slots = key, slots
        self._top = int(slots.max()) if len(slots) else -1
        return slots


def gather(table: PoseTable, slots: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(states (n, 6), awake (n,)) of these slots, as the components hold them.

    A sleeping body's row keeps the speed it fell asleep at, while its RigidBody
    says 0 (Box2D's sleepers have no velocity): the rows of sleepers read 0 too.
    """
    states = table.state[slots]
    asleep = table.asleep[slots]
    if asleep.any():
        states[asleep, 3:] = 0.0
    return states, ~asleep
