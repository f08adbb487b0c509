"""World queries with Box2D semantics: ray casts, AABB, point and shape overlap.

pymunk answers the same questions, but not the way a pybox2d user expects:
its ``segment_query`` is unsorted, reports a shape the ray starts inside (at
alpha 0) and hits polygons on their rounded skin; its queries return sensors
and know nothing about entities. This module turns them into kge answers:

* every result names the **collider entity** and the **body entity** (None for
  the implicit static body), read from the space's
  :class:`~kge.physics.shape_table.ShapeTable`, where the physics system
  registers each pymunk shape it builds (other shapes are never reported);
* geometry is exact and skin-free, as Box2D's ``RayCast`` and ``TestPoint``:
  a box of half-width 0.5 is hit at x = -0.5, not at its 0.01 m skin;
* :func:`raycast` runs Box2D's callback protocol. pymunk finds the candidate
  shapes, kge computes each exact hit and delivers them **in order of
  increasing fraction** within the current clip, so the protocol gives Box2D's
  answers without a tree walk. The callback gets a :class:`RayHit` and returns a
  float: the hit's ``fraction`` clips the ray (closest hit), ``1`` continues
  (all hits), ``0`` stops, ``-1`` (any negative) ignores this hit;
* a ray starting inside a polygon or circle does not report it (a ray starting
  *on* an edge reports it at fraction 0), sensors are reported unless filtered,
  and a zero-length ray is refused with a :class:`~kge.errors.ValidationError`
  where Box2D asserts.

Filtering (the ``filter`` argument of every query):

* ``None``: everything is reported, sensors included (Box2D 2.3);
* a :class:`~kge.components.filter.Filter`: a collider is reported when a
  collider with that filter would *collide* with it - Box2D's contact rule
  (same non-zero group: iff positive; else ``(f.category_bits & c.mask_bits)
  and (c.category_bits & f.mask_bits)``), the rule of Box2D v3's query filter.
  So ``Filter(mask_bits=GROUND)`` reports only ground colliders that accept
  category 1, and a projectile's own filter reports what it would hit;
* a callable ``predicate(collider_entity) -> bool``;
* ``sensors=False`` (keyword) drops sensors whatever the filter says.

>>> import pymunk
>>> space = pymunk.Space()
>>> box = pymunk.Poly.create_box(space.static_body, (1.0, 1.0), radius=0.01)
>>> slot = ShapeTable.of(space).add(box, collider=7, body=None)
>>> space.add(box)
>>> hit = raycast(space, (-2.0, 0.0), (2.0, 0.0))
>>> hit.collider, hit.point, hit.normal, hit.fraction
(7, (-0.5, 0.0), (-1.0, 0.0), 0.375)
>>> raycast(space, (0.0, 0.0), (2.0, 0.0)) is None  # starts inside the box
True
>>> [h.collider for h in query_point(space, (0.5, 0.0))]  # boundary counts
[7]
"""

from __future__ import annotations

import heapq
import math
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass
from enum import StrEnum
from typing import Any

import pymunk

from kge.components.filter import Filter
from kge.components.shapes import SHAPE_TYPES, Box, Chain, Circle, Edge, Polygon
from kge.errors import ComponentTypeError, ValidationError
from kge.physics.cp import body_handle, lib, shape_handle
from kge.physics.shape_table import SENSOR, ShapeTable
from kge.validate import finite, number, vec2

_poly_count = lib.cpPolyShapeGetCount
_poly_vert = lib.cpPolyShapeGetVert
_body_position = lib.cpBodyGetPosition
_body_angle = lib.cpBodyGetAngle

Vec2 = tuple[float, float]


class RayMode(StrEnum):
    """What a ray cast without a callback returns (``Physics.raycast(..., mode=)``)."""

    CLOSEST = "closest"  #: the nearest hit, or None
    ALL = "all"  #: every hit, by increasing fraction
    ANY = "any"  #: the first hit found (cheapest; not necessarily the nearest), or None

#: What every query accepts as ``filter``.
QueryFilter = Filter | Callable[[int], bool] | None

_ALL = pymunk.ShapeFilter()
_MODES = ("closest", "all", "any")


@dataclass(frozen=True, slots=True)
class RayHit:
    """One ray-collider intersection (Box2D's ``ReportFixture`` arguments).

    ``normal`` is the unit surface normal at ``point``, facing the ray's start;
    ``fraction`` is the position along the ray: ``point = p1 + fraction*(p2 - p1)``.
    """

    collider: int
    body: int | None
    point: Vec2
    normal: Vec2
    fraction: float


@dataclass(frozen=True, slots=True)
class QueryHit:
    """A collider found by an AABB, point or shape query.

    Only :func:`query_shape` fills the contact fields: ``point`` (on the
    collider's surface), ``normal`` (unit, from the query shape towards the
    collider) and ``distance`` (the separation, negative when they overlap).
    """

    collider: int
    body: int | None
    point: Vec2 | None = None
    normal: Vec2 | None = None
    distance: float | None = None


# --------------------------------------------------------------------------- filtering


def _acceptor(
    table: ShapeTable, filter: Any, sensors: bool, owner: str
) -> Callable[[pymunk.Shape], bool]:
    """Turn the user's ``filter`` into a shape predicate (shapes not in ``table`` never pass)."""
    if not isinstance(sensors, bool):
        raise ComponentTypeError(f"{owner}: sensors must be True or False, got {sensors!r}")
    index, flags = table.index, table.flags

    def slot(shape: pymunk.Shape) -> int | None:
        """The shape's slot, None when it is not to be reported at all."""
        i = index.get(shape_handle(shape))
        if i is None or (not sensors and flags[i] & SENSOR):
            return None
        return i

    if filter is None:

        def accept(shape: pymunk.Shape) -> bool:
            return slot(shape) is not None
    elif isinstance(filter, Filter):
        query = filter

        def accept(shape: pymunk.Shape) -> bool:
            i = slot(shape)
            return i is not None and query.collides_with(table.filters[i])
    elif callable(filter):
        predicate = filter

        def accept(shape: pymunk.Shape) -> bool:
            i = slot(shape)
            return i is not None and bool(predicate(int(table.collider[i])))
    else:
        raise ComponentTypeError(
            f"{owner}: filter must be a kge Filter, a predicate(collider_entity) -> bool "
            f"or None, got {type(filter).__name__} {filter!r}"
        )
    return accept


def _space(space: Any, owner: str) -> pymunk.Space:
    if not isinstance(space, pymunk.Space):
        raise ComponentTypeError(f"{owner}: expected a pymunk.Space, got {type(space).__name__}")
    return space


def _one_per_collider(table: ShapeTable, shapes: Iterable[pymunk.Shape]) -> list[QueryHit]:
    """A hit for the first shape of each collider (chains have several), by collider entity."""
    seen: dict[int, int] = {}
    index = table.index
    for s in shapes:
        i = index[shape_handle(s)]
        seen.setdefault(int(table.collider[i]), i)
    return [QueryHit(c, table.body_entity(seen[c])) for c in sorted(seen)]


# --------------------------------------------------------------------------- geometry


def _world_vertices(shape: pymunk.Poly) -> list[Vec2]:
    """Core (skin-free) vertices in world space, counter-clockwise.

    Read with Chipmunk's getters and turned with the body's pose once: a lidar of
    ten rays meets a few polygons each per step, and pymunk's ``get_vertices`` and
    ``local_to_world`` build two ``Vec2d`` per vertex.
    """
    cs = shape_handle(shape)
    local = [_poly_vert(cs, i) for i in range(_poly_count(cs))]
    body = shape.body
    if body is None:
        pts = [(v.x, v.y) for v in local]
    else:
        cb = body_handle(body)
        o, a = _body_position(cb), _body_angle(cb)
        c, s = math.cos(a), math.sin(a)
        pts = [(o.x + c * v.x - s * v.y, o.y + s * v.x + c * v.y) for v in local]
    area2 = sum(
        pts[i][0] * pts[(i + 1) % len(pts)][1] - pts[(i + 1) % len(pts)][0] * pts[i][1]
        for i in range(len(pts))
    )
    return pts[::-1] if area2 < 0 else pts


def _world_point(shape: pymunk.Shape, local: Any) -> Vec2:
    p = shape.body.local_to_world(local) if shape.body is not None else local
    return (float(p[0]), float(p[1]))


def _ray_circle(
    c: Vec2, r: float, p1: Vec2, d: Vec2, max_fraction: float = 1.0
) -> tuple[float, Vec2] | None:
    """Box2D b2CircleShape::RayCast (fraction in [0, max_fraction], start inside = miss)."""
    sx, sy = p1[0] - c[0], p1[1] - c[1]
    b = sx * sx + sy * sy - r * r
    cc = sx * d[0] + sy * d[1]
    rr = d[0] * d[0] + d[1] * d[1]
    sigma = cc * cc - rr * b
    if sigma < 0.0 or rr < 1e-30:
        return None
    a = -(cc + math.sqrt(sigma))
    if not 0.0 <= a <= max_fraction * rr:
        return None
    t = a / rr
    nx, ny = sx + t * d[0], sy + t * d[1]
    n = math.hypot(nx, ny)
    return t, ((nx / n, ny / n) if n > 0 else (0.0, 0.0))


def _ray_polygon(
    verts: Sequence[Vec2], p1: Vec2, d: Vec2, max_fraction: float = 1.0
) -> tuple[float, Vec2] | None:
    """Box2D b2PolygonShape::RayCast on the core polygon (start inside = miss)."""
    lower, upper, index = 0.0, max_fraction, -1
    normal = (0.0, 0.0)
    n = len(verts)
    for i in range(n):
        (x0, y0), (x1, y1) = verts[i], verts[(i + 1) % n]
        ex, ey = x1 - x0, y1 - y0
        length = math.hypot(ex, ey)
        if length == 0.0:
            continue
        nx, ny = ey / length, -ex / length
        numerator = nx * (x0 - p1[0]) + ny * (y0 - p1[1])
        denominator = nx * d[0] + ny * d[1]
        if denominator == 0.0:
            if numerator < 0.0:
                return None
        elif denominator < 0.0 and numerator < lower * denominator:
            lower, index, normal = numerator / denominator, i, (nx, ny)
        elif denominator > 0.0 and numerator < upper * denominator:
            upper = numerator / denominator
        if upper < lower:
            return None
    return (lower, normal) if index >= 0 else None


def _ray_edge(
    v1: Vec2, v2: Vec2, p1: Vec2, d: Vec2, max_fraction: float = 1.0
) -> tuple[float, Vec2] | None:
    """Box2D b2EdgeShape::RayCast: two-sided, normal facing the ray."""
    ex, ey = v2[0] - v1[0], v2[1] - v1[1]
    rr = ex * ex + ey * ey
    if rr == 0.0:
        return None
    length = math.sqrt(rr)
    nx, ny = ey / length, -ex / length
    numerator = nx * (v1[0] - p1[0]) + ny * (v1[1] - p1[1])
    denominator = nx * d[0] + ny * d[1]
    if denominator == 0.0:
        return None
    t = numerator / denominator
    if not 0.0 <= t <= max_fraction:
        return None
    qx, qy = p1[0] + t * d[0], p1[1] + t * d[1]
    s = ((qx - v1[0]) * ex + (qy - v1[1]) * ey) / rr
    if not 0.0 <= s <= 1.0:
        return None
    return t, ((-nx, -ny) if numerator > 0.0 else (nx, ny))


def _ray_shape(shape: pymunk.Shape, p1: Vec2, d: Vec2) -> tuple[float, Vec2] | None:
    if isinstance(shape, pymunk.Circle):
        return _ray_circle(_world_point(shape, shape.offset), shape.radius, p1, d)
    if isinstance(shape, pymunk.Poly):
        return _ray_polygon(_world_vertices(shape), p1, d)
    if isinstance(shape, pymunk.Segment):
        return _ray_edge(_world_point(shape, shape.a), _world_point(shape, shape.b), p1, d)
    return None


def _contains(shape: pymunk.Shape, p: Vec2) -> bool:
    """Box2D TestPoint: boundary inclusive, skin ignored, edges never contain."""
    if isinstance(shape, pymunk.Circle):
        cx, cy = _world_point(shape, shape.offset)
        return (p[0] - cx) ** 2 + (p[1] - cy) ** 2 <= shape.radius**2
    if isinstance(shape, pymunk.Poly):
        verts = _world_vertices(shape)
        n = len(verts)
        for i in range(n):
            (x0, y0), (x1, y1) = verts[i], verts[(i + 1) % n]
            # outward normal (y1 - y0, x0 - x1), unnormalised: only the sign matters
            if (y1 - y0) * (p[0] - x0) + (x0 - x1) * (p[1] - y0) > 0.0:
                return False
        return True
    return False


def _point_bb(p: Vec2) -> pymunk.BB:
    return pymunk.BB(p[0], p[1], p[0], p[1])


# --------------------------------------------------------------------------- ray cast


def _hit(
    table: ShapeTable, shape: pymunk.Shape, p1: Vec2, d: Vec2, t: float, normal: Vec2
) -> RayHit:
    point = (p1[0] + t * d[0], p1[1] + t * d[1])
    clean = (normal[0] + 0.0, normal[1] + 0.0)  # no -0.0 in results
    i = table.index[shape_handle(shape)]
    return RayHit(int(table.collider[i]), table.body_entity(i), point, clean, t)


def _ray_hits(
    space: pymunk.Space, table: ShapeTable, p1: Vec2, p2: Vec2,
    accept: Callable[[pymunk.Shape], bool],
) -> Iterator[RayHit]:
    """Exact hits in increasing fraction (ties by collider entity), computed lazily.

    pymunk hits each shape on its skinned outline, which contains the core, so
    its ``alpha`` is a lower bound of the exact fraction. Candidates are
    examined in that order and a hit is released once no unexamined candidate
    can be nearer: "closest" usually computes one or two exact hits.
    """
    d = (p2[0] - p1[0], p2[1] - p1[1])
    bounds: dict[pymunk.Shape, float] = {}
    for info in space.segment_query(p1, p2, 0.0, _ALL):
        bounds[info.shape] = info.alpha
    # shapes containing p1 (a ray starting in a skin) may be missed or reported at 0
    for shape in space.bb_query(_point_bb(p1), _ALL):
        bounds[shape] = 0.0
    candidates = sorted(bounds.items(), key=lambda item: item[1])
    pending: list[tuple[float, int, int, RayHit]] = []
    for order, (shape, bound) in enumerate(candidates):
        while pending and pending[0][0] < bound:
            yield heapq.heappop(pending)[3]
        if not accept(shape):
            continue
        exact = _ray_shape(shape, p1, d)
        if exact is not None:
            t, normal = exact
            hit = _hit(table, shape, p1, d, t, normal)
            heapq.heappush(pending, (t, hit.collider, order, hit))
    while pending:
        yield heapq.heappop(pending)[3]


def _callback_value(value: Any) -> float:
    try:
        v = number(value, "raycast callback", "return value")
    except ComponentTypeError:
        raise ComponentTypeError(
            "raycast callback must return a float: the hit's fraction to clip the ray, "
            f"1 to continue, 0 to stop, -1 to ignore this collider; got {value!r}"
        ) from None
    if math.isnan(v):
        raise ValidationError("raycast callback returned NaN; return fraction, 1, 0 or -1")
    return v


def raycast(
    space: pymunk.Space,
    p1: Any,
    p2: Any,
    callback: Callable[[RayHit], float] | None = None,
    mode: RayMode | str = RayMode.CLOSEST,
    filter: QueryFilter = None,
    *,
    sensors: bool = True,
) -> RayHit | list[RayHit] | None:
    """Cast the segment ``p1 -> p2`` and report the colliders it crosses.

    With ``callback``, Box2D's protocol: each hit within the current clip is
    passed to ``callback(hit)`` in order of increasing fraction; the returned
    float clips the ray to that fraction (return ``hit.fraction`` for the
    closest hit), ``1`` continues, ``0`` stops, ``-1`` ignores the hit. Returns
    None (collect what you need in the callback).

    Without a callback, ``mode`` decides: ``"closest"`` returns the nearest
    :class:`RayHit` or None, ``"all"`` every hit sorted by fraction (a chain
    collider is reported once per segment it crosses, as Box2D's chain
    children), ``"any"`` the first hit found (cheapest; not necessarily the
    nearest) or None.

    >>> import pymunk
    >>> space = pymunk.Space()
    >>> for i, x in enumerate((0.0, 3.0)):
    ...     s = pymunk.Circle(space.static_body, 0.5, (x, 0.0))
    ...     _ = ShapeTable.of(space).add(s, collider=i + 1, body=None)
    ...     space.add(s)
    >>> [round(h.fraction, 4) for h in raycast(space, (-2, 0), (12, 0), mode="all")]
    [0.1071, 0.3214]
    >>> raycast(space, (1, 1), (1, 1))
    Traceback (most recent call last):
    ...
    kge.errors.ValidationError: raycast: p1 and p2 are the same point (1.0, 1.0); ...
    """
    space = _space(space, "raycast")
    a = vec2(p1, "raycast", "p1")
    b = vec2(p2, "raycast", "p2")
    if a == b:
        raise ValidationError(f"raycast: p1 and p2 are the same point {a!r}; a ray needs a length")
    if callback is not None and not callable(callback):
        raise ComponentTypeError(
            f"raycast: callback must be callable or None, got {type(callback).__name__}"
        )
    if mode not in _MODES:
        raise ValidationError(f"raycast: mode must be one of {_MODES}, got {mode!r}")
    table = ShapeTable.of(space)
    accept = _acceptor(table, filter, sensors, "raycast")

    if callback is None and mode == "any":
        d = (b[0] - a[0], b[1] - a[1])
        for info in space.segment_query(a, b, 0.0, _ALL):
            if accept(info.shape) and (exact := _ray_shape(info.shape, a, d)) is not None:
                return _hit(table, info.shape, a, d, *exact)
        # a ray starting in a shape's skin: fall through to the complete search
    hits = _ray_hits(space, table, a, b, accept)
    if callback is None:
        if mode == "all":
            return list(hits)
        return next(hits, None)

    clip = 1.0
    for hit in hits:
        if hit.fraction > clip:
            break  # in order: nothing further can be within the clip
        value = _callback_value(callback(hit))
        if value == 0.0:
            break
        if value > 0.0:
            clip = min(value, 1.0)
    return None


# --------------------------------------------------------------------------- AABB / point


def query_aabb(
    space: pymunk.Space,
    lower: Any,
    upper: Any,
    callback: Callable[[QueryHit], Any] | None = None,
    filter: QueryFilter = None,
    *,
    sensors: bool = True,
) -> list[QueryHit]:
    """Colliders whose bounding box overlaps the box ``lower``..``upper``.

    Box2D's QueryAABB: a bounding-box test, not an exact one (a rotated box's
    corner region counts). Box2D reports fat AABBs (0.1 m margin); kge reports
    the tight ones (polygon and edge skin included), which is the lower bound
    of Box2D's result. One :class:`QueryHit` per collider, ordered by collider
    entity. With ``callback``, each hit is passed in that order and returning
    ``False`` stops the query (any other value continues); the hits delivered
    so far are returned.
    """
    space = _space(space, "query_aabb")
    lo = vec2(lower, "query_aabb", "lower")
    hi = vec2(upper, "query_aabb", "upper")
    if lo[0] > hi[0] or lo[1] > hi[1]:
        raise ValidationError(f"query_aabb: lower {lo!r} must not exceed upper {hi!r}")
    if callback is not None and not callable(callback):
        raise ComponentTypeError(
            f"query_aabb: callback must be callable or None, got {type(callback).__name__}"
        )
    table = ShapeTable.of(space)
    accept = _acceptor(table, filter, sensors, "query_aabb")
    shapes = [s for s in space.bb_query(pymunk.BB(lo[0], lo[1], hi[0], hi[1]), _ALL) if accept(s)]
    hits = _one_per_collider(table, shapes)
    if callback is None:
        return hits
    delivered: list[QueryHit] = []
    for hit in hits:
        delivered.append(hit)
        if callback(hit) is False:
            break
    return delivered


def query_point(
    space: pymunk.Space, p: Any, filter: QueryFilter = None, *, sensors: bool = True
) -> list[QueryHit]:
    """Colliders containing point ``p`` (Box2D TestPoint), ordered by collider entity.

    The boundary counts as inside; the polygon skin does not; an edge or chain
    never contains a point.
    """
    space = _space(space, "query_point")
    q = vec2(p, "query_point", "p")
    table = ShapeTable.of(space)
    accept = _acceptor(table, filter, sensors, "query_point")
    shapes = [s for s in space.bb_query(_point_bb(q), _ALL) if accept(s) and _contains(s, q)]
    return _one_per_collider(table, shapes)


# --------------------------------------------------------------------------- shape overlap


def _as_kge_shape(shape: Any) -> Any:
    """A validated kge shape from a kge shape or a duck-typed look-alike."""
    if isinstance(shape, SHAPE_TYPES):
        return shape
    if hasattr(shape, "radius"):
        return Circle(shape.radius, getattr(shape, "center", (0.0, 0.0)))
    if hasattr(shape, "half_width") and hasattr(shape, "half_height"):
        return Box(
            shape.half_width,
            shape.half_height,
            getattr(shape, "center", (0.0, 0.0)),
            getattr(shape, "angle", 0.0),
        )
    if hasattr(shape, "vertices") and hasattr(shape, "loop"):
        return Chain(shape.vertices, shape.loop)
    if hasattr(shape, "vertices"):
        return Polygon(shape.vertices)
    if hasattr(shape, "v1") and hasattr(shape, "v2"):
        return Edge(shape.v1, shape.v2)
    raise ComponentTypeError(
        "query_shape: shape must be a kge Circle, Box, Polygon, Edge or Chain, got "
        f"{type(shape).__name__} {shape!r}"
    )


def _pose(transform: Any) -> tuple[float, float, float]:
    """(x, y, angle) from a kge Transform, an (x, y, angle) or an (x, y) sequence."""
    if all(hasattr(transform, k) for k in ("x", "y", "angle")):
        values = (transform.x, transform.y, transform.angle)
    elif isinstance(transform, (tuple, list)) and len(transform) in (2, 3):
        values = (*transform, 0.0) if len(transform) == 2 else tuple(transform)
    else:
        raise ComponentTypeError(
            "query_shape: transform must be a kge Transform or an (x, y, angle) tuple, got "
            f"{type(transform).__name__} {transform!r}"
        )
    x, y, angle = values
    return (
        finite(x, "query_shape", "transform.x"),
        finite(y, "query_shape", "transform.y"),
        finite(angle, "query_shape", "transform.angle"),
    )


def _probes(shape: Any) -> list[pymunk.Shape]:
    """Body-less pymunk shapes for a kge shape (no skin: the shape's exact outline)."""
    if isinstance(shape, Circle):
        return [pymunk.Circle(None, shape.radius, shape.center)]
    if isinstance(shape, Box):
        return [pymunk.Poly(None, shape.vertices())]
    if isinstance(shape, Polygon):
        return [pymunk.Poly(None, shape.vertices)]
    if isinstance(shape, Edge):
        return [pymunk.Segment(None, shape.v1, shape.v2, 0.0)]
    return [pymunk.Segment(None, a, b, 0.0) for a, b in shape.segments()]


def query_shape(
    space: pymunk.Space,
    shape: Any,
    transform: Any,
    filter: QueryFilter = None,
    *,
    sensors: bool = True,
) -> list[QueryHit]:
    """Colliders overlapping ``shape`` placed at ``transform``, ordered by collider entity.

    ``shape`` is a kge Circle, Box, Polygon, Edge or Chain (or an object with
    the same fields); ``transform`` a kge Transform or ``(x, y, angle)``. The
    query shape is used exactly, without a skin; colliders are tested with
    their collision outline (polygons and edges include the 0.01 m skin), so a
    shape touching a resting body's surface reports it. Each hit carries the
    deepest contact: ``point`` on the collider, ``normal`` from the query shape
    towards the collider and ``distance`` (negative = overlap depth).
    """
    space = _space(space, "query_shape")
    geometry = _as_kge_shape(shape)
    x, y, angle = _pose(transform)
    table = ShapeTable.of(space)
    accept = _acceptor(table, filter, sensors, "query_shape")
    c, s = math.cos(angle), math.sin(angle)
    placement = pymunk.Transform(a=c, b=s, c=-s, d=c, tx=x, ty=y)
    best: dict[int, QueryHit] = {}
    for probe in _probes(geometry):
        probe.update(placement)  # a body-less shape keeps a stale AABB until updated
        for info in space.shape_query(probe):
            other = info.shape
            if not accept(other):
                continue
            i = table.index[shape_handle(other)]
            collider, body = int(table.collider[i]), table.body_entity(i)
            cps = info.contact_point_set
            if cps.points:
                deepest = min(cps.points, key=lambda cp: cp.distance)
                hit = QueryHit(
                    collider,
                    body,
                    (float(deepest.point_b[0]), float(deepest.point_b[1])),
                    (float(cps.normal[0]) + 0.0, float(cps.normal[1]) + 0.0),
                    float(deepest.distance),
                )
            else:
                hit = QueryHit(collider, body)
            old = best.get(hit.collider)
            if old is None or (old.distance or 0.0) > (hit.distance or 0.0):
                best[hit.collider] = hit
    return [best[k] for k in sorted(best)]
