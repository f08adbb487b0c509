"""``b2Rot``, ``b2Transform``, ``b2AABB`` and ``b2Sweep``: Box2D's small math types.

``body.transform * vertex`` is how pybox2d programs (and Gymnasium's renderers)
turn a fixture's local vertices into world points; ``b2Transform`` does that
with plain floats.

>>> t = b2Transform()
>>> t.position = (1, 2)
>>> t.angle = b2_half_pi = 1.5707963267948966
>>> p = t * (1, 0)
>>> round(p.x, 9), round(p.y, 9)
(1.0, 3.0)
"""

from __future__ import annotations

import math
from typing import Any

from kge.box2d.matrix import b2Mat22
from kge.box2d.vec import as_xy, b2Vec2
from kge.errors import ComponentTypeError


class b2Rot:
    """A rotation as sine and cosine."""

    def __init__(self, angle: float = 0.0) -> None:
        self.angle = angle

    @property
    def angle(self) -> float:
        return math.atan2(self.s, self.c)

    @angle.setter
    def angle(self, value: float) -> None:
        a = float(value)
        self.s, self.c = math.sin(a), math.cos(a)

    @property
    def x_axis(self) -> b2Vec2:
        return b2Vec2(self.c, self.s)

    @property
    def y_axis(self) -> b2Vec2:
        return b2Vec2(-self.s, self.c)

    def SetIdentity(self) -> None:
        self.s, self.c = 0.0, 1.0

    def __mul__(self, v: Any) -> b2Vec2:
        x, y = as_xy(v, "b2Rot", "vector")
        return b2Vec2(self.c * x - self.s * y, self.s * x + self.c * y)

    def __repr__(self) -> str:
        return f"b2Rot(angle={self.angle:g})"


class b2Transform:
    """A position and a rotation: ``transform * local_point -> world point``."""

    def __init__(self, position: Any = (0.0, 0.0), R: Any = None) -> None:
        self.position = b2Vec2(position)
        self.q = b2Rot(0.0)
        if R is not None:
            self.R = R

    @property
    def position(self) -> b2Vec2:
        return self._position

    @position.setter
    def position(self, value: Any) -> None:
        self._position = b2Vec2(*as_xy(value, "b2Transform", "position"))

    @property
    def angle(self) -> float:
        return self.q.angle

    @angle.setter
    def angle(self, value: float) -> None:
        self.q.angle = value

    @property
    def R(self) -> b2Mat22:
        return b2Mat22.from_angle(self.q.angle)

    @R.setter
    def R(self, value: Any) -> None:
        if isinstance(value, (b2Mat22, b2Rot)):
            self.q.angle = value.angle
        else:
            raise ComponentTypeError(f"b2Transform.R must be a b2Mat22 or b2Rot, got {value!r}")

    def Set(self, position: Any, angle: float) -> None:
        self.position = b2Vec2(position)
        self.q.angle = angle

    def SetIdentity(self) -> None:
        self.position = b2Vec2(0.0, 0.0)
        self.q.SetIdentity()

    def __mul__(self, v: Any) -> b2Vec2:
        if type(v) is b2Vec2:
            x, y = v.x, v.y
        else:
            x, y = as_xy(v, "b2Transform", "point")
        q, p = self.q, self._position
        return b2Vec2(q.c * x - q.s * y + p.x, q.s * x + q.c * y + p.y)

    def __repr__(self) -> str:
        return f"b2Transform(position={self.position!r}, angle={self.angle:g})"


def make_transform(x: float, y: float, angle: float) -> b2Transform:
    t = b2Transform.__new__(b2Transform)
    t._position = b2Vec2(x, y)
    q = b2Rot.__new__(b2Rot)
    q.s, q.c = math.sin(angle), math.cos(angle)
    t.q = q
    return t


class b2AABB:
    """An axis-aligned box (``lowerBound``, ``upperBound``)."""

    def __init__(self, lowerBound: Any = (0.0, 0.0), upperBound: Any = (0.0, 0.0)) -> None:
        self.lowerBound = b2Vec2(lowerBound)
        self.upperBound = b2Vec2(upperBound)

    @property
    def valid(self) -> bool:
        lo, hi = self.lowerBound, self.upperBound
        return hi.x >= lo.x and hi.y >= lo.y and lo.valid and hi.valid

    @property
    def center(self) -> b2Vec2:
        return (self.lowerBound + self.upperBound) * 0.5

    @property
    def extents(self) -> b2Vec2:
        return (self.upperBound - self.lowerBound) * 0.5

    @property
    def perimeter(self) -> float:
        d = self.upperBound - self.lowerBound
        return 2.0 * (d.x + d.y)

    def Contains(self, other: b2AABB) -> bool:
        return (
            self.lowerBound.x <= other.lowerBound.x and self.lowerBound.y <= other.lowerBound.y
            and other.upperBound.x <= self.upperBound.x
            and other.upperBound.y <= self.upperBound.y
        )

    def Combine(self, a: b2AABB, b: b2AABB | None = None) -> None:
        if b is None:
            a, b = self, a
        self.lowerBound = b2Vec2(
            min(a.lowerBound.x, b.lowerBound.x), min(a.lowerBound.y, b.lowerBound.y)
        )
        self.upperBound = b2Vec2(
            max(a.upperBound.x, b.upperBound.x), max(a.upperBound.y, b.upperBound.y)
        )

    def __contains__(self, point: Any) -> bool:
        x, y = as_xy(point, "b2AABB", "point")
        lo, hi = self.lowerBound, self.upperBound
        return lo.x <= x <= hi.x and lo.y <= y <= hi.y

    def __repr__(self) -> str:
        return f"b2AABB(lowerBound={self.lowerBound!r}, upperBound={self.upperBound!r})"


class b2Sweep:
    """A body's motion over a step: centres ``c0`` -> ``c``, angles ``a0`` -> ``a``."""

    def __init__(self, a: float = 0.0, a0: float = 0.0, c: Any = (0.0, 0.0),
                 c0: Any = (0.0, 0.0), localCenter: Any = (0.0, 0.0), alpha0: float = 0.0) -> None:
        self.a, self.a0 = float(a), float(a0)
        self.c, self.c0 = b2Vec2(c), b2Vec2(c0)
        self.localCenter = b2Vec2(localCenter)
        self.alpha0 = float(alpha0)

    def GetTransform(self, beta: float) -> b2Transform:
        """The transform at time fraction ``beta`` in [0, 1] (Box2D's b2Sweep::GetTransform)."""
        cx = (1.0 - beta) * self.c0.x + beta * self.c.x
        cy = (1.0 - beta) * self.c0.y + beta * self.c.y
        angle = (1.0 - beta) * self.a0 + beta * self.a
        t = make_transform(cx, cy, angle)
        lc = t.q * self.localCenter
        t.position -= lc
        return t

    def Advance(self, alpha: float) -> None:
        beta = (alpha - self.alpha0) / (1.0 - self.alpha0)
        self.c0 += (self.c - self.c0) * beta
        self.a0 += beta * (self.a - self.a0)
        self.alpha0 = alpha

    def Normalize(self) -> None:
        two_pi = 2.0 * math.pi
        d = two_pi * math.floor(self.a0 / two_pi)
        self.a0 -= d
        self.a -= d
