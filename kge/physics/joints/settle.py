"""Box2D's position iterations: joints and the contacts of their bodies, together.

Box2D ends every step with up to ``positionIterations`` passes in which each
contact pushes its bodies apart (``b2ContactSolver::SolvePositionConstraints``)
and each joint pulls its bodies together, stopping early once every contact
overlaps by less than 3 x b2_linearSlop and every joint is within its slops. The
two take turns, so a joint built with its anchors apart (a walker built with
its legs 0.5 m from their hips) closes by folding the legs against the ground,
not by pushing them into it: the contacts hold while the joints pull.

kge's own physics makes one joint position pass and leaves contacts to pymunk's
velocity bias; ``kge.box2d`` asks for Box2D's loop
(``JointBridge.position_iterations``). The contacts taken in are those of the
bodies the iterated joints move, read from pymunk's arbiters after the step,
whose points are current for the poses the step ended with. Each contact point
is kept as one point on each body (in the body's frame) and a normal fixed to
the non-dynamic body, or to body A when both are dynamic; its separation is
measured again from the poses in every pass, as Box2D's position manifold does.
A correction smaller than ``CONTACT_TOLERANCE`` is left alone: moving a pymunk
body restarts its sleep timer, and a resting body must be allowed to sleep.

Box2D also stops a body the passes push into static ground where it first
touches it (its time of impact covers the whole motion of a step). That is not
done here: tried as a sweep of the passes' motion, it matched pybox2d's first
walker pose to a centimetre but left knees built apart open for good, and the
walker's heuristic then stalled on every seed (kge's continuous collision covers
the motion of the velocity step).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import pymunk

from kge.physics.cp import body_handle, lib
from kge.physics.joints.mechanics import DYNAMIC, cross, inv_mass, journal, push_apart
from kge.physics.joints.positions import LINEAR_SLOP, MAX_CORRECTION

#: Box2D's b2_baumgarte: the fraction of a contact's overlap removed per pass
BAUMGARTE = 0.2
#: the loop may stop once no contact overlaps by more than this (Box2D: 3 slops), m
SEPARATION_OK = -3.0 * LINEAR_SLOP
#: contact corrections below this are skipped (they would keep a body awake), m
CONTACT_TOLERANCE = 1e-4

_local_to_world = lib.cpBodyLocalToWorld
_world_to_local = lib.cpBodyWorldToLocal
_get_cog = lib.cpBodyGetCenterOfGravity
_get_angle = lib.cpBodyGetAngle
_get_type = lib.cpBodyGetType
_is_sleeping = lib.cpBodyIsSleeping


Pose = tuple[float, float, float]


class ContactPoint:
    """One contact point held between two bodies, as Box2D's position manifold."""

    __slots__ = ("a", "angle0", "b", "frame", "la", "lb", "nx", "ny")

    def __init__(self, a: pymunk.Body, b: pymunk.Body, pa: Any, pb: Any, normal: Any,
                 poses: dict[Any, Pose]) -> None:
        """``pa``/``pb``: the world points on each body, ``normal`` from a to b, all as
        the step found them; ``poses``: body poses then (origin x, y, angle), by
        Chipmunk body, for the bodies the position passes moved since."""
        self.a, self.b = a, b
        self.la, self.lb = _to_local(a, pa, poses), _to_local(b, pb, poses)
        # the normal turns with the body that carries it: a static one never does
        a_moves = _get_type(body_handle(a)) == DYNAMIC
        self.frame = b if a_moves and _get_type(body_handle(b)) != DYNAMIC else a
        self.nx, self.ny = float(normal.x), float(normal.y)
        pose = poses.get(body_handle(self.frame))
        self.angle0 = _get_angle(body_handle(self.frame)) if pose is None else pose[2]

    def solve(self) -> float:
        """Push the bodies apart along the normal (Box2D's rule); return the separation
        found before the push, m."""
        a, b = self.a, self.b
        ca, cb = body_handle(a), body_handle(b)
        pa, pb = _local_to_world(ca, self.la), _local_to_world(cb, self.lb)
        turn = _get_angle(body_handle(self.frame)) - self.angle0
        nx, ny = self.nx, self.ny
        if turn:
            c, s = math.cos(turn), math.sin(turn)
            nx, ny = c * nx - s * ny, s * nx + c * ny
        separation = (pb.x - pa.x) * nx + (pb.y - pa.y) * ny
        correction = max(-MAX_CORRECTION, min(0.0, BAUMGARTE * (separation + LINEAR_SLOP)))
        if correction > -CONTACT_TOLERANCE:
            return separation
        px, py = 0.5 * (pa.x + pb.x), 0.5 * (pa.y + pb.y)  # Box2D's point: between the two
        ima, iia = inv_mass(a)
        imb, iib = inv_mass(b)
        loa, lob = _get_cog(ca), _get_cog(cb)
        ga, gb = _local_to_world(ca, loa), _local_to_world(cb, lob)
        rax, ray, rbx, rby = px - ga.x, py - ga.y, px - gb.x, py - gb.y
        rna, rnb = cross(rax, ray, nx, ny), cross(rbx, rby, nx, ny)
        k = ima + imb + iia * rna * rna + iib * rnb * rnb
        if k <= 0.0:
            return separation
        impulse = -correction / k
        jx, jy = impulse * nx, impulse * ny
        push_apart((ca, loa, ga, ima, iia, rax, ray), (cb, lob, gb, imb, iib, rbx, rby), jx, jy)
        return separation


def _to_local(body: pymunk.Body, point: Any, poses: dict[Any, Pose]) -> tuple[float, float]:
    pose = poses.get(body_handle(body))
    if pose is None:
        q = _world_to_local(body_handle(body), (point.x, point.y))
        return q.x, q.y
    x, y, angle = pose
    c, s = math.cos(angle), math.sin(angle)
    dx, dy = point.x - x, point.y - y
    return c * dx + s * dy, -s * dx + c * dy


def contacts_of(bodies: Sequence[pymunk.Body],
                poses: dict[Any, Pose] | None = None) -> list[ContactPoint]:
    """The touching, solid contact points of ``bodies`` (each pair once); ``poses``:
    the poses the step left (see :class:`ContactPoint`), when bodies moved since."""
    known = poses or {}
    seen: set[tuple[int, int]] = set()
    points: list[ContactPoint] = []

    def collect(arbiter: pymunk.Arbiter) -> None:
        sa, sb = arbiter.shapes
        if sa.body is None or sb.body is None:
            return
        key = (id(sa), id(sb)) if id(sa) < id(sb) else (id(sb), id(sa))
        if key in seen or sa.sensor or sb.sensor or not arbiter.process_collision:
            return
        seen.add(key)
        ps = arbiter.contact_point_set
        for p in ps.points:
            points.append(
                ContactPoint(sa.body, sb.body, p.point_a, p.point_b, ps.normal, known))

    for body in bodies:
        body.each_arbiter(collect)
    return points


def position_loop(joints: Sequence[Any], iterations: int) -> None:
    """Box2D's position iterations over ``joints`` and their bodies' contacts.

    The joints go first: when they all report they were within the slops
    (``project()`` returning True or None), that one pass is all (the contacts'
    overlap is pymunk's to resolve, as everywhere in kge), which keeps a settled
    scene at one pass per joint. Otherwise up to ``iterations - 1`` further passes
    of contacts then joints follow, until all are within the slops.
    """
    if iterations <= 1:
        for h in joints:
            h.project()
        return
    journal(True)  # the poses the step left, of the bodies the first pass moves
    try:
        done = True
        for h in joints:
            if h.project() is False:
                done = False
    finally:
        poses = journal(False)
    if done:
        return
    bodies: dict[int, pymunk.Body] = {}
    for h in joints:
        for body in (h.a, h.b):
            cb = body_handle(body)
            if _get_type(cb) == DYNAMIC and not _is_sleeping(cb):
                bodies[id(body)] = body
    contacts = contacts_of(list(bodies.values()), poses)
    for _ in range(iterations - 1):
        lowest = 0.0
        for c in contacts:
            lowest = min(lowest, c.solve())
        done = lowest >= SEPARATION_OK
        for h in joints:
            if h.project() is False:
                done = False
        if done:
            break
