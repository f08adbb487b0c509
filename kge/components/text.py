"""``Text``: a label in the world (follows its entity) or on the screen (HUD).

* World text (``screen_space=False``) sits at the entity's Transform plus
  ``offset`` metres and scales with the camera zoom; ``size`` is the font size
  in points as seen at zoom 1.
* Screen text (``screen_space=True``) ignores the camera: ``offset`` is its
  position in pixels from the window's bottom-left corner. Scores and timers.

``anchor`` is the point of the text's box placed there, as fractions:
(0, 0) bottom-left, (0.5, 0.5) centre, (1, 1) top-right. The render system
rebuilds the glyphs only when ``value`` or the style changes.

>>> t = Text("Score: 0", size=24, screen_space=True, offset=(10, 500), anchor=(0, 1))
>>> t.value = 10
Traceback (most recent call last):
...
kge.errors.ComponentTypeError: Text.value must be a str, got int 10
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from kge.components.color import Color, rgba
from kge.components.tracked import Check, Tracked
from kge.errors import ComponentTypeError, ValidationError
from kge.validate import Vec2, anchor, boolean, integer, positive, vec2


def _str(value: Any, owner: str, field: str) -> str:
    if not isinstance(value, str):
        raise ComponentTypeError(
            f"{owner}.{field} must be a str, got {type(value).__name__} {value!r}"
        )
    return value


def _font(value: Any, owner: str, field: str) -> str | None:
    return None if value is None else _str(value, owner, field)


def _int(value: Any, owner: str, field: str) -> int:
    return integer(value, owner, field)


#: the largest font size, points: FreeType refuses glyphs much larger (a size of 1e6
#: fails at the first draw with "invalid pixel size")
MAX_FONT_SIZE = 1000.0
#: how far (metres in the world, pixels on the screen) a text may sit from its origin
MAX_OFFSET = 1e9


def font_size(value: Any, owner: str, field: str) -> float:
    """A font size in points, in (0, :data:`MAX_FONT_SIZE`]."""
    v = positive(value, owner, field)
    if v > MAX_FONT_SIZE:
        raise ValidationError(
            f"{owner}.{field} must be in (0, {MAX_FONT_SIZE:g}] points, got {v!r}"
        )
    return v


def _offset(value: Any, owner: str, field: str) -> Vec2:
    x, y = vec2(value, owner, field)
    if abs(x) > MAX_OFFSET or abs(y) > MAX_OFFSET:
        raise ValidationError(f"{owner}.{field} must be within +-{MAX_OFFSET:g}, got {(x, y)!r}")
    return (x, y)


@dataclass(slots=True)
class Text(Tracked):
    """A text label. See the module docstring for world vs screen space."""

    _checks: ClassVar[dict[str, Check]] = {
        "value": _str,
        "size": font_size,
        "color": rgba,
        "bold": boolean,
        "anchor": anchor,
        "screen_space": boolean,
        "offset": _offset,
        "layer": _int,
        "order": _int,
        "visible": boolean,
        "font": _font,
    }

    value: str
    size: float = 16.0
    color: Color = (255, 255, 255, 255)
    anchor: Vec2 = (0.5, 0.5)
    screen_space: bool = False
    bold: bool = False
    offset: Vec2 = (0.0, 0.0)
    layer: int = 0
    order: int = 0
    visible: bool = True
    font: str | None = None
