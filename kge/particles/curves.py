"""Over-life curves as lookup tables: one table read per particle per frame.

An emitter's ``size``, ``color`` and ``alpha`` are evenly spaced keys from
birth (t = 0) to death (t = 1), interpolated linearly. Interpolating per
particle per frame with ``np.interp`` would cost a search per particle; the
keys are sampled once into a table of :data:`STEPS` entries instead, and each
frame indexes it with ``(t * (STEPS - 1))`` rounded: one gather per attribute.

>>> import numpy as np
>>> lut = size_table((1.0, 0.0))
>>> float(lut[0]), float(lut[-1]), round(float(lut[STEPS // 2]), 2)
(1.0, 0.0, 0.5)
>>> rgba = color_table(((255, 0, 0), (0, 0, 255)), (255, 0))
>>> rgba[0].tolist(), rgba[-1].tolist()
([255, 0, 0, 255], [0, 0, 255, 0])
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

#: entries per table (256: a 1 s particle changes colour in steps of 4 ms)
STEPS = 256


def _sampled(keys: np.ndarray) -> np.ndarray:
    """``keys`` (k, c) evenly spaced over 0..1, resampled to (STEPS, c)."""
    t = np.linspace(0.0, 1.0, STEPS)
    if len(keys) == 1:
        return np.repeat(keys, STEPS, axis=0)
    xs = np.linspace(0.0, 1.0, len(keys))
    return np.stack([np.interp(t, xs, keys[:, c]) for c in range(keys.shape[1])], axis=1)


def size_table(sizes: Sequence[float]) -> np.ndarray:
    """Size (metres) at each of :data:`STEPS` life fractions, float32."""
    return _sampled(np.asarray(sizes, float).reshape(-1, 1))[:, 0].astype(np.float32)


def color_table(colors: Sequence[Sequence[int]], opacities: Sequence[float]) -> np.ndarray:
    """RGBA bytes at each of :data:`STEPS` life fractions, (STEPS, 4) uint8 (opacity 0-255)."""
    rgb = _sampled(np.asarray(colors, float).reshape(-1, 3))
    a = _sampled(np.asarray(opacities, float).reshape(-1, 1))
    return np.clip(np.rint(np.concatenate([rgb, a], axis=1)), 0, 255).astype(np.uint8)


def life_index(age: np.ndarray, life: np.ndarray) -> np.ndarray:
    """Table row of each particle from its age and lifetime."""
    t = age / life
    np.minimum(t, 1.0, out=t)
    t *= STEPS - 1
    t += 0.5
    return t.astype(np.intp)
