"""Resolving what a widget looks like: entity style -> theme style -> theme defaults.

:func:`look` gives a :class:`Look` with every field set, for a widget kind in a
state, already scaled to window pixels (the UI scale multiplies sizes, the text
scale multiplies font sizes too). Looks are cached: a frame of an unchanged UI
resolves nothing.

When a widget's own style (or the theme's style for its kind) sets a background but
says nothing of its hover or pressed states, those states are shaded from it, so a
red button still answers the pointer:

>>> from kge.components.ui_style import Style
>>> red = Style(background=(200, 0, 0))
>>> look(DEFAULT_THEME, "Button", "normal", red).background
(200, 0, 0, 255)
>>> look(DEFAULT_THEME, "Button", "hover", red).background
(206, 26, 26, 255)
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from functools import lru_cache
from typing import Any

from kge.components.color import Color
from kge.components.ui_style import Style
from kge.ui.measure import Font
from kge.ui.theme import DEFAULT_THEME, Theme

#: widget states, as :meth:`kge.ui.state.UIState.state_of` names them
STATES = ("normal", "hover", "pressed", "focused", "disabled", "selected")


@dataclass(slots=True, frozen=True)
class Look:
    """Everything drawing a widget needs, resolved (pixels and points already scaled)."""

    background: Color
    text: Color
    border: Color
    accent: Color
    border_width: float
    radius: float
    padding: float
    font: Font
    image: Any
    image_border: float


def _defaults(t: Theme, kind: str) -> Style:
    """The built-in style of ``kind`` from the theme's shared colours."""
    base = dict(
        background=(0, 0, 0, 0), text=t.text, border=t.panel_border, accent=t.accent,
        border_width=0.0, radius=t.radius, padding=t.padding, font_name=t.font_name,
        font_size=t.font_size, bold=False, italic=False, image_border=8.0,
    )  # fmt: skip
    muted = Style(text=t.text_disabled, accent=t.text_disabled)
    if kind in ("Button", "Dropdown", "Tabs"):
        base["background"] = t.button
        states = dict(hover=Style(background=t.button_hover),
                      pressed=Style(background=t.button_pressed),
                      disabled=Style(background=t.button_disabled, text=t.text_disabled),
                      selected=Style(background=t.panel, text=t.text))  # fmt: skip
        if kind == "Tabs":
            states["selected"] = Style(background=t.accent, text=t.field)
        return Style(**base, **states)  # type: ignore[arg-type]
    if kind in ("TextInput", "TextArea", "SpinBox", "ScrollList", "TreeView", "ColorPicker"):
        base.update(background=t.field, border=t.panel_border, border_width=2.0,
                    accent=t.selection)  # fmt: skip
        return Style(**base, focused=Style(border=t.focus), disabled=muted)  # type: ignore[arg-type]
    if kind in ("Toggle", "RadioGroup"):
        base.update(background=t.field)
        return Style(**base, hover=Style(background=t.button_hover),  # type: ignore[arg-type]
                     pressed=Style(background=t.button_hover), disabled=muted)  # fmt: skip
    if kind in ("Slider", "ProgressBar", "ScrollBar"):
        base.update(background=t.track, text=t.text)
        return Style(**base, pressed=Style(text=t.button_pressed),  # type: ignore[arg-type]
                     hover=Style(text=t.text), disabled=muted)  # fmt: skip
    if kind in ("Panel", "Dialog", "Tooltip"):
        base.update(background=t.panel, border=t.panel_border, border_width=1.0)
        if kind == "Tooltip":
            base.update(padding=t.padding * 0.6, radius=t.radius * 0.75,
                        font_size=t.font_size * 0.85, background=(*t.panel[:3], 250))  # fmt: skip
        return Style(**base)  # type: ignore[arg-type]
    return Style(**base, disabled=muted)  # type: ignore[arg-type]


def shade(c: Color, amount: float) -> Color:
    """Lighter (amount > 0) or darker (< 0) by a fraction, alpha kept."""
    r, g, b = c[0], c[1], c[2]
    a = c[3] if len(c) > 3 else 255
    if amount >= 0:
        k = amount
        return (round(r + (255 - r) * k), round(g + (255 - g) * k), round(b + (255 - b) * k), a)
    k = 1 + amount
    return (round(r * k), round(g * k), round(b * k), a)


def _pick(chain: list[tuple[Style | None, bool]], name: str) -> tuple[Any, bool]:
    """The first set value of ``name`` along ``chain`` and whether it came from a state."""
    for style, is_state in chain:
        if style is not None:
            v = getattr(style, name)
            if v is not None:
                return v, is_state
    return None, False


_SHADE = {"hover": 0.1, "pressed": -0.25, "disabled": -0.3}


@lru_cache(maxsize=4096)
def _resolve(theme: Theme, kind: str, state: str, own: Style | None, scale: float,
             text_scale: float) -> Look:  # fmt: skip
    built = _defaults(theme, kind)
    themed = theme.styles.get(kind)
    chain: list[tuple[Style | None, bool]] = []
    for level in (own, themed, built):
        variant = getattr(level, state) if level is not None and state != "normal" else None
        chain.append((variant, True))
        chain.append((level, False))
    values: dict[str, Any] = {}
    for f in fields(Look):
        if f.name == "font":
            continue
        v, from_state = _pick(chain, f.name)
        if f.name == "background" and not from_state and state in _SHADE:
            came_from_override = _pick(chain[:4], "background")[0] is not None
            if came_from_override:
                v = shade(v, _SHADE[state])
        values[f.name] = v
    for name in ("border_width", "radius", "padding", "image_border"):
        values[name] = float(values[name]) * scale
    size, _ = _pick(chain, "font_size")
    name, _ = _pick(chain, "font_name")
    bold, _ = _pick(chain, "bold")
    italic, _ = _pick(chain, "italic")
    values["font"] = Font(name, float(size) * scale * text_scale, bool(bold), bool(italic))
    return Look(**values)


def look(theme: Theme, kind: str, state: str = "normal", own: Style | None = None,
         scale: float = 1.0, text_scale: float = 1.0) -> Look:  # fmt: skip
    """The resolved look of a ``kind`` widget (its class name) in ``state``."""
    try:
        return _resolve(theme, kind, state, own, scale, text_scale)
    except TypeError:  # a style holding an unhashable image: resolve without the cache
        return _resolve.__wrapped__(theme, kind, state, own, scale, text_scale)


__all__ = ["DEFAULT_THEME", "STATES", "Look", "look", "shade"]
