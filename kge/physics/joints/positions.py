"""Box2D's position pass for rods, pivots, sliders and gears, run after the step.

pymunk corrects joint drift only through velocity bias, which lets a swinging rod
stretch by centimetres and, if made stronger, pumps energy into long chains.
Worse, two biased constraints that disagree (a gear and a slider's rotation lock
asking for two different angles of one body) push against each other with
velocities the bodies keep, and pymunk's warm start carries the growing impulses
from step to step until a body is thrown kilometres. Box2D instead moves the
bodies back onto their constraints after the velocity solve without touching
velocities (its position iterations), and its velocity constraints all agree on
"no relative motion". These helpers do the same, limited like Box2D to
``MAX_CORRECTION`` / ``MAX_ANGULAR_CORRECTION`` per step.
"""

from __future__ import annotations

import math

import pymunk

from kge.physics.cp import body_handle, lib
from kge.physics.joints.mechanics import (
    cog_world,
    cross,
    inv_mass,
    point_mass,
    push_apart,
    shift,
)
from kge.physics.joints.rows import Row, merge

Vec2 = tuple[float, float]

_local_to_world = lib.cpBodyLocalToWorld
_get_cog = lib.cpBodyGetCenterOfGravity
_get_angle = lib.cpBodyGetAngle

#: Box2D's b2_linearSlop: the joint gap (and contact overlap) its position
#: iterations settle for, m
LINEAR_SLOP = 0.005
#: Box2D's b2_maxLinearCorrection: the most a position pass moves per step, m
MAX_CORRECTION = 0.2
#: Box2D's b2_angularSlop (2°): the limit overshoot its position iterations settle for
ANGULAR_SLOP = math.radians(2.0)
#: iterated hinges: pivot gaps below this (a tenth of b2_linearSlop) are not projected,
#: m: moving a body wakes it (pymunk), and a motor holding a load leaves such a gap
ITERATED_PIVOT_TOLERANCE = 0.0005
#: Box2D's b2_maxAngularCorrection (8°): the most an angle is corrected per step, rad
MAX_ANGULAR_CORRECTION = math.radians(8.0)
#: an error (m or rad) below which the scalar passes (sliders, gears) leave a joint
#: alone: a settled slider drifts by about 1e-9 m per step, and building the rows
#: to remove that would double its cost per step (measured: 100 wheels, 3.2 -> 6.4 ms)
SETTLED = 1e-6


def project_point(a: pymunk.Body, b: pymunk.Body, la: Vec2, lb: Vec2) -> float:
    """Box2D's position pass for a pivot: bring the two anchors together.

    Returns the gap found, m (before the correction, which is at most ``MAX_CORRECTION``).
    """
    pa, pb = _local_to_world(body_handle(a), la), _local_to_world(body_handle(b), lb)
    return project_gap(a, b, pa.x, pa.y, pb.x, pb.y)


def project_gap(a: pymunk.Body, b: pymunk.Body, pax: float, pay: float, pbx: float,
                pby: float) -> float:
    """:func:`project_point` for anchors already in world coordinates (floats)."""
    cx, cy = pbx - pax, pby - pay
    n = math.hypot(cx, cy)
    if n < 1e-9:
        return n
    if n > MAX_CORRECTION:
        cx, cy = cx * MAX_CORRECTION / n, cy * MAX_CORRECTION / n
    ima, iia = inv_mass(a)
    imb, iib = inv_mass(b)
    ca, cb = body_handle(a), body_handle(b)
    loa, lob = _get_cog(ca), _get_cog(cb)
    ga, gb = _local_to_world(ca, loa), _local_to_world(cb, lob)
    rax, ray = pax - ga.x, pay - ga.y
    rbx, rby = pbx - gb.x, pby - gb.y
    k11 = ima + imb + iia * ray * ray + iib * rby * rby
    k12 = -iia * rax * ray - iib * rbx * rby
    k22 = ima + imb + iia * rax * rax + iib * rbx * rbx
    det = k11 * k22 - k12 * k12
    if abs(det) < 1e-12:
        return n
    px = -(k22 * cx - k12 * cy) / det
    py = -(-k12 * cx + k11 * cy) / det
    # P at pb on b, -P at pa on a
    push_apart((ca, loa, ga, ima, iia, rax, ray), (cb, lob, gb, imb, iib, rbx, rby), px, py)
    return n


def project_length(a: pymunk.Body, b: pymunk.Body, la: Vec2, lb: Vec2, length: float) -> float:
    """Box2D's position pass for a rod: restore the anchors' distance to ``length``.

    Returns the length error found, m (the correction is at most ``MAX_CORRECTION``).
    """
    pa, pb = a.local_to_world(la), b.local_to_world(lb)
    d = pb - pa
    n = abs(d)
    if n < 1e-9:
        return abs(length - n)
    u = d / n
    c = max(-MAX_CORRECTION, min(MAX_CORRECTION, n - length))
    k = point_mass(a, pa, u) + point_mass(b, pb, u)
    if k > 0:
        lam = -c / k
        _push(a, b, pa, pb, lam * u.x, lam * u.y)
    return abs(n - length)


def _push(
    a: pymunk.Body, b: pymunk.Body, pa: pymunk.Vec2d, pb: pymunk.Vec2d, px: float, py: float
) -> None:
    """Apply the position "impulse" P at ``pb`` on b and -P at ``pa`` on a."""
    ima, iia = inv_mass(a)
    imb, iib = inv_mass(b)
    ra, rb = pa - cog_world(a), pb - cog_world(b)
    if ima or iia:
        shift(a, -ima * px, -ima * py, -iia * cross(ra.x, ra.y, px, py))
    if imb or iib:
        shift(b, imb * px, imb * py, iib * cross(rb.x, rb.y, px, py))


def project_rows(rows: list[Row], error: float, max_correction: float) -> float:
    """Box2D's position pass for one scalar constraint with Jacobian ``rows``.

    Moves the bodies along the rows (weighted by their inverse masses) to remove
    ``error``, clamped to ``max_correction``, and leaves velocities alone.
    Returns ``|error|``.
    """
    merged, k = merge(rows)
    if k > 0.0:
        lam = -max(-max_correction, min(max_correction, error)) / k
        for body, jx, jy, jw, im, ii in merged:
            if im or ii:
                shift(body, im * lam * jx, im * lam * jy, ii * lam * jw)
    return abs(error)


def project_limit(
    rows: list[Row], value: float, lower: float, upper: float, max_correction: float
) -> None:
    """Box2D's position pass for a joint limit: bring ``value`` back into [lower, upper].

    The limit's velocity step pushes back too, but with a bounded speed that a load
    can hold off (a ragdoll lying on its bent knee stayed 25° past the limit); Box2D
    moves the bodies back by up to 8° (or 0.2 m) per step, and so does this.
    """
    if value < lower:
        project_rows(rows, value - lower, max_correction)
    elif value > upper:
        project_rows(rows, value - upper, max_correction)
