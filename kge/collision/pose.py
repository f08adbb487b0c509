"""Where a shape is: a pose (x, y, angle) and the rigid transform it stands for.

Every function of :mod:`kge.collision` takes shapes in their body-local
coordinates plus a pose, exactly as Box2D's collision functions take a shape
and a ``b2Transform``: the same frozen :class:`~kge.components.shapes.Box` can
be tested at a thousand places without building a thousand shapes.

A pose may be given as a :class:`Pose`, any ``(x, y, angle)`` triple or a
:class:`~kge.components.transform.Transform`; :func:`pose` turns each into a
validated :class:`Pose` and refuses NaN, infinities and non-numbers at the
call, so no answer is ever computed from a broken pose.

>>> p = pose((1.0, 2.0, math.pi))
>>> p.apply((1.0, 0.0))  # body-local point -> world
(0.0, 2.0...)
>>> p.inverse((0.0, 2.0))  # world point -> body-local
(1.0, ...)
>>> pose((0.0, float("nan"), 0.0))
Traceback (most recent call last):
...
kge.errors.ValidationError: pose.y must be finite, got nan
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from kge.errors import ComponentTypeError, ValidationError
from kge.validate import finite, vec2

Vec2 = tuple[float, float]

#: Largest world coordinate accepted, in metres. Far beyond any game world; past it
#: float64's spacing (0.1 mm at 1e12 m) approaches Box2D's tolerances, and sums of
#: coordinates near float64's limit overflow to infinity and NaN answers.
MAX_COORDINATE = 1e12


@dataclass(slots=True, frozen=True)
class Pose:
    """A rigid transform: rotate by ``angle`` (radians, counter-clockwise), then move by (x, y).

    ``c`` and ``s`` cache the angle's cosine and sine (Box2D's ``b2Rot``), so a
    pose applied to many points computes them once.
    """

    x: float = 0.0
    y: float = 0.0
    angle: float = 0.0
    c: float = 1.0
    s: float = 0.0

    @staticmethod
    def of(x: float, y: float, angle: float) -> Pose:
        """A pose from already validated floats (cosine and sine computed here)."""
        return Pose(x, y, angle, math.cos(angle), math.sin(angle))

    @property
    def position(self) -> Vec2:
        return (self.x, self.y)

    def apply(self, p: Vec2) -> Vec2:
        """Body-local point -> world (Box2D ``b2Mul(xf, v)``)."""
        return (self.c * p[0] - self.s * p[1] + self.x, self.s * p[0] + self.c * p[1] + self.y)

    def rotate(self, v: Vec2) -> Vec2:
        """Body-local direction -> world (rotation only)."""
        return (self.c * v[0] - self.s * v[1], self.s * v[0] + self.c * v[1])

    def inverse(self, p: Vec2) -> Vec2:
        """World point -> body-local (Box2D ``b2MulT(xf, v)``)."""
        dx, dy = p[0] - self.x, p[1] - self.y
        return (self.c * dx + self.s * dy, -self.s * dx + self.c * dy)

    def unrotate(self, v: Vec2) -> Vec2:
        """World direction -> body-local."""
        return (self.c * v[0] + self.s * v[1], -self.s * v[0] + self.c * v[1])


IDENTITY = Pose()


def pose(value: Any, field: str = "pose") -> Pose:
    """A validated :class:`Pose` from a Pose, an (x, y, angle) triple or a Transform.

    ``field`` names the argument in error messages (``pose_a``, ``sweep.c0``...).
    """
    if type(value) is Pose:
        return value
    if isinstance(value, Pose):  # pragma: no cover - Pose is not meant to be subclassed
        value = (value.x, value.y, value.angle)
    elif hasattr(value, "x") and hasattr(value, "y") and hasattr(value, "angle"):
        value = (value.x, value.y, value.angle)  # a kge Transform (or anything alike)
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__"):
        raise ComponentTypeError(
            f"{field} must be a Pose, a Transform or an (x, y, angle) triple, "
            f"got {type(value).__name__} {value!r}"
        )
    if len(value) != 3:
        raise ValidationError(f"{field} must be an (x, y, angle) triple, got {value!r}")
    x = _coordinate(finite(value[0], field, "x"), f"{field}.x")
    y = _coordinate(finite(value[1], field, "y"), f"{field}.y")
    a = finite(value[2], field, "angle")
    return Pose.of(x, y, a)


def point(value: Any, field: str) -> Vec2:
    """A finite (x, y) argument within :data:`MAX_COORDINATE`, named ``field`` in errors."""
    x, y = vec2(value, "", field)
    return (_coordinate(x, f"{field}[0]"), _coordinate(y, f"{field}[1]"))


def _coordinate(v: float, label: str) -> float:
    if -MAX_COORDINATE <= v <= MAX_COORDINATE:
        return v
    raise ValidationError(f"{label} must be within {MAX_COORDINATE:g} m of the origin, got {v!r}")
