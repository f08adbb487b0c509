"""The size a widget asks for (an ``"auto"`` node's size), from its look and measured text.

One :class:`Sizer` serves a layout pass: it knows the theme, the scales, the text
measure and each entity's own :class:`~kge.components.ui_style.Style`, and resolves
looks for the layout, the input handling and the drawing alike.
"""

from __future__ import annotations

import re
from typing import Any

from kge.components.ui import (
    Button,
    ColorPicker,
    Dropdown,
    Label,
    ProgressBar,
    RadioGroup,
    RichText,
    ScrollList,
    Slider,
    SpinBox,
    Style,
    Tabs,
    TextArea,
    TextInput,
    Toggle,
    TreeView,
    UIImage,
)
from kge.components.ui_markup import Run
from kge.ui.measure import Font, TextMeasure, positions, visible, width, wrap
from kge.ui.style import Look, look
from kge.ui.theme import Theme

_TOKENS = re.compile(r"\S+\s*|\s+")
#: a piece of a rich text line: its text, the markup run it comes from, its font
Piece = tuple[str, Run, Font]

#: options measured for an auto-sized dropdown (a 10,000-option one is sized by these)
MEASURED_OPTIONS = 200


class Sizer:
    """Looks and natural sizes for one layout pass (see the module docstring)."""

    def __init__(self, theme: Theme, scale: float, text_scale: float, measure: TextMeasure,
                 styles: dict[int, Style]) -> None:  # fmt: skip
        self.theme, self.scale, self.text_scale = theme, scale, text_scale
        self.measure, self.styles = measure, styles
        self._looks: dict[tuple[Any, ...], Look] = {}
        self._widths: dict[tuple[str, Font], float] = {}
        self._lines: dict[Font, float] = {}

    def same(self, theme: Theme, scale: float, text_scale: float,
             measure: TextMeasure | None) -> bool:  # fmt: skip
        """Does this sizer answer for these settings (so its caches stay good)?"""
        return (theme is self.theme and scale == self.scale and text_scale == self.text_scale
                and (measure is None or measure is self.measure))  # fmt: skip

    def restyle(self, styles: dict[int, Style]) -> None:
        """The entities' own styles of a new layout (looks resolved for them are dropped)."""
        if styles != self.styles:
            self.styles = styles
            self._looks.clear()
        if len(self._widths) > 20_000:  # texts that come and go (a timer): keep it bounded
            self._widths.clear()

    def look(self, e: int | None, kind: str, state: str = "normal") -> Look:
        own = self.styles.get(e) if e is not None else None
        key = (id(own), kind, state)
        got = self._looks.get(key)
        if got is None:
            got = self._looks[key] = look(self.theme, kind, state, own, self.scale,
                                          self.text_scale)  # fmt: skip
        return got

    def line(self, font: Font) -> float:
        got = self._lines.get(font)
        if got is None:
            got = self._lines[font] = self.measure.line_height(font)
        return got

    def width(self, text: str, font: Font) -> float:
        if len(text) > 256:  # not worth keeping (a 100,000-character label)
            return width(self.measure, text, font)
        key = (text, font)
        got = self._widths.get(key)
        if got is None:
            got = self._widths[key] = width(self.measure, text, font)
        return got

    def row_height(self, e: int, declared: float | None, font: Font) -> float:
        """A list or tree row: the declared height, else the theme's (at least a line of
        text, so a larger text scale makes the rows taller)."""
        if declared is not None:
            return declared * self.scale
        return max(self.theme.row_height * self.scale, self.line(font) + 2 * self.scale)

    # -- text blocks ------------------------------------------------------------------------------
    def label_font(self, e: int, w: Label | RichText) -> Font:
        f = self.look(e, type(w).__name__).font
        if w.size is not None:
            f = Font(f.name, w.size * self.scale * self.text_scale, f.bold, f.italic)
        return f

    def label_lines(self, e: int, w: Label, max_width: float | None) -> list[str]:
        font = self.label_font(e, w)
        text = w.text
        spans = wrap(self.measure, text, font, max_width if w.wrap else None)
        return [visible(text[a:b]) for a, b in spans]

    def rich_lines(self, e: int, w: RichText, max_width: float | None) -> list[list[Piece]]:
        """Lines of (text, run, font) pieces, broken at newlines and, when ``wrap``,
        between words at ``max_width`` (a word longer than a line between characters)."""
        base = self.label_font(e, w)
        room = max_width if w.wrap else None
        lines: list[list[Piece]] = [[]]
        x = 0.0
        for run in w.runs:
            size = run.size * self.scale * self.text_scale if run.size else base.size
            font = Font(base.name, size, run.bold or base.bold, run.italic or base.italic)
            for k, part in enumerate(run.text.split("\n")):
                if k:
                    lines.append([])
                    x = 0.0
                for token in _TOKENS.findall(part):
                    tw = self.width(token, font)
                    if room is not None and x > 0 and x + self.width(token.rstrip(), font) > room:
                        lines.append([])
                        x = 0.0
                    spans = [(0, len(token))]
                    if room is not None and tw > room:
                        spans = wrap(self.measure, token, font, room)
                    for i, (a, b) in enumerate(spans):
                        if i:
                            lines.append([])
                            x = 0.0
                        piece = visible(token[a:b])
                        last = lines[-1][-1] if lines[-1] else None
                        if last is not None and last[1] is run:
                            lines[-1][-1] = (last[0] + piece, run, font)
                        else:
                            lines[-1].append((piece, run, font))
                        x += self.width(token[a:b], font)
        return lines

    # -- natural sizes ----------------------------------------------------------------------------
    def intrinsic(self, e: int, w: Any, avail_w: float) -> tuple[float, float]:
        """The size an ``"auto"`` node with this widget and no children takes."""
        s = self.scale
        kind = type(w).__name__
        lk = self.look(e, kind)
        f, pad = lk.font, lk.padding
        line = self.line(f)
        if isinstance(w, Label):
            lines = self.label_lines(e, w, avail_w if w.wrap else None)
            font = self.label_font(e, w)
            wide = max((self.width(t, font) for t in lines), default=0.0)
            return (wide + 4 * s, self.line(font) * max(len(lines), 1))
        if isinstance(w, RichText):
            rl = self.rich_lines(e, w, avail_w)
            wide = max((sum(self.width(t, fo) for t, _, fo in ln) for ln in rl), default=0.0)
            return (wide + 4 * s, sum(self.rich_line_heights(e, w, rl)))
        if isinstance(w, Button):
            icon = line if w.image is not None else 0.0
            gap = 6 * s if (icon and w.text) else 0.0
            return (max(self.width(w.text, f) + icon + gap + 2 * pad, line + pad), line + pad)
        if isinstance(w, Toggle):
            return (line + 8 * s + self.width(w.text, f), line)
        if isinstance(w, RadioGroup):
            widths = [line + 8 * s + self.width(o, f) for o in w.options[:MEASURED_OPTIONS]]
            if w.horizontal:
                return (sum(widths) + 12 * s * max(len(widths) - 1, 0), line)
            return (max(widths, default=line), line * max(len(w.options), 1))
        if isinstance(w, Slider):
            return (160.0 * s, line)
        if isinstance(w, ProgressBar):
            return (160.0 * s, 14.0 * s)
        if isinstance(w, SpinBox):
            return (140.0 * s, line + pad)
        if isinstance(w, TextInput):
            return (220.0 * s, line + pad)
        if isinstance(w, TextArea):
            return (320.0 * s, line * 5 + pad)
        if isinstance(w, Dropdown):
            longest = max((self.width(o, f) for o in w.options[:MEASURED_OPTIONS]), default=40 * s)
            return (longest + 2 * pad + line, line + pad)
        if isinstance(w, ScrollList):
            return (220.0 * s, self.row_height(e, w.row_height, f) * 5)
        if isinstance(w, TreeView):
            return (240.0 * s, self.row_height(e, w.row_height, f) * 8)
        if isinstance(w, Tabs):
            return (sum(self.width(t, f) + 2 * pad for t in w.labels), line + pad)
        if isinstance(w, ColorPicker):
            return (240.0 * s, 200.0 * s)
        if isinstance(w, UIImage):
            return (64.0 * s, 64.0 * s)
        return (0.0, 0.0)

    def rich_line_heights(self, e: int, w: RichText, lines: list[list[Piece]]) -> list[float]:
        """Each line's height: its tallest piece's, plus ``line_spacing`` between lines."""
        plain = self.line(self.label_font(e, w))
        gap = w.line_spacing * self.scale
        out = [max((self.line(fo) for _, _, fo in ln), default=plain) for ln in lines]
        return [h + (gap if i < len(out) - 1 else 0.0) for i, h in enumerate(out)]

    def title_bar(self, e: int, title: str) -> float:
        """The height of a dialog's title bar (0 without a title)."""
        if not title:
            return 0.0
        lk = self.look(e, "Dialog")
        return self.line(lk.font) + lk.padding

    def tab_bar(self, e: int, w: Tabs) -> float:
        lk = self.look(e, "Tabs")
        return self.line(lk.font) + lk.padding

    def caret_xs(self, text: str, font: Font) -> list[float]:
        return positions(self.measure, text, font)
