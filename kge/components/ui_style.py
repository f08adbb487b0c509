"""``Style``: how one widget (or, in a theme, every widget of a kind) looks.

Every field is optional: ``None`` takes the value from the next place down the
chain *entity style -> theme style of the widget kind -> theme defaults*. The
state variants (``hover``, ``pressed``, ``focused``, ``disabled``, ``selected``)
are Styles too, laid over the base one while the widget is in that state, so a
button can have its own colours, corner radius, font and a nine-patch image per
state. Styles are plain data and round-trip through dicts (themes keep them in
JSON):

>>> s = Style.from_data({"background": [200, 40, 40], "radius": 0,
...                      "hover": {"background": [230, 60, 60]}})
>>> s.background, s.radius, s.hover.background
((200, 40, 40, 255), 0.0, (230, 60, 60, 255))
>>> Style.from_data({"backgruond": [1, 2, 3]})
Traceback (most recent call last):
...
kge.errors.ValidationError: Style has no field 'backgruond' (did you mean 'background'?)
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Any, ClassVar

from kge.components.color import Color
from kge.components.ui_checks import font_size, known, opt_color, opt_image, px, text
from kge.errors import ValidationError
from kge.validate import boolean

STATES = ("hover", "pressed", "focused", "disabled", "selected")


def _opt(check: Any) -> Any:
    return lambda v, o, n: None if v is None else check(v, o, n)


@dataclass(slots=True, frozen=True, eq=True)
class Style:
    """Per-widget look overrides (see the module docstring). Add it to a UI node's entity."""

    _checks: ClassVar[dict[str, Any]] = {
        "background": opt_color, "text": opt_color, "border": opt_color, "accent": opt_color,
        "border_width": _opt(px), "radius": _opt(px), "padding": _opt(px),
        "font_name": _opt(text), "font_size": font_size, "bold": _opt(boolean),
        "italic": _opt(boolean), "image": opt_image, "image_border": _opt(px),
    }  # fmt: skip

    background: Color | None = None  #: fill of the widget's box
    text: Color | None = None  #: text colour
    border: Color | None = None  #: outline colour (drawn when border_width > 0)
    accent: Color | None = None  #: check marks, slider fills, selections, progress
    border_width: float | None = None
    radius: float | None = None  #: corner radius, pixels
    padding: float | None = None  #: space between the box and the text, pixels
    font_name: str | None = None
    font_size: float | None = None  #: points
    bold: bool | None = None
    italic: bool | None = None
    image: Any = None  #: a nine-patch background (asset name, PixelImage or pyglet image)
    image_border: float | None = None  #: the nine-patch's unscaled corner pixels
    hover: Style | None = None
    pressed: Style | None = None
    focused: Style | None = None
    disabled: Style | None = None
    selected: Style | None = None

    def __post_init__(self) -> None:
        for name, check in self._checks.items():
            value = getattr(self, name)
            if value is not None:
                object.__setattr__(self, name, check(value, "Style", name))
        for state in STATES:
            variant = getattr(self, state)
            if variant is not None and not isinstance(variant, Style):
                raise ValidationError(f"Style.{state} must be a Style or None, got {variant!r}")

    def over(self, base: Style | None) -> Style:
        """This style laid over ``base``: its set fields win, the rest come from ``base``."""
        if base is None:
            return self
        values = {}
        for f in fields(self):
            mine = getattr(self, f.name)
            values[f.name] = mine if mine is not None else getattr(base, f.name)
        return Style(**values)

    def to_data(self) -> dict[str, Any]:
        out: dict[str, Any] = {}
        for f in fields(self):
            v = getattr(self, f.name)
            if v is None:
                continue
            if isinstance(v, Style):
                out[f.name] = v.to_data()
            elif isinstance(v, tuple):
                out[f.name] = list(v)
            elif f.name == "image" and not isinstance(v, str):
                continue  # only asset names are data
            else:
                out[f.name] = v
        return out

    @classmethod
    def from_data(cls, data: Any, where: str = "Style") -> Style:
        """A style from a dict (lists for colours, dicts for state variants)."""
        if isinstance(data, Style):
            return data
        if not isinstance(data, dict):
            raise ValidationError(f"{where} must be a dict, got {type(data).__name__}")
        names = [f.name for f in fields(cls)]
        values: dict[str, Any] = {}
        for key, value in data.items():
            known(key, names, where)
            if key in STATES:
                values[key] = cls.from_data(value, f"{where}.{key}")
            elif isinstance(value, list):
                values[key] = tuple(value)
            else:
                values[key] = value
        return cls(**values)
