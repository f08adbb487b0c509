"""Tilesets -> :class:`~kge.tilemap.model.GidTable` (per-gid arrays) and Wang sets.

Sizes are checked before the table is allocated (``firstgid`` >= 1, tile counts,
the highest gid against :class:`~kge.tilemap.files.MapLimits`). What old files
omit gets Tiled's defaults: ``tilecount`` and ``columns`` (Tiled before 0.15)
are computed from the image; terrains (Tiled 0.9-1.4) and the edge/corner Wang
sets of Tiled 1.1-1.4 become Tiled 1.5's Wang sets.
"""

from __future__ import annotations

import itertools
from pathlib import Path
from typing import Any

import numpy as np

from kge.tilemap.errors import TilemapError
from kge.tilemap.files import MapReader
from kge.tilemap.model import GidTable, TilesetData, TileShape, WangSet
from kge.tilemap.tileshapes import classify
from kge.tilemap.values import color, number, properties


def _shapes(tile: dict[str, Any], where: str) -> list[TileShape]:
    out: list[TileShape] = []
    for o in (tile.get("objectgroup") or {}).get("objects") or []:
        x = number(o, "x", where, "collision shape", 0.0, integer=False)
        y = number(o, "y", where, "collision shape", 0.0, integer=False)
        w = number(o, "width", where, "collision shape", 0.0, integer=False, minimum=0)
        h = number(o, "height", where, "collision shape", 0.0, integer=False, minimum=0)
        if o.get("ellipse"):
            out.append(TileShape("ellipse", x, y, w, h))
        elif o.get("polygon") or o.get("polyline"):
            raw = o.get("polygon") or o.get("polyline")
            pts = [(float(p["x"]), float(p["y"])) for p in raw]
            if len(pts) > 3 and pts[0] == pts[-1]:
                pts = pts[:-1]  # a polyline drawn closed: its last point repeats the first
            if len(pts) >= 3:
                out.append(TileShape("polygon", x, y, points=tuple(pts)))
        elif not o.get("point") and w > 0 and h > 0:
            out.append(TileShape("rectangle", x, y, w, h))
    return out


class TilesetBuilder:
    def __init__(self, reader: MapReader) -> None:
        self.reader = reader
        self.image_ids: dict[Path, int] = {}

    def image(
        self, table: GidTable, owner: Path, name: str, what: str, key: Any
    ) -> tuple[int, tuple[int, int]]:
        path = self.reader.resolve(owner, name)
        keyc = None if not key else color(key, str(owner), f"{what}: transparent colour")[:3]
        if path not in self.image_ids:
            size = self.reader.image_size(owner, path, what)
            self.image_ids[path] = len(table.images)
            table.images.append(path)
            table.image_sizes.append(size)
            table.image_keys.append(keyc)
        i = self.image_ids[path]
        return i, table.image_sizes[i]

    def build(self, raw: list[dict[str, Any]]) -> tuple[list[TilesetData], GidTable]:
        limits = self.reader.limits
        plans = []
        for ts in raw:
            owner: Path = ts["_file"]
            name = str(ts.get("name", ""))
            where = f"{owner}: tileset {name!r}"
            first = number(ts, "firstgid", f"{self.reader.map}", f"tileset {name!r}", 1, minimum=1)
            limits.check(f"{where}: firstgid", first, "gids")
            tw = number(ts, "tilewidth", where, "tileset", minimum=1, since="0.9")
            th = number(ts, "tileheight", where, "tileset", minimum=1, since="0.9")
            spacing = number(ts, "spacing", where, "tileset", 0, minimum=0)
            margin = number(ts, "margin", where, "tileset", 0, minimum=0)
            tiles = [t for t in ts.get("tiles") or [] if isinstance(t, dict)]
            ids = [number(t, "id", where, "tile", minimum=0) for t in tiles]
            count = number(ts, "tilecount", where, "tileset", -1, minimum=0)
            columns = number(ts, "columns", where, "tileset", -1, minimum=0)
            plans.append(
                (ts, owner, name, where, first, tw, th, spacing, margin, tiles, ids, count, columns)
            )
        # sheet sizes come from the image headers (checked against the pixel limit)
        table_images: list[tuple[int, tuple[int, int]] | None] = []
        scratch = GidTable(0, *(np.zeros(0) for _ in range(5)))  # type: ignore[arg-type]
        size = 1
        finals = []
        for ts, owner, name, where, first, tw, th, sp, mg, _tiles, ids, count, columns in plans:
            img = None
            if ts.get("image"):
                img = self.image(
                    scratch,
                    owner,
                    str(ts["image"]),
                    f"tileset {name!r}: image",
                    ts.get("transparentcolor"),
                )
                iw, ih = img[1]
                fit_c = max((iw - 2 * mg + sp) // (tw + sp), 0)
                fit_r = max((ih - 2 * mg + sp) // (th + sp), 0)
                columns = fit_c if columns < 0 else columns
                count = fit_c * fit_r if count < 0 else count
            table_images.append(img)
            limits.check(f"{where}: tilecount", max(count, 0), "tilecount")
            n = max([max(count, 0), *(i + 1 for i in ids)])
            limits.check(f"{where}: tile ids", n, "tilecount")
            finals.append((max(count, 0), max(columns, 0)))
            size = max(size, first + n)
            limits.check(f"{where}: the highest gid + 1", first + n, "gids")
        spans = sorted(
            (p[4], p[4] + max([f, *(i + 1 for i in p[10])]), p[2])
            for p, (f, _) in zip(plans, finals, strict=True)
        )
        for (a0, a1, an), (b0, _, bn) in itertools.pairwise(spans):
            if b0 < a1:
                raise TilemapError(
                    f"{self.reader.map}: tilesets {an!r} (gids {a0}-{a1 - 1}) and {bn!r} "
                    f"(from gid {b0}) overlap: a firstgid is wrong"
                )
        table = GidTable(
            size=size,
            tileset=np.full(size, -1, np.int16),
            image=np.full(size, -1, np.int32),
            rect=np.zeros((size, 4), np.int32),
            offset=np.zeros((size, 2), np.int32),
            kind=np.zeros(size, np.uint8),
            images=scratch.images,
            image_sizes=scratch.image_sizes,
            image_keys=scratch.image_keys,
        )
        sets = []
        for index, (plan, img, (count, cols)) in enumerate(
            zip(plans, table_images, finals, strict=True)
        ):
            sets.append(self._fill(table, index, (*plan[:-1], cols), img, count))
        classify(table)
        return sets, table

    def _fill(
        self,
        table: GidTable,
        index: int,
        plan: tuple[Any, ...],
        img: tuple[int, tuple[int, int]] | None,
        count: int,
    ) -> TilesetData:
        ts, owner, name, where, first, tw, th, sp, mg, tiles, ids, _, columns = plan
        off = ts.get("tileoffset") or {}
        offset = (
            int(number(off, "x", where, "tileoffset", 0)),
            int(number(off, "y", where, "tileoffset", 0)),
        )
        n = max([count, *(i + 1 for i in ids)])
        span = slice(first, first + n)
        table.offset[span] = offset
        if img is not None:
            cols = max(columns, 1)
            local = np.arange(count)
            g = first + local
            table.tileset[g] = index
            table.image[g] = img[0]
            table.rect[g, 0] = mg + (local % cols) * (tw + sp)
            table.rect[g, 1] = mg + (local // cols) * (th + sp)
            table.rect[g, 2] = tw
            table.rect[g, 3] = th
        ts_props = properties(ts.get("properties"), where)
        for tid, tile in zip(ids, tiles, strict=True):
            g = first + tid
            table.tileset[g] = index
            tw_where = f"{where}: tile {tid}"
            if tile.get("image"):
                i, (w, h) = self.image(
                    table,
                    owner,
                    str(tile["image"]),
                    f"{tw_where} image",
                    ts.get("transparentcolor"),
                )
                table.image[g] = i
                sub_w = number(tile, "width", tw_where, "tile", 0, minimum=0)
                sub_h = number(tile, "height", tw_where, "tile", 0, minimum=0)
                if sub_w and sub_h:  # a sub-rectangle of the image (Tiled 1.9+)
                    x = number(tile, "x", tw_where, "tile", 0, minimum=0)
                    y = number(tile, "y", tw_where, "tile", 0, minimum=0)
                    if x + sub_w > w or y + sub_h > h:
                        raise TilemapError(f"{tw_where}: sub-rectangle outside its {w}x{h} image")
                    table.rect[g] = (x, y, sub_w, sub_h)
                else:
                    table.rect[g] = (0, 0, w, h)
            elif table.image[g] < 0:
                raise TilemapError(
                    f"{tw_where}: no image (the tileset has no sheet and the tile no image)"
                )
            props = {**ts_props, **properties(tile.get("properties"), tw_where)}
            if props:
                table.properties[g] = props
            if tile.get("class"):
                table.classes[g] = str(tile["class"])
            shapes = _shapes(tile, tw_where)
            if shapes:
                table.shapes[g] = shapes
            anim = tile.get("animation")
            if anim:
                table.animations[g] = self._animation(table, first, n, anim, tw_where)
        if ts_props:
            for g in range(first, first + n):
                table.properties.setdefault(g, dict(ts_props))
        data = TilesetData(
            name,
            first,
            n,
            tw,
            th,
            max(columns, 0),
            sp,
            mg,
            None if img is None else table.images[img[0]],
            offset,
        )
        data.wangsets = wangsets(ts, first, n, where)
        return data

    @staticmethod
    def _animation(
        table: GidTable, first: int, n: int, anim: Any, where: str
    ) -> tuple[np.ndarray, np.ndarray]:
        frames, ms = [], []
        for f in anim:
            tid = number(f, "tileid", where, "animation frame", minimum=0)
            dur = number(f, "duration", where, "animation frame", 100, minimum=0)
            if tid >= n or table.image[first + tid] < 0:
                raise TilemapError(
                    f"{where}: animation frame names tile {tid}, which does not exist"
                )
            frames.append(first + tid)
            ms.append(max(dur, 1))
        return np.array(frames, np.uint32), np.cumsum(np.array(ms, float) / 1000.0)


def _wang_ids(raw: Any, where: str) -> list[int]:
    if isinstance(raw, str) and raw.lower().startswith("0x"):  # Tiled 1.1-1.4 TMX
        v = int(raw, 16)
        return [(v >> (4 * i)) & 0xF for i in range(8)]
    if isinstance(raw, str):
        raw = raw.split(",")
    try:
        ids = [int(x) for x in raw]
    except (TypeError, ValueError):
        raise TilemapError(f"{where}: wangid {raw!r} is not 8 colour numbers") from None
    if len(ids) != 8 or min(ids) < 0 or max(ids) > 254:
        raise TilemapError(f"{where}: wangid {raw!r} is not 8 colour numbers 0-254")
    return ids


def wangsets(ts: dict[str, Any], first: int, n: int, where: str) -> list[WangSet]:
    out = []
    terrains = ts.get("terrains")
    if terrains:  # Tiled 0.9-1.4: corner terrains per tile, "tl,tr,bl,br"
        gids, ids = [], []
        for t in ts.get("tiles") or []:
            raw = t.get("terrain")
            if raw is None:
                continue
            parts = raw.split(",") if isinstance(raw, str) else list(raw)
            c = [int(p) + 1 if str(p).strip() not in ("", "-1") else 0 for p in parts]
            if len(c) != 4:
                raise TilemapError(f"{where}: tile {t.get('id')}: terrain {raw!r} is not 4 corners")
            tl, tr, bl, br = c
            gids.append(first + int(t["id"]))
            ids.append([0, tr, 0, br, 0, bl, 0, tl])
        names = [str(t.get("name", f"terrain {i}")) for i, t in enumerate(terrains)]
        out.append(_set("terrains", "corner", names, gids, ids, None))
    for w in ts.get("wangsets") or []:
        name = str(w.get("name", ""))
        colors = w.get("colors") or []
        edges, corners = w.get("edgecolors") or [], w.get("cornercolors") or []
        old = not colors and (edges or corners)
        gids, ids, probs = [], [], []
        for t in w.get("wangtiles") or []:
            tid = number(t, "tileid", where, f"wang set {name!r} tile", minimum=0)
            if tid >= n:
                raise TilemapError(
                    f"{where}: wang set {name!r} names tile {tid}, which does not exist"
                )
            wid = _wang_ids(t.get("wangid"), f"{where}: wang set {name!r}: tile {tid}")
            if old:  # edges index edgecolors, corners cornercolors: one list, edges first
                wid = [v if i % 2 == 0 or v == 0 else v + len(edges) for i, v in enumerate(wid)]
            gids.append(first + tid)
            ids.append(wid)
            probs.append(1.0)
        if old:
            names = [str(c.get("name", "")) for c in (*edges, *corners)]
            kind = "mixed" if edges and corners else ("edge" if edges else "corner")
        else:
            names = [str(c.get("name", "")) for c in colors]
            kind = str(w.get("type", "mixed"))
            if kind not in ("corner", "edge", "mixed"):
                raise TilemapError(
                    f"{where}: wang set {name!r}: type {kind!r} is not corner, edge or mixed"
                )
        if ids and max(max(i) for i in ids) > len(names):
            raise TilemapError(
                f"{where}: wang set {name!r}: a tile names a colour it does not define"
            )
        out.append(_set(name, kind, names, gids, ids, probs))
    return out


def _set(
    name: str, kind: str, colors: list[str], gids: list[int], ids: list[list[int]], probs: Any
) -> WangSet:
    return WangSet(
        name,
        kind,
        colors,
        np.array(gids, np.uint32),
        np.array(ids, np.uint8).reshape(-1, 8),
        np.array(probs if probs is not None else [1.0] * len(gids), float),
    )
