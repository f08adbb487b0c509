"""``b2RayCastInput`` / ``b2RayCastOutput`` and the ray casts that fill them.

Box2D's single-shape ray cast (``shape.RayCast(output, input, transform,
childIndex)``, ``fixture.RayCast(output, input, childIndex)``,
``aabb.RayCast(output, input)``) returns whether the ray ``p1 -> p2`` hits
before ``maxFraction`` and writes the hit's ``fraction`` and ``normal`` into
``output``. The shapes' casts run on :func:`kge.collision.ray_cast`.

>>> from kge.box2d.shapes import b2PolygonShape
>>> from kge.box2d.transform import b2Transform
>>> out = b2RayCastOutput()
>>> b2PolygonShape(box=(1, 1)).RayCast(out, b2RayCastInput(p1=(-3, 0), p2=(3, 0)),
...                                    b2Transform(), 0)
True
>>> round(out.fraction, 6), out.normal
(0.333333, b2Vec2(-1,0))
"""

from __future__ import annotations

from typing import Any

from kge import collision
from kge.box2d.vec import as_xy, b2Vec2
from kge.components.shapes import Shape
from kge.errors import ComponentTypeError


class b2RayCastInput:
    """A ray from ``p1`` towards ``p2``, up to ``maxFraction`` of the way."""

    def __init__(self, p1: Any = (0.0, 0.0), p2: Any = (0.0, 0.0),
                 maxFraction: float = 1.0) -> None:
        self.p1, self.p2 = b2Vec2(p1), b2Vec2(p2)
        self.maxFraction = float(maxFraction)


class b2RayCastOutput:
    """Where a ray hit: ``fraction`` of the way from p1 to p2, and the surface ``normal``."""

    def __init__(self, normal: Any = (0.0, 0.0), fraction: float = 0.0) -> None:
        self.normal = b2Vec2(normal)
        self.fraction = float(fraction)


def _check(output: Any, given: Any) -> None:
    if not isinstance(output, b2RayCastOutput):
        raise ComponentTypeError(f"RayCast output must be a b2RayCastOutput, got {output!r}")
    if not isinstance(given, b2RayCastInput):
        raise ComponentTypeError(f"RayCast input must be a b2RayCastInput, got {given!r}")


def cast(shape: Shape, pose: tuple[float, float, float], output: Any, given: Any,
         child: int) -> bool:
    """Cast ``given`` at the kge ``shape`` placed at ``pose``; fill ``output`` on a hit."""
    _check(output, given)
    p1, p2 = as_xy(given.p1, "b2RayCastInput", "p1"), as_xy(given.p2, "b2RayCastInput", "p2")
    if p1 == p2:
        return False
    hit = collision.ray_cast(shape, pose, p1, p2, given.maxFraction, child)
    if hit is None:
        return False
    output.normal = b2Vec2(*hit.normal)
    output.fraction = hit.fraction
    return True


def cast_box(lower: Any, upper: Any, output: Any, given: Any) -> bool:
    """Box2D's b2AABB::RayCast (slab test): the ray's entry into the box."""
    _check(output, given)
    (lx, ly), (ux, uy) = as_xy(lower), as_xy(upper)
    p1, p2 = as_xy(given.p1), as_xy(given.p2)
    tmin, tmax = -1e300, float(given.maxFraction)
    normal = (0.0, 0.0)
    for axis, lo, hi in ((0, lx, ux), (1, ly, uy)):
        p, d = p1[axis], p2[axis] - p1[axis]
        if abs(d) < 1.1920929e-07:
            if p < lo or hi < p:
                return False
            continue
        t1, t2, s = (lo - p) / d, (hi - p) / d, -1.0
        if t1 > t2:
            t1, t2, s = t2, t1, 1.0
        if t1 > tmin:
            tmin = t1
            normal = (s, 0.0) if axis == 0 else (0.0, s)
        tmax = min(tmax, t2)
        if tmin > tmax:
            return False
    if tmin < 0.0 or given.maxFraction < tmin:
        return False
    output.fraction, output.normal = tmin, b2Vec2(*normal)
    return True
