"""Pure geometry for drawables and debug outlines, in the entity's local frame.

Shapes are turned into flat vertex arrays once (when the component changes);
each frame only their pose moves (see :mod:`kge.render.bulk`). Filled shapes
become triangle lists (ear clipping, so concave polygons work); outlines
become one quad per edge, ``thickness`` wide, with square caps so corners
close; debug outlines are hairline segment lists (GL_LINES).

>>> tri = triangulate([(0, 0), (2, 0), (2, 2), (1, 1), (0, 2)])   # concave
>>> len(tri) // 3, round(float(triangles_area(tri)), 6)
(3, 3.0)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from kge.errors import ValidationError

Points = Sequence[tuple[float, float]]


def circle_segments(radius: float) -> int:
    """A segment count that looks round at typical zooms (24..96)."""
    return max(24, min(96, int(radius * 64 / 3)))


def circle_points(
    radius: float, segments: int, center: tuple[float, float] = (0.0, 0.0)
) -> np.ndarray:
    """``segments`` points on a circle, counter-clockwise from angle 0."""
    t = np.linspace(0.0, 2 * math.pi, segments, endpoint=False)
    return np.stack([center[0] + radius * np.cos(t), center[1] + radius * np.sin(t)], axis=1)


def rect_points(
    width: float, height: float, center: tuple[float, float] = (0.0, 0.0)
) -> np.ndarray:
    hw, hh = width / 2, height / 2
    cx, cy = center
    return np.array(
        [(cx - hw, cy - hh), (cx + hw, cy - hh), (cx + hw, cy + hh), (cx - hw, cy + hh)]
    )


def _signed_area(p: np.ndarray) -> float:
    x, y = p[:, 0], p[:, 1]
    return float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y)) / 2


def triangles_area(tris: np.ndarray) -> float:
    """Total area of a triangle list (for tests)."""
    t = np.asarray(tris, float).reshape(-1, 3, 2)
    a, b, c = t[:, 0], t[:, 1], t[:, 2]
    cross = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    return float(np.abs(cross).sum() / 2)


def _is_convex(p: np.ndarray) -> bool:
    d1 = np.roll(p, -1, axis=0) - p
    d2 = np.roll(d1, -1, axis=0)
    cross = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
    return bool(np.all(cross >= -1e-12) or np.all(cross <= 1e-12))


def triangulate(points: Any) -> np.ndarray:
    """Triangle list (n*3, 2) covering a simple polygon of any winding."""
    p = np.asarray(points, dtype=float).reshape(-1, 2)
    if len(p) < 3:
        raise ValidationError(f"a polygon needs at least 3 points, got {len(p)}")
    if _signed_area(p) < 0:
        p = p[::-1]
    if _is_convex(p):
        idx = [(0, i, i + 1) for i in range(1, len(p) - 1)]
        return p[np.array(idx).reshape(-1)]
    remaining = list(range(len(p)))
    out: list[int] = []
    guard = 0
    while len(remaining) > 3 and guard < 10_000:
        guard += 1
        n = len(remaining)
        for k in range(n):
            i0, i1, i2 = remaining[k - 1], remaining[k], remaining[(k + 1) % n]
            a, b, c = p[i0], p[i1], p[i2]
            if (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) <= 1e-12:
                continue  # reflex corner: not an ear
            if any(_inside(p[j], a, b, c) for j in remaining if j not in (i0, i1, i2)):
                continue
            out += [i0, i1, i2]
            remaining.pop(k)
            break
        else:  # self-intersecting input: fall back to a fan rather than loop forever
            break
    for k in range(1, len(remaining) - 1):
        out += [remaining[0], remaining[k], remaining[k + 1]]
    return p[np.array(out, dtype=int)]


def _inside(q: np.ndarray, a: np.ndarray, b: np.ndarray, c: np.ndarray) -> bool:
    def side(p1: np.ndarray, p2: np.ndarray) -> float:
        return float((p2[0] - p1[0]) * (q[1] - p1[1]) - (p2[1] - p1[1]) * (q[0] - p1[0]))

    return side(a, b) >= 0 and side(b, c) >= 0 and side(c, a) >= 0


def stroke(points: Any, thickness: float, closed: bool, caps: bool = True) -> np.ndarray:
    """Triangles for a polyline ``thickness`` wide: one quad per edge.

    ``caps`` extends each edge by half the thickness at both ends (square caps),
    which closes the corners of outlines; a lone line uses butt ends.
    """
    p = np.asarray(points, dtype=float).reshape(-1, 2)
    a = p if closed else p[:-1]
    b = np.roll(p, -1, axis=0) if closed else p[1:]
    d = b - a
    length = np.hypot(d[:, 0], d[:, 1])
    keep = length > 1e-12
    a, b, d, length = a[keep], b[keep], d[keep], length[keep]
    u = d / length[:, None] * (thickness / 2)
    n = np.stack([-u[:, 1], u[:, 0]], axis=1)
    a0, b0 = (a - u, b + u) if caps else (a, b)
    q = np.stack([a0 - n, b0 - n, b0 + n, a0 - n, b0 + n, a0 + n], axis=1)
    return q.reshape(-1, 2)


def segments(points: Any, closed: bool) -> np.ndarray:
    """Hairline segment list (GL_LINES pairs) along a polyline."""
    p = np.asarray(points, dtype=float).reshape(-1, 2)
    b = np.roll(p, -1, axis=0) if closed else p[1:]
    a = p if closed else p[:-1]
    return np.stack([a, b], axis=1).reshape(-1, 2)


def drawable_triangles(d: Any) -> np.ndarray:
    """Local-frame triangle list for a Rect/Circle/Triangle/Polygon/Line component."""
    from kge.components import drawables as dr

    off = d.offset
    if isinstance(d, dr.Line):
        pts = np.array([d.start, d.end], float) + off
        return stroke(pts, d.thickness, closed=False, caps=False)
    if isinstance(d, dr.Rect):
        pts = rect_points(d.width, d.height, off)
    elif isinstance(d, dr.Circle):
        pts = circle_points(d.radius, d.segments or circle_segments(d.radius), off)
    elif isinstance(d, dr.Triangle):
        pts = np.array([d.a, d.b, d.c], float) + off
    elif isinstance(d, dr.Polygon):
        pts = np.array(d.vertices, float) + off
    else:
        raise TypeError(f"not a drawable: {type(d).__name__}")
    return triangulate(pts) if d.filled else stroke(pts, d.thickness, closed=True)


def shape_outline(shape: Any) -> np.ndarray:
    """Hairline segments for a physics shape (Circle/Box/Polygon/Edge/Chain), body frame.

    Circles get a radius line from the centre along local +x, so rotation shows,
    as in Box2D's debug draw. Works on any object with the documented fields.
    """
    kind = type(shape).__name__
    if kind == "Circle":
        cx, cy = getattr(shape, "center", (0.0, 0.0))
        c = (float(cx), float(cy))
        ring = circle_points(shape.radius, circle_segments(shape.radius), c)
        spoke = np.array([c, (c[0] + shape.radius, c[1])], float)
        return np.concatenate([segments(ring, closed=True), spoke])
    return segments(*shape_polyline(shape))


def shape_polyline(shape: Any) -> tuple[np.ndarray, bool]:
    """(points, closed) of a non-circle physics shape, in the body frame."""
    kind = type(shape).__name__
    if kind == "Box":
        pts = rect_points(2 * shape.half_width, 2 * shape.half_height)
        ang = float(getattr(shape, "angle", 0.0))
        c, s = math.cos(ang), math.sin(ang)
        pts = pts @ np.array([[c, s], [-s, c]]) + np.asarray(
            getattr(shape, "center", (0, 0)), float
        )
        return pts, True
    if kind == "Polygon":
        return np.asarray(shape.vertices, float), True
    if kind == "Edge":
        return np.array([shape.v1, shape.v2], float), False
    if kind == "Chain":
        return np.asarray(shape.vertices, float), bool(getattr(shape, "loop", False))
    if kind == "Circle":
        cx, cy = getattr(shape, "center", (0.0, 0.0))
        return circle_points(shape.radius, circle_segments(shape.radius), (cx, cy)), True
    raise TypeError(f"unknown shape type {kind}")


def shape_fill(shape: Any) -> np.ndarray | None:
    """Triangles filling a physics shape in the body frame (None for edges and chains,
    which have no inside). Box2D v3's samples fill shapes translucently under their
    outlines; this is that fill."""
    kind = type(shape).__name__
    if kind == "Circle":
        cx, cy = getattr(shape, "center", (0.0, 0.0))
        ring = circle_points(shape.radius, circle_segments(shape.radius), (float(cx), float(cy)))
        return triangulate(ring)
    if kind in ("Box", "Polygon"):
        pts, _ = shape_polyline(shape)
        return triangulate(pts)
    return None
