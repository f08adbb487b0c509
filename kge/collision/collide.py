"""One entry point for manifolds: :func:`collide` picks the b2Collide* function.

Box2D registers one function per pair of shape kinds, with the "bigger" kind
as A (polygon before circle, edge before both). :func:`collide` accepts the
shapes in either order: when they come reversed it computes the canonical
manifold and exchanges A and B in it (``face_a`` becomes ``face_b``, the
contact ids swap their halves), so the world normal still points from the
``shape_a`` you passed to the ``shape_b``. Two edges (or chain children)
never collide, as in Box2D: they have no inside.

>>> from kge.components.shapes import Box, Circle
>>> m = collide(Box(1.0, 1.0), (0.0, 0.0, 0.0), Box(1.0, 1.0), (0.0, 1.9, 0.0))
>>> m.type, m.normal, len(m.points)
('face_a', (0.0, 1.0), 2)
>>> [round(s, 6) for s in m.separations]
[-0.12, -0.12]
>>> bool(collide(Circle(0.5), (0, 0, 0), Circle(0.5), (2, 0, 0)))  # apart
False
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from kge.collision.collide_convex import collide_circles, collide_polygon_circle, collide_polygons
from kge.collision.collide_edge import collide_edge_circle, collide_edge_polygon
from kge.collision.geometry import Convex, convex
from kge.collision.manifold import EMPTY, LocalManifold, Manifold, world_form
from kge.collision.pose import Pose, pose

Collider = Callable[[Convex, Pose, Convex, Pose], LocalManifold]

#: (kind of A, kind of B) -> function, for the canonical order
_PAIRS: dict[tuple[str, str], Collider] = {
    ("circle", "circle"): collide_circles,
    ("polygon", "circle"): collide_polygon_circle,
    ("polygon", "polygon"): collide_polygons,
    ("edge", "circle"): collide_edge_circle,
    ("edge", "polygon"): collide_edge_polygon,
}


def collide(
    shape_a: Any, pose_a: Any, shape_b: Any, pose_b: Any, *, child_a: Any = 0, child_b: Any = 0
) -> Manifold:
    """The contact manifold of two posed shapes (empty and falsy if they do not touch)."""
    a, b = convex(shape_a, child_a, "shape_a"), convex(shape_b, child_b, "shape_b")
    xa, xb = pose(pose_a, "pose_a"), pose(pose_b, "pose_b")
    return world_form(local_manifold(a, xa, b, xb), xa, a.radius, xb, b.radius)


def local_manifold(a: Convex, xa: Pose, b: Convex, xb: Pose) -> LocalManifold:
    """The local form for two convex pieces, in the order given."""
    fn = _PAIRS.get((a.kind, b.kind))
    if fn is not None:
        return fn(a, xa, b, xb)
    fn = _PAIRS.get((b.kind, a.kind))
    if fn is not None:
        m = fn(b, xb, a, xa)
        return m.flipped() if m.points else m
    return EMPTY  # edge vs edge: Box2D never collides them
