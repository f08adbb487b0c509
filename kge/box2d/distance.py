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
from kge.box2d.vec import as_xy
from kge.collision.geometry import Convex, convex
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


class b2DistanceProxy:
    """One convex child of a shape, as GJK sees it (``b2DistanceProxy(shape, index)``)."""

    def __init__(self, shape: Any = None, index: int = 0) -> None:
        self.shape = shape
        self.index = index

    def Set(self, shape: Any, index: int) -> None:
        self.shape, self.index = shape, index

    def _convex(self) -> Convex:
        return convex(_shape(self.shape, "b2DistanceProxy.shape"), self.index)

    @property
    def vertices(self) -> list[tuple[float, float]]:
        return list(self._convex().vertices)

    @property
    def radius(self) -> float:
        return self._convex().radius

    def GetSupport(self, d: Any) -> int:
        """The index of the vertex furthest along ``d``."""
        dx, dy = as_xy(d, "b2DistanceProxy.GetSupport", "d")
        vs = self._convex().vertices
        return max(range(len(vs)), key=lambda i: vs[i][0] * dx + vs[i][1] * dy)

    def GetSupportVertex(self, d: Any) -> tuple[float, float]:
        return self._convex().vertices[self.GetSupport(d)]


class b2DistanceInput:
    """Everything ``b2Distance(input)`` needs: two proxies, their transforms, useRadii."""

    def __init__(self, proxyA: Any = None, proxyB: Any = None, transformA: Any = None,
                 transformB: Any = None, useRadii: bool = True) -> None:
        self.proxyA, self.proxyB = proxyA, proxyB
        self.transformA, self.transformB = transformA, transformB
        self.useRadii = useRadii


class b2TOIInput:
    """Everything ``b2TimeOfImpact(input)`` needs: two proxies, their sweeps, ``tMax``."""

    def __init__(self, proxyA: Any = None, proxyB: Any = None, sweepA: Any = None,
                 sweepB: Any = None, tMax: float = 1.0) -> None:
        self.proxyA, self.proxyB = proxyA, proxyB
        self.sweepA, self.sweepB = sweepA, sweepB
        self.tMax = tMax


def _proxy(value: Any, name: str) -> b2DistanceProxy:
    if not isinstance(value, b2DistanceProxy):
        raise ComponentTypeError(f"{name} must be a b2DistanceProxy, got {value!r}")
    return value


def b2Distance(shapeA: Any = None, idxA: int = 0, shapeB: Any = None, idxB: int = 0,
               transformA: Any = None, transformB: Any = None,
               useRadii: bool = True) -> b2DistanceResult:
    """The closest points of two placed shapes and their distance (GJK).

    Called with keywords, or with one ``b2DistanceInput`` (pybox2d's two forms).
    """
    if isinstance(shapeA, b2DistanceInput):
        given = shapeA
        pa, pb = _proxy(given.proxyA, "proxyA"), _proxy(given.proxyB, "proxyB")
        return b2Distance(shapeA=pa.shape, idxA=pa.index, shapeB=pb.shape, idxB=pb.index,
                          transformA=given.transformA, transformB=given.transformB,
                          useRadii=given.useRadii)
    out = collision.distance(_shape(shapeA, "shapeA"), _pose(transformA, "transformA"),
                             _shape(shapeB, "shapeB"), _pose(transformB, "transformB"),
                             child_a=idxA, child_b=idxB, use_radii=useRadii)
    return b2DistanceResult(tuple(out.point_a), tuple(out.point_b), out.distance,
                            out.iterations)


b2DistanceOutput = b2DistanceResult


def b2TimeOfImpact(shapeA: Any = None, idxA: int = 0, shapeB: Any = None, idxB: int = 0,
                   sweepA: Any = None, sweepB: Any = None,
                   tMax: float = 0.0) -> tuple[int, float]:
    """``(state, t)``: when in [0, tMax] two sweeping shapes first touch.

    Called with keywords, or with one ``b2TOIInput`` (pybox2d's two forms).
    """
    if isinstance(shapeA, b2TOIInput):
        given = shapeA
        pa, pb = _proxy(given.proxyA, "proxyA"), _proxy(given.proxyB, "proxyB")
        return b2TimeOfImpact(shapeA=pa.shape, idxA=pa.index, shapeB=pb.shape, idxB=pb.index,
                              sweepA=given.sweepA, sweepB=given.sweepB, tMax=given.tMax)
    out = collision.time_of_impact(_shape(shapeA, "shapeA"), _sweep(sweepA, "sweepA"),
                                   _shape(shapeB, "shapeB"), _sweep(sweepB, "sweepB"), tMax,
                                   child_a=idxA, child_b=idxB)
    return _STATES[out.state], out.t
