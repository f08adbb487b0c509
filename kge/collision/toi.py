"""When two moving shapes first touch: time of impact by conservative advancement.

A shape's motion over a step is a :class:`Sweep` (Box2D's ``b2Sweep``): its
centre of mass moves in a straight line from ``c0`` to ``c`` while its angle
goes linearly from ``a0`` to ``a``; ``local_center`` is where the centre of
mass sits in the shape's frame, so the pose at time ``beta`` in [0, 1] is
``c(beta) - R(angle(beta)) * local_center``.

:func:`time_of_impact` answers "when is the gap first down to about
``linear_slop``?" (Box2D's ``b2TimeOfImpact``, rounded shapes, the polygon skin
included). It alternates two steps:

1. GJK (:mod:`kge.collision.distance`) at the current time t1 finds the
   closest features; they define a *separating axis* (two points, or a face
   of A or of B);
2. along that axis the deepest points at the end time t2 are found; if they
   are still apart, the shapes never meet (``separated``); otherwise a root
   finder (alternating bisection and secant steps) finds when their
   separation reaches the target, which becomes the new t1, and the
   axis is rebuilt there.

The result is a state and a time: ``touching`` at ``t`` (the time at which
the cores' gap is the *target*, the sum of radii less 3 * linear slop: the
rounded shapes then overlap by about 0.015 m, Box2D's choice so that the
manifold finds the contact and the solver keeps it),
``separated`` (no impact before ``t_max``; ``t`` = ``t_max``), ``overlapped``
(already overlapping at t = 0) or ``failed`` (did not converge; ``t`` is the
last safe time). Rotation can make the answer miss a brief, grazing contact,
as in Box2D; a tunnelling motion is never missed.

>>> from kge.components.shapes import Box, Circle
>>> ball = Sweep.between((-5.0, 0.0, 0.0), (5.0, 0.0, 0.0))
>>> wall = Sweep.between((0.0, 0.0, 0.0), (0.0, 0.0, 0.0))
>>> out = time_of_impact(Circle(0.5), ball, Box(0.1, 2.0), wall)
>>> out.state, round(out.t, 3)
('touching', 0.441)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Literal

from kge.collision.distance import SimplexCache, gjk, support
from kge.collision.geometry import Convex, convex
from kge.collision.pose import Pose, point, pose
from kge.components.shapes import LINEAR_SLOP
from kge.errors import ValidationError
from kge.validate import finite

Vec2 = tuple[float, float]
State = Literal["failed", "overlapped", "touching", "separated"]

#: Box2D's limits: outer iterations, root-finder iterations, axis push-backs
MAX_ITERATIONS = 20
MAX_ROOT_ITERATIONS = 50
MAX_PUSH_BACKS = 16
#: a core gap this small is an overlap: GJK ending on an edge through the origin
#: leaves float64 rounding (~1e-17 m) where Box2D's float32 usually gives exactly 0
OVERLAP_GAP = 1e-12


@dataclass(slots=True, frozen=True)
class Sweep:
    """Linear motion of a centre of mass from ``c0`` to ``c``, angle from ``a0`` to ``a``."""

    local_center: Vec2
    c0: Vec2
    c: Vec2
    a0: float
    a: float
    alpha0: float = 0.0

    def __post_init__(self) -> None:
        for name in ("local_center", "c0", "c"):
            object.__setattr__(self, name, point(getattr(self, name), f"Sweep.{name}"))
        for name in ("a0", "a"):
            object.__setattr__(self, name, finite(getattr(self, name), "Sweep", name))
        alpha0 = finite(self.alpha0, "Sweep", "alpha0")
        if not 0.0 <= alpha0 < 1.0:
            raise ValidationError(f"Sweep.alpha0 must be in [0, 1), got {alpha0!r}")
        object.__setattr__(self, "alpha0", alpha0)

    @staticmethod
    def between(start: Any, end: Any, local_center: Any = (0.0, 0.0)) -> Sweep:
        """The sweep of a shape moving from pose ``start`` to pose ``end``."""
        p0, p1 = pose(start, "start"), pose(end, "end")
        lc = point(local_center, "local_center")
        c0, c1 = p0.apply(lc), p1.apply(lc)
        return Sweep(lc, c0, c1, p0.angle, p1.angle)

    def transform(self, beta: float) -> Pose:
        """The pose at fraction ``beta`` of the step (b2Sweep::GetTransform)."""
        cx = (1.0 - beta) * self.c0[0] + beta * self.c[0]
        cy = (1.0 - beta) * self.c0[1] + beta * self.c[1]
        angle = (1.0 - beta) * self.a0 + beta * self.a
        c, s = math.cos(angle), math.sin(angle)
        lx, ly = self.local_center
        return Pose(cx - (c * lx - s * ly), cy - (s * lx + c * ly), angle, c, s)

    def advance(self, alpha: float) -> Sweep:
        """The sweep restarted at time ``alpha`` (b2Sweep::Advance): c0, a0 move there.

        ``alpha0`` is the time the sweep starts at, within the step; times of impact
        are fractions of what remains after it.
        """
        a = finite(alpha, "Sweep.advance", "alpha")
        if not self.alpha0 <= a < 1.0:
            raise ValidationError(f"Sweep.advance alpha must be in [alpha0, 1), got {a!r}")
        beta = (a - self.alpha0) / (1.0 - self.alpha0)
        c0 = (self.c0[0] + beta * (self.c[0] - self.c0[0]),
              self.c0[1] + beta * (self.c[1] - self.c0[1]))
        return Sweep(self.local_center, c0, self.c, self.a0 + beta * (self.a - self.a0), self.a, a)

    def normalized(self) -> Sweep:
        """The same sweep with ``a0`` wrapped into [0, 2 pi) (b2Sweep::Normalize)."""
        d = 2.0 * math.pi * math.floor(self.a0 / (2.0 * math.pi))
        return Sweep(self.local_center, self.c0, self.c, self.a0 - d, self.a - d, self.alpha0)


@dataclass(slots=True, frozen=True)
class TOIOutput:
    """``state`` and time ``t`` (a fraction of the sweeps, in [0, t_max])."""

    state: State
    t: float


class _Separation:
    """Box2D's b2SeparationFunction: the separation of two features along one axis."""

    __slots__ = ("a", "axis", "b", "kind", "local_point", "sa", "sb")

    def __init__(self, cache: SimplexCache, a: Convex, sa: Sweep, b: Convex, sb: Sweep,
                 t1: float) -> None:
        self.a, self.b, self.sa, self.sb = a, b, sa, sb
        xa, xb = sa.transform(t1), sb.transform(t1)
        if cache.count == 1:
            self.kind = "points"
            pa = xa.apply(a.vertices[cache.index_a[0]])
            pb = xb.apply(b.vertices[cache.index_b[0]])
            self.axis = _unit((pb[0] - pa[0], pb[1] - pa[1]))
            self.local_point = (0.0, 0.0)
            return
        if cache.index_a[0] == cache.index_a[1]:  # two points on B: a face of B
            self.kind = "face_b"
            face, fx, other, ox = b, xb, a.vertices[cache.index_a[0]], xa
            i1, i2 = cache.index_b[0], cache.index_b[1]
        else:
            self.kind = "face_a"
            face, fx, other, ox = a, xa, b.vertices[cache.index_b[0]], xb
            i1, i2 = cache.index_a[0], cache.index_a[1]
        v1, v2 = face.vertices[i1], face.vertices[i2]
        self.axis = _unit((v2[1] - v1[1], v1[0] - v2[0]))
        self.local_point = (0.5 * (v1[0] + v2[0]), 0.5 * (v1[1] + v2[1]))
        n = fx.rotate(self.axis)
        pf, po = fx.apply(self.local_point), ox.apply(other)
        if (po[0] - pf[0]) * n[0] + (po[1] - pf[1]) * n[1] < 0.0:
            self.axis = (-self.axis[0], -self.axis[1])

    def find_min(self, t: float) -> tuple[int, int, float]:
        """The deepest pair of features along the axis at time t, and their separation."""
        xa, xb = self.sa.transform(t), self.sb.transform(t)
        ax, ay = self.axis
        if self.kind == "points":
            ia = support(self.a.vertices, *xa.unrotate((ax, ay)))
            ib = support(self.b.vertices, *xb.unrotate((-ax, -ay)))
        elif self.kind == "face_a":
            n = xa.rotate(self.axis)
            ia, ib = -1, support(self.b.vertices, *xb.unrotate((-n[0], -n[1])))
        else:
            n = xb.rotate(self.axis)
            ia, ib = support(self.a.vertices, *xa.unrotate((-n[0], -n[1]))), -1
        return ia, ib, self._separation(ia, ib, xa, xb)

    def evaluate(self, ia: int, ib: int, t: float) -> float:
        return self._separation(ia, ib, self.sa.transform(t), self.sb.transform(t))

    def _separation(self, ia: int, ib: int, xa: Pose, xb: Pose) -> float:
        if self.kind == "points":
            pa, pb = xa.apply(self.a.vertices[ia]), xb.apply(self.b.vertices[ib])
            return (pb[0] - pa[0]) * self.axis[0] + (pb[1] - pa[1]) * self.axis[1]
        if self.kind == "face_a":
            n, pf, po = xa.rotate(self.axis), xa.apply(self.local_point), xb.apply(
                self.b.vertices[ib])
        else:
            n, pf, po = xb.rotate(self.axis), xb.apply(self.local_point), xa.apply(
                self.a.vertices[ia])
        return (po[0] - pf[0]) * n[0] + (po[1] - pf[1]) * n[1]


def _unit(v: Vec2) -> Vec2:
    n = math.hypot(v[0], v[1])
    return (v[0] / n, v[1] / n) if n > 0.0 else (0.0, 0.0)


def _sweep(value: Any, field: str) -> Sweep:
    if not isinstance(value, Sweep):
        raise ValidationError(f"{field} must be a kge.collision.Sweep, got {value!r}")
    return value


def time_of_impact(
    shape_a: Any, sweep_a: Any, shape_b: Any, sweep_b: Any, t_max: Any = 1.0, *,
    child_a: Any = 0, child_b: Any = 0,
) -> TOIOutput:
    """The first time in [0, t_max] at which the two sweeping shapes touch (b2TimeOfImpact)."""
    a, b = convex(shape_a, child_a, "shape_a"), convex(shape_b, child_b, "shape_b")
    sa, sb = _sweep(sweep_a, "sweep_a").normalized(), _sweep(sweep_b, "sweep_b").normalized()
    limit = finite(t_max, "", "t_max")
    if not 0.0 <= limit <= 1.0:
        raise ValidationError(f"t_max must be in [0, 1], got {limit!r}")
    return _toi(a, sa, b, sb, limit)


def _toi(a: Convex, sa: Sweep, b: Convex, sb: Sweep, t_max: float) -> TOIOutput:
    target = max(LINEAR_SLOP, a.radius + b.radius - 3.0 * LINEAR_SLOP)
    tolerance = 0.25 * LINEAR_SLOP
    t1 = 0.0
    cache = SimplexCache()
    for _ in range(MAX_ITERATIONS):
        pa, pb, _iters = gjk(a, sa.transform(t1), b, sb.transform(t1), cache)
        gap = math.hypot(pb[0] - pa[0], pb[1] - pa[1])
        if gap <= OVERLAP_GAP:
            return TOIOutput("overlapped", 0.0)
        if gap < target + tolerance:
            return TOIOutput("touching", t1)
        fcn = _Separation(cache, a, sa, b, sb, t1)
        t2 = t_max
        for _push in range(MAX_PUSH_BACKS):
            ia, ib, s2 = fcn.find_min(t2)
            if s2 > target + tolerance:
                return TOIOutput("separated", t_max)
            if s2 > target - tolerance:
                t1 = t2  # the axis is good up to t2: advance the sweeps
                break
            s1 = fcn.evaluate(ia, ib, t1)
            if s1 < target - tolerance:
                return TOIOutput("failed", t1)
            if s1 <= target + tolerance:
                return TOIOutput("touching", t1)
            t2 = _root(fcn, ia, ib, t1, s1, t2, s2, target, tolerance)
        else:
            pass  # push-backs exhausted: go round with the same t1, as Box2D does
    return TOIOutput("failed", t1)


def _root(fcn: _Separation, ia: int, ib: int, a1: float, s1: float, a2: float, s2: float,
          target: float, tolerance: float) -> float:
    """The time in [a1, a2] where the separation crosses ``target`` (bisection + secant)."""
    t = a2
    for i in range(MAX_ROOT_ITERATIONS):
        t = a1 + (target - s1) * (a2 - a1) / (s2 - s1) if i & 1 else 0.5 * (a1 + a2)
        s = fcn.evaluate(ia, ib, t)
        if abs(s - target) < tolerance:
            return t
        if s > target:
            a1, s1 = t, s
        else:
            a2, s2 = t, s
    return t
