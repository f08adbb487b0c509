"""Tiled files (TMX/TSX/TX or JSON) -> :class:`~kge.tilemap.model.MapData`.

kge reads Tiled's files itself (:mod:`kge.tilemap.source`), so that every file
a map names is read through one confined reader with size limits
(:mod:`kge.tilemap.files`), every version of the format since Tiled 1.0 gets
Tiled's defaults for what it omits, and every refusal is a
:class:`TilemapError` naming the file, the layer and what is wrong, raised
before anything is allocated or spawned.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Iterator
from pathlib import Path
from typing import Any

import numpy as np

from kge.tilemap.errors import TilemapError
from kge.tilemap.files import MapLimits, MapReader
from kge.tilemap.grid import ORIENTATIONS, GridShape
from kge.tilemap.layerdata import decode_tiles
from kge.tilemap.model import (
    GID_MASK,
    ImageLayerData,
    LayerStyle,
    MapData,
    ObjectData,
    ObjectLayerData,
    TileLayerData,
    split_gids,
)
from kge.tilemap.source import MapSource
from kge.tilemap.tilesets import TilesetBuilder
from kge.tilemap.tileshapes import covers_tile
from kge.tilemap.units import MapUnits
from kge.tilemap.values import color, flag, number, properties

__all__ = ["covers_tile", "read_map"]


def read_map(
    path: str | os.PathLike[str],
    *,
    pixels_per_meter: float | None = None,
    origin: tuple[float, float] = (0.0, 0.0),
    roots: Iterable[str | os.PathLike[str]] = (),
    limits: MapLimits | None = None,
) -> MapData:
    """Parse the map at ``path``; ``pixels_per_meter`` defaults to the tile width.

    ``roots`` are folders besides the map's own that its tilesets, templates
    and images may be in; ``limits`` bounds sizes (see :class:`MapLimits`).
    """
    p = Path(os.path.abspath(path))
    if not p.is_file():
        raise TilemapError(f"map file {str(path)!r} not found")
    reader = MapReader(p, roots, limits)
    try:
        return _build(MapSource(reader), pixels_per_meter, origin)
    except TilemapError:
        raise
    except (KeyError, TypeError, ValueError, AttributeError, IndexError, OverflowError) as exc:
        raise TilemapError(f"{p}: cannot read the map ({type(exc).__name__}: {exc})") from exc
    except RecursionError:
        raise TilemapError(f"{p}: the file nests too deeply to be a Tiled map") from None


def _style(d: dict[str, Any], where: str) -> LayerStyle:
    tint = d.get("tintcolor")
    return LayerStyle(
        opacity=min(max(number(d, "opacity", where, "layer", 1.0, integer=False), 0.0), 1.0),
        visible=flag(d, "visible", True),
        tint=(255, 255, 255, 255) if not tint else color(tint, where, "tintcolor"),
        offset=(
            number(d, "offsetx", where, "layer", 0.0, integer=False),
            number(d, "offsety", where, "layer", 0.0, integer=False),
        ),
        parallax=(
            number(d, "parallaxx", where, "layer", 1.0, integer=False),
            number(d, "parallaxy", where, "layer", 1.0, integer=False),
        ),
    )


def _flatten(
    layers: list[Any], outer: LayerStyle, prefix: str, where: str
) -> Iterator[tuple[str, dict[str, Any], LayerStyle]]:
    """Leaf layers in draw order, each with its name path and combined style."""
    for d in layers:
        name = f"{prefix}{d.get('name', '')}"
        style = outer.nested(_style(d, f"{where}: layer {name!r}"))
        if d.get("type") == "group":
            yield from _flatten(d.get("layers") or [], style, f"{name}/", where)
        elif d.get("type") in ("tilelayer", "objectgroup", "imagelayer"):
            yield name, d, style
        else:
            raise TilemapError(f"{where}: layer {name!r} has unknown type {d.get('type')!r}")


def _grid_shape(doc: dict[str, Any], where: str, limits: MapLimits) -> GridShape:
    orientation = str(doc.get("orientation", "orthogonal"))
    if orientation not in ORIENTATIONS:
        raise TilemapError(
            f"{where}: orientation {orientation!r} is not a Tiled orientation "
            f"({', '.join(ORIENTATIONS)})"
        )
    cols = number(doc, "width", where, "map", minimum=0)
    rows = number(doc, "height", where, "map", minimum=0)
    tw = number(doc, "tilewidth", where, "map", minimum=1)
    th = number(doc, "tileheight", where, "map", minimum=1)
    limits.check(f"{where}: the map's width x height in tiles", cols * rows, "tiles")
    axis = str(doc.get("staggeraxis", "y"))
    index = str(doc.get("staggerindex", "odd"))
    if axis not in ("x", "y") or index not in ("odd", "even"):
        raise TilemapError(
            f"{where}: staggeraxis {axis!r} / staggerindex {index!r} are not x|y / odd|even"
        )
    side = number(doc, "hexsidelength", where, "map", 0, minimum=0)
    return GridShape(orientation, tw, th, cols, rows, axis, index, side)


def _extent(
    doc: dict[str, Any], flat: list[Any], grid: GridShape, where: str, limits: MapLimits
) -> tuple[int, int, int, int]:
    """(first column, first row, columns, rows) of the grid holding every layer."""
    if not flag(doc, "infinite", False):  # maps before Tiled 1.1 have no "infinite"
        return 0, 0, grid.cols, grid.rows
    if grid.orientation != "orthogonal":
        raise TilemapError(
            f"{where}: infinite {grid.orientation} maps are not supported; in Tiled uncheck "
            "Map > Map Properties > Infinite (kge reads infinite orthogonal maps)"
        )
    boxes = []
    for name, d, _ in flat:
        for ch in d.get("chunks") or []:
            w = f"{where}: layer {name!r}: chunk"
            boxes.append(
                (
                    number(ch, "x", w, "chunk"),
                    number(ch, "y", w, "chunk"),
                    number(ch, "width", w, "chunk", minimum=1),
                    number(ch, "height", w, "chunk", minimum=1),
                )
            )
    if not boxes:
        return 0, 0, 1, 1
    x0 = min(b[0] for b in boxes)
    y0 = min(b[1] for b in boxes)
    x1 = max(b[0] + b[2] for b in boxes)
    y1 = max(b[1] + b[3] for b in boxes)
    limits.check(
        f"{where}: the chunks' span ({x1 - x0} x {y1 - y0} tiles)", (x1 - x0) * (y1 - y0), "tiles"
    )
    return x0, y0, x1 - x0, y1 - y0


def _tile_grid(
    d: dict[str, Any], where: str, col0: int, row0: int, cols: int, rows: int
) -> np.ndarray:
    chunks = d.get("chunks")
    out = np.zeros((rows, cols), np.uint32)
    if chunks:
        for ch in chunks:
            w, h = int(ch["width"]), int(ch["height"])
            data = decode_tiles(ch.get("data"), w * h, f"{where}: chunk at {ch['x']},{ch['y']}")
            y, x = int(ch["y"]) - row0, int(ch["x"]) - col0
            out[y : y + h, x : x + w] = data.reshape(h, w)
        return out
    if "data" not in d:
        return out
    lw = number(d, "width", where, "tile layer", cols, minimum=0)
    lh = number(d, "height", where, "tile layer", rows, minimum=0)
    if (lw, lh) != (cols, rows):
        raise TilemapError(f"{where}: the layer is {lw} x {lh} tiles, the map {cols} x {rows}")
    out[:] = decode_tiles(d["data"], cols * rows, where).reshape(rows, cols)
    return out


class _Objects:
    """Object dicts (templates applied) -> :class:`ObjectData`, with unique ids."""

    def __init__(self, source: MapSource, tilesets: list[dict[str, Any]], limits: MapLimits):
        self.source = source
        self.tilesets = tilesets
        self.limits = limits
        self.count = 0
        self.used: set[int] = set()
        self.pending: list[ObjectData] = []

    def _template(self, o: dict[str, Any], where: str) -> dict[str, Any]:
        t = self.source.template(self.source.path, str(o["template"]))
        merged = {**t["object"], **{k: v for k, v in o.items() if k != "template"}}
        if "properties" in o and "properties" in t["object"]:
            names = {p.get("name") for p in o["properties"]}
            merged["properties"] = [
                *(p for p in t["object"]["properties"] if p.get("name") not in names),
                *o["properties"],
            ]
        ts = t.get("tileset")
        if "gid" in t["object"] and "gid" not in o and isinstance(ts, dict):
            merged["gid"] = self._template_gid(int(t["object"]["gid"]), ts, where)
        return merged

    def _template_gid(self, gid: int, ts: dict[str, Any], where: str) -> int:
        local = (gid & GID_MASK) - int(ts.get("firstgid", 1))
        for m in self.tilesets:
            if m.get("_file") == ts.get("_path"):
                return (gid & ~GID_MASK & 0xFFFFFFFF) | (int(m["firstgid"]) + local)
        raise TilemapError(
            f"{where}: its template's tileset {ts.get('source')!r} is not one of the map's "
            "tilesets (add it to the map in Tiled)"
        )

    def convert(self, o: dict[str, Any], where: str) -> ObjectData:
        self.count += 1
        self.limits.check(f"{self.source.path}: the number of objects", self.count, "objects")
        if o.get("template"):
            o = self._template(o, where)
        oid = number(o, "id", where, "object", 0, minimum=0)
        what = f"{where}: object {oid or '(no id)'}"
        gid = number(o, "gid", what, "object", 0, minimum=0)
        if gid > 0xFFFFFFFF:
            raise TilemapError(f"{what}: gid {gid} is not a gid (0 to 2^32 - 1)")
        kind = (
            "tile"
            if gid
            else "ellipse"
            if o.get("ellipse")
            else "point"
            if o.get("point")
            else "polygon"
            if o.get("polygon")
            else "polyline"
            if o.get("polyline")
            else "text"
            if isinstance(o.get("text"), dict)
            else "rectangle"
        )
        pts: tuple[tuple[float, float], ...] = ()
        if kind in ("polygon", "polyline"):
            pts = tuple((float(q["x"]), float(q["y"])) for q in o[kind])
        text = dict(o["text"]) if kind == "text" else {}
        if kind == "text" and "text" not in text:
            text["text"] = ""
        obj = ObjectData(
            id=oid,
            name=str(o.get("name", "")),
            cls=str(o.get("class", "") or ""),
            kind=kind,
            x=number(o, "x", what, "object", 0.0, integer=False),
            y=number(o, "y", what, "object", 0.0, integer=False),
            width=number(o, "width", what, "object", 0.0, integer=False, minimum=0),
            height=number(o, "height", what, "object", 0.0, integer=False, minimum=0),
            rotation=number(o, "rotation", what, "object", 0.0, integer=False),
            gid=gid,
            visible=flag(o, "visible", True),
            points=pts,
            text=text,
            properties=properties(o.get("properties"), what),
        )
        if oid:
            self.used.add(oid)
        else:  # objects before Tiled 0.11 have no id: numbered after the others
            self.pending.append(obj)
        return obj

    def finish(self) -> None:
        nxt = max(self.used, default=0) + 1
        for obj in self.pending:
            obj.id = nxt
            nxt += 1


def _build(source: MapSource, ppm_arg: float | None, origin: tuple[float, float]) -> MapData:
    doc, p, reader = source.doc, source.path, source.reader
    where = str(p)
    limits = reader.limits
    grid = _grid_shape(doc, where, limits)
    ppm = float(ppm_arg) if ppm_arg is not None else float(grid.tile_w)
    if not np.isfinite(ppm) or ppm <= 0:
        raise TilemapError(f"{p}: pixels_per_meter must be a positive number, got {ppm_arg!r}")
    tilesets, table = TilesetBuilder(reader).build(doc["tilesets"])
    flat = list(_flatten(doc["layers"], LayerStyle(), "", where))
    col0, row0, cols, rows = _extent(doc, flat, grid, where, limits)
    if (col0, row0, cols, rows) != (0, 0, grid.cols, grid.rows):
        grid = GridShape(
            grid.orientation,
            grid.tile_w,
            grid.tile_h,
            cols,
            rows,
            grid.stagger_axis,
            grid.stagger_index,
            grid.side,
            col0,
            row0,
        )
    height = None if grid.orientation == "orthogonal" else grid.size_px[1]
    units = MapUnits(
        grid.tile_w,
        grid.tile_h,
        ppm,
        col0,
        row0,
        rows,
        (float(origin[0]), float(origin[1])),
        height,
    )
    objects = _Objects(source, doc["tilesets"], limits)
    tile_layers: list[TileLayerData] = []
    image_layers: list[ImageLayerData] = []
    object_layers: list[ObjectLayerData] = []
    for index, (name, d, style) in enumerate(flat):
        lw = f"{p}: layer {name!r}"
        props = properties(d.get("properties"), lw)
        kind = d["type"]
        if kind == "tilelayer":
            gids, flags = split_gids(_tile_grid(d, lw, col0, row0, cols, rows))
            bad = ~table.known(gids)
            if bad.any():
                r, c = (int(v[0]) for v in np.nonzero(bad))
                raise TilemapError(
                    f"{lw}: tile id {int(gids[r, c])} at column {c + col0}, row {r + row0} "
                    "is in no tileset"
                )
            tile_layers.append(TileLayerData(name, index, gids, flags, style, props))
        elif kind == "imagelayer":
            if not d.get("image"):
                continue
            img = reader.resolve(p, str(d["image"]))
            size = reader.image_size(p, img, f"layer {name!r}: image")
            key = d.get("transparentcolor")
            image_layers.append(
                ImageLayerData(
                    name,
                    index,
                    img,
                    style,
                    props,
                    (flag(d, "repeatx", False), flag(d, "repeaty", False)),
                    size,
                    None if not key else color(key, lw, "transparent colour")[:3],
                )
            )
        else:
            objs = [objects.convert(o, lw) for o in d.get("objects") or []]
            for obj in objs:
                g = obj.gid & GID_MASK
                if obj.gid and (g >= table.size or table.tileset[g] < 0):
                    raise TilemapError(
                        f"{lw}: object {obj.id} ({obj.name!r}): tile id {g} is in no tileset"
                    )
            order = str(d.get("draworder", "topdown"))
            object_layers.append(ObjectLayerData(name, index, objs, style, props, order))
    objects.finish()
    bg = doc.get("backgroundcolor")
    po = (
        number(doc, "parallaxoriginx", where, "map", 0.0, integer=False),
        number(doc, "parallaxoriginy", where, "map", 0.0, integer=False),
    )
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
        properties=properties(doc.get("properties"), where),
        background=None if not bg else color(bg, where, "backgroundcolor"),
        parallax_origin=units.point(*po),
        grid=grid,
        version=str(doc.get("version", "")),
    )
