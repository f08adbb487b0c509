"""New contacts start at the linear slop: Box2D's time of impact for every landing.

Chipmunk moves a body by its velocity and only then looks for contacts, so a
body arriving at a surface is already ``v * h`` inside it when its contact is
made (``h`` the substep), and the contact's bias pushes it back out over the
next substeps: a box dropped onto the ground sank 8-50 mm before it rose to
rest, a ball thrown at 50 m/s stopped 15 cm deep. A pre-solve hook that compares
positions (the manual's one-sided platform) saw the sunk body and let it fall
through. Box2D instead computes the time of impact of every dynamic body against
static and kinematic ones (and of bullets against dynamic ones) and moves it
back there, so a body touches a surface before it sinks into it.

:func:`settle` does that in the ``begin`` callback of a new contact, which
Chipmunk runs after the move and before any pre-solve hook and the solver: the
body is moved back along the contact normal until its outline overlaps the other
by the linear slop (where it will rest), but never further back than this
substep's approach carried it in (so bodies that start overlapping, spawned or
teleported into each other, are left to the solver as in Box2D). The solver
then stops the approach with no bias to push back, restitution sees the full
approach speed, and the pre-solve hooks see the settled pose. Pairs follow
Box2D's rule for time of impact: a dynamic body against a static or kinematic
one, or any pair with a bullet; two ordinary dynamic bodies are left to the
solver. Continuous collision (:mod:`kge.physics.ccd`) stops fast bodies just
inside the surface; this moves them back to the slop.
"""

from __future__ import annotations

from typing import Any

from kge.physics.cp import ffi as _ffi
from kge.physics.cp import lib as _lib

_DYNAMIC = _lib.CP_BODY_TYPE_DYNAMIC
_PAIR = (_ffi.new("cpBody *[1]"), _ffi.new("cpBody *[1]"))

#: (Chipmunk body, dx, dy) moves made for one contact, for an undo
Moves = list[tuple[Any, float, float]]


def settle(arb: Any, slop: float, h: float) -> Moves:
    """Move the bodies of the new contact ``arb`` (a Chipmunk arbiter) back to the slop.

    The caller decides that the pair gets a time of impact (Box2D's rule, see the
    module docstring). Returns the moves made (empty when none was needed or allowed).
    """
    a_p, b_p = _PAIR
    _lib.cpArbiterGetBodies(arb, a_p, b_p)
    b0, b1 = a_p[0], b_p[0]
    # the bodies that may be moved back: dynamic and awake (a sleeper hit by a body
    # is woken by Chipmunk after this pass; it stays where it slept)
    dyn0 = _lib.cpBodyGetType(b0) == _DYNAMIC and not _lib.cpBodyIsSleeping(b0)
    dyn1 = _lib.cpBodyGetType(b1) == _DYNAMIC and not _lib.cpBodyIsSleeping(b1)
    if not (dyn0 or dyn1):
        return []
    cps = _lib.cpArbiterGetContactPointSet(arb)
    # the deepest point; distances follow the bodies' current positions
    k = 0
    if cps.count == 2 and cps.points[1].distance < cps.points[0].distance:
        k = 1
    p = cps.points[k]
    depth = -p.distance - slop
    if depth <= 0.0:
        return []
    n = cps.normal  # from body 0 to body 1
    px, py = 0.5 * (p.pointA.x + p.pointB.x), 0.5 * (p.pointA.y + p.pointB.y)
    va = _lib.cpBodyGetVelocityAtWorldPoint(b0, (px, py))
    vb = _lib.cpBodyGetVelocityAtWorldPoint(b1, (px, py))
    # each body's part of the approach along the normal: how far it came in
    in0 = (va.x * n.x + va.y * n.y) if dyn0 else 0.0
    in1 = -(vb.x * n.x + vb.y * n.y) if dyn1 else 0.0
    approach = (va.x - vb.x) * n.x + (va.y - vb.y) * n.y
    back = min(depth, approach * h)
    if not back > 0.0:
        return []  # it did not arrive by moving: overlapping from the start
    # rewind the movable bodies along the normal by what each contributed (a body
    # at rest, or moving away, stays where it is); a kinematic or sleeping body
    # cannot be rewound, so what it drove in is taken back from the other one
    w0, w1 = max(in0, 0.0), max(in1, 0.0)
    if w0 + w1 <= 0.0:
        w0, w1 = float(dyn0), float(dyn1)
    moves: Moves = []
    for cp, s in ((b0, -back * w0 / (w0 + w1)), (b1, back * w1 / (w0 + w1))):
        if s:
            dx, dy = n.x * s, n.y * s
            o = _lib.cpBodyGetPosition(cp)
            _lib.cpBodySetPosition(cp, (o.x + dx, o.y + dy))
            moves.append((cp, dx, dy))
    return moves


def undo(moves: Moves) -> None:
    """Put the bodies back where :func:`settle` found them (a hook disabled the contact)."""
    for cp, dx, dy in moves:
        o = _lib.cpBodyGetPosition(cp)
        _lib.cpBodySetPosition(cp, (o.x - dx, o.y - dy))
