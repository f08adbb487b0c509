"""Screen-space UI as entities: a :class:`UINode` places a box, a widget fills it.

The model is Bevy UI and Arcade's ``arcade.gui``: every UI element is an entity with
a ``UINode`` (where and how big, in window pixels, origin bottom-left) and at most one
widget component (what it is). Nodes nest through ``parent``; a parent with a
``layout`` places its children in a row, a column or a grid, otherwise each child is
anchored inside it. Everything is pure data: the UI plugin (``kge.systems.ui``)
computes the boxes every frame from the window size (so percent sizes and anchors
survive resizes), turns pointer, keyboard and gamepad input into widget changes and
events, and the render pass draws them.

Sizes are pixels (``120``), percents of the parent's inner box (``"50%"``), or
``"auto"`` (fit the children or the widget's text). Anchors name a point of the
parent: ``"center"``, ``"top_left"``, ``"top"``, ``"top_right"``, ``"left"``,
``"right"``, ``"bottom_left"``, ``"bottom"``, ``"bottom_right"``; the same point of
the node is put there, moved by ``offset`` pixels (y up).

>>> UINode(width=-5)
Traceback (most recent call last):
...
kge.errors.ValidationError: UINode.width must be >= 0 pixels, a percent like '50%' or 'auto', got -5
>>> Slider(min=10, max=0)
Traceback (most recent call last):
...
kge.errors.ValidationError: Slider: min (10.0) must be <= max (0.0)
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, ClassVar

from kge.components.color import Color, rgba
from kge.components.tracked import Check, Tracked
from kge.errors import ComponentTypeError, ValidationError
from kge.validate import boolean, finite, integer, non_negative, vec2, within

Size = float | str

ANCHORS: dict[str, tuple[float, float]] = {
    "center": (0.5, 0.5),
    "top_left": (0.0, 1.0),
    "top": (0.5, 1.0),
    "top_right": (1.0, 1.0),
    "left": (0.0, 0.5),
    "right": (1.0, 0.5),
    "bottom_left": (0.0, 0.0),
    "bottom": (0.5, 0.0),
    "bottom_right": (1.0, 0.0),
}
LAYOUTS = ("free", "row", "column", "grid")
ALIGNS = ("start", "center", "end", "stretch")


def _choice(options: tuple[str, ...]) -> Check:
    def check(value: Any, owner: str, name: str) -> str:
        if value not in options:
            raise ValidationError(
                f"{owner}.{name} must be one of {', '.join(options)}, got {value!r}"
            )
        return str(value)

    return check


def size(value: Any, owner: str, name: str) -> Size:
    """A size: pixels >= 0, ``"NN%"`` (0..1000) or ``"auto"``."""
    bad = ValidationError(
        f"{owner}.{name} must be >= 0 pixels, a percent like '50%' or 'auto', got {value!r}"
    )
    if isinstance(value, str):
        if value == "auto":
            return value
        if value.endswith("%"):
            try:
                pct = float(value[:-1])
            except ValueError:
                raise bad from None
            if 0.0 <= pct <= 1000.0:
                return value
        raise bad
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise bad
    v = float(value)
    if not 0.0 <= v < 1e7:  # NaN fails too
        raise bad
    return v


#: the largest UI distance, pixels (offsets, padding, spacing): layout boxes stay finite
MAX_PIXELS = 1e7
#: the largest magnitude of a slider's or bar's min, max and value: max - min stays finite
MAX_RANGE = 1e300


def pixels(value: Any, owner: str, name: str) -> float:
    """A UI distance in pixels, within +-:data:`MAX_PIXELS`."""
    return within(value, MAX_PIXELS, owner, name, " pixels")


def _gap(value: Any, owner: str, name: str) -> float:
    v = pixels(value, owner, name)
    if v < 0:
        raise ValidationError(f"{owner}.{name} must be >= 0, got {v!r}")
    return v


def _offset(value: Any, owner: str, name: str) -> tuple[float, float]:
    x, y = vec2(value, owner, name)
    return (pixels(x, owner, f"{name}[0]"), pixels(y, owner, f"{name}[1]"))


def _ranged(value: Any, owner: str, name: str) -> float:
    return within(value, MAX_RANGE, owner, name)


def anchor(value: Any, owner: str, name: str) -> str:
    if value not in ANCHORS:
        raise ValidationError(f"{owner}.{name} must be one of {', '.join(ANCHORS)}, got {value!r}")
    return str(value)


def parent(value: Any, owner: str, name: str) -> int | None:
    return None if value is None else integer(value, owner, name)


def text(value: Any, owner: str, name: str) -> str:
    if not isinstance(value, str):
        raise ComponentTypeError(
            f"{owner}.{name} must be a str, got {type(value).__name__} {value!r}"
        )
    return value


def _columns(value: Any, owner: str, name: str) -> int:
    v = integer(value, owner, name)
    if v < 1:
        raise ValidationError(f"{owner}.{name} must be >= 1, got {v}")
    return v


def _font_size(value: Any, owner: str, name: str) -> float | None:
    if value is None:
        return None
    v = finite(value, owner, name)
    if not 0 < v <= 1000:  # FreeType refuses much larger glyphs at the first draw
        raise ValidationError(f"{owner}.{name} must be in (0, 1000] points, got {v}")
    return v


def _opt_color(value: Any, owner: str, name: str) -> Color | None:
    return None if value is None else rgba(value, owner, name)


def image(value: Any, owner: str, name: str) -> Any:
    """An asset name, a :class:`kge.render.images.PixelImage` or a pyglet image."""
    if isinstance(value, str) or (hasattr(value, "width") and hasattr(value, "height")):
        return value
    raise ComponentTypeError(
        f"{owner}.{name} must be an asset name, a PixelImage or an image, got {value!r}"
    )


def _opt_image(value: Any, owner: str, name: str) -> Any:
    return None if value is None else image(value, owner, name)


def _strings(value: Any, owner: str, name: str) -> list[str]:
    if isinstance(value, str) or not hasattr(value, "__iter__"):
        raise ComponentTypeError(f"{owner}.{name} must be a list of str, got {value!r}")
    items = list(value)
    for item in items:
        text(item, owner, name)
    return items


@dataclass(slots=True)
class UINode(Tracked):
    """Where a UI element goes and how big it is (see the module docstring)."""

    #: the parent must be another live UI node, not a descendant (checked by the UI plugin)
    _world_fields: ClassVar[frozenset[str]] = frozenset({"parent"})

    _checks: ClassVar[dict[str, Check]] = {
        "parent": parent,
        "anchor": anchor,
        "offset": _offset,
        "width": size,
        "height": size,
        "layout": _choice(LAYOUTS),
        "padding": _gap,
        "spacing": _gap,
        "align": _choice(ALIGNS),
        "justify": _choice(("start", "center", "end")),
        "columns": _columns,
        "visible": boolean,
        "order": integer,
        "focusable": boolean,
    }

    anchor: str = "center"
    offset: tuple[float, float] = (0.0, 0.0)
    width: Size = "auto"
    height: Size = "auto"
    parent: int | None = None
    layout: str = "free"  #: how children are placed: free (anchored), row, column, grid
    padding: float = 0.0  #: pixels between the box and its children
    spacing: float = 0.0  #: pixels between children in a row, column or grid
    align: str = "center"  #: cross-axis placement of children (stretch fills)
    justify: str = "start"  #: main-axis placement of the whole row/column
    columns: int = 2  #: grid columns
    visible: bool = True
    order: int = 0  #: among siblings: lower first (placed first, drawn below)
    focusable: bool = True  #: interactive widgets take keyboard/gamepad focus


@dataclass(slots=True)
class Label(Tracked):
    """Text. ``size``/``color`` None use the theme's."""

    _checks: ClassVar[dict[str, Check]] = {
        "text": text,
        "size": _font_size,
        "color": _opt_color,
        "align": _choice(("left", "center", "right")),
    }

    text: str = ""
    size: float | None = None
    color: Color | None = None
    align: str = "center"


@dataclass(slots=True)
class UIImage(Tracked):
    """An image (asset name) stretched over the node, tinted by ``tint``."""

    _world_fields: ClassVar[frozenset[str]] = frozenset({"image"})  #: looked up in the assets
    _checks: ClassVar[dict[str, Check]] = {"image": image, "tint": rgba}

    image: Any  #: an asset name, a PixelImage or a pyglet image
    tint: Color = (255, 255, 255, 255)


@dataclass(slots=True)
class Panel(Tracked):
    """A background box: the theme's rounded panel, a colour, or a nine-patch image.

    A nine-patch keeps its ``border`` pixels of corners unscaled and stretches the
    edges and middle, so one small image makes a frame of any size.
    """

    _world_fields: ClassVar[frozenset[str]] = frozenset({"image"})  #: looked up in the assets
    _checks: ClassVar[dict[str, Check]] = {
        "color": _opt_color, "image": _opt_image, "border": non_negative, "radius": non_negative,
        "blocks": boolean,
    }  # fmt: skip

    color: Color | None = None
    image: Any = None  #: a nine-patch image (asset name, PixelImage or pyglet image)
    border: float = 8.0
    radius: float = 8.0
    blocks: bool = True  #: takes clicks over it (keeps them from the game)


@dataclass(slots=True)
class Button(Tracked):
    """A button with text and/or an image. Clicked: ``ButtonClicked`` and ``on_click``."""

    _world_fields: ClassVar[frozenset[str]] = frozenset({"image"})  #: looked up in the assets
    _checks: ClassVar[dict[str, Check]] = {"text": text, "image": _opt_image, "disabled": boolean}

    text: str = ""
    image: Any = None  #: an icon: asset name, PixelImage or pyglet image
    disabled: bool = False


@dataclass(slots=True)
class Toggle(Tracked):
    """A checkbox with a label. Changed: ``ValueChanged`` and ``on_value_changed``."""

    _checks: ClassVar[dict[str, Check]] = {"value": boolean, "text": text, "disabled": boolean}

    value: bool = False
    text: str = ""
    disabled: bool = False


def _ranged_setattr(self: Any, name: str, value: Any) -> None:
    """Write a field of a min/max/value widget, keeping min <= value <= max."""
    old = getattr(self, name, None)
    Tracked.__setattr__(self, name, value)
    if old is None:
        return  # the first write, inside __init__: __post_init__ checks the whole
    try:
        lo, hi, v = self.min, self.max, self.value
    except AttributeError:  # still inside __init__ (__post_init__ checks the whole)
        return
    if lo > hi:
        Tracked.__setattr__(self, name, old)
        raise ValidationError(f"{self._owner()}: min ({lo}) must be <= max ({hi})")
    if not lo <= v <= hi:
        Tracked.__setattr__(self, "value", min(max(v, lo), hi))


@dataclass(slots=True)
class Slider(Tracked):
    """A value between ``min`` and ``max`` (kept inside: writes are clamped), ``step`` 0 for
    continuous. Dragging, arrow keys and the d-pad change it."""

    _checks: ClassVar[dict[str, Check]] = {
        "min": _ranged, "max": _ranged, "value": _ranged, "step": non_negative,
        "disabled": boolean,
    }  # fmt: skip

    min: float = 0.0
    max: float = 1.0
    value: float = 0.0
    step: float = 0.0
    disabled: bool = False

    def __post_init__(self) -> None:
        if self.min > self.max:
            raise ValidationError(f"{self._owner()}: min ({self.min}) must be <= max ({self.max})")
        self.value = min(max(self.value, self.min), self.max)

    __setattr__ = _ranged_setattr


@dataclass(slots=True)
class ProgressBar(Tracked):
    """A bar filled to ``value / max`` (health bars, loading). ``color`` None: theme accent."""

    _checks: ClassVar[dict[str, Check]] = {
        "value": _ranged, "max": _ranged, "color": _opt_color, "min": _ranged,
    }  # fmt: skip

    value: float = 0.0
    max: float = 1.0
    color: Color | None = None
    min: float = 0.0

    def __post_init__(self) -> None:
        if self.min > self.max:
            raise ValidationError(f"{self._owner()}: min ({self.min}) must be <= max ({self.max})")
        self.value = min(max(self.value, self.min), self.max)

    __setattr__ = _ranged_setattr

    @property
    def fraction(self) -> float:
        span = self.max - self.min
        return 0.0 if span <= 0 else (self.value - self.min) / span


@dataclass(slots=True)
class TextInput(Tracked):
    """A one-line text field: caret, selection, typing, paste, ``max_length``.

    ``caret`` and ``anchor`` are character indices; the selection is between them.
    Setting ``text`` longer than ``max_length`` is refused; typing beyond it is dropped.
    Enter emits ``TextSubmitted`` (and ``on_text_submitted``).
    """

    _checks: ClassVar[dict[str, Check]] = {
        "text": text, "placeholder": text, "max_length": integer, "caret": integer,
        "anchor": integer, "disabled": boolean,
    }  # fmt: skip

    text: str = ""
    placeholder: str = ""
    max_length: int = 256
    caret: int = -1  #: -1: at the end
    anchor: int = -1  #: the other end of the selection (-1: no selection)
    disabled: bool = False

    def __post_init__(self) -> None:
        if self.max_length < 0:
            raise ValidationError(f"{self._owner()}.max_length must be >= 0, got {self.max_length}")
        if len(self.text) > self.max_length:
            raise ValidationError(
                f"{self._owner()}.text has {len(self.text)} characters, more than max_length "
                f"{self.max_length}"
            )
        if self.caret < 0 or self.caret > len(self.text):
            self.caret = len(self.text)

    def __setattr__(self, name: str, value: Any) -> None:
        if name == "text":
            value = text(value, self._owner(), name)
            limit = getattr(self, "max_length", None)
            if limit is not None and len(value) > limit:
                raise ValidationError(
                    f"{self._owner()}.text has {len(value)} characters, "
                    f"more than max_length {limit}"
                )
        elif name == "max_length" and hasattr(self, "caret"):  # a write after __init__
            value = integer(value, self._owner(), name)
            if value < max(0, len(self.text)):
                raise ValidationError(
                    f"{self._owner()}.max_length must be >= 0 and hold the text's "
                    f"{len(self.text)} characters, got {value}"
                )
        elif name in ("caret", "anchor") and hasattr(self, "caret"):
            value = integer(value, self._owner(), name)
            if not -1 <= value <= len(self.text):
                raise ValidationError(
                    f"{self._owner()}.{name} must be a character index 0..{len(self.text)} "
                    f"(or -1), got {value}"
                )
        Tracked.__setattr__(self, name, value)
        if name == "text" and hasattr(self, "caret"):
            Tracked.__setattr__(self, "caret", min(max(self.caret, 0), len(value)))
            Tracked.__setattr__(self, "anchor", -1)

    @property
    def selection(self) -> tuple[int, int] | None:
        """(start, end) of the selected characters, or None."""
        if self.anchor < 0 or self.anchor == self.caret:
            return None
        return (min(self.anchor, self.caret), max(self.anchor, self.caret))


@dataclass(slots=True)
class Dropdown(Tracked):
    """Pick one of ``options``; opens a list below it. Changed: ``ValueChanged``."""

    _checks: ClassVar[dict[str, Check]] = {
        "options": _strings, "selected": integer, "open": boolean, "disabled": boolean,
    }  # fmt: skip

    options: list[str] = field(default_factory=list)
    selected: int = 0
    open: bool = False
    disabled: bool = False

    def __post_init__(self) -> None:
        self._check_selected(self.selected, self.options)

    def __setattr__(self, name: str, value: Any) -> None:
        if name == "selected" and hasattr(self, "selected"):
            value = integer(value, self._owner(), name)
            self._check_selected(value, self.options)
        Tracked.__setattr__(self, name, value)

    def _check_selected(self, selected: int, options: list[str]) -> None:
        if options and not 0 <= selected < len(options):
            raise ValidationError(
                f"{self._owner()}.selected {selected} is not an index of its "
                f"{len(options)} options"
            )

    @property
    def value(self) -> str | None:
        return self.options[self.selected] if 0 <= self.selected < len(self.options) else None


@dataclass(slots=True)
class ScrollList(Tracked):
    """A scrollable list of text rows (wheel, drag-free); clicking a row selects it."""

    _checks: ClassVar[dict[str, Check]] = {
        "items": _strings, "selected": integer, "scroll": non_negative, "row_height": _font_size,
    }  # fmt: skip

    items: list[str] = field(default_factory=list)
    selected: int = -1
    scroll: float = 0.0  #: pixels scrolled from the top
    row_height: float | None = None  #: None: the theme's
