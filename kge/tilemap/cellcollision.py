"""Tile colliders of isometric, staggered and hexagonal maps.

A solid cell of a non-orthogonal map collides as its cell's shape on screen (a
diamond or a hexagon, which is what a player sees); a one-way tile gets the
same shape with a :class:`~kge.components.platform.OneWayPlatform`; tiles with
collision-editor shapes get those shapes where the tile image is drawn, as on
orthogonal maps.

On **isometric** maps the cell grid is an affine image of an orthogonal one, so
solid cells are merged exactly as on orthogonal maps (outlines traced in cell
space, their corners projected onto the diamonds): a 1,000 x 1,000 cave map gets
a few thousand outlines, not 600,000 polygons (:class:`IsoCollision`). Staggered
and hexagonal cells do not line up that way: there each solid cell is one
polygon (:class:`CellCollision`), and an edit rebuilds its one cell.
"""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np

from kge.components.platform import OneWayPlatform
from kge.components.shapes import Polygon
from kge.components.tilemap import TileCollider
from kge.components.transform import Transform
from kge.tilemap.collision import LayerCollision, Piece, collider
from kge.tilemap.model import ONE_WAY, SHAPES, SOLID


class CellCollision(LayerCollision):
    """:class:`LayerCollision` for non-orthogonal maps (same interface)."""

    def build(self) -> Iterator[Piece]:
        rr, cc = np.nonzero(self.kind != 0)
        for r, c in zip(rr.tolist(), cc.tolist(), strict=True):
            self.cells[(c, r)] = self._cell(c, r)
            yield from self.cells[(c, r)]

    def _cell(self, c: int, r: int) -> list[Piece]:
        kind = int(self.kind[r, c])
        if kind == SHAPES:
            return self._cell_shapes(c, r)
        if kind not in (SOLID, ONE_WAY):
            return []
        grid = self.data.grid
        assert grid is not None
        units = self.data.units
        pts = grid.cell_outline(c, r)
        cx = sum(p[0] for p in pts) / len(pts)
        cy = sum(p[1] for p in pts) / len(pts)
        local = [units.vector(x - cx, y - cy) for x, y in pts][::-1]  # counter-clockwise
        mat = self.materials[int(self.material[r, c])]
        comps: tuple[object, ...] = (
            Transform(*units.point(cx, cy)),
            collider(Polygon(local), mat),
            TileCollider(
                self.layer.name, "one_way" if kind == ONE_WAY else "cell", (c, r, c + 1, r + 1)
            ),
        )
        if kind == ONE_WAY:
            comps = (*comps, OneWayPlatform())
        return [Piece(comps, ("cell", c, r))]

    def update_cell(self, c: int, r: int) -> tuple[list[Piece], list[Piece]]:
        k, m = self._classify(self.layer.gids[r : r + 1, c : c + 1])
        self.kind[r, c], self.material[r, c] = k[0, 0], m[0, 0]
        gone = self.cells.pop((c, r), [])
        born = self._cell(c, r)
        if born:
            self.cells[(c, r)] = born
        return gone, born


class IsoCollision(CellCollision):
    """Isometric maps: solid cells merged into outlines, other colliders per cell."""

    def build(self) -> Iterator[Piece]:
        yield from self._build_solid()
        rr, cc = np.nonzero((self.kind != 0) & (self.kind != SOLID))
        for r, c in zip(rr.tolist(), cc.tolist(), strict=True):
            self.cells[(c, r)] = self._cell(c, r)
            yield from self.cells[(c, r)]

    def _corners(self, cols: np.ndarray, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        grid = self.data.grid
        assert grid is not None
        return self.data.units.points(*grid.lattice(cols, rows))

    def update_cell(self, c: int, r: int) -> tuple[list[Piece], list[Piece]]:
        gone, born, _, new_kind = self._update_solid(c, r)
        gone += self.cells.pop((c, r), [])
        if new_kind != SOLID:
            cell = self._cell(c, r)
            if cell:
                self.cells[(c, r)] = cell
                born += cell
        return gone, born
