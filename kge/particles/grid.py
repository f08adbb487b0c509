"""Particle collision with static colliders, in bulk, through an occupancy grid.

Asking pymunk about each particle each frame would cost a Python call per
particle. Static geometry does not move, so it is rasterised once into a
boolean grid (cells whose centre is inside a static collider; edges and chains
mark the cells they cross). Colliding N particles is then one gather of N
cells: a particle whose new cell is solid either dies or is put back at its
previous position with the velocity component across the wall reflected (the
axis is found by testing the cell it would have entered moving along x only
and along y only).

>>> import numpy as np
>>> g = StaticGrid.from_geometry(polygons=[np.array([[-5, -1], [5, -1], [5, 0], [-5, 0]])],
...                              circles=[], segments=[], cell=0.1)
>>> pos, vel = np.array([[0.0, -0.05]], np.float32), np.array([[0.0, -1.0]], np.float32)
>>> old = np.array([[0.0, 0.05]], np.float32)
>>> hit = g.collide(old, pos, vel, bounce=0.5)
>>> pos.tolist(), vel.tolist()
([[0.0, 0.05000000074505806]], [[0.0, 0.5]])
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

#: the grid never has more cells than this (the cell size grows instead)
MAX_CELLS = 4_000_000


class StaticGrid:
    """A boolean occupancy grid over the static colliders' bounds."""

    def __init__(self, solid: np.ndarray, origin: tuple[float, float], cell: float) -> None:
        self.solid = solid  #: (nx, ny) bool
        self.origin = origin
        self.cell = cell

    @classmethod
    def from_geometry(
        cls,
        polygons: Sequence[np.ndarray],
        circles: Sequence[tuple[float, float, float]],
        segments: Sequence[np.ndarray],
        cell: float = 0.1,
    ) -> StaticGrid | None:
        """Rasterise world-space convex polygons, (x, y, r) circles and (2, 2) segments."""
        boxes = [(p.min(axis=0), p.max(axis=0)) for p in polygons]
        boxes += [(np.array([x - r, y - r]), np.array([x + r, y + r])) for x, y, r in circles]
        boxes += [(s.min(axis=0), s.max(axis=0)) for s in segments]
        if not boxes:
            return None
        lo = np.min([b[0] for b in boxes], axis=0) - 2 * cell
        hi = np.max([b[1] for b in boxes], axis=0) + 2 * cell
        span = hi - lo
        while (span[0] / cell + 1) * (span[1] / cell + 1) > MAX_CELLS:
            cell *= 2.0
        nx, ny = int(span[0] / cell) + 1, int(span[1] / cell) + 1
        grid = cls(np.zeros((nx, ny), bool), (float(lo[0]), float(lo[1])), cell)
        for p in polygons:
            grid._fill_polygon(np.asarray(p, float))
        for x, y, r in circles:
            grid._fill_circle(x, y, r)
        for s in segments:
            grid._fill_segment(np.asarray(s, float))
        return grid

    def _window(
        self, lo: np.ndarray, hi: np.ndarray
    ) -> tuple[slice, slice, np.ndarray, np.ndarray]:
        """Cell slices covering [lo, hi] and the centres of those cells."""
        ox, oy = self.origin
        c = self.cell
        i0, j0 = max(0, int((lo[0] - ox) / c)), max(0, int((lo[1] - oy) / c))
        i1 = min(self.solid.shape[0], int((hi[0] - ox) / c) + 2)
        j1 = min(self.solid.shape[1], int((hi[1] - oy) / c) + 2)
        xs = ox + (np.arange(i0, i1) + 0.5) * c
        ys = oy + (np.arange(j0, j1) + 0.5) * c
        return slice(i0, i1), slice(j0, j1), xs[:, None], ys[None, :]

    def _fill_polygon(self, verts: np.ndarray) -> None:
        si, sj, xs, ys = self._window(verts.min(axis=0), verts.max(axis=0))
        area2 = np.sum(
            verts[:, 0] * np.roll(verts[:, 1], -1) - np.roll(verts[:, 0], -1) * verts[:, 1]
        )
        sign = 1.0 if area2 >= 0 else -1.0
        inside = np.ones((len(xs), ys.shape[1]), bool)
        for a, b in zip(verts, np.roll(verts, -1, axis=0), strict=True):
            cross = (b[0] - a[0]) * (ys - a[1]) - (b[1] - a[1]) * (xs - a[0])
            inside &= cross * sign >= 0
        self.solid[si, sj] |= inside

    def _fill_circle(self, x: float, y: float, r: float) -> None:
        si, sj, xs, ys = self._window(np.array([x - r, y - r]), np.array([x + r, y + r]))
        self.solid[si, sj] |= (xs - x) ** 2 + (ys - y) ** 2 <= r * r

    def _fill_segment(self, seg: np.ndarray) -> None:
        length = float(np.hypot(*(seg[1] - seg[0])))
        steps = max(2, int(length / (self.cell * 0.5)) + 1)
        t = np.linspace(0.0, 1.0, steps)[:, None]
        pts = seg[0] + (seg[1] - seg[0]) * t
        ij = self.cells(pts)
        ok = self._inside(ij)
        self.solid[ij[ok, 0], ij[ok, 1]] = True

    def cells(self, pts: np.ndarray) -> np.ndarray:
        """(n, 2) integer cell indices of world points."""
        return np.floor(
            (pts - np.asarray(self.origin, pts.dtype)) / pts.dtype.type(self.cell)
        ).astype(np.intp)

    def _inside(self, ij: np.ndarray) -> np.ndarray:
        nx, ny = self.solid.shape
        return (ij[:, 0] >= 0) & (ij[:, 0] < nx) & (ij[:, 1] >= 0) & (ij[:, 1] < ny)

    def solid_at(self, pts: np.ndarray) -> np.ndarray:
        """True for points inside a solid cell (points off the grid are free)."""
        ij = self.cells(pts)
        ok = self._inside(ij)
        out = np.zeros(len(pts), bool)
        out[ok] = self.solid[ij[ok, 0], ij[ok, 1]]
        return out

    def collide(
        self, old: np.ndarray, pos: np.ndarray, vel: np.ndarray, bounce: float | None
    ) -> np.ndarray | None:
        """Resolve particles that moved from ``old`` into solid cells (in place).

        Returns the indices that hit (or None). With ``bounce`` None the caller
        kills them; otherwise they return to ``old`` with the crossing velocity
        component reflected and scaled by ``bounce``.
        """
        hit_mask = self.solid_at(pos)
        if not hit_mask.any():
            return None
        hit = np.nonzero(hit_mask)[0]
        if bounce is None:
            return hit
        o, p = old[hit], pos[hit]
        along_x = self.solid_at(np.stack([p[:, 0], o[:, 1]], axis=1))
        along_y = self.solid_at(np.stack([o[:, 0], p[:, 1]], axis=1))
        neither = ~along_x & ~along_y
        flip_x = along_x | neither
        flip_y = along_y | neither
        v = vel[hit]
        v[flip_x, 0] *= -bounce
        v[flip_y, 1] *= -bounce
        vel[hit] = v
        pos[hit] = o
        return hit
