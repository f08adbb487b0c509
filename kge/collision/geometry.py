"""What Box2D's collision code sees of a kge shape: one convex piece per child.

Box2D's algorithms work on convex pieces: a circle is a point with a radius, a
polygon (and a :class:`~kge.components.shapes.Box`) its vertices with outward
normals, an edge two vertices. A :class:`~kge.components.shapes.Chain` is a
row of edges, its *children*, addressed by index as ``b2ChainShape`` does;
each child edge remembers its neighbours (``vertex0`` before, ``vertex3``
after, Box2D's ghost vertices), which the edge manifolds use to avoid bumps
at the joins.

**The skin.** Box2D gives polygons and edges a radius of
:data:`POLYGON_RADIUS` (0.01 m, twice the linear slop). Point tests and ray
casts ignore it; AABBs, distances, times of impact and manifolds include it,
exactly as ``b2Distance`` and ``b2Collide*`` do: two boxes one metre apart
are 0.98 m apart "with radii". :func:`~kge.collision.distance` takes
``use_radii=False`` for the core distance.

>>> from kge.components.shapes import Box, Chain
>>> piece = convex(Box(1.0, 0.5))
>>> piece.vertices[0], piece.normals[0], piece.radius
((-1.0, -0.5), (0.0, -1.0), 0.01)
>>> edge = convex(Chain([(0, 0), (1, 0), (2, 1)]), child=1)
>>> edge.vertices, edge.vertex0, edge.vertex3
(((1.0, 0.0), (2.0, 1.0)), (0.0, 0.0), None)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any, Literal

from kge.components.shapes import LINEAR_SLOP, SHAPE_TYPES, Box, Chain, Circle, Edge, Polygon
from kge.errors import ComponentTypeError, ValidationError
from kge.physics.mass import polygon_mass
from kge.validate import integer

Vec2 = tuple[float, float]
Kind = Literal["circle", "polygon", "edge"]

#: Box2D's b2_polygonRadius: the skin around polygons and edges (2 * linear slop).
POLYGON_RADIUS = 2.0 * LINEAR_SLOP


@dataclass(slots=True, frozen=True)
class Convex:
    """One convex piece in body-local coordinates (Box2D's shape as its algorithms see it).

    ``normals[i]`` is the outward unit normal of the side from ``vertices[i]`` to
    ``vertices[i + 1]`` (polygons only); ``vertex0`` / ``vertex3`` are an edge's
    neighbours in its chain (None at an open end or for a lone edge).
    """

    kind: Kind
    vertices: tuple[Vec2, ...]
    normals: tuple[Vec2, ...]
    radius: float
    centroid: Vec2
    vertex0: Vec2 | None = None
    vertex3: Vec2 | None = None


def shape_of(value: Any, field: str = "shape") -> Any:
    """``value`` if it is a kge shape, else a clear :class:`ComponentTypeError`."""
    if not isinstance(value, SHAPE_TYPES):
        names = ", ".join(t.__name__ for t in SHAPE_TYPES)
        raise ComponentTypeError(
            f"{field} must be a kge shape ({names}), got {type(value).__name__} {value!r}"
        )
    return value


def child_count(shape: Any) -> int:
    """How many children a shape has: a chain's segment count, 1 for the others."""
    if isinstance(shape, Chain):
        n = len(shape.vertices)
        return n if shape.loop else n - 1
    return 1


def convex(shape: Any, child: Any = 0, field: str = "shape") -> Convex:
    """The convex piece ``child`` of ``shape`` (validated; cached by value)."""
    shape_of(shape, field)
    index = integer(child, "", f"{field} child")
    count = child_count(shape)
    if not 0 <= index < count:
        raise ValidationError(
            f"{field} child must be in [0, {count - 1}] for {type(shape).__name__}, got {index}"
        )
    return _convex(shape, index)


@lru_cache(maxsize=1024)
def _convex(shape: Any, child: int) -> Convex:
    if isinstance(shape, Circle):
        return Convex("circle", (shape.center,), (), shape.radius, shape.center)
    if isinstance(shape, (Box, Polygon)):
        verts = shape.vertices() if isinstance(shape, Box) else tuple(shape.vertices)
        return Convex("polygon", verts, _normals(verts), POLYGON_RADIUS, _centroid(shape, verts))
    if isinstance(shape, Edge):
        mid = (0.5 * (shape.v1[0] + shape.v2[0]), 0.5 * (shape.v1[1] + shape.v2[1]))
        return Convex("edge", (shape.v1, shape.v2), (), POLYGON_RADIUS, mid, shape.vertex0,
                      shape.vertex3)
    return _chain_child(shape, child)


def _normals(verts: tuple[Vec2, ...]) -> tuple[Vec2, ...]:
    out = []
    n = len(verts)
    for i in range(n):
        ex, ey = verts[(i + 1) % n][0] - verts[i][0], verts[(i + 1) % n][1] - verts[i][1]
        length = math.hypot(ex, ey)
        out.append((ey / length, -ex / length))
    return tuple(out)


def _centroid(shape: Box | Polygon, verts: tuple[Vec2, ...]) -> Vec2:
    if isinstance(shape, Box):
        return shape.center  # Box2D's SetAsBox sets the centroid to the centre exactly
    return polygon_mass(verts, 1.0).center


def _chain_child(chain: Chain, i: int) -> Convex:
    """Box2D's b2ChainShape::GetChildEdge: a loop repeats its first vertex at the end."""
    pts = tuple(chain.vertices) + ((chain.vertices[0],) if chain.loop else ())
    n = len(pts)
    v1, v2 = pts[i], pts[i + 1]
    if i > 0:
        v0: Vec2 | None = pts[i - 1]
    else:
        v0 = pts[n - 2] if chain.loop else None
    if i < n - 2:
        v3: Vec2 | None = pts[i + 2]
    else:
        v3 = pts[1] if chain.loop else None
    mid = (0.5 * (v1[0] + v2[0]), 0.5 * (v1[1] + v2[1]))
    return Convex("edge", (v1, v2), (), POLYGON_RADIUS, mid, v0, v3)
