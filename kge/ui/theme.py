"""Themes: every colour, font size and spacing the UI draws with, as plain data.

The default theme is a dark slate with a teal accent that reads well over any game
and needs no asset: rounded panels and buttons are drawn shapes, text uses the
default font. A theme is a resource (``world.insert_resource(my_theme)``) and
round-trips through dicts, so games can keep theirs in a JSON file:

>>> t = Theme.from_data({"accent": [255, 120, 0, 255], "font_size": 20})
>>> t.accent, t.font_size, t.panel == DEFAULT_THEME.panel
((255, 120, 0, 255), 20.0, True)
>>> Theme.from_data({"accentt": [1, 2, 3]})
Traceback (most recent call last):
...
kge.errors.ValidationError: Theme has no field 'accentt' (did you mean 'accent'?)
"""

from __future__ import annotations

import difflib
from dataclasses import asdict, dataclass, fields, replace
from typing import Any

from kge.components.color import Color, rgba
from kge.components.text import MAX_FONT_SIZE
from kge.components.ui import MAX_PIXELS
from kge.errors import ValidationError
from kge.validate import at_most, finite


@dataclass(slots=True, frozen=True)
class Theme:
    """Colours (RGBA), sizes (pixels / points) of every widget state."""

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
    font_size: float = 16.0
    font_name: str | None = None
    padding: float = 10.0
    radius: float = 8.0
    focus_width: float = 2.0
    row_height: float = 28.0

    def __post_init__(self) -> None:
        for f in fields(self):
            v = getattr(self, f.name)
            if f.name == "font_name":
                if v is not None and not isinstance(v, str):
                    raise ValidationError(f"Theme.font_name must be a str or None, got {v!r}")
            elif isinstance(f.default, tuple):
                object.__setattr__(self, f.name, rgba(v, "Theme", f.name))
            else:
                n = finite(v, "Theme", f.name)
                if n < 0 or (f.name in ("font_size", "row_height") and n == 0):
                    raise ValidationError(f"Theme.{f.name} must be > 0, got {v!r}")
                if f.name == "font_size":  # FreeType refuses much larger glyphs
                    at_most(n, MAX_FONT_SIZE, "Theme", f.name, "points")
                else:  # layout boxes stay finite
                    at_most(n, MAX_PIXELS, "Theme", f.name, "pixels")
                object.__setattr__(self, f.name, n)

    def to_data(self) -> dict[str, Any]:
        return {k: list(v) if isinstance(v, tuple) else v for k, v in asdict(self).items()}

    @classmethod
    def from_data(cls, data: dict[str, Any], base: Theme | None = None) -> Theme:
        """A theme from a dict; missing fields come from ``base`` (the default theme)."""
        if not isinstance(data, dict):
            raise ValidationError(f"Theme data must be a dict, got {type(data).__name__}")
        names = [f.name for f in fields(cls)]
        for key in data:
            if key not in names:
                near = difflib.get_close_matches(str(key), names, n=1)
                hint = f" (did you mean {near[0]!r}?)" if near else ""
                raise ValidationError(f"Theme has no field {key!r}{hint}")
        values = {k: tuple(v) if isinstance(v, list) else v for k, v in data.items()}
        return replace(base or DEFAULT_THEME, **values)  # type: ignore[arg-type]


DEFAULT_THEME = Theme()
