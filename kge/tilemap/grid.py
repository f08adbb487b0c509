"""Where the cells of each Tiled orientation are, in map pixels (y down), as Tiled draws them.

Four orientations, one :class:`GridShape`:

* **orthogonal**: cell (c, r) covers ``[c*tw, (c+1)*tw] x [r*th, (r+1)*th]``;
* **isometric**: diamonds; the top corner of (c, r) is at
  ``((c - r) * tw/2 + rows * tw/2, (c + r) * th/2)``;
* **staggered**: diamonds in rows (or columns) shifted by half a tile every other
  row (``staggeraxis``/``staggerindex``);
* **hexagonal**: like staggered with a flat side of ``hexsidelength`` pixels.

Each cell has a bounding box (``cell_box``): a tile image is drawn with its
bottom-left corner on the box's bottom-left corner (taller images reach up),
as Tiled does. ``cell_at`` inverts it for picking.

>>> g = GridShape("isometric", 64, 32, cols=4, rows=4)
>>> g.size_px
(256.0, 128.0)
>>> [float(v) for v in g.cell_box(0, 0)]   # x, y of the box's top-left, w, h
[96.0, 0.0, 64.0, 32.0]
>>> g.cell_at(128.0, 16.0)
(0, 0)
>>> GridShape("staggered", 64, 32, cols=4, rows=4, stagger_axis="y", stagger_index="odd"
...           ).cell_box(0, 1)[:2]
(32.0, 16.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

ORIENTATIONS = ("orthogonal", "isometric", "staggered", "hexagonal")


@dataclass(frozen=True, slots=True)
class GridShape:
    orientation: str
    tile_w: int
    tile_h: int
    cols: int
    rows: int
    stagger_axis: str = "y"  #: "x" or "y" (staggered and hexagonal maps)
    stagger_index: str = "odd"  #: "odd" or "even"
    side: int = 0  #: hexsidelength (hexagonal maps)
    col0: int = 0  #: first column (infinite orthogonal maps)
    row0: int = 0

    # -- Tiled's render parameters --------------------------------------------------
    @property
    def _hex(self) -> tuple[int, int, float, float, float, float]:
        tw, th = self.tile_w & ~1, self.tile_h & ~1
        side = self.side if self.orientation == "hexagonal" else 0
        sx = side if self.stagger_axis == "x" else 0
        sy = side if self.stagger_axis == "y" else 0
        col_w = (tw - sx) / 2 + sx
        row_h = (th - sy) / 2 + sy
        return tw, th, sx, sy, col_w, row_h

    def _staggered(self, i: np.ndarray) -> np.ndarray:
        odd = (np.asarray(i) & 1).astype(bool)
        return odd if self.stagger_index == "odd" else ~odd

    @property
    def size_px(self) -> tuple[float, float]:
        """The map's size in pixels (what Tiled shows as the map's bounds)."""
        o, tw, th, c, r = self.orientation, self.tile_w, self.tile_h, self.cols, self.rows
        if o == "orthogonal":
            return (float(c * tw), float(r * th))
        if o == "isometric":
            return ((c + r) * tw / 2, (c + r) * th / 2)
        tw2, th2, sx, sy, col_w, row_h = self._hex
        if self.stagger_axis == "x":
            return (c * col_w + (tw2 - sx) / 2, r * (th2 + sy) + (row_h if c > 1 else 0))
        return (c * (tw2 + sx) + (col_w if r > 1 else 0), r * row_h + (th2 - sy) / 2)

    def cell_boxes(
        self, cols: np.ndarray, rows: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, float, float]:
        """(left, top) pixels of the boxes of cells (cols, rows) (grid indices), and w, h."""
        c = np.asarray(cols, np.float64) + self.col0
        r = np.asarray(rows, np.float64) + self.row0
        o, tw, th = self.orientation, float(self.tile_w), float(self.tile_h)
        if o == "orthogonal":
            return c * tw, r * th, tw, th
        if o == "isometric":
            return (c - r) * tw / 2 + (self.rows - 1) * tw / 2, (c + r) * th / 2, tw, th
        tw2, th2, sx, sy, col_w, row_h = self._hex
        ci, ri = np.asarray(cols, np.int64), np.asarray(rows, np.int64)
        if self.stagger_axis == "x":
            y = ri * (th2 + sy) + np.where(self._staggered(ci), row_h, 0.0)
            return ci * col_w, y.astype(np.float64), tw, th
        x = ci * (tw2 + sx) + np.where(self._staggered(ri), col_w, 0.0)
        return x.astype(np.float64), ri * row_h, tw, th

    def lattice(self, cols: np.ndarray, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Map pixels of grid corners (col, row) of an isometric map: the top corner of
        cell (c, r) is corner (c, r), its right corner (c + 1, r), and so on.

        >>> [float(v[0]) for v in GridShape("isometric", 64, 32, cols=4, rows=4).lattice(
        ...     np.array([0.0]), np.array([1.0]))]
        [96.0, 16.0]
        """
        c, r = np.asarray(cols, np.float64), np.asarray(rows, np.float64)
        return (c - r + self.rows) * self.tile_w / 2, (c + r) * self.tile_h / 2

    def cell_box(self, col: int, row: int) -> tuple[float, float, float, float]:
        x, y, w, h = self.cell_boxes(np.array([col]), np.array([row]))
        return (float(x[0]), float(y[0]), w, h)

    def cell_outline(self, col: int, row: int) -> list[tuple[float, float]]:
        """The cell's shape in pixels (a rectangle, diamond or hexagon), clockwise on screen."""
        x, y, w, h = self.cell_box(col, row)
        o = self.orientation
        if o == "orthogonal":
            return [(x, y), (x + w, y), (x + w, y + h), (x, y + h)]
        if o in ("isometric", "staggered") or self.side == 0:
            return [(x + w / 2, y), (x + w, y + h / 2), (x + w / 2, y + h), (x, y + h / 2)]
        _, _, sx, sy, _, _ = self._hex
        if self.stagger_axis == "x":
            a = (w - sx) / 2
            return [
                (x + a, y),
                (x + a + sx, y),
                (x + w, y + h / 2),
                (x + a + sx, y + h),
                (x + a, y + h),
                (x, y + h / 2),
            ]
        b = (h - sy) / 2
        return [
            (x + w / 2, y),
            (x + w, y + b),
            (x + w, y + b + sy),
            (x + w / 2, y + h),
            (x, y + b + sy),
            (x, y + b),
        ]

    def cell_at(self, px: float, py: float) -> tuple[int, int]:
        """The grid (col, row) whose cell shape holds map pixel (px, py) (may be outside)."""
        o = self.orientation
        if o == "orthogonal":
            return (
                math.floor(px / self.tile_w) - self.col0,
                math.floor(py / self.tile_h) - self.row0,
            )
        if o == "isometric":
            x = px - self.rows * self.tile_w / 2
            ty, tx = py / self.tile_h, x / self.tile_w
            return (math.floor(ty + tx), math.floor(ty - tx))
        # staggered / hexagonal: the nearest cell centre among the candidates around
        tw2, th2, sx, sy, col_w, row_h = self._hex
        if self.stagger_axis == "x":
            c_guess, r_guess = math.floor(px / col_w), math.floor(py / (th2 + sy))
        else:
            c_guess, r_guess = math.floor(px / (tw2 + sx)), math.floor(py / row_h)
        best, best_d = (c_guess, r_guess), math.inf
        for dc in (-1, 0, 1):
            for dr in (-1, 0, 1):
                c, r = c_guess + dc, r_guess + dr
                if self._inside(c, r, px, py):
                    return (c, r)
                x, y, w, h = self.cell_box(c, r)
                d = (x + w / 2 - px) ** 2 + (y + h / 2 - py) ** 2
                if d < best_d:
                    best, best_d = (c, r), d
        return best

    def _inside(self, c: int, r: int, px: float, py: float) -> bool:
        pts = self.cell_outline(c, r)
        inside = False
        for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1], strict=True):
            if (y0 > py) != (y1 > py) and px < x0 + (py - y0) * (x1 - x0) / (y1 - y0):
                inside = not inside
        return inside

    def object_px(self, x: float, y: float) -> tuple[float, float]:
        """An object's Tiled position as map pixels (isometric maps store it projected)."""
        if self.orientation != "isometric":
            return (x, y)
        tx, ty = x / self.tile_h, y / self.tile_h
        return (
            (tx - ty) * self.tile_w / 2 + self.rows * self.tile_w / 2,
            (tx + ty) * self.tile_h / 2,
        )

    def depth(self, cols: np.ndarray, rows: np.ndarray) -> np.ndarray:
        """Tiled's draw order of cells: the bottom of each cell's box, then x (painter's)."""
        x, y, _, h = self.cell_boxes(cols, rows)
        return np.lexsort((x, y + h))
