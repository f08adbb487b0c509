"""The characters of one step as numpy columns (read from their components once).

Every :class:`~kge.components.character.CharacterBody` is read with one
``attrgetter`` call (its settings and inputs as a tuple), so a thousand characters
cost a thousand C calls, not twenty thousand attribute reads; shapes are converted
once per distinct shape (:func:`~kge.character.shapes.character_core`).
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import chain
from operator import attrgetter

import numpy as np

from kge.character.shapes import character_core
from kge.components.character import CharacterBody, CharacterMode, CharacterShape

_PLATFORMER = CharacterMode.PLATFORMER

READ = attrgetter(
    "shape", "velocity", "mode", "up", "max_floor_angle", "snap_length", "step_height",
    "gravity_scale", "max_slides", "push_force", "mass", "jump_speed", "jump", "jump_cut",
    "coyote_time", "jump_buffer", "hard_landing_speed", "drop_through",
)


@dataclass(slots=True)
class Batch:
    """C characters, sorted by entity."""

    entity: np.ndarray  # (C,) int64
    bodies: list[CharacterBody]
    pos: np.ndarray  # (C, 2) where each is now
    core: np.ndarray  # (C, k, 2) core vertices in the entity's frame (padded)
    radius: np.ndarray  # (C,)
    lo: np.ndarray  # (C, 2) the shape's box, relative to the entity
    hi: np.ndarray
    foot: np.ndarray  # (C,) the shape's lowest point along up, relative to the entity
    small: np.ndarray  # (C,) bool: a core of at most two vertices (capsule, circle)
    velocity: np.ndarray  # (C, 2) as the components hold it
    platformer: np.ndarray  # (C,) bool
    up: np.ndarray  # (C, 2)
    floor_cos: np.ndarray  # (C,) surfaces with n . up >= this are floors
    snap: np.ndarray
    step: np.ndarray
    gravity_scale: np.ndarray
    slides: np.ndarray  # (C,) int
    push_force: np.ndarray
    mass: np.ndarray
    jump_speed: np.ndarray
    jump: np.ndarray  # (C,) bool, held this step
    jump_cut: np.ndarray
    coyote: np.ndarray
    buffer: np.ndarray
    hard_speed: np.ndarray
    drop: np.ndarray  # (C,) bool
    bits: np.ndarray  # (C, 3) the filter of the character's collider

    def __len__(self) -> int:
        return len(self.entity)

    def vertices(self, rows: np.ndarray, pos: np.ndarray) -> np.ndarray:
        """World core vertices (n, k, 2) of characters ``rows`` placed at ``pos`` (n, 2)."""
        return self.core[rows] + pos[:, None, :]


def _cores(shapes: tuple[CharacterShape, ...]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(core vertices (C, k, 2), radii (C,), vertex counts (C,)) of each shape: each
    distinct shape is converted once and the rows are one gather."""
    by_id: dict[int, int] = {}  # characters made alike share one shape object
    by_value: dict[CharacterShape, int] = {}
    firsts: list[CharacterShape] = []
    which = []
    for s in shapes:
        k = by_id.get(id(s))
        if k is None:
            k = by_value.get(s)
            if k is None:
                k = by_value[s] = len(firsts)
                firsts.append(s)
            by_id[id(s)] = k
        which.append(k)
    cores = [character_core(s) for s in firsts]
    k = max((len(c) for c, _ in cores), default=1)
    table = np.array([np.concatenate([c, np.repeat(c[-1:], k - len(c), 0)]) for c, _ in cores])
    radii = np.array([r for _, r in cores], dtype=np.float64)
    counts = np.array([len(c) for c, _ in cores], dtype=np.int64)
    rows = np.array(which, dtype=np.intp)
    return table.reshape(len(cores), k, 2)[rows], radii[rows], counts[rows]


def read(entities: list[int], bodies: list[CharacterBody], positions: list[tuple[float, float]],
         bits: list[tuple[int, int, int]]) -> Batch:
    """The batch of these characters (entities sorted, one body and position each)."""
    cols = list(zip(*map(READ, bodies), strict=True))
    n = len(bodies)

    def pairs(i: int) -> np.ndarray:
        return np.fromiter(chain.from_iterable(cols[i]), np.float64, 2 * n).reshape(n, 2)

    core, radius, counts = _cores(cols[0])
    lo = core.min(axis=1) - radius[:, None]
    hi = core.max(axis=1) + radius[:, None]
    up = pairs(3)
    foot = np.einsum("ckd,cd->ck", core, up).min(axis=1) - radius

    def f(i: int) -> np.ndarray:
        return np.array(cols[i], dtype=np.float64)

    return Batch(
        entity=np.array(entities, dtype=np.int64),
        bodies=bodies,
        pos=np.fromiter(chain.from_iterable(positions), np.float64, 2 * n).reshape(n, 2),
        core=core,
        radius=radius,
        lo=lo,
        hi=hi,
        foot=foot,
        small=counts <= 2,
        velocity=pairs(1),
        platformer=np.fromiter((m is _PLATFORMER for m in cols[2]), bool, n),
        up=up,
        floor_cos=np.cos(f(4)) - 1e-12,
        snap=f(5),
        step=f(6),
        gravity_scale=f(7),
        slides=np.array(cols[8], dtype=np.int64),
        push_force=f(9),
        mass=f(10),
        jump_speed=f(11),
        jump=np.array(cols[12], dtype=bool),
        jump_cut=f(13),
        coyote=f(14),
        buffer=f(15),
        hard_speed=f(16),
        drop=np.array(cols[17], dtype=bool),
        bits=np.array(bits, dtype=np.int64).reshape(-1, 3),
    )
