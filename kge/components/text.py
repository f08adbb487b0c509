"""``Text`` (a label in the world or on the screen) and ``TextStyle`` (how text looks).

* World text (``screen_space=False``) sits at the entity's Transform plus
  ``offset`` metres and turns and scales with it and with the camera; ``size`` is
  the font size in points as seen at zoom 1, and the glyphs are re-rasterised at
  the size they cover on screen, so zoomed text stays crisp.
* Screen text (``screen_space=True``) ignores the camera: ``offset`` is its
  position in pixels from the window's (or design resolution's) bottom-left
  corner. Scores, timers, HUD.

``anchor`` is the point of the text's *box* placed at that position, as fractions:
(0, 0) bottom-left, (0.5, 0.5) centre, (1, 1) top-right. ``align`` is where each
line sits inside the box (:class:`TextAlign`: ``LEFT``, ``CENTER``, ``RIGHT``,
``JUSTIFY``), ``valign`` where the block of lines sits (:class:`VerticalAlign`).
The box is ``width`` x ``height`` when given (metres for world text, pixels for
screen text), else the size of the text. ``width`` wraps lines; ``overflow`` says
what happens to text that does not fit ``height`` / ``max_lines``
(:class:`TextOverflow`: ``VISIBLE``, ``CLIP``, ``ELLIPSIS`` or ``SHRINK``, the font
shrinking until it fits).

:class:`TextStyle` is the same set of looks without the placement, for UI labels and
:func:`kge.render.text.measure`. Everything is validated at the call: a font size
of 1e6 or a negative outline raise a ``ValidationError`` naming the field.

>>> t = Text("Score: 0", size=24, screen_space=True, offset=(10, 500), anchor=(0, 1))
>>> t.text = 10
Traceback (most recent call last):
...
kge.errors.ComponentTypeError: Text.text must be a str, got int 10
>>> Text("big", size=1e6)
Traceback (most recent call last):
...
kge.errors.ValidationError: Text.size must be in (0, 1000] points, got 1000000.0
>>> TextStyle(weight="light").weight, TextStyle(weight=650).weight
(300, 650)
>>> Text("hi", bold=True).style().weight
700
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, fields
from enum import StrEnum
from typing import Any, ClassVar

from kge.components.color import RGBA, Color, rgba
from kge.components.tracked import Check, Tracked
from kge.errors import ComponentTypeError, ValidationError
from kge.validate import Vec2, anchor, boolean, choice, finite, integer, vec2

#: the largest font size, points (FreeType fails on a glyph millions of pixels tall)
MAX_FONT_SIZE = 1000.0
#: the largest text box side, in the text's units (pixels or font pixels)
MAX_BOX = 1e6



class TextAlign(StrEnum):
    """Where each line sits inside the text's box."""

    LEFT = "left"
    CENTER = "center"
    RIGHT = "right"
    JUSTIFY = "justify"  #: spread to the box's width (a paragraph's last line: left)


class VerticalAlign(StrEnum):
    """Where the block of lines sits inside a box taller than the text."""

    TOP = "top"
    CENTER = "center"
    BOTTOM = "bottom"


class TextOverflow(StrEnum):
    """What becomes of text that does not fit its box's height or ``max_lines``."""

    VISIBLE = "visible"  #: drawn past the box
    CLIP = "clip"  #: cut at the box
    ELLIPSIS = "ellipsis"  #: the last line that fits ends with an ellipsis
    SHRINK = "shrink"  #: the size goes down until everything fits
#: CSS / OpenType weight names
WEIGHTS = {
    "thin": 100, "extralight": 200, "ultralight": 200, "light": 300, "semilight": 350,
    "normal": 400, "regular": 400, "book": 400, "medium": 500, "semibold": 600,
    "demibold": 600, "bold": 700, "extrabold": 800, "ultrabold": 800, "black": 900,
    "heavy": 900,
}  # fmt: skip
BOLD = 700


def _str(value: Any, owner: str, field: str) -> str:
    if not isinstance(value, str):
        raise ComponentTypeError(
            f"{owner}.{field} must be a str, got {type(value).__name__} {value!r}"
        )
    return value


def _font(value: Any, owner: str, field: str) -> str | None:
    if value is None:
        return None
    name = _str(value, owner, field)
    if not name.strip():
        raise ValidationError(f"{owner}.{field} must be a font family, file or None, got ''")
    return name


def font_points(value: Any, owner: str, field: str) -> float:
    """A font size in points, in (0, :data:`MAX_FONT_SIZE`]."""
    v = finite(value, owner, field)
    if not 0.0 < v <= MAX_FONT_SIZE:
        raise ValidationError(
            f"{owner}.{field} must be in (0, {MAX_FONT_SIZE:g}] points, got {v!r}"
        )
    return v


def _weight(value: Any, owner: str, field: str) -> int:
    if isinstance(value, str):
        w = WEIGHTS.get(value.lower().replace("-", "").replace(" ", ""))
        if w is None:
            raise ValidationError(
                f"{owner}.{field}: unknown weight {value!r}; use 100..900 or one of "
                f"{', '.join(sorted(WEIGHTS))}"
            )
        return w
    w = integer(value, owner, field)
    if not 1 <= w <= 1000:
        raise ValidationError(f"{owner}.{field} must be in 1..1000, got {w}")
    return w


def _box(value: Any, owner: str, field: str) -> float | None:
    if value is None:
        return None
    v = finite(value, owner, field)
    if not 0.0 < v <= MAX_BOX:
        raise ValidationError(f"{owner}.{field} must be None or in (0, {MAX_BOX:g}], got {v!r}")
    return v


def _spacing(value: Any, owner: str, field: str) -> float:
    v = finite(value, owner, field)
    if not 0.1 <= v <= 10.0:
        raise ValidationError(f"{owner}.{field} must be in [0.1, 10] (line heights), got {v!r}")
    return v


def _letter_spacing(value: Any, owner: str, field: str) -> float:
    v = finite(value, owner, field)
    if not -100.0 <= v <= 1000.0:
        raise ValidationError(f"{owner}.{field} must be in [-100, 1000] pixels, got {v!r}")
    return v


def _effect_px(value: Any, owner: str, field: str) -> float:
    v = finite(value, owner, field)
    if not 0.0 <= v <= 64.0:
        raise ValidationError(f"{owner}.{field} must be in [0, 64] pixels, got {v!r}")
    return v


def _max_lines(value: Any, owner: str, field: str) -> int | None:
    if value is None:
        return None
    n = integer(value, owner, field)
    if n < 1:
        raise ValidationError(f"{owner}.{field} must be None or >= 1, got {n}")
    return n


def _shadow(value: Any, owner: str, field: str) -> Vec2 | None:
    if value is None:
        return None
    dx, dy = vec2(value, owner, field)
    if max(abs(dx), abs(dy)) > 64.0:
        raise ValidationError(f"{owner}.{field} offset must be within 64 pixels, got {value!r}")
    return (dx, dy)


def _int(value: Any, owner: str, field: str) -> int:
    return integer(value, owner, field)


#: how far (metres in the world, pixels on the screen) a text may sit from its origin
MAX_OFFSET = 1e9


def _offset(value: Any, owner: str, field: str) -> Vec2:
    x, y = vec2(value, owner, field)
    if abs(x) > MAX_OFFSET or abs(y) > MAX_OFFSET:
        raise ValidationError(f"{owner}.{field} must be within +-{MAX_OFFSET:g}, got {(x, y)!r}")
    return (x, y)


def _opacity(value: Any, owner: str, field: str) -> int:
    v = integer(value, owner, field)
    if not 0 <= v <= 255:
        raise ValidationError(f"{owner}.{field} must be an int in 0..255, got {v}")
    return v


#: checks of the looks shared by Text and TextStyle (one table, one meaning per name)
STYLE_CHECKS: dict[str, Check] = {
    "size": font_points,
    "color": rgba,
    "font": _font,
    "weight": _weight,
    "italic": boolean,
    "align": choice(TextAlign),
    "valign": choice(VerticalAlign),
    "width": _box,
    "height": _box,
    "wrap": boolean,
    "line_spacing": _spacing,
    "letter_spacing": _letter_spacing,
    "overflow": choice(TextOverflow),
    "max_lines": _max_lines,
    "outline": _effect_px,
    "outline_color": rgba,
    "shadow": _shadow,
    "shadow_color": rgba,
    "shadow_blur": _effect_px,
    "markup": boolean,
}

_BLACK: RGBA = (0, 0, 0, 255)
_WHITE: RGBA = (255, 255, 255, 255)
_SHADE: RGBA = (0, 0, 0, 160)


@dataclass(slots=True, frozen=True)
class TextStyle:
    """How text is drawn and laid out; one value shared by many labels.

    Sizes are in the text's own pixels (screen pixels for HUD and UI text, font
    pixels at zoom 1 for world text): ``width``/``height`` the box, ``outline``
    its thickness, ``shadow`` its offset (x right, y up), ``shadow_blur`` its blur
    radius. ``size`` is in points (a pixel is 3/4 of a point, as in CSS).
    ``markup=True`` reads ``[b]``, ``[i]``, ``[color=#f80]``, ``[size=20]``,
    ``[font=...]``, ``[weight=light]`` and ``[img]icon.png[/img]`` tags
    (:mod:`kge.text.markup`).
    """

    size: float = 16.0
    color: Color = _WHITE
    font: str | None = None
    weight: int | str = 400
    italic: bool = False
    align: TextAlign = TextAlign.LEFT
    valign: VerticalAlign = VerticalAlign.TOP
    width: float | None = None
    height: float | None = None
    wrap: bool = True
    line_spacing: float = 1.0
    letter_spacing: float = 0.0
    overflow: TextOverflow = TextOverflow.VISIBLE
    max_lines: int | None = None
    outline: float = 0.0
    outline_color: Color = _BLACK
    shadow: Vec2 | None = None
    shadow_color: Color = _SHADE
    shadow_blur: float = 0.0
    markup: bool = False

    def __post_init__(self) -> None:
        for f in fields(self):
            value = STYLE_CHECKS[f.name](getattr(self, f.name), "TextStyle", f.name)
            object.__setattr__(self, f.name, value)

    @property
    def pixel_size(self) -> float:
        """The font size in pixels (points x 4/3)."""
        return self.size * 4.0 / 3.0

    @property
    def padding(self) -> int:
        """Pixels around the box that outline, shadow and blur may cover."""
        dx, dy = self.shadow if self.shadow is not None else (0.0, 0.0)
        reach = self.outline + max(abs(dx), abs(dy)) + 2.0 * self.shadow_blur
        return math.ceil(reach) + 1 if reach > 0 else 0

    def replace(self, **changes: Any) -> TextStyle:
        """A copy with some fields changed (validated like the constructor)."""
        values = {f.name: getattr(self, f.name) for f in fields(self)}
        values.update(changes)
        return TextStyle(**values)


STYLE_FIELDS: tuple[str, ...] = tuple(f.name for f in fields(TextStyle))


@dataclass(slots=True)
class Text(Tracked):
    """A text label. See the module docstring for world vs screen space and the box."""

    #: markup and font are checked by the render plugin at every write (the world's assets)
    _world_fields: ClassVar[frozenset[str]] = frozenset({"text", "font", "markup"})

    _checks: ClassVar[dict[str, Check]] = {
        **STYLE_CHECKS,
        "text": _str,
        "bold": boolean,
        "anchor": anchor,
        "screen_space": boolean,
        "offset": _offset,
        "layer": _int,
        "order": _int,
        "visible": boolean,
        "opacity": _opacity,
    }

    text: str
    size: float = 16.0
    color: Color = _WHITE
    anchor: Vec2 = (0.5, 0.5)
    screen_space: bool = False
    bold: bool = False
    offset: Vec2 = (0.0, 0.0)
    layer: int = 0
    order: int = 0
    visible: bool = True
    font: str | None = None
    weight: int | str = 400
    italic: bool = False
    align: TextAlign = TextAlign.LEFT
    valign: VerticalAlign = VerticalAlign.TOP
    width: float | None = None
    height: float | None = None
    wrap: bool = True
    line_spacing: float = 1.0
    letter_spacing: float = 0.0
    overflow: TextOverflow = TextOverflow.VISIBLE
    max_lines: int | None = None
    outline: float = 0.0
    outline_color: Color = _BLACK
    shadow: Vec2 | None = None
    shadow_color: Color = _SHADE
    shadow_blur: float = 0.0
    markup: bool = False
    #: multiplies the whole label's alpha when drawn (no re-layout: cheap to fade)
    opacity: int = 255

    def style(self, box_scale: float = 1.0) -> TextStyle:
        """The looks of this label as a :class:`TextStyle`.

        ``box_scale`` converts ``width``/``height`` into text pixels (world text: the
        camera's ``pixels_per_meter``, since its box is in metres).
        """
        values = {name: getattr(self, name) for name in STYLE_FIELDS}
        if self.bold:
            values["weight"] = max(int(values["weight"]), BOLD)
        for name in ("width", "height"):
            if values[name] is not None:
                values[name] = min(values[name] * box_scale, MAX_BOX)
        return TextStyle(**values)

    @property
    def value(self) -> str:
        """Deprecated name of :attr:`text` (kept for one release)."""
        warnings.warn("Text.value is deprecated: use Text.text", DeprecationWarning, stacklevel=2)
        return self.text

    @value.setter
    def value(self, new: str) -> None:
        # stack: the caller's line -> Tracked.__setattr__ -> here
        warnings.warn("Text.value is deprecated: use Text.text", DeprecationWarning, stacklevel=3)
        self.text = new
