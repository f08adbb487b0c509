"""Tile objects of parallax object layers: drawn with their layer, where their entity is.

A tile object on an object layer with parallax 1 is an ordinary
:class:`~kge.components.sprite.Sprite`. On a parallax layer it must move with the
layer as the camera moves (as Tiled shows it), which sprites do not do, so the map
renderer draws it with its layer's shift, tint and opacity. Its quad still follows
the object's entity: each frame the corners are put around the entity's blended
pose (position and angle), so an object with a body, a script or a tween moves and
turns on screen, and one whose entity is gone is no longer drawn.

The entities' poses come from the world's pose table (the one sprites are drawn
from), in which this module holds a row per object entity while the map is drawn.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from kge.components.tilemap import MapObject
from kge.tilemap.model import MapData, split_gids

#: unit corners of a quad (BL, BR, TR, TL), as the tile quads order them
_CORNERS = np.array([[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]])


@dataclass(slots=True)
class ObjectQuads:
    """One vertex list of a layer's tile objects sharing an image."""

    vlist: Any
    group: Any
    style: Any
    entities: list[int]  #: -1 once an entity is gone
    size: np.ndarray  #: (n, 2) width, height in metres
    last: np.ndarray = field(default_factory=lambda: np.zeros(0, np.float32))


def object_entities(world: Any, entities: list[int]) -> dict[tuple[str, int], int]:
    """(object layer, object id) -> entity, for the map's object entities alive now."""
    out = {}
    for e in entities:
        mo = world.try_get(e, MapObject)
        if mo is not None:
            out[(mo.layer, mo.id)] = e
    return out


def layer_objects(
    data: MapData, layer: Any, by_id: dict[tuple[str, int], int]
) -> tuple[list[Any], np.ndarray, np.ndarray, list[int], np.ndarray]:
    """The layer's visible tile objects with an entity: (objects, gids, flags, entities,
    sizes in metres)."""
    objs = [o for o in layer.objects if o.gid and o.visible and (layer.name, o.id) in by_id]
    gids, flags = split_gids(np.array([o.gid for o in objs], np.uint32))
    gids = gids.astype(np.int64)
    u = data.units
    sizes = np.array(
        [
            (
                u.length(o.width or float(data.tiles.rect[g, 2])),
                u.length(o.height or float(data.tiles.rect[g, 3])),
            )
            for o, g in zip(objs, gids.tolist(), strict=True)
        ],
        np.float64,
    ).reshape(-1, 2)
    return objs, gids, flags, [by_id[(layer.name, o.id)] for o in objs], sizes


def place(quads: ObjectQuads, frame: Any, world: Any, release: Any) -> None:
    """Put each quad around its entity's blended pose (degenerate once it is gone);
    ``release(entity)`` is called once for each entity found gone."""
    from kge.components.transform import Transform

    n = len(quads.entities)
    pose = np.zeros((n, 3))
    alive = np.zeros(n, bool)
    for i, e in enumerate(quads.entities):
        if e < 0:
            continue
        if not world.exists(e):
            release(e)
            quads.entities[i] = -1
            continue
        row = frame.rows.get(e)
        if row is not None and row < len(frame.poses):
            pose[i] = frame.poses[row, :3]
        else:  # not blended this frame yet (the first one): where it is now
            t = world.try_get(e, Transform)
            if t is None:
                continue
            pose[i] = (t.x, t.y, t.angle)
        alive[i] = True
    c, s = np.cos(pose[:, 2]), np.sin(pose[:, 2])
    local = _CORNERS[None, :, :] * quads.size[:, None, :]  # (n, 4, 2)
    x = pose[:, None, 0] + c[:, None] * local[..., 0] - s[:, None] * local[..., 1]
    y = pose[:, None, 1] + s[:, None] * local[..., 0] + c[:, None] * local[..., 1]
    x[~alive], y[~alive] = 0.0, 0.0
    pos = np.stack([x, y], axis=-1).astype(np.float32).ravel()
    if not np.array_equal(pos, quads.last):
        quads.vlist.position[:] = pos
        quads.last = pos
