"""Map pixels to world metres, in one place.

Tiled measures in pixels with y pointing down from the map's top-left corner;
kge measures in metres with y up. A :class:`MapUnits` converts between the two
for one map: ``pixels_per_meter`` pixels make a metre (by default one tile width,
so a tile is 1 m wide) and the map's bottom-left corner sits at ``origin``.

>>> u = MapUnits(tile_w=16, tile_h=16, pixels_per_meter=16, col0=0, row0=0, rows=10)
>>> u.point(0, 160)          # Tiled's bottom-left pixel is the origin
(0.0, 0.0)
>>> u.point(32, 0)           # the top edge is 10 tiles up
(2.0, 10.0)
>>> u.cell_at(2.5, 9.5)      # (column, row) in Tiled's tile grid
(2, 0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True, slots=True)
class MapUnits:
    tile_w: int  #: map tile width, pixels
    tile_h: int  #: map tile height, pixels
    pixels_per_meter: float
    col0: int  #: Tiled column of the grid's first column (negative in infinite maps)
    row0: int  #: Tiled row of the grid's first row
    rows: int  #: rows in the grid
    origin: tuple[float, float] = (0.0, 0.0)  #: world position of the grid's bottom-left
    #: the map's pixel height when it is not rows x tile height (isometric, hexagonal...)
    height_px: float | None = None

    @property
    def bottom_px(self) -> float:
        """Tiled's pixel y of the grid's bottom edge."""
        if self.height_px is not None:
            return float(self.height_px)
        return float((self.row0 + self.rows) * self.tile_h)

    @property
    def left_px(self) -> float:
        return float(self.col0 * self.tile_w)

    def point(self, px: float, py: float) -> tuple[float, float]:
        """A Tiled pixel position (y down) as world metres (y up)."""
        s = self.pixels_per_meter
        return (
            self.origin[0] + (px - self.left_px) / s,
            self.origin[1] + (self.bottom_px - py) / s,
        )

    def points(self, px: np.ndarray, py: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`point` for arrays."""
        s = self.pixels_per_meter
        return (
            self.origin[0] + (px - self.left_px) / s,
            self.origin[1] + (self.bottom_px - py) / s,
        )

    def length(self, pixels: float) -> float:
        """A distance in pixels as metres."""
        return pixels / self.pixels_per_meter

    def vector(self, dx: float, dy: float) -> tuple[float, float]:
        """A Tiled pixel offset (y down) as a world vector (y up)."""
        return (dx / self.pixels_per_meter, -dy / self.pixels_per_meter)

    @property
    def tile_size(self) -> tuple[float, float]:
        """One grid cell in metres."""
        return (self.tile_w / self.pixels_per_meter, self.tile_h / self.pixels_per_meter)

    def pixel(self, x: float, y: float) -> tuple[float, float]:
        """A world point (metres, y up) as Tiled map pixels (y down): :meth:`point` inverted."""
        s = self.pixels_per_meter
        return (self.left_px + (x - self.origin[0]) * s, self.bottom_px - (y - self.origin[1]) * s)

    def cell_at(self, x: float, y: float) -> tuple[int, int]:
        """The (column, row) grid index (0-based, row 0 at the top) under a world point."""
        w, h = self.tile_size
        col = math.floor((x - self.origin[0]) / w)
        row = self.rows - 1 - math.floor((y - self.origin[1]) / h)
        return (col, row)

    def corner(self, col: float, row: float) -> tuple[float, float]:
        """World position of grid corner (col, row) (row counted down from the top)."""
        w, h = self.tile_size
        return (self.origin[0] + col * w, self.origin[1] + (self.rows - row) * h)

    def corners(self, col: np.ndarray, row: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`corner` for arrays."""
        w, h = self.tile_size
        return (self.origin[0] + col * w, self.origin[1] + (self.rows - row) * h)
