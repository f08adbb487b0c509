"""What a tracked body sweeps: its shapes reduced to points and circles.

A sweep moves a few circles along the body's motion instead of whole shapes: a
circle is itself, a polygon is its vertices (plus one *guard*, a circle deep
inside it, that catches a body the solver pushed into an obstacle), an edge its
two ends. Every radius is shrunk by the sweep's ``margin`` so that surfaces the
body already rests on are never reported as hits.

The points depend only on a shape's body-local geometry, so they are cached by
that geometry (read through Chipmunk's C getters): a wave of identical boxes is
analysed once.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Any

import pymunk

from kge.physics.cp import body_handle, shape_handle
from kge.physics.cp import lib as _lib


@dataclass(slots=True)
class Part:
    """One shape of a tracked body and the points swept for it (body-local)."""

    shape: pymunk.Shape
    #: (x, y, radius, guard): the point is swept as a circle of that radius; a
    #: guard is a small circle deep inside the shape (see Tracked._time_of_impact)
    points: tuple[tuple[float, float, float, bool], ...]


#: what :func:`shape_points` computes for one shape: points, core radius, reach
_ShapePoints = tuple[tuple[tuple[float, float, float, bool], ...], float, float]


def geometry_of(shape: pymunk.Shape) -> tuple[Any, ...] | None:
    """A hashable description of a shape's body-local geometry (Chipmunk's getters).

    Read through Chipmunk directly: pymunk's ``get_vertices`` builds a Vec2d per
    vertex, and a game spawning a wave of 1,000 boxes tracks 1,000 bodies at once.
    """
    cp = shape_handle(shape)
    if isinstance(shape, pymunk.Circle):
        o = _lib.cpCircleShapeGetOffset(cp)
        return ("circle", _lib.cpCircleShapeGetRadius(cp), o.x, o.y)
    if isinstance(shape, pymunk.Poly):
        verts = []
        for i in range(_lib.cpPolyShapeGetCount(cp)):
            v = _lib.cpPolyShapeGetVert(cp, i)
            verts.append((v.x, v.y))
        c = _lib.cpShapeGetCenterOfGravity(cp)
        return ("poly", _lib.cpPolyShapeGetRadius(cp), tuple(verts), (c.x, c.y))
    if isinstance(shape, pymunk.Segment):
        a, b = _lib.cpSegmentShapeGetA(cp), _lib.cpSegmentShapeGetB(cp)
        return ("segment", _lib.cpSegmentShapeGetRadius(cp), (a.x, a.y), (b.x, b.y))
    return None


@functools.lru_cache(maxsize=128)
def shape_points(
    geometry: tuple[Any, ...], cog: tuple[float, float], margin: float
) -> _ShapePoints:
    """Sweep points, core radius and reach (from ``cog``) of one shape's geometry.

    Cached: a wave of identical boxes shares one answer.
    """
    kind, skin = geometry[0], geometry[1]
    points: list[tuple[float, float, float, bool]] = []
    if kind == "circle":
        r, ox, oy = skin, geometry[2], geometry[3]
        points.append((ox, oy, max(r - margin, 0.5 * r), False))
        points.append((ox, oy, 0.5 * r, True))
        return tuple(points), r, math.dist((ox, oy), cog) + r
    if kind == "poly":
        verts: tuple[tuple[float, float], ...] = geometry[2]
        cx, cy = geometry[3]
        inradius = min(
            abs((q[0] - p[0]) * (cy - p[1]) - (q[1] - p[1]) * (cx - p[0])) / math.dist(p, q)
            for p, q in zip(verts, verts[1:] + verts[:1], strict=True)
            if p != q
        )
        points.append((cx, cy, max(inradius + skin - margin, 0.5 * inradius), False))
        points.append((cx, cy, 0.5 * inradius, True))
        reach = 0.0
        for vx, vy in verts:
            d = math.hypot(cx - vx, cy - vy)
            k = min(margin, 0.5 * d) / d if d > 0 else 0.0
            points.append((vx + (cx - vx) * k, vy + (cy - vy) * k, 0.0, False))
            reach = max(reach, math.dist((vx, vy), cog) + skin)
        return tuple(points), inradius + skin, reach
    (ax, ay), (bx, by) = geometry[2], geometry[3]
    points.extend(
        (x, y, 0.0, False) for x, y in ((ax, ay), ((ax + bx) / 2, (ay + by) / 2), (bx, by))
    )
    return tuple(points), max(skin, margin), max(math.dist((ax, ay), cog), math.dist((bx, by), cog))


def parts_of(
    body: pymunk.Body, shapes: tuple[pymunk.Shape, ...], margin: float
) -> tuple[list[Part], float, float]:
    """Sweep points per shape, core radius (thinnest part) and reach (from the centre of gravity).

    Circles sweep their centre with the radius shrunk by ``margin``; polygons
    sweep an inscribed circle plus their vertices pulled ``margin`` inwards;
    segments their ends and middle. Shrinking keeps a body that already rests
    on a surface (overlap about one slop) from "hitting" it, or the next
    segment of a chain, while it slides. Circles and polygons also get a guard:
    a circle of half their core radius at their centre.
    """
    g = _lib.cpBodyGetCenterOfGravity(body_handle(body))
    cog = (g.x, g.y)
    parts: list[Part] = []
    core = math.inf
    reach = 0.0
    for shape in shapes:
        geometry = geometry_of(shape)
        if geometry is None:
            continue
        points, shape_core, shape_reach = shape_points(geometry, cog, margin)
        core = min(core, shape_core)
        reach = max(reach, shape_reach)
        parts.append(Part(shape, points))
    return parts, (core if math.isfinite(core) else margin), reach


def extent_of(body: pymunk.Body, shapes: tuple[pymunk.Shape, ...], reach: float) -> float:
    """Radius about the body's origin that holds all its shapes' bounding boxes (skin included).

    With the positions read in bulk, ``position ± extent`` bounds the body in
    any orientation, so fast bodies are screened against the obstacle index
    in one vectorised pass. ``reach`` (from the centre of gravity, see
    :func:`parts_of`) leaves out only a segment's radius.
    """
    pad = 0.0
    for shape in shapes:
        if isinstance(shape, pymunk.Segment):
            pad = max(pad, shape.radius)
        elif not isinstance(shape, (pymunk.Circle, pymunk.Poly)):
            return math.inf
    gx, gy = body.center_of_gravity
    return math.hypot(gx, gy) + reach + pad
