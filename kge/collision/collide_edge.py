"""Manifolds between an edge (or chain child) and a circle or polygon.

Edges are one-dimensional, so the question is not only "do they touch" but
"from which side, and which way should the normal point". Box2D answers with
the edge's neighbours in its chain (``vertex0`` and ``vertex3``, the ghost
vertices): a shape sliding along a chain must not catch on the joins between
segments.

* **edge vs circle** (b2CollideEdgeAndCircle): the circle's centre is in the
  Voronoi region of vertex 1, of vertex 2 or of the segment. At a vertex
  shared with a neighbour whose own segment region holds the centre, this
  edge reports nothing (the neighbour will), so the ball rolls across a join
  with one contact, never two;
* **edge vs polygon** (b2EPCollider): the edge's *smooth normal range* is
  computed from the neighbours (a convex join widens it, a concave join
  narrows it), with a front/back side chosen by where the polygon's centroid
  is. The edge's own axis and the polygon's face normals (only those inside
  the admissible range, with 2 degrees of angular slop) are the candidate
  separating axes; the edge axis wins unless a polygon axis is better by a
  2 % + 1 mm margin. Then the incident feature is clipped to the reference
  face, as for two polygons. Up to two points.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from kge.collision.geometry import Convex
from kge.collision.manifold import (
    EMPTY,
    FACE,
    VERTEX,
    ClipVertex,
    ContactId,
    LocalManifold,
    ManifoldPoint,
    clip_segment,
)
from kge.collision.pose import Pose

Vec2 = tuple[float, float]
#: Box2D's b2_angularSlop (2 degrees)
ANGULAR_SLOP = 2.0 / 180.0 * math.pi


def _dot(a: Vec2, b: Vec2) -> float:
    return a[0] * b[0] + a[1] * b[1]


def _sub(a: Vec2, b: Vec2) -> Vec2:
    return (a[0] - b[0], a[1] - b[1])


def _neg(a: Vec2) -> Vec2:
    return (-a[0], -a[1])


def _unit(v: Vec2) -> Vec2:
    n = math.hypot(v[0], v[1])
    return (v[0] / n, v[1] / n) if n > 0.0 else (0.0, 0.0)


def collide_edge_circle(a: Convex, xa: Pose, b: Convex, xb: Pose) -> LocalManifold:
    q = xa.inverse(xb.apply(b.vertices[0]))
    va, vb = a.vertices
    e = _sub(vb, va)
    u, v = _dot(e, _sub(vb, q)), _dot(e, _sub(q, va))
    radius = a.radius + b.radius
    point_b = b.vertices[0]
    if v <= 0.0:  # region of vertex 1
        if _dot(_sub(q, va), _sub(q, va)) > radius * radius:
            return EMPTY
        if a.vertex0 is not None and _dot(_sub(va, a.vertex0), _sub(va, q)) > 0.0:
            return EMPTY  # in the previous segment's region: it reports the contact
        return LocalManifold("circles", (0.0, 0.0), va,
                             (ManifoldPoint(point_b, ContactId(0, 0, VERTEX, VERTEX)),))
    if u <= 0.0:  # region of vertex 2
        if _dot(_sub(q, vb), _sub(q, vb)) > radius * radius:
            return EMPTY
        if a.vertex3 is not None and _dot(_sub(a.vertex3, vb), _sub(q, vb)) > 0.0:
            return EMPTY  # in the next segment's region
        return LocalManifold("circles", (0.0, 0.0), vb,
                             (ManifoldPoint(point_b, ContactId(1, 0, VERTEX, VERTEX)),))
    den = _dot(e, e)
    p = ((u * va[0] + v * vb[0]) / den, (u * va[1] + v * vb[1]) / den)
    d = _sub(q, p)
    if _dot(d, d) > radius * radius:
        return EMPTY
    n = (-e[1], e[0])
    if _dot(n, _sub(q, va)) < 0.0:
        n = _neg(n)
    return LocalManifold("face_a", _unit(n), va,
                         (ManifoldPoint(point_b, ContactId(0, 0, FACE, VERTEX)),))


@dataclass(slots=True)
class _Axis:
    kind: str  # "unknown", "edge_a", "edge_b"
    index: int
    separation: float


@dataclass(slots=True)
class _Frame:
    """The edge's smooth normal, its admissible range and its side (b2EPCollider state)."""

    normal: Vec2
    lower: Vec2
    upper: Vec2
    front: bool
    normal1: Vec2


def _edge_frame(edge: Convex, centroid: Vec2) -> _Frame:
    v0, (v1, v2), v3 = edge.vertex0, edge.vertices, edge.vertex3
    e1 = _unit(_sub(v2, v1))
    n1 = (e1[1], -e1[0])
    off1 = _dot(n1, _sub(centroid, v1))
    n0 = n2 = (0.0, 0.0)
    off0 = off2 = 0.0
    convex1 = convex2 = False
    if v0 is not None:
        e0 = _unit(_sub(v1, v0))
        n0 = (e0[1], -e0[0])
        convex1 = e0[0] * e1[1] - e0[1] * e1[0] >= 0.0
        off0 = _dot(n0, _sub(centroid, v0))
    if v3 is not None:
        e2 = _unit(_sub(v3, v2))
        n2 = (e2[1], -e2[0])
        convex2 = e1[0] * e2[1] - e1[1] * e2[0] > 0.0
        off2 = _dot(n2, _sub(centroid, v2))
    m1 = _neg(n1)
    if v0 is not None and v3 is not None:
        if convex1 and convex2:
            front = off0 >= 0.0 or off1 >= 0.0 or off2 >= 0.0
            lo, hi = (n0, n2) if front else (m1, m1)
        elif convex1:
            front = off0 >= 0.0 or (off1 >= 0.0 and off2 >= 0.0)
            lo, hi = (n0, n1) if front else (_neg(n2), m1)
        elif convex2:
            front = off2 >= 0.0 or (off0 >= 0.0 and off1 >= 0.0)
            lo, hi = (n1, n2) if front else (m1, _neg(n0))
        else:
            front = off0 >= 0.0 and off1 >= 0.0 and off2 >= 0.0
            lo, hi = (n1, n1) if front else (_neg(n2), _neg(n0))
    elif v0 is not None:
        if convex1:
            front = off0 >= 0.0 or off1 >= 0.0
            lo, hi = (n0, m1) if front else (n1, m1)
        else:
            front = off0 >= 0.0 and off1 >= 0.0
            lo, hi = (n1, m1) if front else (n1, _neg(n0))
    elif v3 is not None:
        if convex2:
            front = off1 >= 0.0 or off2 >= 0.0
            lo, hi = (m1, n2) if front else (m1, n1)
        else:
            front = off1 >= 0.0 and off2 >= 0.0
            lo, hi = (m1, n1) if front else (_neg(n2), n1)
    else:
        front = off1 >= 0.0
        lo, hi = (m1, m1) if front else (n1, n1)
    return _Frame(n1 if front else m1, lo, hi, front, n1)


def _edge_separation(f: _Frame, v1: Vec2, verts: list[Vec2]) -> _Axis:
    return _Axis("edge_a", 0 if f.front else 1, min(_dot(f.normal, _sub(p, v1)) for p in verts))


def _polygon_separation(f: _Frame, v1: Vec2, v2: Vec2, verts: list[Vec2],
                        normals: list[Vec2], radius: float) -> _Axis:
    axis = _Axis("unknown", -1, -math.inf)
    perp = (-f.normal[1], f.normal[0])
    for i, (p, pn) in enumerate(zip(verts, normals, strict=True)):
        n = _neg(pn)
        s = min(_dot(n, _sub(p, v1)), _dot(n, _sub(p, v2)))
        if s > radius:  # a separating axis: no collision
            return _Axis("edge_b", i, s)
        limit = f.upper if _dot(n, perp) >= 0.0 else f.lower
        if _dot(_sub(n, limit), f.normal) < -ANGULAR_SLOP:
            continue  # outside the smooth normal range: would catch on a join
        if s > axis.separation:
            axis = _Axis("edge_b", i, s)
    return axis


def collide_edge_polygon(a: Convex, xa: Pose, b: Convex, xb: Pose) -> LocalManifold:
    # the polygon in the edge's frame
    rel = Pose.of(*xa.inverse(xb.position), xb.angle - xa.angle)
    verts = [rel.apply(v) for v in b.vertices]
    normals = [rel.rotate(n) for n in b.normals]
    f = _edge_frame(a, rel.apply(b.centroid))
    v1, v2 = a.vertices
    radius = a.radius + b.radius
    edge_axis = _edge_separation(f, v1, verts)
    if edge_axis.separation > radius:
        return EMPTY
    poly_axis = _polygon_separation(f, v1, v2, verts, normals, radius)
    if poly_axis.kind != "unknown" and poly_axis.separation > radius:
        return EMPTY
    if poly_axis.kind == "unknown" or not (
        poly_axis.separation > 0.98 * edge_axis.separation + 0.001
    ):
        primary = edge_axis
    else:
        primary = poly_axis
    count = len(verts)
    if primary.kind == "edge_a":
        best = min(range(count), key=lambda i: (_dot(f.normal, normals[i]), i))
        i2 = (best + 1) % count
        incident = (ClipVertex(verts[best], ContactId(0, best, FACE, VERTEX)),
                    ClipVertex(verts[i2], ContactId(0, i2, FACE, VERTEX)))
        r1, r2 = (0, 1) if f.front else (1, 0)
        rv1, rv2 = (v1, v2) if f.front else (v2, v1)
        rn = f.normal1 if f.front else _neg(f.normal1)
    else:
        incident = (ClipVertex(v1, ContactId(0, primary.index, VERTEX, FACE)),
                    ClipVertex(v2, ContactId(0, primary.index, VERTEX, FACE)))
        r1, r2 = primary.index, (primary.index + 1) % count
        rv1, rv2, rn = verts[r1], verts[r2], normals[r1]
    side1 = (rn[1], -rn[0])
    side2 = _neg(side1)
    clip1 = clip_segment(incident, side1, _dot(side1, rv1), r1)
    if len(clip1) < 2:
        return EMPTY
    clip2 = clip_segment((clip1[0], clip1[1]), side2, _dot(side2, rv2), r2)
    if len(clip2) < 2:
        return EMPTY
    points = []
    for cv in clip2[:2]:
        if _dot(rn, _sub(cv.v, rv1)) <= radius:
            if primary.kind == "edge_a":
                points.append(ManifoldPoint(rel.inverse(cv.v), cv.id))
            else:
                points.append(ManifoldPoint(cv.v, cv.id.flipped()))
    if not points:
        return EMPTY
    if primary.kind == "edge_a":
        return LocalManifold("face_a", rn, rv1, tuple(points))
    return LocalManifold("face_b", b.normals[r1], b.vertices[r1], tuple(points))
