"""Autotiling with Tiled's terrain (Wang) sets: paint a colour, the right tiles follow.

A corner set gives each tile a colour at its four corners; painting a cell sets
the four corners around it, and every cell touching them gets the tile whose
corners match (edge sets likewise with the four edges; mixed sets both). The
colours of the grid's corners and edges are read from the layer's tiles the
first time a set paints it.
"""

from __future__ import annotations

import numpy as np

from kge.tilemap.errors import TilemapError
from kge.tilemap.model import TileLayerData, WangSet

#: wangid positions: top, top-right, right, bottom-right, bottom, bottom-left, left, top-left
CORNERS = (7, 1, 3, 5)  # tl, tr, br, bl
EDGES = (0, 2, 4, 6)  # top, right, bottom, left


class WangPainter:
    """The corner and edge colours of one layer under one Wang set."""

    def __init__(self, wang: WangSet, layer: TileLayerData) -> None:
        self.wang = wang
        self.layer = layer
        rows, cols = layer.gids.shape
        self.corners = np.zeros((rows + 1, cols + 1), np.uint8)
        self.hedges = np.zeros((rows + 1, cols), np.uint8)  # top edge of row r
        self.vedges = np.zeros((rows, cols + 1), np.uint8)  # left edge of column c
        self.lookup = {int(g): wang.wangids[i] for i, g in enumerate(wang.gids.tolist())}
        for (r, c), g in np.ndenumerate(layer.gids):
            wid = self.lookup.get(int(g))
            if wid is not None:
                self._store(c, r, wid)

    def _store(self, c: int, r: int, wid: np.ndarray) -> None:
        tl, tr, br, bl = (int(wid[i]) for i in CORNERS)
        self.corners[r, c], self.corners[r, c + 1] = tl, tr
        self.corners[r + 1, c + 1], self.corners[r + 1, c] = br, bl
        t, rt, b, lf = (int(wid[i]) for i in EDGES)
        self.hedges[r, c], self.hedges[r + 1, c] = t, b
        self.vedges[r, c], self.vedges[r, c + 1] = lf, rt

    def wanted(self, c: int, r: int) -> np.ndarray:
        wid = np.zeros(8, np.uint8)
        kind = self.wang.kind
        if kind in ("corner", "mixed"):
            wid[list(CORNERS)] = (
                self.corners[r, c],
                self.corners[r, c + 1],
                self.corners[r + 1, c + 1],
                self.corners[r + 1, c],
            )
        if kind in ("edge", "mixed"):
            wid[list(EDGES)] = (
                self.hedges[r, c],
                self.vedges[r, c + 1],
                self.hedges[r + 1, c],
                self.vedges[r, c],
            )
        return wid

    def best(self, wid: np.ndarray) -> int:
        """The gid matching ``wid`` at every position (most probable first); 0: none."""
        match = (self.wang.wangids == wid).all(axis=1)
        if not match.any():
            return 0
        i = int(np.argmax(np.where(match, self.wang.probability, -1.0)))
        return int(self.wang.gids[i])

    def paint(self, c: int, r: int, color: int) -> list[tuple[int, int, int]]:
        """Set the cell's corners/edges to ``color``: (col, row, gid) of the cells to change."""
        if self.wang.kind in ("corner", "mixed"):
            self.corners[r : r + 2, c : c + 2] = color
        if self.wang.kind in ("edge", "mixed"):
            self.hedges[r : r + 2, c] = color
            self.vedges[r, c : c + 2] = color
        rows, cols = self.layer.gids.shape
        out = []
        for rr in range(max(r - 1, 0), min(r + 2, rows)):
            for cc in range(max(c - 1, 0), min(c + 2, cols)):
                wid = self.wanted(cc, rr)
                gid = self.best(wid) if wid.any() else 0
                if gid or (rr, cc) == (r, c):
                    out.append((cc, rr, gid))
        return out


def color_index(wang: WangSet, color: int | str, where: str) -> int:
    if isinstance(color, str):
        if color not in wang.colors:
            raise TilemapError(
                f"{where}: Wang set {wang.name!r} has no colour {color!r} "
                f"(colours: {', '.join(map(repr, wang.colors))})"
            )
        return wang.colors.index(color) + 1
    if isinstance(color, bool) or not 0 <= int(color) <= len(wang.colors):
        raise TilemapError(f"{where}: colour {color!r} is not 0..{len(wang.colors)}")
    return int(color)
