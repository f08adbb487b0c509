"""Pure-data components of entities made from a Tiled map.

:class:`MapObject` is on every entity spawned from a map object (it carries the
object's Tiled name, class and custom properties, so game code can query them);
:class:`TileCollider` marks the static colliders built from tile layers.

>>> MapObject(map="level.tmx", layer="Objects", id=3, name="coin", cls="Coin",
...           kind="point", properties={"value": 5}).properties["value"]
5
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any


@dataclass(slots=True)
class MapObject:
    """A Tiled object this entity was spawned from."""

    map: str  #: the map file
    layer: str  #: object layer name (group path with '/')
    id: int  #: Tiled's object id (unique in the map)
    name: str
    cls: str  #: Tiled class (or the older "type"); for tile objects the tile's class by default
    kind: str  #: "rectangle", "ellipse", "polygon", "polyline", "point", "tile" or "text"
    properties: dict[str, Any] = field(default_factory=dict)
    size: tuple[float, float] = (0.0, 0.0)  #: width, height in metres (rectangles, ellipses, tiles)
    points: tuple[
        tuple[float, float], ...
    ] = ()  #: polygon/polyline points relative to the Transform, metres


@dataclass(slots=True)
class TileCollider:
    """A static collider built from a tile layer (outline, one-way run or tile shape)."""

    layer: str
    kind: str  #: "outline", "one_way" or "tile"
    cells: tuple[int, int, int, int]  #: (col0, row0, col1, row1) grid corners it covers
