"""``b2Mat22`` and ``b2Mat33``: Box2D's small matrices, by columns, with pybox2d's arithmetic.

pybox2d builds a 2x2 matrix from two columns or from four numbers row by row,
and a 3x3 one from three columns; ``+``, ``-``, ``+=``, ``-=`` work element by
element and ``*`` multiplies a vector or (2x2) another matrix.

>>> m = b2Mat22(1, 2, 3, 4)          # a11, a12, a21, a22
>>> m.col1, m.col2, m * (1, 0)
(b2Vec2(1,3), b2Vec2(2,4), b2Vec2(1,3))
>>> (m + m).col2, (m * m).col1
(b2Vec2(4,8), b2Vec2(7,15))
>>> b2Mat33((1, 2, 3), (0, 1, 4), (5, 6, 0)) * (1, 1, 1)
b2Vec3(6,9,7)
"""

from __future__ import annotations

import math
from typing import Any

from kge.box2d.vec import as_xy, as_xyz, b2Vec2, b2Vec3
from kge.errors import ComponentTypeError


class b2Mat22:
    """A 2x2 matrix by columns (``col1``, ``col2``; Box2D 2.3 calls them ``ex``, ``ey``)."""

    def __init__(self, *args: Any) -> None:
        if not args:
            self.col1, self.col2 = b2Vec2(1.0, 0.0), b2Vec2(0.0, 1.0)
        elif len(args) == 2:
            self.col1, self.col2 = b2Vec2(args[0]), b2Vec2(args[1])
        elif len(args) == 4:  # row by row, as Box2D's b2Mat22(a11, a12, a21, a22)
            a11, a12, a21, a22 = args
            self.col1, self.col2 = b2Vec2(a11, a21), b2Vec2(a12, a22)
        else:
            raise ComponentTypeError(
                f"b2Mat22 takes no arguments, two columns or four numbers, got {args!r}")

    @classmethod
    def from_angle(cls, angle: float) -> b2Mat22:
        c, s = math.cos(angle), math.sin(angle)
        return cls((c, s), (-s, c))

    @property
    def ex(self) -> b2Vec2:
        return self.col1

    @ex.setter
    def ex(self, value: Any) -> None:
        self.col1 = b2Vec2(value)

    @property
    def ey(self) -> b2Vec2:
        return self.col2

    @ey.setter
    def ey(self, value: Any) -> None:
        self.col2 = b2Vec2(value)

    x_axis = property(lambda self: self.col1.copy())
    y_axis = property(lambda self: self.col2.copy())

    @property
    def angle(self) -> float:
        return math.atan2(self.col1.y, self.col1.x)

    @angle.setter
    def angle(self, value: float) -> None:
        """Make this the rotation by ``value`` radians (Box2D's b2Mat22::Set(angle))."""
        other = b2Mat22.from_angle(value)
        self.col1, self.col2 = other.col1, other.col2

    def set(self, col1: Any, col2: Any) -> None:
        self.col1, self.col2 = b2Vec2(col1), b2Vec2(col2)

    def SetIdentity(self) -> None:
        self.col1, self.col2 = b2Vec2(1, 0), b2Vec2(0, 1)

    def SetZero(self) -> None:
        self.col1, self.col2 = b2Vec2(0, 0), b2Vec2(0, 0)

    @property
    def inverse(self) -> b2Mat22:
        a, b, c, d = self.col1.x, self.col2.x, self.col1.y, self.col2.y
        det = a * d - b * c
        if det != 0.0:
            det = 1.0 / det
        return b2Mat22((det * d, -det * c), (-det * b, det * a))

    def GetInverse(self) -> b2Mat22:
        return self.inverse

    def Solve(self, b: Any) -> b2Vec2:
        """``x`` with ``A x = b`` (Box2D's: a singular matrix gives 0)."""
        bx, by = as_xy(b, "b2Mat22.Solve", "b")
        a11, a12, a21, a22 = self.col1.x, self.col2.x, self.col1.y, self.col2.y
        det = a11 * a22 - a12 * a21
        if det != 0.0:
            det = 1.0 / det
        return b2Vec2(det * (a22 * bx - a12 * by), det * (a11 * by - a21 * bx))

    def __add__(self, other: b2Mat22) -> b2Mat22:
        return b2Mat22(self.col1 + other.col1, self.col2 + other.col2)

    def __sub__(self, other: b2Mat22) -> b2Mat22:
        return b2Mat22(self.col1 - other.col1, self.col2 - other.col2)

    def __iadd__(self, other: b2Mat22) -> b2Mat22:
        self.col1, self.col2 = self.col1 + other.col1, self.col2 + other.col2
        return self

    def __isub__(self, other: b2Mat22) -> b2Mat22:
        self.col1, self.col2 = self.col1 - other.col1, self.col2 - other.col2
        return self

    def __mul__(self, v: Any) -> Any:
        if isinstance(v, b2Mat22):
            return b2Mat22(self * v.col1, self * v.col2)
        x, y = as_xy(v, "b2Mat22", "vector")
        return b2Vec2(self.col1.x * x + self.col2.x * y, self.col1.y * x + self.col2.y * y)

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, b2Mat22):
            return NotImplemented
        return self.col1 == other.col1 and self.col2 == other.col2

    __hash__ = None  # type: ignore[assignment]  # mutable

    def __repr__(self) -> str:
        return f"b2Mat22(col1={self.col1!r}, col2={self.col2!r})"


class b2Mat33:
    """A 3x3 matrix by columns (``col1``, ``col2``, ``col3``; ``ex``, ``ey``, ``ez``)."""

    def __init__(self, col1: Any = (1.0, 0.0, 0.0), col2: Any = (0.0, 1.0, 0.0),
                 col3: Any = (0.0, 0.0, 1.0)) -> None:
        self.col1, self.col2, self.col3 = b2Vec3(col1), b2Vec3(col2), b2Vec3(col3)

    ex = property(lambda self: self.col1, lambda self, v: setattr(self, "col1", b2Vec3(v)))
    ey = property(lambda self: self.col2, lambda self, v: setattr(self, "col2", b2Vec3(v)))
    ez = property(lambda self: self.col3, lambda self, v: setattr(self, "col3", b2Vec3(v)))

    def SetZero(self) -> None:
        self.col1, self.col2, self.col3 = b2Vec3(), b2Vec3(), b2Vec3()

    def Solve33(self, b: Any) -> b2Vec3:
        """``x`` with ``A x = b`` by Cramer's rule (a singular matrix gives 0)."""
        bv = b2Vec3(*as_xyz(b, "b2Mat33.Solve33", "b"))
        ex, ey, ez = self.col1, self.col2, self.col3
        det = ex.dot(ey.cross(ez))
        if det != 0.0:
            det = 1.0 / det
        return b2Vec3(det * bv.dot(ey.cross(ez)), det * ex.dot(bv.cross(ez)),
                      det * ex.dot(ey.cross(bv)))

    def Solve22(self, b: Any) -> b2Vec2:
        """Solve with the upper-left 2x2 block only."""
        return b2Mat22((self.col1.x, self.col1.y), (self.col2.x, self.col2.y)).Solve(b)

    def GetInverse22(self, M: b2Mat33) -> None:
        """Write the inverse of the upper-left 2x2 block into ``M`` (the rest zero)."""
        inv = b2Mat22((self.col1.x, self.col1.y), (self.col2.x, self.col2.y)).inverse
        M.col1 = b2Vec3(inv.col1.x, inv.col1.y, 0.0)
        M.col2 = b2Vec3(inv.col2.x, inv.col2.y, 0.0)
        M.col3 = b2Vec3(0.0, 0.0, 0.0)

    def GetSymInverse33(self, M: b2Mat33) -> None:
        """Write the inverse of this symmetric matrix into ``M`` (zero when singular)."""
        ex, ey, ez = self.col1, self.col2, self.col3
        det = ex.dot(ey.cross(ez))
        if det != 0.0:
            det = 1.0 / det
        a11, a12, a13 = ex.x, ey.x, ez.x
        a22, a23, a33 = ey.y, ez.y, ez.z
        m12 = det * (a13 * a23 - a12 * a33)
        m13 = det * (a12 * a23 - a13 * a22)
        m23 = det * (a13 * a12 - a11 * a23)
        M.col1 = b2Vec3(det * (a22 * a33 - a23 * a23), m12, m13)
        M.col2 = b2Vec3(m12, det * (a11 * a33 - a13 * a13), m23)
        M.col3 = b2Vec3(m13, m23, det * (a11 * a22 - a12 * a12))

    def __add__(self, other: b2Mat33) -> b2Mat33:
        return b2Mat33(self.col1 + other.col1, self.col2 + other.col2, self.col3 + other.col3)

    def __sub__(self, other: b2Mat33) -> b2Mat33:
        return b2Mat33(self.col1 - other.col1, self.col2 - other.col2, self.col3 - other.col3)

    def __iadd__(self, other: b2Mat33) -> b2Mat33:
        self.col1, self.col2, self.col3 = (self + other).columns
        return self

    def __isub__(self, other: b2Mat33) -> b2Mat33:
        self.col1, self.col2, self.col3 = (self - other).columns
        return self

    @property
    def columns(self) -> tuple[b2Vec3, b2Vec3, b2Vec3]:
        return self.col1, self.col2, self.col3

    def __mul__(self, v: Any) -> b2Vec3:
        x, y, z = as_xyz(v, "b2Mat33", "vector")
        return self.col1 * x + self.col2 * y + self.col3 * z

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, b2Mat33):
            return NotImplemented
        return self.columns == other.columns

    __hash__ = None  # type: ignore[assignment]  # mutable

    def __repr__(self) -> str:
        return f"b2Mat33(col1={self.col1!r}, col2={self.col2!r}, col3={self.col3!r})"
