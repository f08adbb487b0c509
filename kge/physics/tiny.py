"""Coordinates too small to mean anything are zero before they reach Chipmunk.

Chipmunk turns the offset between two features into a contact normal with
``v / (|v| + DBL_MIN)``. When the offset is nonzero but below about 1.5e-154 m
its squared length underflows to 0, the "normal" comes out some 1e140 long,
and the position correction it drives turns both bodies' poses into inf and
then NaN in one step. The long fuzz found it: a circle at the origin and a
triangle whose corner sat at x = 1.3e-167. Box2D's ``b2Normalize`` returns a
zero vector below ``b2_epsilon`` instead; pymunk gives no such hook.

Two features can only be that close if their coordinates are themselves
below about 1e-138 m (a float's spacing is 2.2e-16 of its size), so kge
flushes every coordinate, angle and velocity it hands to Chipmunk (poses,
shapes, velocities written to components or made by impulses) below
:data:`TINY` (1e-100, some 65 orders of magnitude below the Planck length) to
exactly zero. Components keep the values the user wrote; only the pymunk side
sees the zero.

>>> flush(1.3e-167), flush(-2e-101), flush(1e-99), flush(0.25)
(0.0, 0.0, 1e-99, 0.25)
>>> flush_point((1e-200, 3.0))
(0.0, 3.0)
"""

from __future__ import annotations

from collections.abc import Sequence

Vec2 = tuple[float, float]

#: magnitudes below this are zero to the simulation
TINY = 1e-100


def flush(v: float) -> float:
    """``v``, or 0.0 when it is smaller than :data:`TINY` in magnitude."""
    return 0.0 if -TINY < v < TINY else v


def flush_point(p: Vec2) -> Vec2:
    """A point with both coordinates flushed."""
    x, y = p
    if -TINY < x < TINY or -TINY < y < TINY:
        return (flush(x), flush(y))
    return (x, y)


def flush_points(points: Sequence[Vec2]) -> tuple[Vec2, ...]:
    """Every point of ``points`` flushed."""
    return tuple(flush_point(p) for p in points)
