"""Collision shapes: frozen value objects in body-local metres.

A shape only describes geometry; density, friction and filtering live on the
:class:`~kge.components.collider.Collider` that holds it. Shapes are frozen so
that changing one means assigning a new shape to ``collider.shape``, which the
physics system sees as a write and rebuilds the pymunk shape for.

Sizes follow the pybox2d manual: :class:`Box` takes *half* extents, like
``SetAsBox``. Polygons must be convex and counter-clockwise with 3..16
vertices; anything else is an error (pymunk would silently take the hull,
which hides modelling mistakes).

>>> Box(1.0, 0.5).vertices()
((-1.0, -0.5), (1.0, -0.5), (1.0, 0.5), (-1.0, 0.5))
>>> Polygon([(0, 0), (1, 1), (1, 0)])
Traceback (most recent call last):
...
kge.errors.ValidationError: Polygon.vertices must be counter-clockwise (got clockwise order)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

from kge.errors import ValidationError
from kge.validate import finite, positive, vec2

Vec2 = tuple[float, float]

#: Box2D's b2_maxPolygonVertices in pybox2d 2.3.10.
MAX_POLYGON_VERTICES = 16
#: Box2D's b2_linearSlop: lengths below this are degenerate.
LINEAR_SLOP = 0.005
#: Largest size or body-local coordinate of a shape, in metres. Box2D is tuned for
#: moving shapes of 0.1-10 m and static ones up to about 50 m; far beyond, mass and
#: inertia (which grow with the fourth power of size) overflow to infinity and
#: every pose becomes NaN. A thousand kilometres is far past any sensible world.
MAX_LENGTH = 1e6


def _points(value: Any, owner: str, field: str) -> tuple[Vec2, ...]:
    if type(value) is tuple or type(value) is list:
        # what the loop below returns, found without a call per point (an RL reset
        # validates a new terrain outline every episode); anything else takes the
        # loop, which says what is wrong
        pts = tuple(value)
        if all(type(p) is tuple and len(p) == 2 and type(p[0]) is float and type(p[1]) is float
               and -MAX_LENGTH <= p[0] <= MAX_LENGTH and -MAX_LENGTH <= p[1] <= MAX_LENGTH
               for p in pts):
            return pts
    if isinstance(value, (str, bytes)) or not hasattr(value, "__iter__"):
        raise ValidationError(f"{owner}.{field} must be a sequence of (x, y) points, got {value!r}")
    return tuple(_point(p, owner, f"{field}[{i}]") for i, p in enumerate(value))


def _point(value: Any, owner: str, field: str) -> Vec2:
    """A finite (x, y) within :data:`MAX_LENGTH` of the body origin."""
    x, y = vec2(value, owner, field)
    if abs(x) > MAX_LENGTH or abs(y) > MAX_LENGTH:
        raise ValidationError(
            f"{owner}.{field} must lie within {MAX_LENGTH:g} m of the body origin, got {(x, y)!r}"
        )
    return (x, y)


def _length(value: Any, owner: str, field: str) -> float:
    """A positive size no larger than :data:`MAX_LENGTH`."""
    v = positive(value, owner, field)
    if v > MAX_LENGTH:
        raise ValidationError(f"{owner}.{field} must be <= {MAX_LENGTH:g} m, got {v!r}")
    return v


def _set(obj: object, name: str, value: Any) -> None:
    object.__setattr__(obj, name, value)


def signed_area(vertices: Sequence[Vec2]) -> float:
    """Twice-free signed area of a polygon (positive = counter-clockwise)."""
    n = len(vertices)
    s = 0.0
    for i in range(n):
        x0, y0 = vertices[i]
        x1, y1 = vertices[(i + 1) % n]
        s += x0 * y1 - x1 * y0
    return 0.5 * s


def check_convex_ccw(vertices: Sequence[Vec2], owner: str) -> None:
    """Refuse anything Box2D's b2PolygonShape.Set would not take as given."""
    n = len(vertices)
    if not 3 <= n <= MAX_POLYGON_VERTICES:
        raise ValidationError(
            f"{owner}.vertices must have 3..{MAX_POLYGON_VERTICES} vertices, got {n}"
        )
    for i in range(n):
        (x0, y0), (x1, y1) = vertices[i], vertices[(i + 1) % n]
        if math.hypot(x1 - x0, y1 - y0) < 0.5 * LINEAR_SLOP:
            raise ValidationError(
                f"{owner}.vertices {i} and {(i + 1) % n} coincide ({vertices[i]!r}); "
                "remove duplicate points"
            )
    area = signed_area(vertices)
    if abs(area) < 1e-9:
        raise ValidationError(f"{owner} has zero area (collinear vertices)")
    if area < 0:
        raise ValidationError(
            f"{owner}.vertices must be counter-clockwise (got clockwise order)"
        )
    for i in range(n):
        (x0, y0), (x1, y1), (x2, y2) = vertices[i], vertices[(i + 1) % n], vertices[(i + 2) % n]
        cross = (x1 - x0) * (y2 - y1) - (y1 - y0) * (x2 - x1)
        if cross <= 1e-12:
            raise ValidationError(
                f"{owner}.vertices must be convex: the turn at vertex {(i + 1) % n} "
                f"{vertices[(i + 1) % n]!r} is {'reflex' if cross < 0 else 'straight'}; "
                "split concave outlines into several colliders"
            )
    # every turn is to the left; a star (pentagram) is too, but winds around twice
    turning = 0.0
    for i in range(n):
        (x0, y0), (x1, y1), (x2, y2) = vertices[i], vertices[(i + 1) % n], vertices[(i + 2) % n]
        ax, ay, bx, by = x1 - x0, y1 - y0, x2 - x1, y2 - y1
        turning += math.atan2(ax * by - ay * bx, ax * bx + ay * by)
    winds = round(turning / math.tau)
    if winds != 1:
        raise ValidationError(
            f"{owner}.vertices must outline a simple convex polygon: the outline crosses "
            f"itself and winds {winds} times around (a star); list the hull's corners once"
        )


@dataclass(slots=True, frozen=True)
class Circle:
    """A disc of ``radius`` centred at ``center`` (body-local)."""

    radius: float
    center: Vec2 = (0.0, 0.0)

    def __post_init__(self) -> None:
        _set(self, "radius", _length(self.radius, "Circle", "radius"))
        _set(self, "center", _point(self.center, "Circle", "center"))


@dataclass(slots=True, frozen=True)
class Box:
    """A rectangle given by *half* extents, optionally offset and rotated."""

    half_width: float
    half_height: float
    center: Vec2 = (0.0, 0.0)
    angle: float = 0.0

    def __post_init__(self) -> None:
        for name in ("half_width", "half_height"):
            v = _length(getattr(self, name), "Box", name)
            if v < LINEAR_SLOP:
                raise ValidationError(f"Box.{name} must be >= {LINEAR_SLOP} m, got {v!r}")
            _set(self, name, v)
        _set(self, "center", _point(self.center, "Box", "center"))
        _set(self, "angle", finite(self.angle, "Box", "angle"))

    def vertices(self) -> tuple[Vec2, ...]:
        """The four corners, counter-clockwise, in body-local coordinates."""
        return _box_corners(self.half_width, self.half_height, self.center, self.angle)


@lru_cache(maxsize=256)
def _box_corners(hw: float, hh: float, center: Vec2, angle: float) -> tuple[Vec2, ...]:
    """Box corners, cached: games spawn many boxes of a few sizes (the tuples are immutable)."""
    c, s = math.cos(angle), math.sin(angle)
    cx, cy = center
    corners = ((-hw, -hh), (hw, -hh), (hw, hh), (-hw, hh))
    if angle == 0.0:
        return tuple((cx + x, cy + y) for x, y in corners)
    return tuple((cx + c * x - s * y, cy + s * x + c * y) for x, y in corners)


@dataclass(slots=True, frozen=True)
class Polygon:
    """A convex polygon: 3..16 vertices, counter-clockwise, no duplicates."""

    vertices: Sequence[Vec2]  # any sequence in; stored as a tuple

    def __post_init__(self) -> None:
        pts = _points(self.vertices, "Polygon", "vertices")
        check_convex_ccw(pts, "Polygon")
        _set(self, "vertices", pts)


@dataclass(slots=True, frozen=True)
class Edge:
    """A line segment from ``v1`` to ``v2``, two-sided and massless (Box2D edge).

    ``vertex0`` and ``vertex3`` are optional *ghost vertices* (Box2D's names): the
    far ends of the neighbouring edges before ``v1`` and after ``v2``. A shape
    sliding along a row of edges that name their neighbours crosses the joins
    without catching on them, as along a :class:`Chain`.
    """

    v1: Vec2
    v2: Vec2
    vertex0: Vec2 | None = None
    vertex3: Vec2 | None = None

    def __post_init__(self) -> None:
        a = _point(self.v1, "Edge", "v1")
        b = _point(self.v2, "Edge", "v2")
        if math.hypot(b[0] - a[0], b[1] - a[1]) < LINEAR_SLOP:
            raise ValidationError(f"Edge has zero length ({a!r} to {b!r})")
        _set(self, "v1", a)
        _set(self, "v2", b)
        for name in ("vertex0", "vertex3"):
            ghost = getattr(self, name)
            if ghost is not None:
                _set(self, name, _point(ghost, "Edge", name))


@dataclass(slots=True, frozen=True)
class Chain:
    """Connected segments with smooth joins (no bumps between segments).

    ``loop=True`` closes the chain from the last vertex back to the first.
    """

    vertices: Sequence[Vec2]  # any sequence in; stored as a tuple
    loop: bool = False

    def __post_init__(self) -> None:
        pts = _points(self.vertices, "Chain", "vertices")
        need = 3 if self.loop else 2
        if len(pts) < need:
            raise ValidationError(
                f"Chain.vertices needs at least {need} points"
                f"{' for a loop' if self.loop else ''}, got {len(pts)}"
            )
        n = len(pts) if self.loop else len(pts) - 1
        for i in range(n):
            a, b = pts[i], pts[(i + 1) % len(pts)]
            if math.hypot(b[0] - a[0], b[1] - a[1]) < LINEAR_SLOP:
                raise ValidationError(
                    f"Chain.vertices {i} and {(i + 1) % len(pts)} coincide ({a!r}); "
                    "consecutive points must differ"
                )
        if not isinstance(self.loop, bool):
            raise ValidationError(f"Chain.loop must be True or False, got {self.loop!r}")
        _set(self, "vertices", pts)

    def segments(self) -> list[tuple[Vec2, Vec2]]:
        """The chain's segments in order (closing segment included for loops)."""
        pts = self.vertices
        n = len(pts) if self.loop else len(pts) - 1
        return [(pts[i], pts[(i + 1) % len(pts)]) for i in range(n)]


Shape = Circle | Box | Polygon | Edge | Chain
SHAPE_TYPES: tuple[type, ...] = (Circle, Box, Polygon, Edge, Chain)
