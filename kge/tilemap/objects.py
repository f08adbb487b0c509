"""Tiled objects -> entity component lists, and the registry of spawn functions.

Every object becomes one entity with a :class:`~kge.components.transform.Transform`
(at the shape's centre for rectangles, ellipses and tile objects; at the object's
anchor for points, polygons and polylines) and a
:class:`~kge.components.tilemap.MapObject`. It gets a Collider when its
properties (or its class's registered defaults) say ``collider: true``; ``body``
("static", "dynamic", "kinematic") adds a RigidBody. Tile objects also get a
Sprite of their tile.

A :class:`Spawners` registry maps an object's class to a function that receives
a :class:`Spawn` (the object, its properties, its default components) and
returns extra components (one of a type already there replaces it) or None.
Spawn functions must not write to the world: ``load_map`` spawns everything at
the end, so a failing spawner leaves nothing behind.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any, Literal

from kge.components.collider import Collider
from kge.components.filter import Filter
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Chain, Circle, Polygon
from kge.components.sprite import Sprite
from kge.components.text import Text
from kge.components.tilemap import MapObject
from kge.components.transform import Transform
from kge.errors import KgeError
from kge.tilemap.errors import TilemapError, TilemapWarning
from kge.tilemap.model import (
    GID_MASK,
    TILED_FLIP_H,
    TILED_FLIP_V,
    MapData,
    ObjectData,
    ObjectLayerData,
)

Unknown = Literal["warn", "error", "ignore"]


@dataclass(slots=True)
class Spawn:
    """What a spawn function gets: the object and the components it will have."""

    obj: MapObject
    transform: Transform
    components: list[Any]  #: the default components (Transform and MapObject first)

    @property
    def properties(self) -> dict[str, Any]:
        return self.obj.properties


SpawnFn = Callable[[Spawn], Iterable[Any] | None]


@dataclass(slots=True)
class _Entry:
    fn: SpawnFn | None
    defaults: dict[str, Any] = field(default_factory=dict)


class Spawners:
    """Class name -> spawn function (and default properties for that class).

    >>> spawners = Spawners()
    >>> @spawners.register("Coin", collider=True, sensor=True)
    ... def coin(spawn):
    ...     return [Name(f"coin worth {spawn.properties.get('value', 1)}")]
    >>> "Coin" in spawners
    True
    """

    def __init__(self, entries: Mapping[str, SpawnFn] | None = None) -> None:
        self._entries: dict[str, _Entry] = {}
        for name, fn in (entries or {}).items():
            self.register(name, fn)

    def register(self, cls: str, fn: SpawnFn | None = None, **defaults: Any) -> Any:
        """Register ``fn`` for objects of class ``cls`` (usable as a decorator).

        ``defaults`` are properties every object of the class has unless it sets
        them itself (``collider=True, sensor=True, body="dynamic"``...).
        """
        if not isinstance(cls, str) or not cls:
            raise TilemapError(f"Spawners.register: class must be a non-empty string, got {cls!r}")

        def add(f: SpawnFn | None) -> SpawnFn | None:
            if f is not None and not callable(f):
                raise TilemapError(f"Spawners.register({cls!r}): {f!r} is not callable")
            self._entries[cls] = _Entry(f, dict(defaults))
            return f

        add(fn)  # registered now (defaults only, until decorated)
        return add if fn is None else fn

    def __contains__(self, cls: object) -> bool:
        return cls in self._entries

    def get(self, cls: str) -> _Entry | None:
        return self._entries.get(cls)


def _truthy(value: Any) -> bool:
    return value is True or (isinstance(value, str) and value.lower() in ("true", "1", "yes"))


def _rotate(v: tuple[float, float], angle: float) -> tuple[float, float]:
    c, s = math.cos(angle), math.sin(angle)
    return (v[0] * c - v[1] * s, v[0] * s + v[1] * c)


def object_components(
    data: MapData,
    layer: ObjectLayerData,
    obj: Any,
    spawners: Spawners,
    unknown: Unknown,
    warned: set[str],
    draw_layer: int,
) -> list[Any] | None:
    """The components of the entity for ``obj`` (None: its spawner skipped it)."""
    where = f"{data.path}: layer {layer.name!r}: object {obj.id} ({obj.name!r})"
    try:
        return _components(data, layer, obj, spawners, unknown, warned, draw_layer, where)
    except TilemapError:
        raise
    except (KgeError, ValueError, TypeError) as exc:
        raise TilemapError(f"{where}: {exc}") from exc


def _components(
    data: MapData,
    layer: ObjectLayerData,
    obj: Any,
    spawners: Spawners,
    unknown: Unknown,
    warned: set[str],
    draw_layer: int,
    where: str,
) -> list[Any] | None:
    units = data.units
    kind = obj.kind
    gid = int(obj.gid)
    tile = gid & GID_MASK
    cls = obj.cls or (data.tiles.classes.get(tile, "") if tile else "")
    entry = spawners.get(cls) if cls else None
    if cls and entry is None:
        if unknown == "error":
            raise TilemapError(f"{where}: class {cls!r} has no registered spawner")
        if unknown == "warn" and cls not in warned:
            warned.add(cls)
            warnings.warn(
                f"{where}: class {cls!r} has no registered spawner; spawned with the default "
                "components (register one, or pass unknown='ignore')",
                TilemapWarning,
                stacklevel=5,  # _components, object_components, load_map, without_gc, caller
            )
    props: dict[str, Any] = {}
    if tile:
        props.update(data.tiles.properties.get(tile, {}))
    if entry is not None:
        props.update(entry.defaults)
    props.update(obj.properties)
    style = layer.style
    grid = data.grid
    px, py = grid.object_px(obj.x, obj.y) if grid is not None else (obj.x, obj.y)
    ax, ay = units.point(px + style.offset[0], py + style.offset[1])
    angle = -math.radians(float(obj.rotation))
    ow, oh = obj.width, obj.height
    if tile and (ow <= 0 or oh <= 0):  # tile objects saved without a size: the tile's
        ow, oh = float(data.tiles.rect[tile, 2]), float(data.tiles.rect[tile, 3])
    w, h = units.length(ow), units.length(oh)
    points: tuple[tuple[float, float], ...] = ()
    if kind in ("rectangle", "ellipse", "text"):
        off = _rotate((w / 2, -h / 2), angle)
    elif kind == "tile":  # anchored bottom-left (bottom-centre on isometric maps)
        iso = data.orientation == "isometric"
        off = _rotate((0.0 if iso else w / 2, h / 2), angle)
    else:
        off = (0.0, 0.0)
        if kind in ("polygon", "polyline"):
            points = tuple(units.vector(x, y) for x, y in obj.points)
    transform = Transform(ax + off[0], ay + off[1], angle)
    mobj = MapObject(
        map=str(data.path),
        layer=layer.name,
        id=int(obj.id),
        name=obj.name or "",
        cls=cls,
        kind=kind,
        properties=props,
        size=(w, h),
        points=points,
    )
    comps: list[Any] = [transform, mobj]
    if tile and style.parallax == (1.0, 1.0):  # (parallax layers are drawn with the map)
        comps.append(_sprite(data, layer, obj, tile, w, h, draw_layer))
    elif kind == "text":
        comps.append(_text(obj, style, w, h, units.pixels_per_meter, draw_layer, layer.index))
    if _truthy(props.get("collider")):
        comps.append(_collider(kind, w, h, points, props))
        body = str(props.get("body", "static")).lower()
        if body != "static":
            types = {"dynamic": BodyType.DYNAMIC, "kinematic": BodyType.KINEMATIC}
            if body not in types:
                raise TilemapError(
                    f"{where}: property body must be static, dynamic or kinematic, got {body!r}"
                )
            comps.append(
                RigidBody(types[body], fixed_rotation=_truthy(props.get("fixed_rotation")))
            )
    if entry is None or entry.fn is None:
        return comps
    spawn = Spawn(mobj, transform, comps)
    try:
        extra = entry.fn(spawn)
    except Exception as exc:
        name = getattr(entry.fn, "__qualname__", repr(entry.fn))
        raise TilemapError(
            f"{where}: spawner {name} for class {cls!r} raised {type(exc).__name__}: {exc}"
        ) from exc
    if extra is None:
        return spawn.components
    out = {type(c): c for c in spawn.components}
    for c in extra:
        out[type(c)] = c
    return list(out.values())


def _sprite(
    data: MapData,
    layer: ObjectLayerData,
    obj: ObjectData,
    tile: int,
    w: float,
    h: float,
    draw_layer: int,
) -> Sprite:
    """The Sprite of a tile object: its layer's opacity, tint and visibility, its own flips."""
    table = data.tiles
    img = table.images[int(table.image[tile])]
    x, y, tw, th = (int(v) for v in table.rect[tile])
    iw, ih = table.image_sizes[int(table.image[tile])]
    region = None if (x, y, tw, th) == (0, 0, iw, ih) else (x, y, tw, th)
    style = layer.style
    r, g, b, a = style.tint
    order = layer.index - 1000
    if data.orientation != "orthogonal" and layer.draworder == "topdown":
        order = depth_order(data, obj)
    return Sprite(
        str(img),
        layer=int(layer.properties.get("layer", draw_layer)),
        order=order,
        region=region,
        size=(w, h),
        tint=(r, g, b),
        opacity=round(255 * style.opacity * a / 255),
        visible=style.visible and obj.visible,
        flip_x=bool(obj.gid & TILED_FLIP_H),
        flip_y=bool(obj.gid & TILED_FLIP_V),
    )


def depth_order(data: MapData, obj: ObjectData) -> int:
    """Draw order of a tile object among depth-sorted tile rows (see TileMap.depth_order)."""
    grid = data.grid
    assert grid is not None
    _, py = grid.object_px(obj.x, obj.y)
    return DEPTH_BASE + round(py * DEPTH_STEPS / max(grid.tile_h, 1))


#: tile rows of non-orthogonal maps and their objects sort in orders from here up
DEPTH_BASE = 100_000
DEPTH_STEPS = 4  #: orders per tile height of depth (objects between two rows)


def _text(
    obj: ObjectData, style: Any, w: float, h: float, ppm: float, layer: int, index: int
) -> Text:
    """A Tiled text object as kge Text, aligned in its box as Tiled aligns it."""
    t = obj.text
    halign = str(t.get("halign", "left"))
    valign = str(t.get("valign", "top"))
    ax = {"left": 0.0, "center": 0.5, "right": 1.0, "justify": 0.0}.get(halign, 0.0)
    ay = {"top": 1.0, "center": 0.5, "bottom": 0.0}.get(valign, 1.0)
    r, g, b, a = (0, 0, 0, 255)
    if t.get("color"):
        from kge.tilemap.values import color

        r, g, b, a = color(t["color"], obj.name, "text colour")
    tr, tg, tb, ta = style.tint
    pixelsize = float(t.get("pixelsize", 16))
    return Text(
        str(t.get("text", "")),
        size=max(pixelsize * 0.75, 1.0),  # points: 16 map pixels at 96 dpi
        color=(
            r * tr // 255,
            g * tg // 255,
            b * tb // 255,
            round(a * ta / 255 * style.opacity),
        ),
        anchor=(ax, ay),
        bold=str(t.get("bold", "0")).lower() in ("1", "true"),
        offset=((ax - 0.5) * w, (ay - 0.5) * h),
        layer=layer,
        order=index - 1000,
        visible=style.visible and obj.visible,
        font=str(t["fontfamily"]) if t.get("fontfamily") else None,
    )


def _collider(
    kind: str, w: float, h: float, points: tuple[tuple[float, float], ...], props: dict[str, Any]
) -> Collider:
    shape: Any
    if kind in ("rectangle", "tile", "text"):
        shape = Box(w / 2, h / 2)
    elif kind == "ellipse":
        if abs(w - h) < 1e-9:
            shape = Circle(w / 2)
        else:
            n = 12
            shape = Polygon(
                [
                    (w / 2 * math.cos(2 * math.pi * i / n), h / 2 * math.sin(2 * math.pi * i / n))
                    for i in range(n)
                ]
            )
    elif kind == "polygon":
        pts = list(points)
        area = sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(pts, pts[1:] + pts[:1], strict=True))
        pts = pts if area > 0 else pts[::-1]
        try:
            shape = Polygon(pts)
        except ValueError:
            shape = Chain(pts, loop=True)
    elif kind == "polyline":
        shape = Chain(list(points))
    else:  # point
        shape = Circle(float(props.get("radius", 0.5)))
    flt = Filter(
        int(props.get("category_bits", 0x0001)),
        int(props.get("mask_bits", 0xFFFF)),
        int(props.get("group_index", 0)),
    )
    return Collider(
        shape,
        density=float(props.get("density", 1.0)),
        friction=float(props.get("friction", 0.2)),
        restitution=float(props.get("restitution", 0.0)),
        filter=flt,
        sensor=_truthy(props.get("sensor")),
    )
