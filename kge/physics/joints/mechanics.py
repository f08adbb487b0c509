"""Body quantities the joint solvers need: masses, centres, lever arms, nudges.

pymunk keeps a body's *origin* in ``body.position`` and its centre of gravity as
a local offset; velocities are those of the centre of gravity. Joint anchors are
relative to the origin (as in Box2D), so lever arms are measured from
:func:`cog_world`. Static, kinematic and fixed-rotation bodies have zero inverse
mass or inertia here, which is how they drop out of every effective mass.
"""

from __future__ import annotations

import math

import pymunk

DYNAMIC = pymunk.Body.DYNAMIC


def is_dynamic(body: pymunk.Body) -> bool:
    return bool(body.body_type == DYNAMIC)


def cog_world(body: pymunk.Body) -> pymunk.Vec2d:
    return body.local_to_world(body.center_of_gravity)


def inv_mass(body: pymunk.Body) -> tuple[float, float]:
    """(1/m, 1/I) of a body, 0 for static, kinematic and fixed-rotation bodies."""
    if not is_dynamic(body):
        return 0.0, 0.0
    m, i = body.mass, body.moment
    return (1.0 / m if m and math.isfinite(m) else 0.0, 1.0 / i if i and math.isfinite(i) else 0.0)


def cross(ax: float, ay: float, bx: float, by: float) -> float:
    return ax * by - ay * bx


def point_mass(body: pymunk.Body, world_point: pymunk.Vec2d, u: pymunk.Vec2d) -> float:
    """Inverse effective mass of ``body`` at ``world_point`` along unit ``u``."""
    im, ii = inv_mass(body)
    r = world_point - cog_world(body)
    rn = cross(r.x, r.y, u.x, u.y)
    return float(im + ii * rn * rn)


def shift(body: pymunk.Body, dx: float, dy: float, dangle: float) -> None:
    """Move a dynamic body's centre of gravity by (dx, dy) and turn it about it."""
    c = cog_world(body)
    body.angle = body.angle + dangle
    new_c = pymunk.Vec2d(c.x + dx, c.y + dy)
    body.position = new_c - body.center_of_gravity.rotated(body.angle)
