"""Contact manifolds: how two overlapping shapes touch, in Box2D's two forms.

A manifold is what the contact solver needs: up to two contact points, the
normal, and how deep each point is. Box2D stores it in a *local* form that
stays valid while the bodies move a little (so the solver can recompute
separations each iteration) and derives the *world* form from it:

``type`` says which local form:

* ``"circles"``: ``local_point`` is the centre of circle A (A's frame), the
  point's ``local_point`` the centre of circle B (B's frame); the normal is
  the line between them;
* ``"face_a"``: the reference face is on A: ``local_normal`` is its outward
  normal and ``local_point`` a point on it (A's frame); each point's
  ``local_point`` is an incident vertex of B (B's frame);
* ``"face_b"``: the same with the roles swapped (the face is B's).

The world form (``normal``, ``points``, ``separations``; Box2D's
``b2WorldManifold``) always has the normal pointing from A to B, each point
midway between the two rounded surfaces, and each separation negative when the
shapes overlap (the polygon skin counts as surface, as in Box2D).

Each point carries a :class:`ContactId` naming the features that made it
(a vertex or face of A, a vertex or face of B), which is how Box2D matches
points from one step to the next to warm-start the solver.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from kge.collision.pose import Pose

Vec2 = tuple[float, float]
ManifoldType = Literal["circles", "face_a", "face_b"]

VERTEX = 0
FACE = 1


@dataclass(slots=True, frozen=True)
class ContactId:
    """The features of A and B a point comes from (type 0 = vertex, 1 = face)."""

    index_a: int = 0
    index_b: int = 0
    type_a: int = VERTEX
    type_b: int = VERTEX

    @property
    def key(self) -> int:
        """The four bytes packed as Box2D's ``b2ContactID.key``."""
        return self.index_a | self.index_b << 8 | self.type_a << 16 | self.type_b << 24

    def flipped(self) -> ContactId:
        return ContactId(self.index_b, self.index_a, self.type_b, self.type_a)


@dataclass(slots=True, frozen=True)
class ManifoldPoint:
    """One contact point in local form (meaning set by the manifold's ``type``)."""

    local_point: Vec2
    id: ContactId


@dataclass(slots=True, frozen=True)
class Manifold:
    """Local form (``type``, ``local_normal``, ``local_point``, ``local_points``) and world form.

    ``normal``, ``points`` and ``separations`` are the world form for the poses
    the manifold was computed at. An empty manifold (no contact) has no points
    and is falsy.
    """

    type: ManifoldType
    local_normal: Vec2
    local_point: Vec2
    local_points: tuple[ManifoldPoint, ...]
    normal: Vec2
    points: tuple[Vec2, ...]
    separations: tuple[float, ...]

    def __bool__(self) -> bool:
        return bool(self.local_points)

    @property
    def point_count(self) -> int:
        return len(self.local_points)


@dataclass(slots=True, frozen=True)
class LocalManifold:
    """The local form alone, as the b2Collide* functions produce it."""

    type: ManifoldType
    local_normal: Vec2
    local_point: Vec2
    points: tuple[ManifoldPoint, ...]

    def flipped(self) -> LocalManifold:
        """The same contact seen with A and B exchanged."""
        if self.type == "circles":
            (p,) = self.points
            return LocalManifold("circles", self.local_normal, p.local_point,
                                 (ManifoldPoint(self.local_point, p.id.flipped()),))
        kind: ManifoldType = "face_b" if self.type == "face_a" else "face_a"
        return LocalManifold(kind, self.local_normal, self.local_point,
                             tuple(ManifoldPoint(p.local_point, p.id.flipped())
                                   for p in self.points))


EMPTY = LocalManifold("circles", (0.0, 0.0), (0.0, 0.0), ())


def world_form(m: LocalManifold, xa: Pose, ra: float, xb: Pose, rb: float) -> Manifold:
    """Box2D's b2WorldManifold::Initialize: the normal A -> B, midpoints, separations."""
    if not m.points:
        return Manifold(m.type, m.local_normal, m.local_point, (), (0.0, 0.0), (), ())
    pts: list[Vec2] = []
    seps: list[float] = []
    if m.type == "circles":
        pa, pb = xa.apply(m.local_point), xb.apply(m.points[0].local_point)
        n = (1.0, 0.0)
        dx, dy = pb[0] - pa[0], pb[1] - pa[1]
        d = math.hypot(dx, dy)
        if d * d > 1e-30:
            n = (dx / d, dy / d)
        ca = (pa[0] + ra * n[0], pa[1] + ra * n[1])
        cb = (pb[0] - rb * n[0], pb[1] - rb * n[1])
        pts.append((0.5 * (ca[0] + cb[0]), 0.5 * (ca[1] + cb[1])))
        seps.append((cb[0] - ca[0]) * n[0] + (cb[1] - ca[1]) * n[1])
        normal = n
    else:
        ref, inc, r_ref, r_inc = (xa, xb, ra, rb) if m.type == "face_a" else (xb, xa, rb, ra)
        n = ref.rotate(m.local_normal)
        plane = ref.apply(m.local_point)
        for p in m.points:
            clip = inc.apply(p.local_point)
            depth = r_ref - ((clip[0] - plane[0]) * n[0] + (clip[1] - plane[1]) * n[1])
            c_ref = (clip[0] + depth * n[0], clip[1] + depth * n[1])
            c_inc = (clip[0] - r_inc * n[0], clip[1] - r_inc * n[1])
            pts.append((0.5 * (c_ref[0] + c_inc[0]), 0.5 * (c_ref[1] + c_inc[1])))
            seps.append((c_inc[0] - c_ref[0]) * n[0] + (c_inc[1] - c_ref[1]) * n[1])
        normal = n if m.type == "face_a" else (-n[0], -n[1])
    return Manifold(m.type, m.local_normal, m.local_point, m.points,
                    (normal[0] + 0.0, normal[1] + 0.0), tuple(pts), tuple(seps))


PointState = Literal["add", "persist", "remove"]


def point_states(
    old: Manifold | LocalManifold, new: Manifold | LocalManifold
) -> tuple[tuple[PointState, ...], tuple[PointState, ...]]:
    """How contact points changed between two manifolds of a pair (b2GetPointStates).

    Points are matched by :class:`ContactId` (the features they come from).
    Each of ``old``'s points is ``"persist"`` or ``"remove"``, each of ``new``'s
    ``"add"`` or ``"persist"``; the tuples have one state per point (Box2D pads
    its two-slot arrays with ``b2_nullState``).
    """
    old_pts = old.local_points if isinstance(old, Manifold) else old.points
    new_pts = new.local_points if isinstance(new, Manifold) else new.points
    old_ids = {p.id for p in old_pts}
    new_ids = {p.id for p in new_pts}
    before: tuple[PointState, ...] = tuple(
        "persist" if p.id in new_ids else "remove" for p in old_pts)
    after: tuple[PointState, ...] = tuple(
        "persist" if p.id in old_ids else "add" for p in new_pts)
    return before, after


@dataclass(slots=True, frozen=True)
class ClipVertex:
    """A point of an incident edge being clipped, and the features it comes from."""

    v: Vec2
    id: ContactId


def clip_segment(vin: tuple[ClipVertex, ClipVertex], normal: Vec2, offset: float,
                 vertex_a: int) -> list[ClipVertex]:
    """Sutherland-Hodgman on one line: keep the part of a segment with normal.p <= offset.

    A point made by the cut belongs to vertex ``vertex_a`` of the reference
    shape and to the incident face (Box2D's b2ClipSegmentToLine).
    """
    out: list[ClipVertex] = []
    d0 = normal[0] * vin[0].v[0] + normal[1] * vin[0].v[1] - offset
    d1 = normal[0] * vin[1].v[0] + normal[1] * vin[1].v[1] - offset
    if d0 <= 0.0:
        out.append(vin[0])
    if d1 <= 0.0:
        out.append(vin[1])
    if d0 * d1 < 0.0:
        t = d0 / (d0 - d1)
        (x0, y0), (x1, y1) = vin[0].v, vin[1].v
        out.append(ClipVertex((x0 + t * (x1 - x0), y0 + t * (y1 - y0)),
                              ContactId(vertex_a, vin[0].id.index_b, VERTEX, FACE)))
    return out
