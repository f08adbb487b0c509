"""Tiled maps: loading (kge's own TMX/TSX/TX and JSON reader), merged tile collision,
objects to entities.

No GL here: the drawing lives in :mod:`kge.render.tilemap` and is installed by
:class:`kge.systems.tilemap.TilemapPlugin`. See docs/tilemaps.md.
"""

from kge.tilemap.errors import TilemapError, TilemapWarning
from kge.tilemap.files import MapLimits
from kge.tilemap.objects import Spawn, Spawners
from kge.tilemap.runtime import CHUNK, MapFiles, TileMap, TileMaps, load_map, maps_in
from kge.tilemap.units import MapUnits

__all__ = [
    "CHUNK",
    "MapFiles",
    "MapLimits",
    "MapUnits",
    "Spawn",
    "Spawners",
    "TileMap",
    "TileMaps",
    "TilemapError",
    "TilemapWarning",
    "load_map",
    "maps_in",
]
