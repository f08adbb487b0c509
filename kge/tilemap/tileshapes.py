"""Collision kinds of tiles from their properties and collision-editor shapes."""

from __future__ import annotations

from typing import Any

import numpy as np

from kge.tilemap.model import EMPTY, ONE_WAY, SHAPES, SOLID, GidTable, TileShape


def _truthy(value: Any) -> bool:
    return value is True or (isinstance(value, str) and value.lower() in ("true", "1", "yes"))


def _as_box(s: TileShape) -> tuple[float, float, float, float] | None:
    """(left, top, right, bottom) of an axis-aligned rectangle shape, else None."""
    if s.kind == "rectangle":
        return (s.x, s.y, s.x + s.width, s.y + s.height)
    if s.kind == "polygon" and len(s.points) == 4:
        xs = [s.x + p[0] for p in s.points]
        ys = [s.y + p[1] for p in s.points]
        # four corners of a box: each edge horizontal or vertical, two distinct x and y
        edges = zip(s.points, s.points[1:] + s.points[:1], strict=True)
        straight = all(abs(p[0] - q[0]) < 1e-6 or abs(p[1] - q[1]) < 1e-6 for p, q in edges)
        if straight and max(xs) - min(xs) > 1e-6 and max(ys) - min(ys) > 1e-6:
            return (min(xs), min(ys), max(xs), max(ys))
    return None


def covers_tile(shapes: list[TileShape], w: float, h: float) -> bool:
    """True when the shapes are boxes whose union is exactly the w x h tile.

    Such a tile is solid like a tile marked ``solid``: it joins its neighbours'
    merged outline instead of becoming colliders of its own (one full rectangle,
    two halves, a square drawn as a polygon...). Exact on the tile's own
    coordinates: the box edges cut the tile into cells, and every cell must be
    covered, nothing outside the tile.

    >>> covers_tile([TileShape("rectangle", 0, 0, 16, 8), TileShape("rectangle", 0, 8, 16, 8)],
    ...             16, 16)
    True
    >>> covers_tile([TileShape("rectangle", 0, 0, 16, 12)], 16, 16)
    False
    """
    boxes = [_as_box(s) for s in shapes]
    if not boxes or w <= 0 or h <= 0 or any(b is None for b in boxes):
        return False
    arr = np.round(np.array(boxes, float), 6)  # edges within 1e-6 px are one edge
    if arr[:, 0].min() < 0 or arr[:, 1].min() < 0 or arr[:, 2].max() > w or arr[:, 3].max() > h:
        return False
    xs = np.unique(np.concatenate([[0.0, float(w)], arr[:, 0], arr[:, 2]]))
    ys = np.unique(np.concatenate([[0.0, float(h)], arr[:, 1], arr[:, 3]]))
    covered = np.zeros((len(ys) - 1, len(xs) - 1), bool)
    for x0, y0, x1, y1 in arr.tolist():
        i0, i1 = np.searchsorted(xs, [x0, x1])
        j0, j1 = np.searchsorted(ys, [y0, y1])
        covered[j0:j1, i0:i1] = True
    return bool(covered.all())


def classify(table: GidTable) -> None:
    """Collision kind per gid from its properties and collision shapes."""
    for g, props in table.properties.items():
        if _truthy(props.get("one_way")):
            table.kind[g] = ONE_WAY
        elif _truthy(props.get("solid")):
            table.kind[g] = SOLID
    for g, shapes in table.shapes.items():
        if table.kind[g] != EMPTY:
            continue
        w, h = int(table.rect[g, 2]), int(table.rect[g, 3])
        full = covers_tile(shapes, w, h)
        table.kind[g] = SOLID if full else SHAPES
