"""Body quantities the joint solvers need: masses, centres, lever arms, nudges.

pymunk keeps a body's *origin* in ``body.position`` and its centre of gravity as
a local offset; velocities are those of the centre of gravity. Joint anchors are
relative to the origin (as in Box2D), so lever arms are measured from
:func:`cog_world`. Static, kinematic and fixed-rotation bodies have zero inverse
mass or inertia here, which is how they drop out of every effective mass.

These run a few times per joint per step, so they call Chipmunk's getters and
setters directly (``kge.physics.cp.lib``, what pymunk's own properties call)
and work in floats: a pymunk ``Vec2d`` property read costs about five times the
C call it wraps (``body.position`` ~1 µs, ``cpBodyGetPosition`` ~0.15 µs).
"""

from __future__ import annotations

import math
from typing import Any

import pymunk

from kge.physics.cp import body_handle, lib

DYNAMIC = pymunk.Body.DYNAMIC

_get_type = lib.cpBodyGetType
_get_mass = lib.cpBodyGetMass
_get_moment = lib.cpBodyGetMoment
_get_angle = lib.cpBodyGetAngle
_set_angle = lib.cpBodySetAngle
_set_position = lib.cpBodySetPosition
_get_position = lib.cpBodyGetPosition
_get_cog = lib.cpBodyGetCenterOfGravity
_local_to_world = lib.cpBodyLocalToWorld
_isinf = math.isinf
_cos, _sin = math.cos, math.sin


def is_dynamic(body: pymunk.Body) -> bool:
    return bool(_get_type(body_handle(body)) == DYNAMIC)


def cog_xy(body: pymunk.Body) -> tuple[float, float]:
    """The centre of gravity in world coordinates, as floats."""
    cb = body_handle(body)
    c = _local_to_world(cb, _get_cog(cb))
    return c.x, c.y


def cog_world(body: pymunk.Body) -> pymunk.Vec2d:
    x, y = cog_xy(body)
    return pymunk.Vec2d(x, y)


def inv_mass(body: pymunk.Body) -> tuple[float, float]:
    """(1/m, 1/I) of a body, 0 for static, kinematic and fixed-rotation bodies."""
    cb = body_handle(body)
    if _get_type(cb) != DYNAMIC:
        return 0.0, 0.0
    m, i = _get_mass(cb), _get_moment(cb)
    return (1.0 / m if m and not _isinf(m) and m == m else 0.0,
            1.0 / i if i and not _isinf(i) and i == i else 0.0)


def cross(ax: float, ay: float, bx: float, by: float) -> float:
    return ax * by - ay * bx


def point_mass(body: pymunk.Body, world_point: pymunk.Vec2d, u: pymunk.Vec2d) -> float:
    """Inverse effective mass of ``body`` at ``world_point`` along unit ``u``."""
    im, ii = inv_mass(body)
    if not ii:
        return float(im)
    cx, cy = cog_xy(body)
    rn = cross(world_point[0] - cx, world_point[1] - cy, u[0], u[1])
    return float(im + ii * rn * rn)


def shift(body: pymunk.Body, dx: float, dy: float, dangle: float) -> None:
    """Move a dynamic body's centre of gravity by (dx, dy) and turn it about it."""
    cb = body_handle(body)
    cog = _get_cog(cb)
    c = _local_to_world(cb, cog)
    move_cog(cb, cog.x, cog.y, c.x + dx, c.y + dy, _get_angle(cb) + dangle)


#: while a dict: the pose (origin x, y, angle) each Chipmunk body had before
#: :func:`move_cog` first moved it (see :func:`journal`)
_journal: dict[Any, tuple[float, float, float]] | None = None


def journal(on: bool) -> dict[Any, tuple[float, float, float]]:
    """Start (``on``) or stop recording the poses bodies had before position passes
    moved them; returns the record, keyed by Chipmunk body (``body_handle(body)``).

    Box2D's position iterations (:mod:`kge.physics.joints.settle`) need the poses
    the step left only when a pass did move something, so they are recorded at
    the moves rather than read for every body beforehand.
    """
    global _journal
    record = _journal if _journal is not None else {}
    _journal = {} if on else None
    return record


def move_cog(cb: Any, lx: float, ly: float, cx: float, cy: float, angle: float) -> None:
    """Put the Chipmunk body ``cb``'s centre of gravity (local ``(lx, ly)``) at
    ``(cx, cy)`` with rotation ``angle`` (angle first, then origin, as pymunk does)."""
    if _journal is not None and cb not in _journal:
        p = _get_position(cb)
        _journal[cb] = (p.x, p.y, _get_angle(cb))
    _set_angle(cb, angle)
    c, s = _cos(angle), _sin(angle)
    _set_position(cb, (cx - (c * lx - s * ly), cy - (s * lx + c * ly)))


def push_apart(
    a: tuple[Any, Any, Any, float, float, float, float],
    b: tuple[Any, Any, Any, float, float, float, float],
    px: float, py: float,
) -> None:
    """Box2D's position impulse ``P = (px, py)``: ``-P`` on body a, ``+P`` on body b.

    Each side is (Chipmunk body, local centre of gravity, its world position, inverse
    mass, inverse inertia, lever x, lever y); a side with no inverse mass or inertia
    (static, kinematic) stays where it is.
    """
    for (cb, lo, g, im, ii, rx, ry), sign in ((a, -1.0), (b, 1.0)):
        if im or ii:
            move_cog(cb, lo.x, lo.y, g.x + sign * im * px, g.y + sign * im * py,
                     _get_angle(cb) + sign * ii * cross(rx, ry, px, py))
