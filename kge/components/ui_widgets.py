"""The basic widgets: labels, images, panels, buttons, toggles, sliders, bars, spin boxes,
colour pickers. Pure data; the UI plugin handles their input and draws them.

>>> Slider(min=10, max=0)
Traceback (most recent call last):
...
kge.errors.ValidationError: Slider: min (10.0) must be <= max (0.0)
>>> SpinBox(5, min=0, max=3).value                  # writes are clamped into the range
3.0
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, ClassVar

from kge.components.color import RGBA, Color, rgba
from kge.components.tracked import Check, Tracked
from kge.components.ui_checks import (
    choice,
    font_size,
    image,
    opt_color,
    opt_image,
    px,
    ranged,
    text,
)
from kge.errors import ValidationError
from kge.validate import boolean, finite, integer, non_negative, number


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


def _check_range(self: Any) -> None:
    if self.min > self.max:
        raise ValidationError(f"{self._owner()}: min ({self.min}) must be <= max ({self.max})")
    self.value = min(max(self.value, self.min), self.max)


def fraction(value: float, lo: float, hi: float) -> float:
    """Where ``value`` sits in [lo, hi], 0..1 (exact for any finite range: a spin box's
    bounds are not limited to +-MAX_RANGE)."""
    span = hi * 0.5 - lo * 0.5  # halves: hi - lo may overflow to inf
    if not span > 0:
        return 0.0
    return min(max((value * 0.5 - lo * 0.5) / span, 0.0), 1.0)


def lerp(lo: float, hi: float, t: float) -> float:
    """The value at fraction ``t`` of [lo, hi], without overflow for huge ranges."""
    v = lo * (1.0 - t) + hi * t
    return min(max(v, lo), hi)


@dataclass(slots=True)
class Label(Tracked):
    """Text. ``size``/``color`` None use the style's. Newlines break lines; ``wrap=True``
    also breaks at the box's width. Text wider than its box is cut with an ellipsis;
    control characters are not drawn."""

    _checks: ClassVar[dict[str, Check]] = {
        "text": text,
        "size": font_size,
        "color": opt_color,
        "align": choice(("left", "center", "right")),
        "wrap": boolean,
    }

    text: str = ""
    size: float | None = None
    color: Color | None = None
    align: str = "center"
    wrap: bool = False


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
        "color": opt_color, "image": opt_image, "border": px, "radius": px, "blocks": boolean,
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
    _checks: ClassVar[dict[str, Check]] = {"text": text, "image": opt_image, "disabled": boolean}

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


@dataclass(slots=True)
class Slider(Tracked):
    """A value between ``min`` and ``max`` (kept inside: writes are clamped), ``step`` 0 for
    continuous. Dragging, arrow keys, the d-pad and the wheel change it."""

    _checks: ClassVar[dict[str, Check]] = {
        "min": ranged, "max": ranged, "value": ranged, "step": non_negative,
        "disabled": boolean,
    }  # fmt: skip

    min: float = 0.0
    max: float = 1.0
    value: float = 0.0
    step: float = 0.0
    disabled: bool = False

    def __post_init__(self) -> None:
        _check_range(self)

    __setattr__ = _ranged_setattr

    @property
    def fraction(self) -> float:
        return fraction(self.value, self.min, self.max)


@dataclass(slots=True)
class ProgressBar(Tracked):
    """A bar filled to ``value`` between ``min`` and ``max`` (health bars, loading)."""

    _checks: ClassVar[dict[str, Check]] = {
        "value": ranged, "max": ranged, "color": opt_color, "min": ranged,
    }  # fmt: skip

    value: float = 0.0
    max: float = 1.0
    color: Color | None = None  #: None: the style's accent
    min: float = 0.0

    def __post_init__(self) -> None:
        _check_range(self)

    __setattr__ = _ranged_setattr

    @property
    def fraction(self) -> float:
        return fraction(self.value, self.min, self.max)


def _bound(value: Any, owner: str, name: str) -> float:
    """A finite number or +-infinity (an open end of a spin box)."""
    v = number(value, owner, name)
    if math.isnan(v):
        raise ValidationError(f"{owner}.{name} must be a number or +-inf, got nan")
    return v


@dataclass(slots=True)
class SpinBox(Tracked):
    """A number field: ``-``/``+`` buttons, Left/Right, the wheel, drag sideways to change
    it, or click and type a value (Enter keeps it, Escape reverts).

    ``min``/``max`` may be infinite (an inspector's unbounded field). ``step`` is one
    click or key press; dragging moves ``drag_speed`` per pixel (0: a step per 4 px).
    ``decimals`` digits are shown (-1: as many as the value needs, up to 6).
    """

    _checks: ClassVar[dict[str, Check]] = {
        "value": finite, "min": _bound, "max": _bound, "step": non_negative,
        "drag_speed": non_negative, "decimals": integer, "rounded": boolean,
        "suffix": text, "disabled": boolean,
    }  # fmt: skip

    value: float = 0.0
    min: float = -math.inf
    max: float = math.inf
    step: float = 1.0
    drag_speed: float = 0.0
    decimals: int = -1
    rounded: bool = False  #: whole numbers only
    suffix: str = ""  #: shown after the number ("px", " m")
    disabled: bool = False

    def __post_init__(self) -> None:
        if not -1 <= self.decimals <= 12:
            raise ValidationError(
                f"{self._owner()}.decimals must be in -1..12, got {self.decimals}"
            )
        _check_range(self)
        if self.rounded:
            self.value = float(round(self.value))

    __setattr__ = _ranged_setattr

    def text(self) -> str:
        """The value as shown (without the suffix)."""
        if self.rounded:
            return str(int(self.value))
        if self.decimals >= 0:
            return f"{self.value:.{self.decimals}f}"
        return f"{self.value:.6f}".rstrip("0").rstrip(".") or "0"


@dataclass(slots=True)
class ColorPicker(Tracked):
    """Pick a colour: a saturation/value square, a hue bar and (``alpha=True``) an alpha
    bar, with a swatch of the result. Mouse: click or drag in any of them. Keyboard and
    gamepad: Enter/A picks which part the arrows change (hue, saturation, value, alpha),
    Left/Right change it. Changed: ``ValueChanged`` with the RGBA tuple."""

    _checks: ClassVar[dict[str, Check]] = {
        "color": rgba, "alpha": boolean, "disabled": boolean,
    }  # fmt: skip

    color: RGBA = (255, 0, 0, 255)
    alpha: bool = True
    disabled: bool = False


def rgb_to_hsv(c: Color) -> tuple[float, float, float]:
    """(hue 0..1, saturation 0..1, value 0..1) of an RGB(A) colour."""
    r, g, b = (v / 255.0 for v in c[:3])
    hi, lo = max(r, g, b), min(r, g, b)
    d = hi - lo
    s = 0.0 if hi == 0 else d / hi
    if d == 0:
        h = 0.0
    elif hi == r:
        h = ((g - b) / d) % 6.0
    elif hi == g:
        h = (b - r) / d + 2.0
    else:
        h = (r - g) / d + 4.0
    return (h / 6.0, s, hi)


def hsv_to_rgb(h: float, s: float, v: float) -> tuple[int, int, int]:
    """Integer RGB of (hue 0..1, saturation, value)."""
    h = (h % 1.0) * 6.0
    i = int(h) % 6
    f = h - int(h)
    p, q, t = v * (1 - s), v * (1 - s * f), v * (1 - s * (1 - f))
    r, g, b = [(v, t, p), (q, v, p), (p, v, t), (p, q, v), (t, p, v), (v, p, q)][i]
    return (round(r * 255), round(g * 255), round(b * 255))


__all__ = [
    "Button",
    "ColorPicker",
    "Label",
    "Panel",
    "ProgressBar",
    "Slider",
    "SpinBox",
    "Toggle",
    "UIImage",
    "fraction",
    "hsv_to_rgb",
    "lerp",
    "rgb_to_hsv",
]
