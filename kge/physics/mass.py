"""Mass properties computed the way Box2D does (``b2Shape::ComputeMass``).

kge computes body mass itself instead of handing densities to pymunk, because
Box2D's rules differ: the polygon skin does not count, edges and chains are
massless, sensors do count, a dynamic body with no mass gets 1 kg and no
rotational inertia, and a fixed-rotation body has infinite inertia whatever
its shapes say. pymunk shapes are built with density 0 and the body gets
``mass``, ``moment`` and ``center_of_gravity`` from here.

>>> from kge.components.shapes import Circle, Box
>>> md = shape_mass(Circle(0.5), 1.0)
>>> round(md.mass, 6), round(md.inertia, 6)
(0.785398, 0.098175)
>>> md = shape_mass(Box(1.0, 0.5), 2.0)
>>> round(md.mass, 6), round(md.inertia, 5)
(4.0, 1.66667)
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from functools import lru_cache

from kge.components.shapes import Box, Chain, Circle, Edge, Polygon, Shape

Vec2 = tuple[float, float]


@dataclass(slots=True, frozen=True)
class MassData:
    """Mass (kg), rotational inertia about the centre of mass (kg m^2), local centre."""

    mass: float
    inertia: float
    center: Vec2


ZERO = MassData(0.0, 0.0, (0.0, 0.0))

#: masses and inertias at or below this count as none (Box2D's float32 could not even
#: hold them; in float64 their inverses overflow and the solver produces NaN)
TINY = 1e-30
#: larger masses are clamped, larger inertias mean "does not rotate" (overflow guards)
HUGE = 1e30


def polygon_mass(vertices: Sequence[Vec2], density: float) -> MassData:
    """Mass, centroidal inertia and centroid of a convex polygon (Box2D's formula)."""
    ox, oy = vertices[0]  # reference point for precision
    area = cx = cy = inertia = 0.0
    for i in range(1, len(vertices) - 1):
        e1x, e1y = vertices[i][0] - ox, vertices[i][1] - oy
        e2x, e2y = vertices[i + 1][0] - ox, vertices[i + 1][1] - oy
        d = e1x * e2y - e1y * e2x
        tri = 0.5 * d
        area += tri
        cx += tri * (e1x + e2x) / 3.0
        cy += tri * (e1y + e2y) / 3.0
        intx2 = e1x * e1x + e2x * e1x + e2x * e2x
        inty2 = e1y * e1y + e2y * e1y + e2y * e2y
        inertia += (0.25 / 3.0 * d) * (intx2 + inty2)
    mass = density * area
    if area <= 0:
        return ZERO
    cx /= area
    cy /= area
    # inertia about the reference point -> about the centroid
    i_centroid = density * inertia - mass * (cx * cx + cy * cy)
    return MassData(mass, i_centroid, (cx + ox, cy + oy))


@lru_cache(maxsize=256)
def shape_mass(shape: Shape, density: float) -> MassData:
    """Mass data of one shape (centre in body-local coordinates).

    Cached by value (shapes and MassData are frozen): spawning a thousand equal
    boxes computes one polygon mass.
    """
    if isinstance(shape, Circle):
        m = density * math.pi * shape.radius**2
        return MassData(m, 0.5 * m * shape.radius**2, shape.center)
    if isinstance(shape, Box):
        return polygon_mass(shape.vertices(), density)
    if isinstance(shape, Polygon):
        return polygon_mass(shape.vertices, density)
    if isinstance(shape, (Edge, Chain)):
        return ZERO
    raise TypeError(f"unknown shape {shape!r}")  # pragma: no cover - validated earlier


def combine(parts: Iterable[MassData]) -> MassData:
    """Sum shape masses; inertia moved to the common centre (parallel axis)."""
    return _combine(tuple(parts))


@lru_cache(maxsize=256)
def _combine(parts: tuple[MassData, ...]) -> MassData:
    items = [p for p in parts if p.mass > 0]
    mass = sum(p.mass for p in items)
    if mass <= 0:
        return ZERO
    cx = sum(p.mass * p.center[0] for p in items) / mass
    cy = sum(p.mass * p.center[1] for p in items) / mass
    inertia = sum(
        p.inertia + p.mass * ((p.center[0] - cx) ** 2 + (p.center[1] - cy) ** 2) for p in items
    )
    return MassData(mass, inertia, (cx, cy))


@lru_cache(maxsize=256)
def dynamic_mass(
    computed: MassData, override: float | None, fixed_rotation: bool
) -> MassData:
    """Apply Box2D's dynamic-body rules to the collider-derived mass.

    * no mass -> 1 kg and no rotational inertia (``inf`` moment: torque does nothing);
    * ``override`` -> that mass, same centre, inertia scaled by the mass ratio;
    * ``fixed_rotation`` -> infinite moment.
    """
    mass, inertia, center = computed.mass, computed.inertia, computed.center
    if override is not None:
        inertia = inertia * override / mass if mass > 0 else 0.0
        mass = override
    if not mass > TINY:  # also denormal masses (1/m overflows to inf -> NaN poses) and NaN
        mass, inertia = 1.0, 0.0
    mass = min(mass, HUGE)  # density * area can overflow to inf, which pymunk refuses
    if fixed_rotation or not TINY < inertia < HUGE:  # NaN, overflowed or no inertia
        inertia = math.inf
    return MassData(mass, inertia, center)
