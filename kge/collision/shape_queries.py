"""Questions about one posed shape: does it contain a point, where does a ray hit it,
what box bounds it, what does it weigh.

These are Box2D's ``b2Shape::TestPoint``, ``RayCast``, ``ComputeAABB`` and
``ComputeMass``, on kge shapes and without a World:

* :func:`test_point`: the boundary counts as inside; the polygon skin does
  not; edges and chains contain nothing (they have no inside);
* :func:`ray_cast`: the ray runs from ``p1`` to ``p2`` and the hit's
  ``fraction`` is measured along it (``point = p1 + fraction * (p2 - p1)``);
  ``max_fraction`` clips it, as ``b2RayCastInput.maxFraction``. A ray that
  *starts inside* a circle or polygon does not hit it (Box2D's rule: a ray
  is meant to find surfaces from outside); edges are two-sided and the normal
  faces the ray;
* :func:`aabb`: the tight box, skin included for polygons and edges (Box2D
  adds the 0.01 m radius), none for chain children (Box2D 2.3 adds none);
* :func:`mass_data`: what kge's physics computes for a collider of that
  shape and density (:func:`kge.physics.mass.shape_mass`), centre moved to the
  pose, so the numbers agree with the simulation's.

>>> from kge.components.shapes import Box, Circle
>>> hit = ray_cast(Box(1.0, 1.0), (0.0, 0.0, 0.0), (-3.0, 0.0), (3.0, 0.0))
>>> hit.point, hit.normal, hit.fraction
((-1.0, 0.0), (-1.0, 0.0), 0.3333333333333333)
>>> ray_cast(Box(1.0, 1.0), (0.0, 0.0, 0.0), (0.0, 0.0), (3.0, 0.0)) is None  # starts inside
True
>>> test_point(Circle(1.0), (5.0, 0.0, 0.0), (6.0, 0.0))  # on the boundary
True
>>> aabb(Circle(0.5), (1.0, 1.0, 0.0))
AABB(lower=(0.5, 0.5), upper=(1.5, 1.5))
>>> mass_data(Box(1.0, 0.5), (3.0, 0.0, 0.0), density=2.0)
MassData(mass=4.0, inertia=1.666..., center=(3.0, 0.0))
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from kge.collision.geometry import convex, shape_of
from kge.collision.pose import Pose, point, pose
from kge.components.shapes import Chain
from kge.errors import ValidationError
from kge.physics.mass import MassData, shape_mass
from kge.physics.queries import _ray_circle, _ray_edge, _ray_polygon
from kge.validate import finite, non_negative

Vec2 = tuple[float, float]


@dataclass(slots=True, frozen=True)
class AABB:
    """An axis-aligned box from ``lower`` (min x, min y) to ``upper`` (max x, max y)."""

    lower: Vec2
    upper: Vec2

    def overlaps(self, other: AABB) -> bool:
        """Box2D's b2TestOverlap: touching boxes overlap."""
        return not (
            other.lower[0] > self.upper[0] or other.lower[1] > self.upper[1]
            or self.lower[0] > other.upper[0] or self.lower[1] > other.upper[1]
        )

    def contains(self, other: AABB) -> bool:
        """True when ``other`` lies inside this box (boundary included)."""
        return (
            self.lower[0] <= other.lower[0] and self.lower[1] <= other.lower[1]
            and other.upper[0] <= self.upper[0] and other.upper[1] <= self.upper[1]
        )

    def union(self, other: AABB) -> AABB:
        return AABB(
            (min(self.lower[0], other.lower[0]), min(self.lower[1], other.lower[1])),
            (max(self.upper[0], other.upper[0]), max(self.upper[1], other.upper[1])),
        )

    @property
    def perimeter(self) -> float:
        """Box2D's cost measure for the dynamic tree."""
        return 2.0 * ((self.upper[0] - self.lower[0]) + (self.upper[1] - self.lower[1]))


def aabb_of(lower: Any, upper: Any, field: str = "aabb") -> AABB:
    """A validated AABB (finite corners, lower <= upper)."""
    lo, hi = point(lower, f"{field}.lower"), point(upper, f"{field}.upper")
    if lo[0] > hi[0] or lo[1] > hi[1]:
        raise ValidationError(f"{field}.lower {lo!r} must not exceed {field}.upper {hi!r}")
    return AABB(lo, hi)


@dataclass(slots=True, frozen=True)
class RayCastOutput:
    """Where a ray first enters a shape: world ``point``, unit ``normal`` there, ``fraction``."""

    point: Vec2
    normal: Vec2
    fraction: float


def test_point(shape: Any, at: Any, p: Any, child: Any = 0) -> bool:
    """True when world point ``p`` lies in ``shape`` posed at ``at`` (boundary counts)."""
    piece = convex(shape, child)
    xf = pose(at)
    local = xf.inverse(point(p, "p"))
    if piece.kind == "circle":
        (cx, cy), r = piece.vertices[0], piece.radius
        return (local[0] - cx) ** 2 + (local[1] - cy) ** 2 <= r * r
    if piece.kind == "edge":
        return False
    for (vx, vy), (nx, ny) in zip(piece.vertices, piece.normals, strict=True):
        if nx * (local[0] - vx) + ny * (local[1] - vy) > 0.0:
            return False
    return True


test_point.__test__ = False  # type: ignore[attr-defined]  # Box2D's name; not a pytest test


def ray_cast(
    shape: Any, at: Any, p1: Any, p2: Any, max_fraction: Any = 1.0, child: Any = 0
) -> RayCastOutput | None:
    """The first hit of the ray ``p1 -> p2`` on ``shape`` posed at ``at``, or None.

    Computed in the shape's frame (as Box2D does): the ray is moved into it,
    and the normal rotated back out.
    """
    piece = convex(shape, child)
    xf = pose(at)
    a, b = point(p1, "p1"), point(p2, "p2")
    limit = non_negative(max_fraction, "", "max_fraction")
    if a == b:
        raise ValidationError(f"ray_cast needs p1 != p2 (a zero-length ray), got {a!r} twice")
    la, lb = xf.inverse(a), xf.inverse(b)
    d = (lb[0] - la[0], lb[1] - la[1])
    if piece.kind == "circle":
        hit = _ray_circle(piece.vertices[0], piece.radius, la, d, limit)
    elif piece.kind == "polygon":
        hit = _ray_polygon(piece.vertices, la, d, limit)
    else:
        hit = _ray_edge(piece.vertices[0], piece.vertices[1], la, d, limit)
    if hit is None:
        return None
    t, n = hit
    wn = xf.rotate(n)
    pt = (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
    return RayCastOutput(pt, (wn[0] + 0.0, wn[1] + 0.0), t)


def aabb(shape: Any, at: Any, child: Any = 0) -> AABB:
    """The world AABB of ``shape`` posed at ``at`` (Box2D's ComputeAABB)."""
    piece = convex(shape, child)
    xf = pose(at)
    return _aabb(piece.vertices, 0.0 if isinstance(shape, Chain) else piece.radius, xf)


def _aabb(verts: tuple[Vec2, ...], r: float, xf: Pose) -> AABB:
    pts = [xf.apply(v) for v in verts]
    xs = [p[0] for p in pts]
    ys = [p[1] for p in pts]
    return AABB((min(xs) - r, min(ys) - r), (max(xs) + r, max(ys) + r))


def mass_data(shape: Any, at: Any = (0.0, 0.0, 0.0), density: Any = 1.0) -> MassData:
    """Mass, inertia about the centre of mass, and the world centre of mass.

    Uses :func:`kge.physics.mass.shape_mass`, the function the physics
    system builds bodies from; edges and chains are massless (Box2D).
    """
    shape_of(shape)
    xf = pose(at)
    rho = non_negative(finite(density, "", "density"), "", "density")
    md = shape_mass(shape, rho)
    return MassData(md.mass, md.inertia, xf.apply(md.center))
