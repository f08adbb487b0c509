"""A loaded Tiled map as plain data: numpy gid grids and per-gid lookup tables.

Everything here is independent of the file formats (see :mod:`kge.tilemap.parse`)
and of GL: the collision builder, the object spawner and the renderer read it.

Grids keep Tiled's order (row 0 at the top). Tiled stores flips in the top bits
of each gid; they are split off into a ``flags`` grid (``FLIP_H | FLIP_V |
FLIP_D``) so ``gids`` indexes the lookup tables directly.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from kge.tilemap.grid import GridShape
from kge.tilemap.units import MapUnits

TILED_FLIP_H = 0x80000000
TILED_FLIP_V = 0x40000000
TILED_FLIP_D = 0x20000000
TILED_ROT_HEX = 0x10000000
GID_MASK = 0x0FFFFFFF
#: bits of the ``flags`` grids
FLIP_H, FLIP_V, FLIP_D = 1, 2, 4

#: collision kind of a gid
EMPTY, SOLID, ONE_WAY, SHAPES = 0, 1, 2, 3

RGBA = tuple[int, int, int, int]


def split_gids(raw: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Tiled's raw gids (flip bits on top) -> (gids, flags).

    >>> g, f = split_gids(np.array([5, 5 | TILED_FLIP_H | TILED_FLIP_D], np.uint32))
    >>> g.tolist(), f.tolist()
    ([5, 5], [0, 5])
    """
    raw = raw.astype(np.uint32, copy=False)
    gids = raw & np.uint32(GID_MASK)
    flags = (
        ((raw & np.uint32(TILED_FLIP_H)) != 0) * FLIP_H
        + ((raw & np.uint32(TILED_FLIP_V)) != 0) * FLIP_V
        + ((raw & np.uint32(TILED_FLIP_D)) != 0) * FLIP_D
    ).astype(np.uint8)
    return gids, flags


@dataclass(slots=True)
class TileShape:
    """One collision object of a tile (Tiled's collision editor), tile pixels, y down."""

    kind: str  #: "rectangle", "ellipse" or "polygon"
    x: float
    y: float
    width: float = 0.0
    height: float = 0.0
    points: tuple[tuple[float, float], ...] = ()  #: polygon points relative to (x, y)


@dataclass(slots=True)
class TilesetData:
    name: str
    firstgid: int
    count: int  #: local ids 0..count-1
    tile_w: int
    tile_h: int
    columns: int
    spacing: int
    margin: int
    image: Path | None  #: the sheet (None for an image collection)
    offset: tuple[int, int] = (0, 0)  #: Tiled's tileoffset, pixels
    wangsets: list[WangSet] = field(default_factory=list)


@dataclass(slots=True)
class WangSet:
    """A terrain (Wang) set: colours and, per tile, the colour at its 8 corners and edges.

    ``wangids`` rows follow Tiled's order: top, top-right, right, bottom-right,
    bottom, bottom-left, left, top-left (0 = no colour). Tiled 0.9-1.4 terrains
    and 1.1-1.4 Wang sets are converted to this (Tiled 1.5's) form on load.
    """

    name: str
    kind: str  #: "corner", "edge" or "mixed"
    colors: list[str]  #: colour names; colour i is ``i + 1`` in wangids
    gids: np.ndarray  #: (n,) uint32 tiles of the set
    wangids: np.ndarray  #: (n, 8) uint8
    probability: np.ndarray  #: (n,) float: how often a matching tile is picked


@dataclass(slots=True)
class ObjectData:
    """One Tiled object (templates applied), Tiled pixels, y down."""

    id: int
    name: str
    cls: str
    kind: str  #: rectangle, ellipse, point, polygon, polyline, tile or text
    x: float
    y: float
    width: float = 0.0
    height: float = 0.0
    rotation: float = 0.0  #: degrees clockwise
    gid: int = 0  #: raw gid with Tiled's flip bits (tile objects)
    visible: bool = True
    points: tuple[tuple[float, float], ...] = ()
    text: dict[str, Any] = field(default_factory=dict)  #: text objects: text, pixelsize...
    properties: dict[str, Any] = field(default_factory=dict)


@dataclass(slots=True)
class LayerStyle:
    """What a layer (and the groups around it) does to its drawing."""

    opacity: float = 1.0
    visible: bool = True
    tint: RGBA = (255, 255, 255, 255)
    offset: tuple[float, float] = (0.0, 0.0)  #: pixels, y down
    parallax: tuple[float, float] = (1.0, 1.0)

    def nested(self, inner: LayerStyle) -> LayerStyle:
        """The style of a layer inside a group with this style (Tiled multiplies/adds)."""
        return LayerStyle(
            opacity=self.opacity * inner.opacity,
            visible=self.visible and inner.visible,
            tint=tuple(a * b // 255 for a, b in zip(self.tint, inner.tint, strict=True)),  # type: ignore[arg-type]
            offset=(self.offset[0] + inner.offset[0], self.offset[1] + inner.offset[1]),
            parallax=(self.parallax[0] * inner.parallax[0], self.parallax[1] * inner.parallax[1]),
        )


@dataclass(slots=True)
class TileLayerData:
    name: str
    index: int  #: draw order among all layers of the map
    gids: np.ndarray  #: (rows, cols) uint32, 0 = empty
    flags: np.ndarray  #: (rows, cols) uint8 of FLIP_H | FLIP_V | FLIP_D
    style: LayerStyle
    properties: dict[str, Any]


@dataclass(slots=True)
class ImageLayerData:
    name: str
    index: int
    image: Path
    style: LayerStyle
    properties: dict[str, Any]
    repeat: tuple[bool, bool] = (False, False)
    size: tuple[int, int] = (0, 0)  #: the image's pixels
    key: tuple[int, int, int] | None = None  #: transparent colour


@dataclass(slots=True)
class ObjectLayerData:
    name: str
    index: int
    objects: list[ObjectData]  #: in file order
    style: LayerStyle
    properties: dict[str, Any]
    draworder: str = "topdown"


@dataclass(slots=True)
class GidTable:
    """Per-gid lookups, arrays indexed by gid (0 = empty)."""

    size: int
    tileset: np.ndarray  #: int16, -1 for gids in no tileset
    image: np.ndarray  #: int32 index into ``images``
    rect: np.ndarray  #: (n, 4) int32: x, y, w, h pixels in the image, y down from its top
    offset: np.ndarray  #: (n, 2) int32 tileoffset, pixels
    kind: np.ndarray  #: uint8 collision kind (EMPTY, SOLID, ONE_WAY, SHAPES)
    images: list[Path] = field(default_factory=list)
    image_sizes: list[tuple[int, int]] = field(default_factory=list)
    #: per image: the tileset's transparent colour (drawn fully transparent), or None
    image_keys: list[tuple[int, int, int] | None] = field(default_factory=list)
    shapes: dict[int, list[TileShape]] = field(default_factory=dict)
    properties: dict[int, dict[str, Any]] = field(default_factory=dict)
    classes: dict[int, str] = field(default_factory=dict)
    #: gid -> (frame gids, cumulative end times in seconds)
    animations: dict[int, tuple[np.ndarray, np.ndarray]] = field(default_factory=dict)

    def known(self, gids: np.ndarray) -> np.ndarray:
        """Boolean mask: gid is empty or belongs to a tileset."""
        inside = gids < self.size
        ok = np.zeros(gids.shape, bool)
        ok[inside] = self.tileset[gids[inside]] >= 0
        return ok | (gids == 0)


@dataclass(slots=True)
class MapData:
    path: Path
    units: MapUnits
    cols: int
    rows: int
    tilesets: list[TilesetData]
    tiles: GidTable
    tile_layers: list[TileLayerData]
    image_layers: list[ImageLayerData]
    object_layers: list[ObjectLayerData]
    properties: dict[str, Any]
    background: RGBA | None = None
    #: where the camera centre must be for parallax layers to sit at their map position
    #: (Tiled's parallax origin, default the map's top-left corner), world metres
    parallax_origin: tuple[float, float] = (0.0, 0.0)
    grid: GridShape | None = None  #: the cells' geometry (orientation)
    version: str = ""  #: the file format version the map was saved in

    @property
    def orientation(self) -> str:
        return self.grid.orientation if self.grid is not None else "orthogonal"

    def layer(self, name: str) -> TileLayerData:
        for layer in self.tile_layers:
            if layer.name == name:
                return layer
        names = ", ".join(repr(t.name) for t in self.tile_layers) or "none"
        from kge.tilemap.errors import TilemapError

        raise TilemapError(f"{self.path}: no tile layer {name!r} (tile layers: {names})")
