"""``load_map``: one call from a Tiled file to entities, static colliders and drawable layers.

The returned :class:`TileMap` is the run-time handle: tile queries, tile edits
(drawing and collision rebuilt locally), the map's bounds for the camera, and
``unload``. Every loaded map is listed in the world's :class:`TileMaps`
resource, which the tile renderer draws from.

Snapshots carry the loaded maps (:func:`kge.snapshot.carry_running`): a world
restored by ``App.restore`` (or by ``restore_into`` into a world with a
:class:`TileMaps` resource) has its maps as they were, tile edits included, bound
to it, drawn and editable. A :class:`TileMap` that game code
kept in a component (a Behaviour's attribute) is that same restored map; one kept
elsewhere still belongs to the old world, and editing it after that world closed
raises a :class:`TilemapError` saying where the restored one is
(``maps_in(world).find(path)``).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from kge.components.material import Material as DrawMaterial
from kge.errors import KgeError
from kge.gcpause import without_gc
from kge.snapshot import carry_running
from kge.tilemap.cellcollision import CellCollision, IsoCollision
from kge.tilemap.collision import DEFAULT_MATERIAL, LayerCollision, Material, Piece
from kge.tilemap.errors import TilemapError
from kge.tilemap.files import MapLimits
from kge.tilemap.model import (
    FLIP_D,
    FLIP_H,
    FLIP_V,
    TILED_FLIP_D,
    TILED_FLIP_H,
    TILED_FLIP_V,
    TILED_ROT_HEX,
    MapData,
    TileLayerData,
)
from kge.tilemap.objects import Spawners, SpawnFn, Unknown, object_components
from kge.tilemap.parse import read_map

if TYPE_CHECKING:
    from kge.world import World

#: tiles per side of a drawing chunk
CHUNK = 32


@dataclass(slots=True)
class MapFiles:
    """How a world turns a map name into a file (a resource; TilemapPlugin inserts one).

    ``resolve(name)`` returns the map's path. Without this resource a name is a
    plain path; ``TilemapPlugin`` resolves names through the world's asset store,
    so ``load_map(world, "levels/one.tmx")`` finds the map next to the game like any
    other asset, whatever the working directory.
    """

    resolve: Callable[[str | Path], Path]
    #: folders besides a map's own that its tilesets, templates and images may be in
    #: (TilemapPlugin: the asset store's folders)
    roots: Callable[[], Iterable[Path]] = tuple


@carry_running
@dataclass(slots=True)
class TileMaps:
    """The maps loaded into one world (a resource)."""

    maps: list[TileMap] = field(default_factory=list)
    world: World | None = field(default=None, repr=False, compare=False)

    def find(self, path: str | Path) -> TileMap:
        """The loaded map read from ``path`` (a full path, or its file name)."""
        want = Path(path)
        for m in self.maps:
            if m.path == want or (len(want.parts) == 1 and m.path.name == want.name):
                return m
        names = ", ".join(repr(m.path.name) for m in self.maps) or "none"
        raise TilemapError(f"no loaded map {str(path)!r} (loaded: {names})")

    # -- snapshots (kge.snapshot.carry_running) --------------------------------------------
    def export_running(self) -> list[TileMap]:
        """The loaded maps, pickled whole but for their world: data with its edits,
        colliders, object entities and the frames animated tiles show."""
        return [m for m in self.maps if m.loaded]

    def import_running(self, data: list[TileMap]) -> None:
        """Bind the restored maps to this resource's world (their entities are there)."""
        if self.world is None:  # pragma: no cover - maps_in always sets it
            raise TilemapError("TileMaps.import_running: the resource has no world")
        for tmap in data:
            tmap.world = self.world
            if tmap not in self.maps:
                self.maps.append(tmap)


def maps_in(world: World) -> TileMaps:
    found = world.try_resource(TileMaps)
    if found is None:
        found = world.insert_resource(TileMaps(world=world))
    elif found.world is None:
        found.world = world
    return found


class TileMap:
    """A loaded map: its data, the entities made from it, and run-time edits."""

    def __init__(self, world: World, data: MapData, draw_layer: int) -> None:
        self.world = world
        self.data = data
        self.draw_layer = draw_layer
        self.collision: dict[str, LayerCollision | CellCollision] = {}
        self.objects: list[int] = []  #: entities spawned from map objects
        self.colliders: list[int] = []  #: static collider entities from tile layers (initial)
        self._live: dict[int, Piece] = {}  #: collider entity -> piece
        #: (tile layer position, chunk row, chunk column) whose drawing is stale
        self.dirty: set[tuple[int, int, int]] = set()
        #: the gid each gid shows now: itself, or an animated tile's current frame.
        #: The TilemapPlugin's clock advances it on game time (kge.animation's
        #: numpy clips); the renderer draws ``shown[gids]``.
        self.shown = np.arange(max(data.tiles.size, 1), dtype=np.int64)
        for gid, (frames, _) in data.tiles.animations.items():
            self.shown[gid] = frames[0]  # time 0: the first frame
        #: the animated tiles' clock (the TileAnimationSystem's numpy clips), made and
        #: advanced by that system; kept here so that snapshots carry it with the map
        self.clock: Any = None
        self.loaded = True
        #: the load_map options that differ from their defaults (saves name them)
        self.load_options: dict[str, Any] = {}
        #: (layer, col, row) of every cell set since loading (saves write their tiles)
        self.edited: set[tuple[str, int, int]] = set()
        #: tile layer name -> the Material its tiles are drawn with (:meth:`set_material`)
        self.materials: dict[str, DrawMaterial] = {}

    def __getstate__(self) -> dict[str, Any]:
        """Pickled without its world (a snapshot's maps are bound to the restored one)."""
        state = dict(self.__dict__)
        state["world"] = None
        return state

    def _editable(self, op: str) -> None:
        if not self.loaded:
            raise TilemapError(f"{self.path}: {op} on a map that was unloaded")
        if self.world is None or self.world.closed:
            raise TilemapError(
                f"{self.path}: {op} on a map whose world is closed (a restore makes a new "
                "world: edit its map, maps_in(app.world).find(path))"
            )

    # -- geometry ------------------------------------------------------------------------
    @property
    def path(self) -> Path:
        return self.data.path

    @property
    def units(self) -> Any:
        return self.data.units

    @property
    def orientation(self) -> str:
        """ "orthogonal", "isometric", "staggered" or "hexagonal"."""
        return self.data.orientation

    @property
    def bounds(self) -> tuple[float, float, float, float]:
        """(left, bottom, right, top) of the map in metres: clamp the camera to it."""
        u = self.data.units
        grid = self.data.grid
        if grid is None or grid.orientation == "orthogonal":
            w, h = u.tile_size
            return (
                u.origin[0],
                u.origin[1],
                u.origin[0] + self.data.cols * w,
                u.origin[1] + self.data.rows * h,
            )
        pw, ph = grid.size_px
        return (u.origin[0], u.origin[1], u.origin[0] + u.length(pw), u.origin[1] + u.length(ph))

    def map_to_world(self, px: float, py: float) -> tuple[float, float]:
        """Tiled map pixels (y down from the map's top-left) as world metres (y up)."""
        return self.data.units.point(float(px), float(py))

    def world_to_map(self, x: float, y: float) -> tuple[float, float]:
        """World metres as Tiled map pixels: :meth:`map_to_world` inverted."""
        return self.data.units.pixel(float(x), float(y))

    def cell_at(self, point: tuple[float, float]) -> tuple[int, int] | None:
        """The (column, row) whose cell holds a world point (row 0 at the top), or None.

        Any orientation: diamonds on isometric maps, hexagons on hexagonal ones.
        """
        grid = self.data.grid
        if grid is None or grid.orientation == "orthogonal":
            col, row = self.data.units.cell_at(float(point[0]), float(point[1]))
        else:
            col, row = grid.cell_at(*self.world_to_map(*point))
        if 0 <= col < self.data.cols and 0 <= row < self.data.rows:
            return col, row
        return None

    def cell_center(self, col: int, row: int) -> tuple[float, float]:
        """World centre of a grid cell (of its diamond or hexagon on other orientations)."""
        grid = self.data.grid
        if grid is None or grid.orientation == "orthogonal":
            x, y = self.data.units.corner(col + 0.5, row + 0.5)
            return (x, y)
        bx, by, w, h = grid.cell_box(col, row)
        return self.map_to_world(bx + w / 2, by + h / 2)

    def cell_outline(self, col: int, row: int) -> list[tuple[float, float]]:
        """The cell's corners in world metres (a rectangle, diamond or hexagon)."""
        grid = self.data.grid
        if grid is None:
            raise TilemapError(f"{self.path}: the map has no grid")
        return [self.map_to_world(x, y) for x, y in grid.cell_outline(col, row)]

    def depth_order(self, point: tuple[float, float]) -> int:
        """The ``Sprite.order`` that draws a sprite standing at ``point`` among the tile rows.

        On isometric, staggered and hexagonal maps tile rows are drawn back to front
        (each row in its own order, from ``DEPTH_BASE`` up); a sprite with this order
        is drawn in front of the rows behind its feet and behind the rows in front.
        Orthogonal maps draw layer by layer: this returns 0 there.
        """
        if self.orientation == "orthogonal":
            return 0
        from kge.tilemap.objects import DEPTH_BASE, DEPTH_STEPS

        _, py = self.world_to_map(*point)
        return DEPTH_BASE + round(py * DEPTH_STEPS / max(self.data.units.tile_h, 1))

    # -- queries -------------------------------------------------------------------------
    def layer(self, name: str) -> TileLayerData:
        return self.data.layer(name)

    def set_material(self, layer: str, material: DrawMaterial | None) -> None:
        """Draw tile layer ``layer`` with ``material`` (your shader and its uniforms, as
        for sprites: ``effect`` gets the layer's tint and the tile's texture); None
        draws it plainly again. Its uniforms are read at draw time, so tweening or
        ``material.set`` changes them without rebuilding a tile."""
        self.data.layer(layer)  # an unknown name raises, naming the map and its layers
        if material is None:
            self.materials.pop(layer, None)
            return
        if not isinstance(material, DrawMaterial):
            raise TilemapError(
                f"{self.path}: set_material on layer {layer!r}: expected a Material, "
                f"got {type(material).__name__}"
            )
        self.materials[layer] = material

    def tile_at(self, point: tuple[float, float], layer: str | None = None) -> int:
        """The gid under a world point (0 when empty or outside); ``layer=None``: the topmost."""
        cell = self.cell_at(point)
        if cell is None:
            return 0
        col, row = cell
        layers = [self.layer(layer)] if layer is not None else self.data.tile_layers[::-1]
        for lay in layers:
            gid = int(lay.gids[row, col])
            if gid:
                return gid
        return 0

    def tile(self, layer: str, col: int, row: int) -> int:
        lay = self.layer(layer)
        self._check_cell(lay, col, row, "tile")
        return int(lay.gids[row, col])

    def properties(self, gid: int) -> dict[str, Any]:
        """The custom properties of a tile (its tileset's, overridden by its own)."""
        return dict(self.data.tiles.properties.get(int(gid), {}))

    def gid(self, tileset: str, local_id: int) -> int:
        """The global id of tile ``local_id`` of the tileset named ``tileset``."""
        for ts in self.data.tilesets:
            if ts.name == tileset:
                if not 0 <= local_id < ts.count:
                    raise TilemapError(f"{self.path}: tileset {tileset!r} has no tile {local_id}")
                return ts.firstgid + local_id
        raise TilemapError(f"{self.path}: no tileset {tileset!r}")

    # -- edits -----------------------------------------------------------------------------
    def set_tile(
        self,
        layer: str,
        col: int,
        row: int,
        gid: int,
        *,
        flip_x: bool = False,
        flip_y: bool = False,
        flip_diagonal: bool = False,
    ) -> None:
        """Put tile ``gid`` (0 clears) at (col, row): its chunk redraws, its colliders rebuild."""
        self._editable("set_tile")
        lay = self.layer(layer)
        self._check_cell(lay, col, row, "set_tile")
        if isinstance(gid, bool) or not isinstance(gid, (int, np.integer)) or gid < 0:
            raise TilemapError(f"{self.path}: set_tile: gid must be an int >= 0, got {gid!r}")
        if not self.data.tiles.known(np.array([gid])).all():
            raise TilemapError(f"{self.path}: set_tile: tile id {gid} is in no tileset")
        old = (int(lay.gids[row, col]), int(lay.flags[row, col]))
        lay.gids[row, col] = gid
        lay.flags[row, col] = (
            (FLIP_H if flip_x else 0) | (FLIP_V if flip_y else 0) | (FLIP_D if flip_diagonal else 0)
        )
        coll = self.collision.get(lay.name)
        if coll is not None:
            try:
                gone, born = coll.update_cell(col, row)
                self._swap(gone, born)
            except (KgeError, ValueError) as exc:  # pragma: no cover - defensive
                lay.gids[row, col], lay.flags[row, col] = old
                raise TilemapError(f"{self.path}: set_tile on layer {layer!r}: {exc}") from exc
        self.dirty.add((self.data.tile_layers.index(lay), row // CHUNK, col // CHUNK))
        self.edited.add((lay.name, int(col), int(row)))

    def set_terrain(
        self, layer: str, col: int, row: int, color: int | str, *, wangset: str | None = None
    ) -> list[tuple[int, int, int]]:
        """Paint a terrain colour at (col, row) and autotile around it (Tiled's Wang sets).

        ``color`` is a colour name of the set (or its number; 0 erases). The cell
        and its neighbours get the tiles whose corners (or edges) match, through
        :meth:`set_tile`, so drawing and colliders follow. Returns the
        (col, row, gid) cells changed. ``wangset`` names the set when the map has
        several (Tiled 0.9-1.4 terrains are the set ``"terrains"``).
        """
        from kge.tilemap.wang import WangPainter, color_index

        self._editable("set_terrain")
        lay = self.layer(layer)
        self._check_cell(lay, col, row, "set_terrain")
        sets = [w for ts in self.data.tilesets for w in ts.wangsets]
        chosen = [w for w in sets if wangset is None or w.name == wangset]
        if not chosen:
            names = ", ".join(repr(w.name) for w in sets) or "none"
            raise TilemapError(f"{self.path}: no Wang set {wangset!r} (sets: {names})")
        wang = chosen[0]
        painters = self.__dict__.setdefault("_painters", {})
        painter = painters.get((lay.name, wang.name))
        if painter is None:
            painter = painters[(lay.name, wang.name)] = WangPainter(wang, lay)
        idx = color_index(wang, color, f"{self.path}: set_terrain")
        changes = painter.paint(col, row, idx)
        for c, r, gid in changes:
            self.set_tile(lay.name, c, r, gid)
        return changes

    def clear_tile(self, layer: str, col: int, row: int) -> None:
        self.set_tile(layer, col, row, 0)

    def edits(self) -> list[tuple[str, int, int, int]]:
        """The cells set since loading as (layer, col, row, Tiled gid with its flip bits),
        what a save writes to rebuild the map as it is now."""
        out = []
        for name, col, row in sorted(self.edited):
            lay = self.layer(name)
            flags = int(lay.flags[row, col])
            raw = int(lay.gids[row, col])
            raw |= TILED_FLIP_H if flags & FLIP_H else 0
            raw |= TILED_FLIP_V if flags & FLIP_V else 0
            raw |= TILED_FLIP_D if flags & FLIP_D else 0
            out.append((name, col, row, raw))
        return out

    def apply_edits(self, edits: Iterable[Any]) -> None:
        """Set the cells of :meth:`edits` (a save's list): ``(layer, col, row, gid)`` each,
        the gid with Tiled's flip bits."""
        for i, edit in enumerate(edits):
            if (not isinstance(edit, (list, tuple)) or len(edit) != 4
                    or not isinstance(edit[0], str)
                    or not all(isinstance(v, int) and not isinstance(v, bool) for v in edit[1:])
                    or not 0 <= edit[3] <= 0xFFFFFFFF):  # fmt: skip
                raise TilemapError(
                    f"{self.path}: edit {i} must be [layer, col, row, gid], got {edit!r}"
                )
            name, col, row, raw = edit
            self.set_tile(
                name, col, row, raw & ~(TILED_FLIP_H | TILED_FLIP_V | TILED_FLIP_D | TILED_ROT_HEX),
                flip_x=bool(raw & TILED_FLIP_H), flip_y=bool(raw & TILED_FLIP_V),
                flip_diagonal=bool(raw & TILED_FLIP_D),
            )  # fmt: skip

    def _check_cell(self, lay: TileLayerData, col: int, row: int, op: str) -> None:
        for v, n, what in ((col, self.data.cols, "col"), (row, self.data.rows, "row")):
            if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or not 0 <= v < n:
                raise TilemapError(
                    f"{self.path}: {op} on layer {lay.name!r}: "
                    f"{what} must be an int in [0, {n}), got {v!r}"
                )

    def _swap(self, gone: list[Piece], born: list[Piece]) -> None:
        for p in gone:
            if p.entity is not None and self.world.exists(p.entity):
                self.world.despawn(p.entity)
            self._live.pop(p.entity or -1, None)
            p.entity = None
        for p in born:
            p.entity = self.world.spawn(*p.components)
            self._live[p.entity] = p

    @property
    def collider_entities(self) -> list[int]:
        """The static collider entities of the tile layers now."""
        return list(self._live)

    def unload(self) -> None:
        """Despawn everything the map made and stop drawing it."""
        if not self.loaded:
            return
        for e in [*self.objects, *self._live]:
            if self.world.exists(e):
                self.world.despawn(e)
        self.objects.clear()
        self._live.clear()
        self.loaded = False
        maps = self.world.try_resource(TileMaps)
        if maps is not None and self in maps.maps:
            maps.maps.remove(self)

    def __repr__(self) -> str:
        return f"TileMap({str(self.path)!r}, {self.data.cols}x{self.data.rows})"


@without_gc  # a large map makes 100,000s of objects at once (see kge.gcpause)
def load_map(
    world: World,
    path: str | Path,
    *,
    pixels_per_meter: float | None = None,
    origin: tuple[float, float] = (0.0, 0.0),
    solid_layers: Iterable[str] = (),
    spawners: Spawners | Mapping[str, SpawnFn] | None = None,
    unknown: Unknown = "warn",
    layer: int = 0,
    friction: float = DEFAULT_MATERIAL[0],
    restitution: float = DEFAULT_MATERIAL[1],
    roots: Iterable[str | Path] | None = None,
    limits: MapLimits | None = None,
) -> TileMap:
    """Load a Tiled map into ``world`` in one call and return its :class:`TileMap`.

    ``pixels_per_meter`` defaults to the map's tile width (a tile is 1 m wide);
    the map's bottom-left corner lands at ``origin``. ``solid_layers`` names tile
    layers whose every tile is solid (a layer property ``solid: true`` does the
    same). ``spawners`` maps object classes to spawn functions; an object whose
    class has none is spawned with the default components and a
    :class:`~kge.tilemap.errors.TilemapWarning` (``unknown="error"`` raises,
    ``"ignore"`` stays silent). ``layer`` is the draw layer of the map's tiles
    (tile layers sort below sprites of the same layer; a layer property
    ``layer`` overrides it).

    The map reads only files inside ``roots`` (default: the map's own folder and
    the folders of the world's asset store) and checks ``limits`` (default
    :class:`MapLimits()`) before allocating anything.

    On any error a :class:`TilemapError` names the file, layer and object, and
    nothing of the map is left in the world.
    """
    if unknown not in ("warn", "error", "ignore"):
        raise TilemapError(
            f"load_map: unknown must be 'warn', 'error' or 'ignore', got {unknown!r}"
        )
    reg = spawners if isinstance(spawners, Spawners) else Spawners(spawners)
    files = world.try_resource(MapFiles)
    if files is not None:
        path = files.resolve(path)
    if roots is None:
        roots = list(files.roots()) if files is not None else []
    data = read_map(
        path, pixels_per_meter=pixels_per_meter, origin=origin, roots=roots, limits=limits
    )
    solid_names = set(solid_layers)
    known = {t.name for t in data.tile_layers}
    missing = solid_names - known
    if missing:
        raise TilemapError(f"{data.path}: solid_layers names no tile layer: {sorted(missing)!r}")
    base: Material = (float(friction), float(restitution), *DEFAULT_MATERIAL[2:])
    tmap = TileMap(world, data, int(layer))
    given: dict[str, Any] = {"pixels_per_meter": pixels_per_meter, "origin": tuple(origin),
             "solid_layers": sorted(solid_names), "unknown": unknown, "layer": int(layer),
             "friction": float(friction), "restitution": float(restitution)}  # fmt: skip
    defaults: dict[str, Any] = {"pixels_per_meter": None, "origin": (0.0, 0.0), "solid_layers": [],
                "unknown": "warn", "layer": 0, "friction": DEFAULT_MATERIAL[0],
                "restitution": DEFAULT_MATERIAL[1]}  # fmt: skip
    tmap.load_options = {k: v for k, v in given.items() if v != defaults[k]}
    pieces: list[Piece] = []
    try:
        for lay in data.tile_layers:
            solid = (
                lay.name in solid_names or str(lay.properties.get("solid", "")).lower() == "true"
            )
            kinds = {"orthogonal": LayerCollision, "isometric": IsoCollision}
            coll = kinds.get(data.orientation, CellCollision)(data, lay, solid, base)
            tmap.collision[lay.name] = coll
            pieces.extend(coll.build())
    except (KgeError, ValueError) as exc:
        if isinstance(exc, TilemapError):
            raise
        raise TilemapError(f"{data.path}: building tile colliders: {exc}") from exc
    objects: list[tuple[str, list[Any]]] = []
    warned: set[str] = set()
    for olayer in data.object_layers:
        for obj in olayer.objects:
            comps = object_components(data, olayer, obj, reg, unknown, warned, int(layer))
            if comps is not None:
                objects.append((f"layer {olayer.name!r}: object {obj.id} ({obj.name!r})", comps))
    # everything is built: spawn it all, or nothing
    spawned: list[int] = []
    what = "tile colliders"
    try:
        for p in pieces:
            p.entity = world.spawn(*p.components)
            spawned.append(p.entity)
            tmap._live[p.entity] = p
        for label, comps in objects:
            what = label  # named in the error if this spawn is refused
            e = world.spawn(*comps)
            spawned.append(e)
            tmap.objects.append(e)
    except (KgeError, ValueError, TypeError) as exc:
        if spawned:  # (nothing was spawned when the world itself refused, e.g. locked)
            for e in spawned:
                if world.exists(e):
                    world.despawn(e)
            world.flush()
        raise TilemapError(f"{data.path}: {what}: {exc}") from exc
    tmap.colliders = list(tmap._live)
    maps_in(world).maps.append(tmap)
    return tmap
