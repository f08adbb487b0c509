"""What the character system remembers about each character between steps.

Not component data (the user never sets it): timers for coyote time and the jump
buffer, the jump button as it was, whether a jump may still be cut short, the floor
stood on (its body carries the character next step). Kept in numpy columns, one
row per character (a slot, reused when characters come and go), so a step reads
and writes everyone's state with one gather and one scatter.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from kge.snapshot import carry_running

#: the columns and their starting values
COLUMNS: dict[str, tuple[type, float]] = {
    "on_floor": (bool, False),
    "air_time": (float, np.inf),  # seconds since it last stood on a floor
    "buffer": (float, 0.0),  # seconds left of a buffered jump press
    "jump_held": (bool, False),  # the jump input at the last step
    "rising": (bool, False),  # in a jump that releasing the button still cuts
    "jumped": (bool, False),  # has jumped since it last stood (no coyote jump then)
    "floor_body": (np.int64, -1),  # body entity of the floor, -1: none or static
    "floor_collider": (np.int64, -1),
    "floor_vx": (float, 0.0),  # the floor's velocity under the feet
    "floor_vy": (float, 0.0),
    # the read-back fields as last written into the component (only changes are written)
    "component": (np.int64, 0),  # id() of the component written to (0: none yet)
    "shown_flags": (np.int64, 0),  # on_floor, on_wall, on_ceiling, jumped, landed, hard: bits
    "shown_collider": (np.int64, -1),
    "shown_wall_collider": (np.int64, -1),
    "shown_landing": (float, 0.0),
    "shown_floor_n": (float, 0.0),  # x; _y columns follow
    "shown_floor_n_y": (float, 0.0),
    "shown_wall_n": (float, 0.0),
    "shown_wall_n_y": (float, 0.0),
    "shown_ceiling_n": (float, 0.0),
    "shown_ceiling_n_y": (float, 0.0),
    "shown_floor_v": (float, 0.0),
    "shown_floor_v_y": (float, 0.0),
}


#: the columns snapshots carry (the others say what was last written into a component:
#: a restored world's components are new objects, written afresh at their first step)
CARRIED = ("on_floor", "air_time", "buffer", "jump_held", "rising", "jumped", "floor_body",
           "floor_collider", "floor_vx", "floor_vy")


@carry_running
class CharacterState:
    """Rows of state by character entity (a resource of the world, so that snapshots
    carry it: a restored character goes on mid-jump, on its platform, in its sensors)."""

    def __init__(self) -> None:
        self.slot: dict[int, int] = {}
        self._free: list[int] = []
        self._size = 0
        self.cols: dict[str, np.ndarray] = {
            name: np.full(16, default, dtype=dtype) for name, (dtype, default) in COLUMNS.items()
        }
        #: one-way platform colliders each character is dropping or passing through
        self.passing: dict[int, set[int]] = {}
        #: sensor pieces (collider, child) each character overlaps
        self.sensors: dict[int, set[tuple[int, int]]] = {}
        #: which rows of the last :meth:`rows` call were new characters
        self.fresh = np.zeros(0, bool)

    def rows(self, entities: np.ndarray) -> np.ndarray:
        """The slots of ``entities`` (new ones start from the defaults, and ``fresh``
        says which they were); characters not listed are forgotten."""
        present = entities.tolist()
        keep = set(present)
        for e in [e for e in self.slot if e not in keep]:
            self._free.append(self.slot.pop(e))
            self.passing.pop(e, None)
        out = np.empty(len(present), np.int64)
        fresh = np.zeros(len(present), bool)
        for k, e in enumerate(present):
            s = self.slot.get(e)
            if s is None:
                s = self._new()
                self.slot[e] = s
                fresh[k] = True
            out[k] = s
        self.fresh = fresh
        return out

    def _new(self) -> int:
        if self._free:
            s = self._free.pop()
        else:
            s = self._size
            self._size += 1
            cap = len(self.cols["on_floor"])
            if s >= cap:
                for name, (dtype, default) in COLUMNS.items():
                    grown: np.ndarray = np.full(2 * cap, default, dtype=dtype)
                    grown[:cap] = self.cols[name]
                    self.cols[name] = grown
        for name, (_dtype, default) in COLUMNS.items():
            self.cols[name][s] = default
        return s

    def __getitem__(self, name: str) -> np.ndarray:
        return self.cols[name]

    # -- snapshots (kge.snapshot.carry_running) ------------------------------------------
    def export_running(self) -> dict[int, tuple[dict[str, Any], list[int], list[tuple[int, int]]]]:
        """Each character's timers, jump and floor, the one-way platforms it is passing
        through and the sensors it is in."""
        return {
            e: ({name: self.cols[name][s].item() for name in CARRIED},
                sorted(self.passing.get(e, ())), sorted(self.sensors.get(e, ())))
            for e, s in sorted(self.slot.items())
        }

    def import_running(
        self, carried: dict[int, tuple[dict[str, Any], list[int], list[tuple[int, int]]]]
    ) -> None:
        """Characters of a restored world go on from where they were (not as new ones)."""
        for e, (values, passing, sensors) in sorted(carried.items()):
            s = self.slot.get(e)
            if s is None:
                s = self.slot[e] = self._new()
            for name in CARRIED:
                self.cols[name][s] = values[name]
            if passing:
                self.passing[e] = set(passing)
            if sensors:
                self.sensors[e] = set(sensors)
