"""Shape drawables: ``Rect``, ``Circle``, ``Triangle``, ``Polygon`` and ``Line``.

Flat-coloured shapes for prototypes, UI blocks and effects, drawn without any
image. Everything is in **world units** (metres) in the entity's local frame:
the entity's Transform moves and rotates the shape, ``offset`` shifts it
within that frame. ``filled=False`` draws an outline ``thickness`` metres wide.
Colours are RGBA 0-255; an RGB tuple means opaque.

These are visual only; physics shapes live in :mod:`kge.components.shapes`
(``Rect`` here takes full width/height, a physics ``Box`` takes half extents,
as Box2D does).

>>> Rect(2.0, 1.0, color=(255, 0, 0)).color
(255, 0, 0, 255)
>>> Circle(-1.0)
Traceback (most recent call last):
...
kge.errors.ValidationError: Circle.radius must be > 0, got -1.0
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import KW_ONLY, dataclass
from typing import Any, ClassVar

from kge.components.blend import Blend
from kge.components.color import RGBA, Color, rgba
from kge.components.tracked import Check, Tracked
from kge.errors import ComponentTypeError, ValidationError
from kge.validate import Vec2, boolean, choice, extent, integer, point

_WHITE: RGBA = (255, 255, 255, 255)


def _int(value: Any, owner: str, field: str) -> int:
    return integer(value, owner, field)


def _points(value: Any, owner: str, field: str) -> tuple[Vec2, ...]:
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__"):
        raise ComponentTypeError(f"{owner}.{field} must be a sequence of (x, y) points")
    pts = tuple(point(p, owner, f"{field}[{i}]") for i, p in enumerate(value))
    if len(pts) < 3:
        raise ValidationError(f"{owner}.{field} needs at least 3 points, got {len(pts)}")
    area2 = sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(pts, pts[1:] + pts[:1], strict=True))
    if abs(area2) < 1e-12:
        raise ValidationError(f"{owner}.{field} encloses no area: {pts!r}")
    return pts


def _segments(value: Any, owner: str, field: str) -> int | None:
    if value is None:
        return None
    n = integer(value, owner, field)
    if not 3 <= n <= 1024:
        raise ValidationError(f"{owner}.{field} must be in 3..1024, got {n}")
    return n


_COMMON: dict[str, Check] = {
    "color": rgba,
    "filled": boolean,
    "thickness": extent,
    "offset": point,
    "layer": _int,
    "order": _int,
    "visible": boolean,
    "blend": choice(Blend),
}


@dataclass(slots=True)
class _Drawn(Tracked):
    """Style every drawable shares; keyword-only, after each shape's own geometry."""

    _: KW_ONLY
    color: Color = _WHITE
    thickness: float = 0.05
    offset: Vec2 = (0.0, 0.0)
    layer: int = 0
    order: int = 0
    visible: bool = True
    #: how it is drawn over what is behind (:class:`~kge.components.blend.Blend`)
    blend: Blend = Blend.ALPHA


@dataclass(slots=True)
class _Fillable(_Drawn):
    _: KW_ONLY
    filled: bool = True


@dataclass(slots=True)
class Rect(_Fillable):
    """An axis-aligned (in the entity frame) rectangle, ``width`` x ``height`` metres, centred."""

    _checks: ClassVar[dict[str, Check]] = {**_COMMON, "width": extent, "height": extent}

    width: float
    height: float


@dataclass(slots=True)
class Circle(_Fillable):
    """A disc (or ring) of ``radius`` metres; ``segments=None`` picks a smooth count."""

    _checks: ClassVar[dict[str, Check]] = {**_COMMON, "radius": extent, "segments": _segments}

    radius: float
    _: KW_ONLY
    segments: int | None = None


@dataclass(slots=True)
class Triangle(_Fillable):
    """A triangle with corners ``a``, ``b``, ``c`` in the entity frame (any winding)."""

    _checks: ClassVar[dict[str, Check]] = {**_COMMON, "a": point, "b": point, "c": point}

    a: Vec2
    b: Vec2
    c: Vec2

    def __post_init__(self) -> None:
        _points((self.a, self.b, self.c), "Triangle", "corners")


@dataclass(slots=True)
class Polygon(_Fillable):
    """A simple polygon (convex or not, any winding) from ``vertices`` in the entity frame."""

    _checks: ClassVar[dict[str, Check]] = {**_COMMON, "vertices": _points}

    vertices: Sequence[Vec2]  # any sequence in; stored as a tuple


@dataclass(slots=True)
class Line(_Drawn):
    """A segment from ``start`` to ``end`` (entity frame), ``thickness`` metres wide."""

    _checks: ClassVar[dict[str, Check]] = {**_COMMON, "start": point, "end": point}

    start: Vec2
    end: Vec2

    @property
    def filled(self) -> bool:
        """A line is always drawn as a solid strip."""
        return True


Drawable = Rect | Circle | Triangle | Polygon | Line
DRAWABLE_TYPES: tuple[type, ...] = (Rect, Circle, Triangle, Polygon, Line)
