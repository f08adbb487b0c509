"""Themes: every colour, font and spacing the UI draws with, as plain data.

The default theme is a dark slate with a teal accent that reads well over any game
and needs no asset: rounded panels and buttons are drawn shapes, text uses the
default font. A theme is a resource (``world.insert_resource(my_theme)``) and
round-trips through dicts, so games can keep theirs in a JSON file. Besides the
shared colours and sizes, ``styles`` gives any kind of widget its own
:class:`~kge.components.ui_style.Style` (colours, font, padding, corner radius,
images, per state):

>>> t = Theme.from_data({"accent": [255, 120, 0, 255], "font_size": 20,
...                      "styles": {"Button": {"radius": 0, "hover": {"background": [90, 0, 0]}}}})
>>> t.accent, t.font_size, t.panel == DEFAULT_THEME.panel, t.styles["Button"].radius
((255, 120, 0, 255), 20.0, True, 0.0)
>>> Theme.from_data({"accentt": [1, 2, 3]})
Traceback (most recent call last):
...
kge.errors.ValidationError: Theme has no field 'accentt' (did you mean 'accent'?)
>>> Theme.from_data({"styles": {"Buton": {}}})
Traceback (most recent call last):
...
kge.errors.ValidationError: Theme.styles has no widget kind 'Buton' (did you mean 'Button'?)
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace
from dataclasses import field as _field
from typing import Any

from kge.components.color import Color, rgba
from kge.components.text import MAX_FONT_SIZE
from kge.components.ui_checks import MAX_PIXELS, known
from kge.components.ui_style import Style
from kge.errors import ValidationError
from kge.validate import at_most, finite

#: the widget kinds a theme can style (a node's widget class name, plus the parts
#: that are not widgets of their own)
KINDS = (
    "Button", "Toggle", "Slider", "SpinBox", "TextInput", "TextArea", "Dropdown",
    "ScrollList", "RadioGroup", "Tabs", "TreeView", "ColorPicker", "Label", "RichText",
    "ProgressBar", "UIImage", "Panel", "Dialog", "Tooltip", "ScrollBar",
)  # fmt: skip


@dataclass(slots=True, frozen=True)
class Theme:
    """Colours (RGBA), sizes (pixels / points) of every widget state, and per-kind styles."""

    text: Color = (236, 239, 244, 255)
    text_muted: Color = (150, 158, 172, 255)
    text_disabled: Color = (110, 116, 128, 255)
    panel: Color = (30, 34, 44, 235)
    panel_border: Color = (70, 78, 96, 255)
    button: Color = (52, 60, 78, 255)
    button_hover: Color = (68, 80, 104, 255)
    button_pressed: Color = (36, 150, 140, 255)
    button_disabled: Color = (44, 48, 58, 255)
    accent: Color = (46, 196, 182, 255)
    focus: Color = (255, 206, 84, 255)
    field: Color = (20, 23, 30, 255)
    selection: Color = (46, 120, 182, 200)
    track: Color = (20, 23, 30, 255)
    scrim: Color = (0, 0, 0, 140)  #: behind a modal dialog
    font_size: float = 16.0
    font_name: str | None = None
    padding: float = 10.0
    radius: float = 8.0
    focus_width: float = 2.0
    row_height: float = 28.0
    scrollbar: float = 10.0  #: scrollbar thickness, pixels
    styles: dict[str, Style] = _field(default_factory=dict)

    def __post_init__(self) -> None:
        for f in fields(self):
            v = getattr(self, f.name)
            if f.name == "font_name":
                if v is not None and not isinstance(v, str):
                    raise ValidationError(f"Theme.font_name must be a str or None, got {v!r}")
            elif f.name == "styles":
                object.__setattr__(self, "styles", _styles(v))
            elif isinstance(f.default, tuple):
                object.__setattr__(self, f.name, rgba(v, "Theme", f.name))
            else:
                n = finite(v, "Theme", f.name)
                sized = f.name in ("font_size", "row_height")
                if n < 0 or (sized and n == 0):
                    raise ValidationError(
                        f"Theme.{f.name} must be {'> 0' if sized else '>= 0'}, got {v!r}"
                    )
                if f.name == "font_size":  # FreeType refuses much larger glyphs
                    at_most(n, MAX_FONT_SIZE, "Theme", f.name, "points")
                else:  # layout boxes stay finite
                    at_most(n, MAX_PIXELS, "Theme", f.name, "pixels")
                object.__setattr__(self, f.name, n)

    def __hash__(self) -> int:
        return id(self)

    def to_data(self) -> dict[str, Any]:
        out: dict[str, Any] = {}
        for f in fields(self):
            v = getattr(self, f.name)
            if f.name == "styles":
                out["styles"] = {k: s.to_data() for k, s in v.items()}
            else:
                out[f.name] = list(v) if isinstance(v, tuple) else v
        return out

    @classmethod
    def from_data(cls, data: dict[str, Any], base: Theme | None = None) -> Theme:
        """A theme from a dict; missing fields come from ``base`` (the default theme)."""
        if not isinstance(data, dict):
            raise ValidationError(f"Theme data must be a dict, got {type(data).__name__}")
        names = [f.name for f in fields(cls)]
        for key in data:
            known(key, names, "Theme")
        values: dict[str, Any] = {
            k: tuple(v) if isinstance(v, list) else v for k, v in data.items()
        }
        if "styles" in values:
            base_styles = (base or DEFAULT_THEME).styles
            values["styles"] = {**base_styles, **_styles(values["styles"])}
        return replace(base or DEFAULT_THEME, **values)


def _styles(value: Any) -> dict[str, Style]:
    if not isinstance(value, dict):
        raise ValidationError(f"Theme.styles must be a dict of kind -> style, got {value!r}")
    out: dict[str, Style] = {}
    for kind, style in value.items():
        known(kind, KINDS, "Theme.styles", "widget kind")
        out[kind] = Style.from_data(style, f"Theme.styles[{kind!r}]")
    return out


DEFAULT_THEME = Theme()

__all__ = ["DEFAULT_THEME", "KINDS", "Theme"]
