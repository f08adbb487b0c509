"""Particle trails: per-particle position history in numpy ring buffers, and the
triangle-strip geometry of trails and ribbons.

A :class:`~kge.components.particle_trail.ParticleTrail` gives the emitter's pool
``2 x points`` extra float32 rows (:meth:`~kge.particles.pool.ParticlePool.
extra_rows`), a ring of ``points`` (x, y) samples per particle that moves with the
particle when the dead are removed. The ring's head is one index for the whole
emitter: every ``duration / points`` seconds of game time all live particles write
their position into the next slot at once (one row copy). A newborn particle fills
its whole ring with its birth position, so its trail grows from there.

:func:`strip` turns polylines into the two edges of a strip of varying width: the
head of a trail is the particle's current position, then the ring newest to oldest.

>>> import numpy as np
>>> line = np.array([[[0.0, 1.0, 2.0]], [[0.0, 0.0, 0.0]]], np.float32)  # x, y planes
>>> strip(line, np.array([2.0, 2.0, 0.0], np.float32))[0].reshape(-1, 2).tolist()
[[0.0, 1.0], [0.0, -1.0], [1.0, 1.0], [1.0, -1.0], [2.0, 0.0], [2.0, 0.0]]
"""

from __future__ import annotations

from typing import Any

import numpy as np

from kge.particles.curves import STEPS, color_table, size_table
from kge.particles.emitter import EmitterState

KEY = "trail"


def state(st: EmitterState, points: int) -> dict[str, Any]:
    """The emitter's trail state: its ring rows, head and sampling clock (made once, and
    again if ``points`` changes)."""
    ts = st.extras.get(KEY)
    if ts is None or ts["points"] != points:
        ts = st.extras[KEY] = {
            "row": st.pool.extra_rows(2 * points),
            "points": points,
            "head": 0,
            "clock": 0.0,
            "mark": st.born - st.pool.count,  # live particles start their rings now
        }
    return ts


def _ring(st: EmitterState, ts: dict[str, Any]) -> np.ndarray:
    """(points, 2, capacity) view of the ring rows."""
    row, p = ts["row"], ts["points"]
    return st.pool.data[row : row + 2 * p].reshape(p, 2, -1)


def record(st: EmitterState, ts: dict[str, Any], duration: float, dt: float) -> None:
    """Start the rings of the particles born since the last call; sample every live
    particle's position when the clock has run ``duration / points`` seconds."""
    pool = st.pool
    n = pool.count
    ring = _ring(st, ts)
    k = min(st.born - ts["mark"], n)
    ts["mark"] = st.born
    if k > 0:
        ring[:, :, n - k : n] = pool.data[0:2, n - k : n]
    interval = duration / ts["points"]
    ts["clock"] += dt
    if ts["clock"] >= interval:
        ts["clock"] = min(ts["clock"] - interval, interval)  # a long frame skips samples
        ts["head"] = (ts["head"] + 1) % ts["points"]
        ring[ts["head"], :, :n] = pool.data[0:2, :n]


def polylines(st: EmitterState, ts: dict[str, Any], out: np.ndarray | None = None
              ) -> np.ndarray:  # fmt: skip
    """(2, n, points + 1) x and y planes of each live particle's trail: its position,
    then its samples from the newest to the oldest (in the emitter's space); into
    ``out`` (at least that big) when given."""
    pool = st.pool
    n = pool.count
    p = ts["points"]
    order = (ts["head"] - np.arange(p)) % p
    out = np.empty((2, n, p + 1), np.float32) if out is None else out[:, :n, : p + 1]
    out[:, :, 0] = pool.data[0:2, :n]
    out[:, :, 1:] = _ring(st, ts)[order, :, :n].transpose(1, 2, 0)
    return out


def ribbon(st: EmitterState) -> np.ndarray:
    """(2, 1, n) x and y planes of one line through the live particles from the youngest
    to the oldest."""
    pool = st.pool
    n = pool.count
    order = np.argsort(pool.age[:n], kind="stable")
    return pool.data[0:2, :n][:, order][:, None, :]


def strip(lines: np.ndarray, widths: np.ndarray, out: np.ndarray | None = None,
          work: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None) -> np.ndarray:
    """(s, m, 2, 2) left and right edge points of the ``s`` lines of ``m`` points in the
    x and y planes ``lines`` (2, s, m), each point ``widths[j]`` wide across the line's
    direction there (a point whose neighbours coincide gets no width); into ``out``.

    Points are complex numbers here (x + iy): a turn by 90 degrees is a product by i,
    and each vertex is written as one 8-byte value. ``work``: scratch arrays (complex,
    complex, float32, each at least (s, m)) reused from frame to frame, as fresh pages
    are what a loaded machine makes slow."""
    s_, m = lines.shape[1:]
    p: Any
    t: Any
    length: Any
    if work is None:
        p, t, length = (np.empty((s_, m), np.complex64), np.empty((s_, m), np.complex64),
                        np.empty((s_, m), np.float32))  # fmt: skip
    else:
        p, t, length = (w[:s_, :m] for w in work)
    p.real, p.imag = lines[0], lines[1]
    np.subtract(p[:, 2:], p[:, :-2], out=t[:, 1:-1])
    t[:, 0] = p[:, 1] - p[:, 0]
    t[:, -1] = p[:, -1] - p[:, -2]
    np.abs(t, out=length)
    np.maximum(length, np.float32(1e-30), out=length)  # t is 0 there: the width too
    np.divide(widths * np.float32(0.5), length, out=length)
    t *= length
    t *= np.complex64(1j)  # across the line, to the left
    if out is None:
        out = np.empty((p.shape[0], p.shape[1], 2, 2), np.float32)
    edges = out.view(np.complex64)[..., 0]  # (s, m, 2): one complex per vertex
    np.add(p, t, out=edges[:, :, 0])
    np.subtract(p, t, out=edges[:, :, 1])
    return out


def along(table: np.ndarray, m: int) -> np.ndarray:
    """A :mod:`~kge.particles.curves` table sampled at ``m`` points from head to tail."""
    return table[np.rint(np.linspace(0.0, STEPS - 1, m)).astype(np.intp)]


_LOOKS: dict[tuple[Any, ...], tuple[np.ndarray, np.ndarray]] = {}


def looks(trail: Any, m: int) -> tuple[np.ndarray, np.ndarray]:
    """(widths (m,), RGBA (m, 4) uint16) of a trail of ``m`` points (cached by style)."""
    key = (tuple(trail.width), tuple(trail.color), tuple(trail.opacity), m)
    found = _LOOKS.get(key)
    if found is None:
        if len(_LOOKS) > 256:
            _LOOKS.clear()
        widths = along(size_table(trail.width), m)
        rgba = along(color_table(trail.color, trail.opacity), m).astype(np.uint16)
        found = _LOOKS[key] = (widths, rgba)
    return found
