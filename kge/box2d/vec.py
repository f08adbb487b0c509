"""``b2Vec2``: pybox2d's mutable 2D vector, with its arithmetic and methods.

pybox2d programs treat vectors and tuples interchangeably: they index them,
unpack them, compare them with tuples and pass tuples wherever a vector goes.
``b2Vec2`` does all of that; :func:`as_xy` is the one place where a
user-given vector or pair becomes two checked floats.

>>> v = b2Vec2(3, 4)
>>> v.length, v * 2, -v, v == (3, 4)
(5.0, b2Vec2(6,8), b2Vec2(-3,-4), True)
>>> x, y = v
>>> v.Normalize(), v
(5.0, b2Vec2(0.6,0.8))
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import Any

from kge.errors import ComponentTypeError, ValidationError


def as_xy(value: Any, owner: str = "b2Vec2", field: str = "value") -> tuple[float, float]:
    """Two finite floats from a ``b2Vec2`` or any 2-sequence of numbers (else a kge error)."""
    if type(value) is b2Vec2:
        return value.x, value.y
    try:
        x, y = value
        fx, fy = float(x), float(y)
    except (TypeError, ValueError):
        raise ComponentTypeError(
            f"{owner}.{field} must be a 2D vector (b2Vec2 or a pair of numbers), got {value!r}"
        ) from None
    if not (math.isfinite(fx) and math.isfinite(fy)):
        raise ValidationError(f"{owner}.{field} must be finite, got {value!r}")
    return fx, fy


def _fmt(v: float) -> str:
    return f"{v:g}"


class b2Vec2:
    """A 2D column vector (metres, newtons, ...)."""

    __slots__ = ("x", "y")

    def __init__(self, x: Any = None, y: float | None = None) -> None:
        if x is None and y is None:
            self.x = self.y = 0.0
        elif y is None:
            if isinstance(x, (int, float)):
                raise ComponentTypeError(f"b2Vec2 needs two components, got {x!r}")
            self.x, self.y = as_xy(x)
        else:
            self.x = float(x)
            self.y = float(y)

    # -- sequence protocol ---------------------------------------------------------------
    def __len__(self) -> int:
        return 2

    def __iter__(self) -> Iterator[float]:
        return iter((self.x, self.y))

    def __getitem__(self, i: int) -> float:
        if i == 0 or i == -2:
            return self.x
        if i == 1 or i == -1:
            return self.y
        raise IndexError(f"b2Vec2 index {i} out of range")

    def __setitem__(self, i: int, value: float) -> None:
        if i in (0, -2):
            self.x = float(value)
        elif i in (1, -1):
            self.y = float(value)
        else:
            raise IndexError(f"b2Vec2 index {i} out of range")

    @property
    def tuple(self) -> tuple[float, float]:
        return (self.x, self.y)

    @tuple.setter
    def tuple(self, value: Any) -> None:
        self.x, self.y = as_xy(value)

    def __repr__(self) -> str:
        return f"b2Vec2({_fmt(self.x)},{_fmt(self.y)})"

    def __eq__(self, other: object) -> bool:
        seq: Any = other
        try:
            ox, oy = seq
        except (TypeError, ValueError):
            return NotImplemented
        return bool(self.x == ox and self.y == oy)

    def __ne__(self, other: object) -> bool:
        eq = self.__eq__(other)
        return eq if eq is NotImplemented else not eq

    __hash__ = None  # type: ignore[assignment]  # mutable, like pybox2d's

    # -- arithmetic -------------------------------------------------------------------------
    def __add__(self, other: Any) -> b2Vec2:
        ox, oy = other
        return b2Vec2(self.x + ox, self.y + oy)

    __radd__ = __add__

    def __sub__(self, other: Any) -> b2Vec2:
        ox, oy = other
        return b2Vec2(self.x - ox, self.y - oy)

    def __rsub__(self, other: Any) -> b2Vec2:
        ox, oy = other
        return b2Vec2(ox - self.x, oy - self.y)

    def __mul__(self, k: float) -> b2Vec2:
        return b2Vec2(self.x * k, self.y * k)

    __rmul__ = __mul__

    def __truediv__(self, k: float) -> b2Vec2:
        return b2Vec2(self.x / k, self.y / k)

    def __neg__(self) -> b2Vec2:
        return b2Vec2(-self.x, -self.y)

    def __pos__(self) -> b2Vec2:
        return b2Vec2(self.x, self.y)

    def __abs__(self) -> b2Vec2:
        return b2Vec2(abs(self.x), abs(self.y))

    def __iadd__(self, other: Any) -> b2Vec2:
        ox, oy = other
        self.x += ox
        self.y += oy
        return self

    def __isub__(self, other: Any) -> b2Vec2:
        ox, oy = other
        self.x -= ox
        self.y -= oy
        return self

    def __imul__(self, k: float) -> b2Vec2:
        self.x *= k
        self.y *= k
        return self

    def __itruediv__(self, k: float) -> b2Vec2:
        self.x /= k
        self.y /= k
        return self

    # -- methods ------------------------------------------------------------------------------
    def copy(self) -> b2Vec2:
        return b2Vec2(self.x, self.y)

    def Set(self, x: float, y: float) -> None:
        self.x, self.y = float(x), float(y)

    def SetZero(self) -> None:
        self.x = self.y = 0.0

    def dot(self, other: Any) -> float:
        ox, oy = other
        return float(self.x * ox + self.y * oy)

    def cross(self, other: Any) -> Any:
        """Vector x vector -> scalar; vector x scalar -> vector (Box2D's b2Cross)."""
        if isinstance(other, (int, float)):
            return b2Vec2(other * self.y, -other * self.x)
        ox, oy = other
        return float(self.x * oy - self.y * ox)

    @property
    def length(self) -> float:
        return math.hypot(self.x, self.y)

    @property
    def lengthSquared(self) -> float:
        return self.x * self.x + self.y * self.y

    def Normalize(self) -> float:
        """Make this a unit vector; return the old length (0 leaves it unchanged)."""
        n = math.hypot(self.x, self.y)
        if n < 1.1920929e-07:
            return 0.0
        self.x /= n
        self.y /= n
        return n

    @property
    def skew(self) -> b2Vec2:
        return b2Vec2(-self.y, self.x)

    @property
    def valid(self) -> bool:
        return math.isfinite(self.x) and math.isfinite(self.y)


def vec(value: Any, owner: str = "b2Vec2", field: str = "value") -> b2Vec2:
    """A new ``b2Vec2`` from any vector-like value (checked)."""
    x, y = as_xy(value, owner, field)
    return b2Vec2(x, y)


def as_xyz(value: Any, owner: str = "b2Vec3", field: str = "value") -> tuple[float, float, float]:
    """Three finite floats from a ``b2Vec3`` or any 3-sequence of numbers (else a kge error)."""
    if type(value) is b2Vec3:
        return value.x, value.y, value.z
    try:
        x, y, z = value
        out = (float(x), float(y), float(z))
    except (TypeError, ValueError):
        raise ComponentTypeError(
            f"{owner}.{field} must be a 3D vector (b2Vec3 or three numbers), got {value!r}"
        ) from None
    if not all(math.isfinite(v) for v in out):
        raise ValidationError(f"{owner}.{field} must be finite, got {value!r}")
    return out


class b2Vec3:
    """A 3D column vector (Box2D's solver uses it for 3x3 blocks: x, y and an angle).

    >>> v = b2Vec3(1, 2, 3)
    >>> v + v, v.cross((0, 0, 1)), v.dot((1, 1, 1))
    (b2Vec3(2,4,6), b2Vec3(2,-1,0), 6.0)
    """

    __slots__ = ("x", "y", "z")

    def __init__(self, x: Any = None, y: float | None = None, z: float | None = None) -> None:
        if x is None and y is None and z is None:
            self.x = self.y = self.z = 0.0
        elif y is None and z is None:
            self.x, self.y, self.z = as_xyz(x)
        else:
            self.x, self.y, self.z = as_xyz((x, y, z))

    def __len__(self) -> int:
        return 3

    def __iter__(self) -> Iterator[float]:
        return iter((self.x, self.y, self.z))

    def __getitem__(self, i: int) -> float:
        return (self.x, self.y, self.z)[i]

    def __setitem__(self, i: int, value: float) -> None:
        name = ("x", "y", "z")[i]
        setattr(self, name, float(value))

    @property
    def tuple(self) -> tuple[float, float, float]:
        return (self.x, self.y, self.z)

    @tuple.setter
    def tuple(self, value: Any) -> None:
        self.x, self.y, self.z = as_xyz(value)

    def __repr__(self) -> str:
        return f"b2Vec3({_fmt(self.x)},{_fmt(self.y)},{_fmt(self.z)})"

    def __eq__(self, other: object) -> bool:
        seq: Any = other
        try:
            ox, oy, oz = seq
        except (TypeError, ValueError):
            return NotImplemented
        return bool(self.x == ox and self.y == oy and self.z == oz)

    __hash__ = None  # type: ignore[assignment]  # mutable, like pybox2d's

    def __add__(self, other: Any) -> b2Vec3:
        ox, oy, oz = other
        return b2Vec3(self.x + ox, self.y + oy, self.z + oz)

    __radd__ = __add__

    def __sub__(self, other: Any) -> b2Vec3:
        ox, oy, oz = other
        return b2Vec3(self.x - ox, self.y - oy, self.z - oz)

    def __rsub__(self, other: Any) -> b2Vec3:
        ox, oy, oz = other
        return b2Vec3(ox - self.x, oy - self.y, oz - self.z)

    def __mul__(self, k: float) -> b2Vec3:
        return b2Vec3(self.x * k, self.y * k, self.z * k)

    __rmul__ = __mul__

    def __truediv__(self, k: float) -> b2Vec3:
        return b2Vec3(self.x / k, self.y / k, self.z / k)

    def __neg__(self) -> b2Vec3:
        return b2Vec3(-self.x, -self.y, -self.z)

    def __iadd__(self, other: Any) -> b2Vec3:
        self.x, self.y, self.z = (self + other).tuple
        return self

    def __isub__(self, other: Any) -> b2Vec3:
        self.x, self.y, self.z = (self - other).tuple
        return self

    def __imul__(self, k: float) -> b2Vec3:
        self.x, self.y, self.z = self.x * k, self.y * k, self.z * k
        return self

    def __itruediv__(self, k: float) -> b2Vec3:
        self.x, self.y, self.z = self.x / k, self.y / k, self.z / k
        return self

    def copy(self) -> b2Vec3:
        return b2Vec3(self.x, self.y, self.z)

    def Set(self, x: float, y: float, z: float) -> None:
        self.x, self.y, self.z = as_xyz((x, y, z))

    def SetZero(self) -> None:
        self.x = self.y = self.z = 0.0

    def dot(self, other: Any) -> float:
        ox, oy, oz = other
        return float(self.x * ox + self.y * oy + self.z * oz)

    def cross(self, other: Any) -> b2Vec3:
        ox, oy, oz = other
        return b2Vec3(self.y * oz - self.z * oy, self.z * ox - self.x * oz,
                      self.x * oy - self.y * ox)

    @property
    def length(self) -> float:
        return math.sqrt(self.lengthSquared)

    @property
    def lengthSquared(self) -> float:
        return self.x * self.x + self.y * self.y + self.z * self.z

    @property
    def valid(self) -> bool:
        return all(math.isfinite(v) for v in (self.x, self.y, self.z))
