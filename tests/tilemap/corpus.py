"""A corpus of maps in every orientation, written as several Tiled versions write them.

Each case is (orientation, flavour): the flavour is the file format of one era
of Tiled (``tmx-1.0``: CSV, no ``tilecount``/``columns``/``infinite``, objects
without ids; ``tmx-1.4-zlib``: base64+zlib; ``tmx-1.10-gzip`` / ``-zstd``;
``json-1.2``: old JSON with properties as dicts; ``json-1.10``: current JSON).
:func:`expected` paints the picture Tiled draws, cell by cell from Tiled's own
placement rules (independent of kge's renderer), to compare pixels with.
"""

from __future__ import annotations

import base64
import gzip
import json
import zlib
from pathlib import Path
from typing import Any

import numpy as np

from kge.testbed import png

ORIENTATIONS = ("orthogonal", "isometric", "staggered", "hexagonal")
FLAVOURS = ("tmx-1.0", "tmx-1.4-zlib", "tmx-1.10-gzip", "tmx-1.10-zstd", "json-1.2", "json-1.10")
TILE = {"orthogonal": (16, 16), "isometric": (32, 16), "staggered": (32, 16), "hexagonal": (28, 24)}
SIDE = 12  # hexsidelength
COLS, ROWS = 5, 4
COLORS = [(220, 60, 40), (40, 190, 70), (50, 80, 220), (230, 210, 40)]


def cell_mask(orientation: str, w: int, h: int) -> np.ndarray:
    """The cell's shape inside its w x h box (diamond, hexagon or rectangle), pixel centres."""
    y, x = np.mgrid[0:h, 0:w] + 0.5
    if orientation == "orthogonal":
        return np.ones((h, w), bool)
    if orientation in ("isometric", "staggered"):
        return np.abs(x - w / 2) / (w / 2) + np.abs(y - h / 2) / (h / 2) <= 1.0
    b = (h - SIDE) / 2  # pointy-top hexagon, stagger axis y
    top = np.abs(x - w / 2) / (w / 2) * b
    return (y >= top) & (y <= h - top)


def sheet(orientation: str) -> np.ndarray:
    w, h = TILE[orientation]
    img = np.zeros((h, w * len(COLORS), 4), np.uint8)
    m = cell_mask(orientation, w, h)
    for i, c in enumerate(COLORS):
        tile = img[:, i * w : (i + 1) * w]
        tile[m] = (*c, 255)
        tile[m & (np.arange(h)[:, None] < h // 3)] = (*(v // 2 for v in c), 255)  # a darker top
    return img


def grid() -> np.ndarray:
    g = (np.arange(ROWS)[:, None] + 2 * np.arange(COLS)[None, :]) % (len(COLORS) + 1)
    return g.astype(np.int64)  # gid 0 (empty) where the pattern gives 0


def map_size(orientation: str) -> tuple[int, int]:
    tw, th = TILE[orientation]
    if orientation == "orthogonal":
        return COLS * tw, ROWS * th
    if orientation == "isometric":
        return (COLS + ROWS) * tw // 2, (COLS + ROWS) * th // 2
    side = SIDE if orientation == "hexagonal" else 0
    col_w = (tw - 0) // 2 + 0  # stagger axis y: the side is vertical
    row_h = (th - side) // 2 + side
    return COLS * tw + col_w, ROWS * row_h + (th - side) // 2


def cell_box(orientation: str, c: int, r: int) -> tuple[int, int]:
    """Top-left of the cell's box, from Tiled's tileToScreenCoords (stagger y, odd)."""
    tw, th = TILE[orientation]
    if orientation == "orthogonal":
        return c * tw, r * th
    if orientation == "isometric":
        return (c - r) * tw // 2 + ROWS * tw // 2 - tw // 2, (c + r) * th // 2
    side = SIDE if orientation == "hexagonal" else 0
    row_h = (th - side) // 2 + side
    return c * tw + (tw // 2 if r % 2 else 0), r * row_h


def expected(orientation: str) -> np.ndarray:
    """What Tiled draws: cells in its render order, each image over the previous ones."""
    w, h = map_size(orientation)
    out = np.zeros((h, w, 3), np.uint8)
    tiles = sheet(orientation)
    tw, th = TILE[orientation]
    g = grid()
    cells = [(c, r) for r in range(ROWS) for c in range(COLS)]
    if orientation == "isometric":
        cells.sort(key=lambda cr: (cr[0] + cr[1], cr[0]))
    for c, r in cells:
        gid = int(g[r, c])
        if not gid:
            continue
        x, y = cell_box(orientation, c, r)
        img = tiles[:, (gid - 1) * tw : gid * tw]
        a = img[..., 3:] > 0
        region = out[y : y + th, x : x + tw]
        region[:] = np.where(a, img[..., :3], region)
    return out


def _csv(g: np.ndarray) -> str:
    return "\n" + ",\n".join(",".join(str(int(v)) for v in row) for row in g) + "\n"


def _b64(g: np.ndarray, comp: str) -> str:
    raw = g.astype("<u4").tobytes()
    if comp == "zlib":
        raw = zlib.compress(raw)
    elif comp == "gzip":
        raw = gzip.compress(raw)
    elif comp == "zstd":
        import zstandard

        raw = zstandard.ZstdCompressor().compress(raw)
    return base64.b64encode(raw).decode()


def write(folder: Path, orientation: str, flavour: str) -> Path:
    """Write the case's map (and its sheet) into ``folder``; returns the map's path."""
    folder.mkdir(parents=True, exist_ok=True)
    tw, th = TILE[orientation]
    png.write(folder / "sheet.png", sheet(orientation))
    sw, sh = tw * len(COLORS), th
    g = grid()
    stagger = ""
    extra: dict[str, Any] = {}
    if orientation in ("staggered", "hexagonal"):
        stagger = ' staggeraxis="y" staggerindex="odd"'
        extra = {"staggeraxis": "y", "staggerindex": "odd"}
        if orientation == "hexagonal":
            stagger += f' hexsidelength="{SIDE}"'
            extra["hexsidelength"] = SIDE
    if flavour.startswith("tmx"):
        version = flavour.split("-")[1]
        if flavour == "tmx-1.0":  # no tilecount, columns, infinite; object without id
            ts = f'<tileset firstgid="1" name="s" tilewidth="{tw}" tileheight="{th}">'
            data = f'<data encoding="csv">{_csv(g)}</data>'
            obj = '<objectgroup name="o"><object name="spot" x="4" y="4"/></objectgroup>'
            head = ""
        else:
            ts = (
                f'<tileset firstgid="1" name="s" tilewidth="{tw}" tileheight="{th}" '
                f'tilecount="{len(COLORS)}" columns="{len(COLORS)}">'
            )
            comp = flavour.split("-")[2]
            data = f'<data encoding="base64" compression="{comp}">{_b64(g, comp)}</data>'
            obj = '<objectgroup id="2" name="o"><object id="1" name="spot" x="4" y="4"/></objectgroup>'
            head = ' infinite="0" nextlayerid="3" nextobjectid="2"'
        text = (
            f'<?xml version="1.0" encoding="UTF-8"?>\n<map version="{version}" '
            f'orientation="{orientation}" renderorder="right-down" width="{COLS}" '
            f'height="{ROWS}" tilewidth="{tw}" tileheight="{th}"{stagger}{head}>'
            f'{ts}<image source="sheet.png" width="{sw}" height="{sh}"/></tileset>'
            f'<layer name="ground" width="{COLS}" height="{ROWS}">{data}</layer>{obj}</map>\n'
        )
        path = folder / "map.tmx"
        path.write_text(text)
        return path
    old = flavour == "json-1.2"
    tileset: dict[str, Any] = {
        "firstgid": 1,
        "name": "s",
        "tilewidth": tw,
        "tileheight": th,
        "image": "sheet.png",
        "imagewidth": sw,
        "imageheight": sh,
        "margin": 0,
        "spacing": 0,
    }
    layer: dict[str, Any] = {
        "name": "ground",
        "type": "tilelayer",
        "width": COLS,
        "height": ROWS,
        "x": 0,
        "y": 0,
        "opacity": 1,
        "visible": True,
        "data": [int(v) for v in g.ravel()],
    }
    objects: dict[str, Any] = {
        "name": "o",
        "type": "objectgroup",
        "opacity": 1,
        "visible": True,
        "objects": [
            {
                "id": 1,
                "name": "spot",
                "type": "",
                "x": 4,
                "y": 4,
                "width": 0,
                "height": 0,
                "rotation": 0,
                "visible": True,
            }
        ],
    }
    doc: dict[str, Any] = {
        "type": "map",
        "orientation": orientation,
        "renderorder": "right-down",
        "width": COLS,
        "height": ROWS,
        "tilewidth": tw,
        "tileheight": th,
        "layers": [layer, objects],
        "tilesets": [tileset],
        **extra,
    }
    if old:  # Tiled 1.2: properties as a dict with propertytypes, no infinite
        doc.update(version=1.2, properties={"level": 3}, propertytypes={"level": "int"})
        tileset["tileproperties"] = {"0": {"solid": True}}
        tileset["tilepropertytypes"] = {"0": {"solid": "bool"}}
    else:
        doc.update(
            version="1.10",
            tiledversion="1.10.2",
            infinite=False,
            properties=[{"name": "level", "type": "int", "value": 3}],
        )
        tileset.update(
            tilecount=len(COLORS),
            columns=len(COLORS),
            tiles=[{"id": 0, "properties": [{"name": "solid", "type": "bool", "value": True}]}],
        )
    path = folder / "map.json"
    path.write_text(json.dumps(doc))
    return path
