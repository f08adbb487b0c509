"""The distance between two convex shapes and their closest points (GJK, as b2Distance).

The Gilbert-Johnson-Keerthi algorithm never looks at whole shapes: it asks
each for its *support point*, the vertex farthest along a direction, and
keeps a simplex (a point, a segment or a triangle) of differences between
support points of B and of A. Each iteration finds the simplex point nearest
the origin, keeps only the vertices that point depends on (barycentric
coordinates, Box2D's ``Solve2`` / ``Solve3``) and asks for the support point
in the direction of the origin. It stops when the simplex encloses the origin
(the cores overlap: distance 0), when the direction vanishes, or when a support
point repeats (no progress possible). The witness points are the barycentric
mixes of the simplex's A and B vertices.

The cores (vertices only) are measured first; with ``use_radii`` the radii are
then subtracted (circles' radius, the 0.01 m polygon skin), which moves the
witness points onto the surfaces, as Box2D does. When the rounded shapes touch
or overlap both points are their midpoint and the distance is 0: GJK gives no
penetration depth (the manifolds in :mod:`kge.collision.manifold` do).

A :class:`SimplexCache` carries the last simplex from one call to the next,
which makes repeated queries on slowly moving shapes converge in one or two
iterations; :mod:`kge.collision.toi` relies on it.

>>> from kge.components.shapes import Box, Circle
>>> out = distance(Box(0.5, 0.5), (0.0, 0.0, 0.0), Circle(0.5), (3.0, 0.0, 0.0))
>>> out.point_a, out.point_b, round(out.distance, 6)
((0.51, 0.0), (2.5, 0.0), 1.99)
>>> distance(Box(0.5, 0.5), (0, 0, 0), Circle(0.5), (3, 0, 0), use_radii=False).distance
2.5
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from kge.collision.geometry import Convex, convex
from kge.collision.pose import Pose, pose
from kge.validate import boolean

Vec2 = tuple[float, float]

#: Box2D's GJK iteration limit (b2_gjkMaxIters)
MAX_ITERATIONS = 20
#: b2_epsilon for float64: directions shorter than this stop the search
EPSILON = 2.220446049250313e-16


@dataclass(slots=True)
class SimplexCache:
    """The vertex indices of the last simplex and its size metric (b2SimplexCache)."""

    count: int = 0
    index_a: list[int] = field(default_factory=list)
    index_b: list[int] = field(default_factory=list)
    metric: float = 0.0


@dataclass(slots=True, frozen=True)
class DistanceOutput:
    """Closest points on A and on B (world), their distance, and GJK iterations used."""

    point_a: Vec2
    point_b: Vec2
    distance: float
    iterations: int


class _Vertex:
    """One simplex vertex: support points on A and B, their difference, its weight."""

    __slots__ = ("a", "ia", "ib", "wa", "wb", "wx", "wy")

    def __init__(self, ia: int, ib: int, wa: Vec2, wb: Vec2, a: float = 1.0) -> None:
        self.ia, self.ib, self.wa, self.wb, self.a = ia, ib, wa, wb, a
        self.wx, self.wy = wb[0] - wa[0], wb[1] - wa[1]


def support(vertices: tuple[Vec2, ...], dx: float, dy: float) -> int:
    """Index of the vertex farthest along (dx, dy); the first one wins ties (Box2D)."""
    best, value = 0, vertices[0][0] * dx + vertices[0][1] * dy
    for i in range(1, len(vertices)):
        v = vertices[i][0] * dx + vertices[i][1] * dy
        if v > value:
            best, value = i, v
    return best


def _make(a: Convex, xa: Pose, b: Convex, xb: Pose, ia: int, ib: int) -> _Vertex:
    return _Vertex(ia, ib, xa.apply(a.vertices[ia]), xb.apply(b.vertices[ib]))


def _metric(s: list[_Vertex]) -> float:
    if len(s) == 2:
        return math.hypot(s[0].wx - s[1].wx, s[0].wy - s[1].wy)
    if len(s) == 3:
        return ((s[1].wx - s[0].wx) * (s[2].wy - s[0].wy)
                - (s[1].wy - s[0].wy) * (s[2].wx - s[0].wx))
    return 0.0


def _read_cache(cache: SimplexCache, a: Convex, xa: Pose, b: Convex, xb: Pose) -> list[_Vertex]:
    s = [_make(a, xa, b, xb, cache.index_a[i], cache.index_b[i]) for i in range(cache.count)]
    for v in s:
        v.a = 0.0
    if len(s) > 1:  # flush a simplex whose size changed a lot: it no longer fits
        m1, m2 = cache.metric, _metric(s)
        if m2 < 0.5 * m1 or 2.0 * m1 < m2 or m2 < EPSILON:
            s = []
    return s or [_make(a, xa, b, xb, 0, 0)]


def _solve2(s: list[_Vertex]) -> list[_Vertex]:
    w1, w2 = s
    ex, ey = w2.wx - w1.wx, w2.wy - w1.wy
    d2 = -(w1.wx * ex + w1.wy * ey)
    if d2 <= 0.0:  # origin beyond w1
        w1.a = 1.0
        return [w1]
    d1 = w2.wx * ex + w2.wy * ey
    if d1 <= 0.0:  # origin beyond w2
        w2.a = 1.0
        return [w2]
    inv = 1.0 / (d1 + d2)
    w1.a, w2.a = d1 * inv, d2 * inv
    return s


def _solve3(s: list[_Vertex]) -> list[_Vertex]:
    """Closest feature of a triangle to the origin, by its Voronoi regions."""
    w1, w2, w3 = s
    e12 = (w2.wx - w1.wx, w2.wy - w1.wy)
    d12_1 = w2.wx * e12[0] + w2.wy * e12[1]
    d12_2 = -(w1.wx * e12[0] + w1.wy * e12[1])
    e13 = (w3.wx - w1.wx, w3.wy - w1.wy)
    d13_1 = w3.wx * e13[0] + w3.wy * e13[1]
    d13_2 = -(w1.wx * e13[0] + w1.wy * e13[1])
    e23 = (w3.wx - w2.wx, w3.wy - w2.wy)
    d23_1 = w3.wx * e23[0] + w3.wy * e23[1]
    d23_2 = -(w2.wx * e23[0] + w2.wy * e23[1])
    n123 = e12[0] * e13[1] - e12[1] * e13[0]
    d123_1 = n123 * (w2.wx * w3.wy - w2.wy * w3.wx)
    d123_2 = n123 * (w3.wx * w1.wy - w3.wy * w1.wx)
    d123_3 = n123 * (w1.wx * w2.wy - w1.wy * w2.wx)
    if d12_2 <= 0.0 and d13_2 <= 0.0:
        w1.a = 1.0
        return [w1]
    if d12_1 > 0.0 and d12_2 > 0.0 and d123_3 <= 0.0:
        inv = 1.0 / (d12_1 + d12_2)
        w1.a, w2.a = d12_1 * inv, d12_2 * inv
        return [w1, w2]
    if d13_1 > 0.0 and d13_2 > 0.0 and d123_2 <= 0.0:
        inv = 1.0 / (d13_1 + d13_2)
        w1.a, w3.a = d13_1 * inv, d13_2 * inv
        return [w1, w3]
    if d12_1 <= 0.0 and d23_2 <= 0.0:
        w2.a = 1.0
        return [w2]
    if d13_1 <= 0.0 and d23_1 <= 0.0:
        w3.a = 1.0
        return [w3]
    if d23_1 > 0.0 and d23_2 > 0.0 and d123_1 <= 0.0:
        inv = 1.0 / (d23_1 + d23_2)
        w2.a, w3.a = d23_1 * inv, d23_2 * inv
        return [w3, w2]
    inv = 1.0 / (d123_1 + d123_2 + d123_3)
    w1.a, w2.a, w3.a = d123_1 * inv, d123_2 * inv, d123_3 * inv
    return s


def _direction(s: list[_Vertex]) -> Vec2:
    """Towards the origin from the simplex (perpendicular to a segment, on its origin side)."""
    if len(s) == 1:
        return (-s[0].wx, -s[0].wy)
    ex, ey = s[1].wx - s[0].wx, s[1].wy - s[0].wy
    if ex * -s[0].wy - ey * -s[0].wx > 0.0:
        return (-ey, ex)
    return (ey, -ex)


def _witness(s: list[_Vertex]) -> tuple[Vec2, Vec2]:
    if len(s) == 1:
        return s[0].wa, s[0].wb
    pa = (sum(v.a * v.wa[0] for v in s), sum(v.a * v.wa[1] for v in s))
    if len(s) == 3:
        return pa, pa
    return pa, (sum(v.a * v.wb[0] for v in s), sum(v.a * v.wb[1] for v in s))


def gjk(
    a: Convex, xa: Pose, b: Convex, xb: Pose, cache: SimplexCache | None = None
) -> tuple[Vec2, Vec2, int]:
    """Closest points of the two cores (no radii) and the iteration count.

    ``cache`` is read first (if it holds a simplex) and rewritten at the end.
    """
    s = _read_cache(cache, a, xa, b, xb) if cache is not None and cache.count else [
        _make(a, xa, b, xb, 0, 0)]
    iterations = 0
    while iterations < MAX_ITERATIONS:
        saved = [(v.ia, v.ib) for v in s]
        if len(s) == 2:
            s = _solve2(s)
        elif len(s) == 3:
            s = _solve3(s)
        if len(s) == 3:  # the origin is inside the triangle: the cores overlap
            break
        dx, dy = _direction(s)
        if dx * dx + dy * dy < EPSILON * EPSILON:
            break  # the origin is on the simplex (touching cores)
        ia = support(a.vertices, *xa.unrotate((-dx, -dy)))
        ib = support(b.vertices, *xb.unrotate((dx, dy)))
        iterations += 1
        if (ia, ib) in saved:
            break  # a repeated support point: no further progress is possible
        s.append(_make(a, xa, b, xb, ia, ib))
    if cache is not None:
        cache.count = len(s)
        cache.index_a = [v.ia for v in s]
        cache.index_b = [v.ib for v in s]
        cache.metric = _metric(s)
    pa, pb = _witness(s)
    return pa, pb, iterations


def distance(
    shape_a: Any, pose_a: Any, shape_b: Any, pose_b: Any, *,
    child_a: Any = 0, child_b: Any = 0, use_radii: Any = True,
) -> DistanceOutput:
    """Closest points between two posed shapes (chains: one child each), as b2Distance."""
    a, b = convex(shape_a, child_a, "shape_a"), convex(shape_b, child_b, "shape_b")
    xa, xb = pose(pose_a, "pose_a"), pose(pose_b, "pose_b")
    radii = boolean(use_radii, "", "use_radii")
    pa, pb, iterations = gjk(a, xa, b, xb)
    return finish(pa, pb, a.radius if radii else 0.0, b.radius if radii else 0.0, iterations)


#: Box2D's b2TestOverlap threshold: 10 float32 epsilons (rounded shapes this close overlap)
OVERLAP_DISTANCE = 10.0 * 1.1920929e-07


def overlap(
    shape_a: Any, pose_a: Any, shape_b: Any, pose_b: Any, *, child_a: Any = 0, child_b: Any = 0
) -> bool:
    """True when the two rounded shapes touch or overlap (b2TestOverlap).

    The polygon skin counts, as in Box2D: two boxes whose cores are 0.015 m apart
    overlap. For "do they collide" with normals and depths, use
    :func:`kge.collision.collide`.
    """
    a, b = convex(shape_a, child_a, "shape_a"), convex(shape_b, child_b, "shape_b")
    xa, xb = pose(pose_a, "pose_a"), pose(pose_b, "pose_b")
    pa, pb, iterations = gjk(a, xa, b, xb)
    return finish(pa, pb, a.radius, b.radius, iterations).distance < OVERLAP_DISTANCE


def finish(pa: Vec2, pb: Vec2, ra: float, rb: float, iterations: int) -> DistanceOutput:
    """Move core witness points out by the radii (or to their midpoint if the shapes touch)."""
    d = math.hypot(pb[0] - pa[0], pb[1] - pa[1])
    if ra == 0.0 and rb == 0.0:
        return DistanceOutput(pa, pb, d, iterations)
    if d > ra + rb and d > EPSILON:
        nx, ny = (pb[0] - pa[0]) / d, (pb[1] - pa[1]) / d
        return DistanceOutput(
            (pa[0] + ra * nx, pa[1] + ra * ny), (pb[0] - rb * nx, pb[1] - rb * ny),
            d - ra - rb, iterations,
        )
    mid = (0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]))
    return DistanceOutput(mid, mid, 0.0, iterations)
