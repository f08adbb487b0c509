"""Manifolds between circles and polygons (b2CollideCircles, PolygonAndCircle, Polygons).

* **circle vs circle**: touching when the centres are within the sum of radii;
  one point, type ``circles``;
* **polygon vs circle**: the polygon face of greatest separation from the
  circle's centre decides; if the centre is inside, that face is the contact
  face; otherwise the centre's Voronoi region (beyond a vertex or beside the
  face) gives the normal. One point;
* **polygon vs polygon**: the separating-axis test on every face normal of
  both polygons (the polygon skins count, so they touch within 0.02 m). The
  face with the largest separation is the *reference face* (A's unless B's is
  clearly better, by 2 % + 1 mm as in Box2D 2.3.0, so the choice does not
  flicker); the
  face of the other polygon most anti-parallel to it is the *incident edge*,
  which is clipped to the reference face's side planes. Up to two points.

All work in the frame of the reference shape and return a
:class:`~kge.collision.manifold.LocalManifold`.
"""

from __future__ import annotations

import math

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
_EPS = 2.220446049250313e-16


def collide_circles(a: Convex, xa: Pose, b: Convex, xb: Pose) -> LocalManifold:
    pa, pb = xa.apply(a.vertices[0]), xb.apply(b.vertices[0])
    r = a.radius + b.radius
    if (pb[0] - pa[0]) ** 2 + (pb[1] - pa[1]) ** 2 > r * r:
        return EMPTY
    return LocalManifold("circles", (0.0, 0.0), a.vertices[0],
                         (ManifoldPoint(b.vertices[0], ContactId()),))


def collide_polygon_circle(a: Convex, xa: Pose, b: Convex, xb: Pose) -> LocalManifold:
    c = xa.inverse(xb.apply(b.vertices[0]))
    radius = a.radius + b.radius
    verts, normals = a.vertices, a.normals
    index, separation = 0, -math.inf
    for i, ((vx, vy), (nx, ny)) in enumerate(zip(verts, normals, strict=True)):
        s = nx * (c[0] - vx) + ny * (c[1] - vy)
        if s > radius:
            return EMPTY  # early out: separated by this face
        if s > separation:
            index, separation = i, s
    v1, v2 = verts[index], verts[(index + 1) % len(verts)]
    point = (ManifoldPoint(b.vertices[0], ContactId()),)
    if separation < _EPS:  # centre inside the polygon
        mid = (0.5 * (v1[0] + v2[0]), 0.5 * (v1[1] + v2[1]))
        return LocalManifold("face_a", normals[index], mid, point)
    u1 = (c[0] - v1[0]) * (v2[0] - v1[0]) + (c[1] - v1[1]) * (v2[1] - v1[1])
    u2 = (c[0] - v2[0]) * (v1[0] - v2[0]) + (c[1] - v2[1]) * (v1[1] - v2[1])
    if u1 <= 0.0 or u2 <= 0.0:  # beyond a vertex: the normal points from it to the centre
        v = v1 if u1 <= 0.0 else v2
        dx, dy = c[0] - v[0], c[1] - v[1]
        d2 = dx * dx + dy * dy
        if d2 > radius * radius:
            return EMPTY
        d = math.sqrt(d2)
        n = (dx / d, dy / d) if d >= _EPS else (0.0, 0.0)
        return LocalManifold("face_a", n, v, point)
    mid = (0.5 * (v1[0] + v2[0]), 0.5 * (v1[1] + v2[1]))
    nx, ny = normals[index]
    if (c[0] - mid[0]) * nx + (c[1] - mid[1]) * ny > radius:
        return EMPTY
    return LocalManifold("face_a", normals[index], mid, point)


def max_separation(p1: Convex, x1: Pose, p2: Convex, x2: Pose) -> tuple[int, float]:
    """The face of p1 that best separates p2, and by how much (cores only).

    Box2D 2.3's search: start at the face whose normal points most towards
    p2's centroid, then climb to a neighbouring face while the separation grows.
    A face's separation is that of p2's deepest vertex against it; p2 is moved
    into p1's frame once for all faces.
    """
    rel = Pose.of(*x1.inverse(x2.position), x2.angle - x1.angle)
    others = [rel.apply(v) for v in p2.vertices]
    verts, normals = p1.vertices, p1.normals
    count = len(verts)

    def separation(i: int) -> float:
        (vx, vy), (nx, ny) = verts[i], normals[i]
        return min(nx * (wx - vx) + ny * (wy - vy) for wx, wy in others)

    cx, cy = rel.apply(p2.centroid)
    dx, dy = cx - p1.centroid[0], cy - p1.centroid[1]
    edge, best_dot = 0, -math.inf
    for i, (nx, ny) in enumerate(normals):
        d = nx * dx + ny * dy
        if d > best_dot:
            edge, best_dot = i, d
    s = separation(edge)
    prev_edge, next_edge = (edge - 1) % count, (edge + 1) % count
    s_prev, s_next = separation(prev_edge), separation(next_edge)
    if s_prev > s and s_prev > s_next:
        step, best, best_sep = -1, prev_edge, s_prev
    elif s_next > s:
        step, best, best_sep = 1, next_edge, s_next
    else:
        return edge, s
    while True:
        edge = (best + step) % count
        s = separation(edge)
        if s <= best_sep:
            return best, best_sep
        best, best_sep = edge, s


def _incident_edge(p1: Convex, x1: Pose, edge1: int, p2: Convex, x2: Pose
                   ) -> tuple[ClipVertex, ClipVertex]:
    """The face of p2 most anti-parallel to p1's reference face, in world coordinates."""
    n1 = x2.unrotate(x1.rotate(p1.normals[edge1]))
    index, min_dot = 0, math.inf
    for i, (nx, ny) in enumerate(p2.normals):
        d = n1[0] * nx + n1[1] * ny
        if d < min_dot:
            index, min_dot = i, d
    i2 = (index + 1) % len(p2.vertices)
    return (
        ClipVertex(x2.apply(p2.vertices[index]), ContactId(edge1, index, FACE, VERTEX)),
        ClipVertex(x2.apply(p2.vertices[i2]), ContactId(edge1, i2, FACE, VERTEX)),
    )


def collide_polygons(a: Convex, xa: Pose, b: Convex, xb: Pose) -> LocalManifold:
    total = a.radius + b.radius
    edge_a, sep_a = max_separation(a, xa, b, xb)
    if sep_a > total:
        return EMPTY
    edge_b, sep_b = max_separation(b, xb, a, xa)
    if sep_b > total:
        return EMPTY
    if sep_b > 0.98 * sep_a + 0.001:
        p1, x1, p2, x2, edge1, flip = b, xb, a, xa, edge_b, True
    else:
        p1, x1, p2, x2, edge1, flip = a, xa, b, xb, edge_a, False
    incident = _incident_edge(p1, x1, edge1, p2, x2)
    n1 = len(p1.vertices)
    iv1, iv2 = edge1, (edge1 + 1) % n1
    v11, v12 = p1.vertices[iv1], p1.vertices[iv2]
    tx, ty = v12[0] - v11[0], v12[1] - v11[1]
    length = math.hypot(tx, ty)
    local_tangent = (tx / length, ty / length)
    local_normal = (local_tangent[1], -local_tangent[0])
    plane_point = (0.5 * (v11[0] + v12[0]), 0.5 * (v11[1] + v12[1]))
    tangent = x1.rotate(local_tangent)
    normal = (tangent[1], -tangent[0])
    w11, w12 = x1.apply(v11), x1.apply(v12)
    front = normal[0] * w11[0] + normal[1] * w11[1]
    side1 = -(tangent[0] * w11[0] + tangent[1] * w11[1]) + total
    side2 = tangent[0] * w12[0] + tangent[1] * w12[1] + total
    clip1 = clip_segment(incident, (-tangent[0], -tangent[1]), side1, iv1)
    if len(clip1) < 2:
        return EMPTY
    clip2 = clip_segment((clip1[0], clip1[1]), tangent, side2, iv2)
    if len(clip2) < 2:
        return EMPTY
    points = []
    for cv in clip2[:2]:
        if normal[0] * cv.v[0] + normal[1] * cv.v[1] - front <= total:
            points.append(ManifoldPoint(x2.inverse(cv.v), cv.id.flipped() if flip else cv.id))
    if not points:
        return EMPTY
    return LocalManifold("face_b" if flip else "face_a", local_normal, plane_point,
                         tuple(points))
