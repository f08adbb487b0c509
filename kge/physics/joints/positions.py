"""Box2D's position pass for rods and pivots, run after the step.

pymunk corrects joint drift only through velocity bias, which lets a swinging rod
stretch by centimetres and, if made stronger, pumps energy into long chains.
Box2D instead moves the bodies back onto their constraints after the velocity
solve without touching velocities (its position iterations); these helpers do
the same, limited like Box2D to ``MAX_CORRECTION`` per step.
"""

from __future__ import annotations

import math

import pymunk

from kge.physics.joints.mechanics import cog_world, cross, inv_mass, point_mass, shift

Vec2 = tuple[float, float]

#: Box2D's b2_maxLinearCorrection: the most a position pass moves per step, m
MAX_CORRECTION = 0.2


def project_point(a: pymunk.Body, b: pymunk.Body, la: Vec2, lb: Vec2) -> None:
    """Box2D's position pass for a pivot: bring the two anchors together."""
    pa, pb = a.local_to_world(la), b.local_to_world(lb)
    cx, cy = pb.x - pa.x, pb.y - pa.y
    n = math.hypot(cx, cy)
    if n < 1e-9:
        return
    if n > MAX_CORRECTION:
        cx, cy = cx * MAX_CORRECTION / n, cy * MAX_CORRECTION / n
    ima, iia = inv_mass(a)
    imb, iib = inv_mass(b)
    ra, rb = pa - cog_world(a), pb - cog_world(b)
    k11 = ima + imb + iia * ra.y * ra.y + iib * rb.y * rb.y
    k12 = -iia * ra.x * ra.y - iib * rb.x * rb.y
    k22 = ima + imb + iia * ra.x * ra.x + iib * rb.x * rb.x
    det = k11 * k22 - k12 * k12
    if abs(det) < 1e-12:
        return
    px = -(k22 * cx - k12 * cy) / det
    py = -(-k12 * cx + k11 * cy) / det
    if ima or iia:
        shift(a, -ima * px, -ima * py, -iia * cross(ra.x, ra.y, px, py))
    if imb or iib:
        shift(b, imb * px, imb * py, iib * cross(rb.x, rb.y, px, py))


def project_length(a: pymunk.Body, b: pymunk.Body, la: Vec2, lb: Vec2, length: float) -> None:
    """Box2D's position pass for a rod: restore the anchors' distance to ``length``."""
    pa, pb = a.local_to_world(la), b.local_to_world(lb)
    d = pb - pa
    n = abs(d)
    if n < 1e-9:
        return
    u = d / n
    c = max(-MAX_CORRECTION, min(MAX_CORRECTION, n - length))
    k = point_mass(a, pa, u) + point_mass(b, pb, u)
    if k <= 0:
        return
    lam = -c / k
    px, py = lam * u.x, lam * u.y
    ima, iia = inv_mass(a)
    imb, iib = inv_mass(b)
    ra, rb = pa - cog_world(a), pb - cog_world(b)
    if ima or iia:
        shift(a, -ima * px, -ima * py, -iia * cross(ra.x, ra.y, px, py))
    if imb or iib:
        shift(b, imb * px, imb * py, iib * cross(rb.x, rb.y, px, py))
