"""Tiled files (TMX/TSX or JSON/TSJ) -> :class:`~kge.tilemap.model.MapData`.

pytiled-parser reads the files (external and embedded tilesets, image
collections, infinite maps, group layers); this module turns its objects into
numpy grids and lookup tables once, and refuses what kge cannot use with a
:class:`TilemapError` naming the file and layer.
"""

from __future__ import annotations

import json
import xml.etree.ElementTree as ElementTree
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np

from kge.tilemap.errors import TilemapError
from kge.tilemap.model import (
    EMPTY,
    ONE_WAY,
    SHAPES,
    SOLID,
    GidTable,
    ImageLayerData,
    LayerStyle,
    MapData,
    ObjectLayerData,
    TileLayerData,
    TilesetData,
    TileShape,
    split_gids,
)
from kge.tilemap.units import MapUnits

SUPPORTED_ORIENTATIONS = ("orthogonal",)


def read_map(
    path: str | Path,
    *,
    pixels_per_meter: float | None = None,
    origin: tuple[float, float] = (0.0, 0.0),
) -> MapData:
    """Parse the map at ``path``; ``pixels_per_meter`` defaults to the tile width."""
    import pytiled_parser

    p = Path(path)
    if not p.is_file():
        raise TilemapError(f"map file {str(p)!r} not found")
    try:
        tmap = pytiled_parser.parse_map(p)
    except FileNotFoundError as exc:
        raise TilemapError(
            f"{p}: file {exc.filename or exc} not found (a tileset or template)"
        ) from exc
    except (
        ValueError,
        KeyError,
        TypeError,
        AttributeError,
        IndexError,
        OSError,
        ElementTree.ParseError,
        json.JSONDecodeError,
    ) as exc:
        raise TilemapError(f"{p}: cannot read the map ({type(exc).__name__}: {exc})") from exc
    if tmap.orientation not in SUPPORTED_ORIENTATIONS:
        raise TilemapError(
            f"{p}: orientation {tmap.orientation!r} is not supported (orthogonal maps only)"
        )
    tw, th = int(tmap.tile_size.width), int(tmap.tile_size.height)
    ppm = float(pixels_per_meter) if pixels_per_meter is not None else float(tw)
    if not np.isfinite(ppm) or ppm <= 0:
        raise TilemapError(
            f"{p}: pixels_per_meter must be a positive number, got {pixels_per_meter!r}"
        )
    tilesets, table = _tilesets(p, tmap.tilesets)
    flat = list(_flatten(tmap.layers, LayerStyle(), ""))
    col0, row0, cols, rows = _extent(tmap, flat)
    units = MapUnits(tw, th, ppm, col0, row0, rows, (float(origin[0]), float(origin[1])))
    tile_layers: list[TileLayerData] = []
    image_layers: list[ImageLayerData] = []
    object_layers: list[ObjectLayerData] = []
    for index, (name, layer, style) in enumerate(flat):
        props = dict(layer.properties or {})
        if isinstance(layer, pytiled_parser.TileLayer):
            raw = _grid(p, name, layer, col0, row0, cols, rows)
            gids, flags = split_gids(raw)
            bad = ~table.known(gids)
            if bad.any():
                r, c = (int(v[0]) for v in np.nonzero(bad))
                raise TilemapError(
                    f"{p}: layer {name!r}: tile id {int(gids[r, c])} at column {c + col0}, "
                    f"row {r + row0} is in no tileset"
                )
            tile_layers.append(TileLayerData(name, index, gids, flags, style, props))
        elif isinstance(layer, pytiled_parser.ImageLayer):
            if layer.image is None:
                continue
            img = Path(layer.image)
            if not img.is_absolute():
                img = p.parent / img
            _need(p, f"layer {name!r}: image", img)
            image_layers.append(
                ImageLayerData(name, index, img, style, props, (layer.repeat_x, layer.repeat_y))
            )
        elif isinstance(layer, pytiled_parser.ObjectLayer):
            for obj in layer.tiled_objects:
                gid = getattr(obj, "gid", None)
                if gid is not None:
                    g = int(gid) & 0x0FFFFFFF
                    if g >= table.size or table.tileset[g] < 0:
                        raise TilemapError(
                            f"{p}: layer {name!r}: object {obj.id} ({obj.name!r}): tile id {g} "
                            "is in no tileset"
                        )
            object_layers.append(
                ObjectLayerData(name, index, list(layer.tiled_objects), style, props)
            )
    bg = tmap.background_color
    po = tmap.parallax_origin
    return MapData(
        path=p,
        units=units,
        cols=cols,
        rows=rows,
        tilesets=tilesets,
        tiles=table,
        tile_layers=tile_layers,
        image_layers=image_layers,
        object_layers=object_layers,
        properties=dict(tmap.properties or {}),
        background=None if bg is None else (bg.red, bg.green, bg.blue, bg.alpha),
        parallax_origin=units.point(float(po.x), float(po.y)),
    )


def _need(map_path: Path, what: str, file: Path) -> None:
    if not file.is_file():
        raise TilemapError(f"{map_path}: {what} {str(file)!r} not found")


def _style(layer: Any) -> LayerStyle:
    tint = layer.tint_color
    return LayerStyle(
        opacity=float(layer.opacity),
        visible=bool(layer.visible),
        tint=(255, 255, 255, 255)
        if tint is None
        else (tint.red, tint.green, tint.blue, tint.alpha),
        offset=(float(layer.offset.x), float(layer.offset.y)),
        parallax=(float(layer.parallax_factor.x), float(layer.parallax_factor.y)),
    )


def _flatten(
    layers: list[Any], outer: LayerStyle, prefix: str
) -> Iterator[tuple[str, Any, LayerStyle]]:
    """Leaf layers in draw order, each with its name path and combined style."""
    import pytiled_parser

    for layer in layers:
        style = outer.nested(_style(layer))
        name = f"{prefix}{layer.name}"
        if isinstance(layer, pytiled_parser.LayerGroup):
            yield from _flatten(layer.layers or [], style, f"{name}/")
        else:
            yield name, layer, style


def _extent(tmap: Any, flat: list[tuple[str, Any, LayerStyle]]) -> tuple[int, int, int, int]:
    """(first column, first row, columns, rows) of the grid holding every layer."""
    if not tmap.infinite:
        return 0, 0, int(tmap.map_size.width), int(tmap.map_size.height)
    boxes = [
        (int(ch.coordinates.x), int(ch.coordinates.y), int(ch.size.width), int(ch.size.height))
        for _, layer, _ in flat
        for ch in (getattr(layer, "chunks", None) or [])
    ]
    if not boxes:
        return 0, 0, 1, 1
    x0 = min(b[0] for b in boxes)
    y0 = min(b[1] for b in boxes)
    x1 = max(b[0] + b[2] for b in boxes)
    y1 = max(b[1] + b[3] for b in boxes)
    return x0, y0, x1 - x0, y1 - y0


def _grid(p: Path, name: str, layer: Any, col0: int, row0: int, cols: int, rows: int) -> np.ndarray:
    out = np.zeros((rows, cols), np.uint32)
    try:
        if layer.chunks:
            for ch in layer.chunks:
                data = np.asarray(ch.data, np.int64).reshape(
                    int(ch.size.height), int(ch.size.width)
                )
                y, x = int(ch.coordinates.y) - row0, int(ch.coordinates.x) - col0
                out[y : y + data.shape[0], x : x + data.shape[1]] = data
        elif layer.data:
            data = np.asarray(layer.data, np.int64)
            out[: data.shape[0], : data.shape[1]] = data.reshape(data.shape[0], -1)
    except (ValueError, TypeError) as exc:
        raise TilemapError(f"{p}: layer {name!r}: tile data does not fit the map ({exc})") from exc
    return out


def _tilesets(p: Path, raw: dict[int, Any]) -> tuple[list[TilesetData], GidTable]:
    sets: list[TilesetData] = []
    size = 1
    for firstgid, ts in sorted(raw.items()):
        ids = [int(t) for t in (ts.tiles or {})]
        count = max([int(ts.tile_count or 0), *(i + 1 for i in ids)])
        size = max(size, firstgid + count)
    table = GidTable(
        size=size,
        tileset=np.full(size, -1, np.int16),
        image=np.full(size, -1, np.int32),
        rect=np.zeros((size, 4), np.int32),
        offset=np.zeros((size, 2), np.int32),
        kind=np.zeros(size, np.uint8),
    )
    image_ids: dict[Path, int] = {}

    def image_id(img: Path, w: int, h: int, what: str) -> int:
        img = img if img.is_absolute() else p.parent / img
        _need(p, what, img)
        if img not in image_ids:
            image_ids[img] = len(table.images)
            table.images.append(img)
            table.image_sizes.append((w, h))
        return image_ids[img]

    for index, (firstgid, ts) in enumerate(sorted(raw.items())):
        count = max([int(ts.tile_count or 0), *(int(i) + 1 for i in (ts.tiles or {}))])
        offset = (
            (0, 0) if ts.tile_offset is None else (int(ts.tile_offset.x), int(ts.tile_offset.y))
        )
        tw, th = int(ts.tile_width), int(ts.tile_height)
        sheet = None if ts.image is None else Path(ts.image)
        sets.append(
            TilesetData(
                ts.name,
                firstgid,
                count,
                tw,
                th,
                int(ts.columns or 0),
                int(ts.spacing or 0),
                int(ts.margin or 0),
                sheet,
                offset,
            )
        )
        span = slice(firstgid, firstgid + count)
        table.offset[span] = offset
        if sheet is not None:
            img = image_id(
                sheet,
                int(ts.image_width or 0),
                int(ts.image_height or 0),
                f"tileset {ts.name!r}: image",
            )
            cols = max(int(ts.columns or 1), 1)
            local = np.arange(int(ts.tile_count or 0))
            sheet_gids = firstgid + local
            table.tileset[sheet_gids] = index
            table.image[sheet_gids] = img
            step_x, step_y = tw + int(ts.spacing or 0), th + int(ts.spacing or 0)
            table.rect[sheet_gids, 0] = int(ts.margin or 0) + (local % cols) * step_x
            table.rect[sheet_gids, 1] = int(ts.margin or 0) + (local // cols) * step_y
            table.rect[sheet_gids, 2] = tw
            table.rect[sheet_gids, 3] = th
        tileset_props = dict(ts.properties or {})
        for tid, tile in (ts.tiles or {}).items():
            g = firstgid + int(tid)
            table.tileset[g] = index
            if tile.image is not None:
                w, h = int(tile.image_width or tw), int(tile.image_height or th)
                table.image[g] = image_id(
                    Path(tile.image), w, h, f"tileset {ts.name!r}: tile {tid} image"
                )
                if tile.width and tile.height:  # a sub-rectangle of the image (Tiled 1.9+)
                    table.rect[g] = (int(tile.x), int(tile.y), int(tile.width), int(tile.height))
                else:
                    table.rect[g] = (0, 0, w, h)
            props = {**tileset_props, **dict(tile.properties or {})}
            if props:
                table.properties[g] = props
            if tile.class_:
                table.classes[g] = tile.class_
            shapes = _tile_shapes(tile)
            if shapes:
                table.shapes[g] = shapes
            if tile.animation:
                frames = np.array([firstgid + int(f.tile_id) for f in tile.animation], np.uint32)
                ends = np.cumsum([max(int(f.duration), 1) / 1000.0 for f in tile.animation])
                table.animations[g] = (frames, ends)
        if tileset_props:
            for g in range(firstgid, firstgid + count):
                table.properties.setdefault(g, dict(tileset_props))
    _classify(table)
    return sets, table


def _tile_shapes(tile: Any) -> list[TileShape]:
    import pytiled_parser.tiled_object as to

    layer = tile.objects
    out: list[TileShape] = []
    for obj in getattr(layer, "tiled_objects", None) or []:
        x, y = float(obj.coordinates.x), float(obj.coordinates.y)
        w, h = float(obj.size.width), float(obj.size.height)
        if isinstance(obj, to.Ellipse):
            out.append(TileShape("ellipse", x, y, w, h))
        elif isinstance(obj, (to.Polygon, to.Polyline)):
            pts = tuple((float(q.x), float(q.y)) for q in obj.points)
            out.append(TileShape("polygon", x, y, points=pts))
        elif isinstance(obj, to.Rectangle) and w > 0 and h > 0:
            out.append(TileShape("rectangle", x, y, w, h))
    return out


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


def _classify(table: GidTable) -> None:
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
