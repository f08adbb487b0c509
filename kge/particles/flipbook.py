"""Flipbook frames of particles: which cell of the sprite sheet each one shows.

A :class:`~kge.components.particle_flipbook.ParticleFlipbook` gives the emitter's
pool one extra float32 row (:meth:`~kge.particles.pool.ParticlePool.extra_rows`):
each particle's start frame, drawn at birth from a generator seeded by the
emitter's seed (0 for all when ``random_start`` is off). The frame shown is then
a function of age, lifetime and that start, computed for all particles at once
when they are drawn; the sheet cell becomes a texture rectangle.

>>> import numpy as np
>>> frame_index(np.array([0.0, 0.5, 0.99]), np.ones(3), np.zeros(3), 4, None, 1.0, True)
array([0, 2, 3])
>>> frame_index(np.array([0.0, 0.26, 1.1]), np.ones(3), np.array([0.0, 0.0, 2.0]), 4, 4.0, 1.0,
...             True)
array([0, 1, 2])
>>> uv_rects(np.array([0, 5]), 4, 2).tolist()
[[0.0, 0.5, 0.25, 1.0], [0.25, 0.0, 0.5, 0.5]]
"""

from __future__ import annotations

from typing import Any

import numpy as np

from kge.particles.emitter import EmitterState

KEY = "flipbook"


def frame_index(age: np.ndarray, life: np.ndarray, start: np.ndarray, frames: int,
                fps: float | None, cycles: float, loop: bool) -> np.ndarray:  # fmt: skip
    """The frame (0 .. frames - 1) of each particle."""
    if fps is None:  # over the lifetime, ``cycles`` times
        t = np.minimum(age / life, 1.0) * (frames * cycles)
        f = np.minimum(np.floor(t), frames * cycles - 1) + start
        return (f.astype(np.int64) % frames).astype(np.intp)
    f = np.floor(age * fps) + start
    if loop:
        return (f.astype(np.int64) % frames).astype(np.intp)
    return np.minimum(f, frames - 1).astype(np.intp)


def uv_rects(index: np.ndarray, columns: int, rows: int) -> np.ndarray:
    """(u0, v0, u1, v1) of each frame's cell; frame 0 is the sheet's top-left cell
    (texture v runs up, image rows run down)."""
    col = (index % columns).astype(np.float32)
    row = (index // columns).astype(np.float32)
    out = np.empty((len(index), 4), np.float32)
    out[:, 0] = col / columns
    out[:, 2] = (col + 1) / columns
    out[:, 1] = 1.0 - (row + 1) / rows
    out[:, 3] = 1.0 - row / rows
    return out


def state(st: EmitterState, seed: int) -> dict[str, Any]:
    """The emitter's flipbook state: its pool row and start-frame generator (made once)."""
    fs = st.extras.get(KEY)
    if fs is None:
        fs = st.extras[KEY] = {
            "row": st.pool.extra_rows(1),
            "rng": np.random.default_rng([seed, 0x5F1B]),
            "mark": st.born - st.pool.count,  # the live ones get theirs on the next call
        }
    return fs


def start_new(st: EmitterState, fs: dict[str, Any], frames: int, random_start: bool) -> None:
    """Give the particles born since the last call their start frame."""
    pool = st.pool
    k = min(st.born - fs["mark"], pool.count)
    fs["mark"] = st.born
    if k <= 0:
        return
    rows = pool.data[fs["row"], pool.count - k : pool.count]
    rows[:] = fs["rng"].integers(0, frames, k) if random_start else 0.0


def rects(st: EmitterState, fb: Any, seed: int) -> np.ndarray:
    """(n, 4) texture rectangles of the live particles' frames."""
    pool = st.pool
    n = pool.count
    fs = state(st, seed)
    frame = frame_index(pool.age[:n], pool.life[:n], pool.data[fs["row"], :n], fb.count, fb.fps,
                        fb.cycles, fb.loop)  # fmt: skip
    return uv_rects(frame, fb.columns, fb.rows)
