"""A seeded curl-noise field for particle turbulence, in numpy over whole arrays.

The field is the curl of a smooth scalar noise ``psi(x, y, t)``: the acceleration
``(d psi / dy, -d psi / dx)`` swirls particles round the noise's hills and valleys
without gathering them in sinks or spreading them from sources (it has no
divergence), which is what makes smoke and magic look like fluid.

``psi`` is 3D value noise: pseudo-random values at the integer lattice (a hash of
the lattice coordinates and the seed, in uint32 arithmetic: the same numbers on
every machine and in every process) blended with the quintic fade
``6t^5 - 15t^4 + 10t^3``, whose derivative is continuous, so the curl is smooth.
Space is scaled by ``frequency`` (lattice cells per metre) and the third axis is
time times ``speed`` (how fast the field changes). The gradient is analytic (no
finite differences): one pass over the 8 lattice corners per particle.

>>> import numpy as np
>>> pts = np.array([[0.3, 0.7], [2.5, -1.2]], np.float32)
>>> a = curl(pts, t=0.0, frequency=1.0, speed=0.0, seed=4)
>>> a.shape, a.dtype.name, bool(np.array_equal(a, curl(pts, 0.0, 1.0, 0.0, 4)))
((2, 2), 'float32', True)
>>> bool(np.array_equal(a, curl(pts, 0.0, 1.0, 0.0, 5)))
False
"""

from __future__ import annotations

import numpy as np

U = np.uint32
#: lattice hash multipliers (large odd constants; any fixed set works)
_PX, _PY, _PZ = U(0x8DA6B343), U(0xD8163841), U(0xCB1AB31F)
#: the largest gradient of the noise per lattice unit (quintic fade: 15/8 per axis,
#: values in [-1, 1]): ``curl`` divides by it so ``strength`` is the peak acceleration
PEAK = 1.875 * 2.0


def _hash(ix: np.ndarray, iy: np.ndarray, iz: np.ndarray, seed: int) -> np.ndarray:
    """A value in [-1, 1] per lattice point (uint32 mixing: the same everywhere)."""
    s = U((seed * 0x9E3779B9) & 0xFFFFFFFF)
    h = ix.astype(U) * _PX ^ iy.astype(U) * _PY ^ iz.astype(U) * _PZ ^ s
    h ^= h >> U(15)
    h *= U(0x2C1B3C6D)
    h ^= h >> U(12)
    h *= U(0x297A2D39)
    h ^= h >> U(15)
    return (h >> U(8)).astype(np.float32) * np.float32(2.0 / (1 << 24)) - np.float32(1.0)


def _fade(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The quintic fade and its derivative."""
    t2 = t * t
    return t2 * t * (t * (t * 6 - 15) + 10), 30 * t2 * (t * (t - 2) + 1)


def value(x: np.ndarray, y: np.ndarray, z: float, seed: int) -> np.ndarray:
    """The noise ``psi`` itself at points (x, y) and time-axis ``z`` (tests, plots)."""
    fx, fy, fz = np.floor(x), np.floor(y), np.floor(z)
    ix, iy = fx.astype(np.int64), fy.astype(np.int64)
    ux, _ = _fade(x - fx)
    uy, _ = _fade(y - fy)
    tz = np.float32(z - fz)
    uz = float(tz * tz * tz * (tz * (tz * 6 - 15) + 10))
    out = np.zeros_like(x)
    for cz, wz in ((0, 1.0 - uz), (1, uz)):
        iz = np.full_like(ix, int(fz) + cz)
        v00, v10 = _hash(ix, iy, iz, seed), _hash(ix + 1, iy, iz, seed)
        v01, v11 = _hash(ix, iy + 1, iz, seed), _hash(ix + 1, iy + 1, iz, seed)
        low, high = v00 + ux * (v10 - v00), v01 + ux * (v11 - v01)
        out += np.float32(wz) * (low + uy * (high - low))
    return out


def gradient(x: np.ndarray, y: np.ndarray, z: float, seed: int) -> tuple[np.ndarray, np.ndarray]:
    """(d psi / dx, d psi / dy) of the value noise at points (x, y) and time-axis ``z``."""
    fx, fy = np.floor(x), np.floor(y)
    tx, ty = x - fx, y - fy
    ix, iy = fx.astype(np.int64), fy.astype(np.int64)
    fz = np.floor(z)
    tz = np.float32(z - fz)
    iz0 = np.full_like(ix, int(fz))
    ux, dux = _fade(tx)
    uy, duy = _fade(ty)
    uz = float(tz * tz * tz * (tz * (tz * 6 - 15) + 10))
    gx = np.zeros_like(x)
    gy = np.zeros_like(y)
    for cz, wz in ((0, 1.0 - uz), (1, uz)):
        if wz == 0.0:
            continue
        iz = iz0 + cz
        v00 = _hash(ix, iy, iz, seed)
        v10 = _hash(ix + 1, iy, iz, seed)
        v01 = _hash(ix, iy + 1, iz, seed)
        v11 = _hash(ix + 1, iy + 1, iz, seed)
        a = v10 - v00
        b = v11 - v01
        low = v00 + ux * a  # along x at y = 0 and y = 1
        high = v01 + ux * b
        w = np.float32(wz)
        gx += w * dux * (a + uy * (b - a))
        gy += w * duy * (high - low)
    return gx, gy


def curl(
    pos: np.ndarray, t: float, frequency: float, speed: float, seed: int
) -> np.ndarray:
    """The field's acceleration direction at ``pos`` (n, 2), magnitude at most about 1.

    ``frequency`` is lattice cells per metre, ``t * speed`` the time axis.
    """
    f = np.float32(frequency)
    x = pos[:, 0].astype(np.float32) * f
    y = pos[:, 1].astype(np.float32) * f
    gx, gy = gradient(x, y, float(t) * float(speed), seed)
    out = np.empty((len(pos), 2), np.float32)
    out[:, 0] = gy
    out[:, 1] = -gx
    out *= np.float32(1.0 / PEAK)
    return out
