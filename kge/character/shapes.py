"""Shapes as the narrow phase sees them: core vertices (body-local) plus a radius.

A character's shape has no skin (a capsule's or circle's radius is its own; a box's
core is the box), so a character box standing on a polygon rests at the height a
dynamic box of the same size does. A collider's pieces carry Box2D's polygon skin on
polygons and edges (``PhysicsSettings.polygon_radius``), as pymunk's shapes do, so
characters meet exactly the surfaces dynamic bodies meet. Pieces are cached by shape
value (shapes are frozen), so a level of a thousand equal crates converts one box.

>>> core, radius = character_core(Capsule(0.25, 0.75))
>>> core.tolist(), radius
([[0.0, -0.5], [0.0, 0.5]], 0.25)
>>> flat, counts, radii, children = collider_pieces(Edge((0, 0), (2, 0)), 0.01)
>>> flat.tolist(), counts.tolist(), radii.tolist(), children.tolist()
([[0.0, 0.0], [2.0, 0.0]], [2], [0.01], [0])
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

import numpy as np

from kge.components.character import Capsule, CharacterShape
from kge.components.shapes import Box, Chain, Circle, Edge, Polygon

#: (vertices (V, 2), vertex counts (n,), radii (n,), child indices (n,)) of n pieces
Pieces = tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]


@lru_cache(maxsize=256)
def character_core(shape: CharacterShape) -> tuple[np.ndarray, float]:
    """The character shape's core vertices (k, 2) in its entity's frame, and radius."""
    if isinstance(shape, Capsule):
        core = np.array(shape.segment, dtype=np.float64)
        radius = shape.radius
    elif isinstance(shape, Circle):
        core = np.array([shape.center], dtype=np.float64)
        radius = shape.radius
    else:
        core = np.array(shape.vertices(), dtype=np.float64)
        radius = 0.0
    core.setflags(write=False)
    return core, radius


@lru_cache(maxsize=4096)
def collider_pieces(shape: Any, skin: float) -> Pieces:
    """A collider shape's convex pieces in its body's frame (a chain: one per segment),
    as flat arrays: vertices (V, 2), vertex counts (n,), radii (n,), child indices (n,).
    A chain's segments are converted without a Python object each (tile maps have
    100,000s)."""
    if isinstance(shape, Chain):
        segs = np.asarray(shape.segments(), dtype=np.float64)
        n = len(segs)
        flat = segs.reshape(-1, 2)
        counts = np.full(n, 2, dtype=np.int64)
        radius = np.full(n, skin)
        child = np.arange(n, dtype=np.int64)
    else:
        if isinstance(shape, Circle):
            verts, r = [shape.center], shape.radius
        elif isinstance(shape, Box):
            verts, r = list(shape.vertices()), skin
        elif isinstance(shape, Polygon):
            verts, r = list(shape.vertices), skin
        elif isinstance(shape, Edge):
            verts, r = [shape.v1, shape.v2], skin
        else:  # pragma: no cover - the Collider refuses anything else
            raise TypeError(f"not a collider shape: {shape!r}")
        flat = np.array(verts, dtype=np.float64)
        counts = np.array([len(verts)], dtype=np.int64)
        radius = np.array([r], dtype=np.float64)
        child = np.zeros(1, dtype=np.int64)
    for a in (flat, counts, radius, child):
        a.setflags(write=False)
    return flat, counts, radius, child
