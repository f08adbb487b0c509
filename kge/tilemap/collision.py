"""Static colliders from tile layers: merged outlines, one-way runs, per-tile shapes.

:class:`LayerCollision` owns the collision state of one tile layer as numpy
grids (collision kind and material per cell) and knows the component lists of
the colliders it wants; the map handle spawns them. A change of one tile
rebuilds only what the tile touches (:meth:`LayerCollision.update_cell`).

Rules (see docs/tilemaps.md):

* a cell is **solid** when its tile is marked solid in the tileset (property
  ``solid``, or one full-tile rectangle in Tiled's collision editor) or its layer
  is a solid layer; solid cells of one material are outlined into closed
  :class:`~kge.components.shapes.Chain` loops (:mod:`kge.tilemap.outline`);
* **one-way** tiles (property ``one_way``) of a row are merged into one box per
  run, with a :class:`~kge.components.platform.OneWayPlatform`;
* tiles with other collision-editor shapes get one collider per shape;
* ``friction``, ``restitution``, ``category_bits``, ``mask_bits`` and
  ``group_index`` come from the tile's properties, else the layer's, else the
  map's options.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from kge.components.collider import Collider
from kge.components.filter import Filter
from kge.components.platform import OneWayPlatform
from kge.components.shapes import Box, Chain, Circle, Polygon
from kge.components.tilemap import TileCollider
from kge.components.transform import Transform
from kge.tilemap.errors import TilemapError
from kge.tilemap.model import (
    EMPTY,
    FLIP_D,
    FLIP_H,
    FLIP_V,
    ONE_WAY,
    SHAPES,
    SOLID,
    MapData,
    TileLayerData,
    TileShape,
)
from kge.tilemap.outline import trace_loops

MATERIAL_KEYS = ("friction", "restitution", "category_bits", "mask_bits", "group_index")
Material = tuple[float, float, int, int, int]
DEFAULT_MATERIAL: Material = (0.2, 0.0, 0x0001, 0xFFFF, 0)


def _truthy(value: Any) -> bool:
    return value is True or (isinstance(value, str) and value.lower() in ("true", "1", "yes"))


def _material(base: Material, *prop_dicts: dict[str, Any]) -> Material:
    values = list(base)
    for props in prop_dicts:
        for i, key in enumerate(MATERIAL_KEYS):
            if key in props:
                values[i] = props[key]
    f, r, cat, mask, group = values
    return (float(f), float(r), int(cat), int(mask), int(group))


def collider(shape: Any, material: Material, **extra: Any) -> Collider:
    f, r, cat, mask, group = material
    return Collider(shape, friction=f, restitution=r, filter=Filter(cat, mask, group), **extra)


@dataclass(slots=True)
class Piece:
    """One wanted static collider: its components and, once spawned, its entity."""

    components: tuple[Any, ...]
    key: Any  #: what identifies it for local rebuilds
    entity: int | None = None


@dataclass(slots=True)
class LayerCollision:
    data: MapData
    layer: TileLayerData
    solid_layer: bool
    base: Material
    kind: np.ndarray = field(init=False)  #: (rows, cols) uint8
    material: np.ndarray = field(init=False)  #: (rows, cols) int32 index into materials
    materials: list[Material] = field(default_factory=list)
    loops: dict[int, list[Piece]] = field(default_factory=dict)  #: material -> loop pieces
    boxes: dict[int, np.ndarray] = field(default_factory=dict)  #: material -> (n, 4) corner bboxes
    runs: dict[int, list[Piece]] = field(default_factory=dict)  #: row -> one-way pieces
    cells: dict[tuple[int, int], list[Piece]] = field(default_factory=dict)  #: per-tile shapes

    def __post_init__(self) -> None:
        self.materials = [self.base]
        self.kind, self.material = self._classify(self.layer.gids)

    # -- classification -------------------------------------------------------------
    def _classify(self, gids: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        table = self.data.tiles
        flag = self.layer.properties.get("collision")
        if flag is not None and not _truthy(flag):  # a decoration layer
            return np.zeros(gids.shape, np.uint8), np.zeros(gids.shape, np.int32)
        kind = table.kind[gids]
        if self.solid_layer:  # every tile solid, unless the tileset says one-way or shapes
            kind = np.where((gids != 0) & (kind == EMPTY), SOLID, kind).astype(np.uint8)
        material = np.zeros(gids.shape, np.int32)
        used = np.unique(gids[kind != EMPTY])
        for g in used.tolist():
            mat = _material(self.base, self.layer.properties, table.properties.get(g, {}))
            if mat not in self.materials:
                self.materials.append(mat)
            idx = self.materials.index(mat)
            if idx:
                material[(gids == g) & (kind != EMPTY)] = idx
        return kind, material

    # -- full build ---------------------------------------------------------------------
    def build(self) -> Iterator[Piece]:
        """Every collider of the layer (the map handle spawns them)."""
        yield from self._build_solid()
        for r in np.unique(np.nonzero(self.kind == ONE_WAY)[0]).tolist():
            self.runs[r] = self._runs(r)
            yield from self.runs[r]
        rr, cc = np.nonzero(self.kind == SHAPES)
        for r, c in zip(rr.tolist(), cc.tolist(), strict=True):
            self.cells[(c, r)] = self._cell_shapes(c, r)
            yield from self.cells[(c, r)]

    def _build_solid(self) -> Iterator[Piece]:
        """The outlines of the solid cells, one set per material."""
        solid = self.kind == SOLID
        for m in np.unique(self.material[solid]).tolist():
            pieces = self._trace(m, 0, 0, self.kind.shape[1], self.kind.shape[0])
            self.loops[m] = pieces
            self.boxes[m] = _bboxes(pieces)
            yield from pieces

    def _corners(self, cols: np.ndarray, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """World positions of grid corners (col, row) (where the outlines' vertices go)."""
        return self.data.units.corners(cols, rows)

    def _trace(
        self, m: int, c0: int, r0: int, c1: int, r1: int, known: dict[Any, Piece] | None = None
    ) -> list[Piece]:
        """The outline pieces of material ``m`` inside the cell rectangle [c0, c1) x [r0, r1).

        A loop whose key (material and absolute corners) is in ``known`` is that
        piece again: no components are built for it (a tile edit re-traces an area,
        and most of its outlines come back unchanged).
        """
        mask = (self.kind[r0:r1, c0:c1] == SOLID) & (self.material[r0:r1, c0:c1] == m)
        mat = self.materials[m]
        loops = trace_loops(mask)
        if not loops:
            return []
        # every corner of every loop converted at once
        sizes = np.array([len(loop) for loop in loops])
        cr = np.concatenate(loops) + np.array([c0, r0])
        x, y = self._corners(cr[:, 0].astype(float), cr[:, 1].astype(float))
        ends = np.cumsum(sizes)
        starts = ends - sizes
        lo = np.minimum.reduceat(cr, starts).tolist()
        hi = np.maximum.reduceat(cr, starts).tolist()
        if known is None:
            xs, ys = x.tolist(), y.tolist()
        out = []
        for start, end, (c_lo, r_lo), (c_hi, r_hi) in zip(
            starts.tolist(), ends.tolist(), lo, hi, strict=True
        ):
            key = (m, cr[start:end].tobytes())
            same = known.get(key) if known is not None else None
            if same is not None:
                out.append(same)
                continue
            if known is None:
                points = list(zip(xs[start:end], ys[start:end], strict=True))
            else:
                points = list(zip(x[start:end].tolist(), y[start:end].tolist(), strict=True))
            comps = (
                Transform(),
                collider(Chain(points, loop=True), mat),
                TileCollider(self.layer.name, "outline", (c_lo, r_lo, c_hi, r_hi)),
            )
            out.append(Piece(comps, key))
        return out

    def _runs(self, r: int) -> list[Piece]:
        row = self.kind[r] == ONE_WAY
        mats = self.material[r]
        units = self.data.units
        tw = units.tile_size[0]
        out = []
        c = 0
        n = len(row)
        while c < n:
            if not row[c]:
                c += 1
                continue
            start, m = c, int(mats[c])
            while c < n and row[c] and int(mats[c]) == m:
                c += 1
            top, height = self._one_way_band(r, start)
            x0, y_top = units.corner(start, r)
            y_top -= top
            cx = x0 + (c - start) * tw / 2
            comps = (
                Transform(cx, y_top - height / 2),
                collider(Box((c - start) * tw / 2, height / 2), self.materials[m]),
                OneWayPlatform(),
                TileCollider(self.layer.name, "one_way", (start, r, c, r + 1)),
            )
            out.append(Piece(comps, ("run", r, start, c)))
        return out

    def _one_way_band(self, r: int, c: int) -> tuple[float, float]:
        """(depth of the top below the cell top, height) in metres of a one-way tile."""
        units = self.data.units
        gid = int(self.layer.gids[r, c])
        shapes = self.data.tiles.shapes.get(gid)
        th = units.tile_size[1]
        if shapes and shapes[0].kind == "rectangle" and shapes[0].height > 0:
            s = shapes[0]
            tile_h = float(self.data.tiles.rect[gid, 3])
            top_px = units.tile_h - tile_h + s.y
            return units.length(top_px), units.length(s.height)
        return 0.0, th

    def _cell_shapes(self, c: int, r: int) -> list[Piece]:
        gid = int(self.layer.gids[r, c])
        flags = int(self.layer.flags[r, c])
        table = self.data.tiles
        units = self.data.units
        w, h = float(table.rect[gid, 2]), float(table.rect[gid, 3])
        ox, oy = (float(v) for v in table.offset[gid])
        # the tile image's top-left in map pixels (tiles sit on the cell box's bottom-left)
        grid = self.data.grid
        if grid is None:
            left = units.left_px + c * units.tile_w + ox
            top = (self.data.units.row0 + r + 1) * units.tile_h - h + oy
        else:
            bx, by, _, bh = grid.cell_box(c, r)
            left, top = bx + ox, by + bh - h + oy
        cx, cy = units.point(left + w / 2, top + h / 2)
        mat = self.materials[int(self.material[r, c])]
        out = []
        for i, s in enumerate(table.shapes.get(gid, [])):
            pts = [_flip(px, py, w, h, flags) for px, py in _outline(s)]
            local = [units.vector(px - w / 2, py - h / 2) for px, py in pts]
            try:
                shape = _shape(s, local)
            except ValueError as exc:
                raise TilemapError(
                    f"{self.data.path}: layer {self.layer.name!r}: tile {gid} at column {c}, "
                    f"row {r}: collision shape {i}: {exc}"
                ) from exc
            comps = (
                Transform(cx, cy),
                collider(shape, mat),
                TileCollider(self.layer.name, "tile", (c, r, c + 1, r + 1)),
            )
            out.append(Piece(comps, ("cell", c, r, i)))
        return out

    # -- local rebuilds -------------------------------------------------------------------
    def update_cell(self, c: int, r: int) -> tuple[list[Piece], list[Piece]]:
        """Re-derive the colliders around cell (c, r) after its tile changed.

        Returns (pieces to despawn, pieces to spawn); unchanged outlines keep
        their entities.
        """
        gone, born, old_kind, new_kind = self._update_solid(c, r)
        if ONE_WAY in (old_kind, new_kind):
            gone += self.runs.pop(r, [])
            self.runs[r] = self._runs(r)
            born += self.runs[r]
        gone += self.cells.pop((c, r), [])
        if new_kind == SHAPES:
            self.cells[(c, r)] = self._cell_shapes(c, r)
            born += self.cells[(c, r)]
        return gone, born

    def _update_solid(self, c: int, r: int) -> tuple[list[Piece], list[Piece], int, int]:
        """Re-classify cell (c, r) and re-trace the outlines it touches: (gone, born, old
        kind, new kind)."""
        old_kind, old_mat = int(self.kind[r, c]), int(self.material[r, c])
        k, m = self._classify(self.layer.gids[r : r + 1, c : c + 1])
        self.kind[r, c], self.material[r, c] = k[0, 0], m[0, 0]
        new_kind, new_mat = int(self.kind[r, c]), int(self.material[r, c])
        gone: list[Piece] = []
        born: list[Piece] = []
        for mat in {old_mat if old_kind == SOLID else -1, new_mat if new_kind == SOLID else -1} - {
            -1
        }:
            g, b = self._retrace(mat, c, r)
            gone += g
            born += b
        return gone, born, old_kind, new_kind

    def _retrace(self, m: int, c: int, r: int) -> tuple[list[Piece], list[Piece]]:
        pieces = self.loops.get(m, [])
        boxes = self.boxes.get(m, np.zeros((0, 4), np.int64))
        lo = np.array([c, r])
        hi = np.array([c + 1, r + 1])
        hit = np.zeros(len(pieces), bool)
        while True:
            now = (
                (boxes[:, 0] <= hi[0])
                & (boxes[:, 2] >= lo[0])
                & (boxes[:, 1] <= hi[1])
                & (boxes[:, 3] >= lo[1])
            )
            if np.array_equal(now, hit):
                break
            hit = now
            if hit.any():
                lo = np.minimum(lo, boxes[hit, :2].min(axis=0))
                hi = np.maximum(hi, boxes[hit, 2:].max(axis=0))
        old = [p for p, h in zip(pieces, hit.tolist(), strict=True) if h]
        keep = [p for p, h in zip(pieces, hit.tolist(), strict=True) if not h]
        # an outline that did not change keeps its piece and entity
        by_key = {p.key: p for p in old}
        final = self._trace(m, int(lo[0]), int(lo[1]), int(hi[0]), int(hi[1]), known=by_key)
        kept = {id(p) for p in final}
        gone = [p for p in old if id(p) not in kept]
        was = {id(p) for p in old}
        born = [p for p in final if id(p) not in was]
        self.loops[m] = keep + final
        self.boxes[m] = _bboxes(self.loops[m])
        return gone, born


def _bboxes(pieces: list[Piece]) -> np.ndarray:
    if not pieces:
        return np.zeros((0, 4), np.int64)
    return np.array([p.components[2].cells for p in pieces], np.int64).reshape(-1, 4)


def _outline(s: TileShape) -> list[tuple[float, float]]:
    if s.kind == "polygon":
        return [(s.x + px, s.y + py) for px, py in s.points]
    if s.kind == "ellipse":
        n = 12
        return [
            (
                s.x + s.width / 2 * (1 + math.cos(2 * math.pi * i / n)),
                s.y + s.height / 2 * (1 + math.sin(2 * math.pi * i / n)),
            )
            for i in range(n)
        ]
    return [
        (s.x, s.y),
        (s.x + s.width, s.y),
        (s.x + s.width, s.y + s.height),
        (s.x, s.y + s.height),
    ]


def _flip(x: float, y: float, w: float, h: float, flags: int) -> tuple[float, float]:
    """A point of the tile image after Tiled's flips (diagonal first, then H, then V)."""
    if flags & FLIP_D:
        x, y = y, x
        w, h = h, w
    if flags & FLIP_H:
        x = w - x
    if flags & FLIP_V:
        y = h - y
    return x, y


def _shape(s: TileShape, local: list[tuple[float, float]]) -> Any:
    """A kge shape from tile-local points in metres (counter-clockwise fixed here)."""
    xs = [p[0] for p in local]
    ys = [p[1] for p in local]
    if s.kind == "ellipse" and abs(s.width - s.height) < 1e-9:
        return Circle((max(xs) - min(xs)) / 2, ((max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2))
    if s.kind == "rectangle":
        return Box(
            (max(xs) - min(xs)) / 2,
            (max(ys) - min(ys)) / 2,
            ((max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2),
        )
    area = sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(local, local[1:] + local[:1], strict=True))
    pts = local if area > 0 else local[::-1]
    try:
        return Polygon(pts)
    except ValueError:
        return Chain(pts, loop=True)  # concave or more than 16 points: an outline
