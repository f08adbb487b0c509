"""``b2Distance`` and ``b2TimeOfImpact``: pybox2d's collision functions on :mod:`kge.collision`.

pybox2d wraps Box2D's GJK distance and conservative-advancement time of impact
with keyword forms; these take the same keywords (b2 shapes, ``b2Transform``,
``b2Sweep``) and answer in pybox2d's shapes: a ``b2DistanceResult`` named tuple
and a ``(state, t)`` pair with ``b2TOIOutput``'s state numbers.

>>> from kge.box2d.shapes import b2CircleShape
>>> from kge.box2d.transform import b2Transform
>>> far = b2Transform()
>>> far.position = (3, 0)
>>> round(b2Distance(shapeA=b2CircleShape(radius=0.5), shapeB=b2CircleShape(radius=0.5),
...                  transformA=b2Transform(), transformB=far).distance, 6)
2.0
"""

from __future__ import annotations

from collections import namedtuple
from typing import Any

from kge import collision
from kge.box2d.shapes import b2Shape
from kge.box2d.transform import b2Sweep, b2Transform
from kge.errors import ComponentTypeError

b2DistanceResult = namedtuple("b2DistanceResult", "pointA pointB distance iterations")


class b2TOIOutput:
    """The states ``b2TimeOfImpact`` reports (Box2D's numbering)."""

    e_unknown, e_failed, e_overlapped, e_touching, e_separated = range(5)


_STATES = {"failed": b2TOIOutput.e_failed, "overlapped": b2TOIOutput.e_overlapped,
           "touching": b2TOIOutput.e_touching, "separated": b2TOIOutput.e_separated}


def _shape(value: Any, name: str) -> Any:
    if not isinstance(value, b2Shape):
        raise ComponentTypeError(f"{name} must be a b2 shape, got {value!r}")
    return value.to_kge()


def _pose(value: Any, name: str) -> tuple[float, float, float]:
    if not isinstance(value, b2Transform):
        raise ComponentTypeError(f"{name} must be a b2Transform, got {value!r}")
    return (value.position.x, value.position.y, value.angle)


def _sweep(value: Any, name: str) -> collision.Sweep:
    if not isinstance(value, b2Sweep):
        raise ComponentTypeError(f"{name} must be a b2Sweep, got {value!r}")
    return collision.Sweep(value.localCenter.tuple, value.c0.tuple, value.c.tuple,
                           value.a0, value.a, value.alpha0)


def b2Distance(shapeA: Any = None, idxA: int = 0, shapeB: Any = None, idxB: int = 0,
               transformA: Any = None, transformB: Any = None,
               useRadii: bool = True) -> b2DistanceResult:
    """The closest points of two placed shapes and their distance (GJK)."""
    out = collision.distance(_shape(shapeA, "shapeA"), _pose(transformA, "transformA"),
                             _shape(shapeB, "shapeB"), _pose(transformB, "transformB"),
                             child_a=idxA, child_b=idxB, use_radii=useRadii)
    return b2DistanceResult(tuple(out.point_a), tuple(out.point_b), out.distance,
                            out.iterations)


def b2TimeOfImpact(shapeA: Any = None, idxA: int = 0, shapeB: Any = None, idxB: int = 0,
                   sweepA: Any = None, sweepB: Any = None,
                   tMax: float = 0.0) -> tuple[int, float]:
    """``(state, t)``: when in [0, tMax] two sweeping shapes first touch."""
    out = collision.time_of_impact(_shape(shapeA, "shapeA"), _sweep(sweepA, "sweepA"),
                                   _shape(shapeB, "shapeB"), _sweep(sweepB, "sweepB"), tMax,
                                   child_a=idxA, child_b=idxB)
    return _STATES[out.state], out.t
