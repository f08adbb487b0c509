"""Where text sits inside text fields: caret positions, scrolling, lines of a text area.

Shared by the input handling (a click puts the caret on the character under it)
and the drawing (the caret is drawn where the input handling thinks it is). Both
measure with the world's text measure and keep the caret in view the same way.
"""

from __future__ import annotations

from dataclasses import dataclass

from kge.components.ui import SpinBox, TextArea, TextInput
from kge.ui.layout import Box
from kge.ui.measure import Font, positions, wrap
from kge.ui.sizing import Sizer
from kge.ui.state import UIState
from kge.ui.style import Look

BULLET = "•"


@dataclass(slots=True)
class FieldView:
    """A one-line field's text as shown: where it starts, its caret x positions (from
    the text's start) and how far it is scrolled left."""

    area: Box  #: where text is drawn (the box less padding)
    shown: str
    xs: list[float]
    scroll: float

    def x_of(self, i: int) -> float:
        return self.area.x + self.xs[min(max(i, 0), len(self.xs) - 1)] - self.scroll

    def index_at(self, x: float) -> int:
        target = x - self.area.x + self.scroll
        xs = self.xs
        best = 0
        for i, v in enumerate(xs):
            if abs(v - target) < abs(xs[best] - target):
                best = i
        return best


def shown_text(w: TextInput | SpinBox, text: str) -> str:
    return BULLET * len(text) if isinstance(w, TextInput) and w.password else text


def field_view(sizer: Sizer, state: UIState, e: int, text: str, caret: int, box: Box,
               look: Look, shown: str) -> FieldView:  # fmt: skip
    """The view of a one-line field, scrolled so the caret is inside it."""
    pad = look.padding
    area = Box(box.x + pad, box.y, max(box.w - 2 * pad, 1.0), box.h)
    comp = state.composition
    if comp is not None and comp[0] == e:  # an IME's text shows at the caret
        shown = shown[:caret] + comp[1] + shown[caret:]
    xs = positions(sizer.measure, shown, look.font)
    scroll = state.text_scroll.get(e, 0.0)
    cx = xs[min(max(caret, 0), len(xs) - 1)]
    margin = min(area.w * 0.25, 24.0)
    if cx - scroll > area.w - 2:
        scroll = cx - area.w + margin
    elif cx - scroll < 0:
        scroll = max(cx - margin, 0.0)
    scroll = min(max(scroll, 0.0), max(xs[-1] - area.w + 2, 0.0))
    state.text_scroll[e] = scroll
    return FieldView(area, shown, xs, scroll)


@dataclass(slots=True)
class AreaView:
    """A text area's lines as shown: spans of the text, the area they scroll in, the
    line height, and the largest vertical scroll."""

    view: Box
    lines: list[tuple[int, int]]
    line_h: float
    max_scroll: float
    font: Font
    bar: bool  #: a scrollbar is shown

    def line_of(self, i: int) -> int:
        """The line holding caret position ``i`` (the later one at a wrap)."""
        lo, hi = 0, len(self.lines) - 1
        while lo < hi:
            mid = (lo + hi + 1) // 2
            if self.lines[mid][0] <= i:
                lo = mid
            else:
                hi = mid - 1
        return lo

    def line_top(self, line: int, scroll: float) -> float:
        return self.view.top - line * self.line_h + scroll


def area_view(sizer: Sizer, state: UIState, e: int, w: TextArea, box: Box, look: Look) -> AreaView:
    """The lines of a text area (cached until its text, width or font changes)."""
    pad = look.padding * 0.6
    inner = box.inset(pad)
    font = look.font
    line_h = sizer.line(font)
    bar = sizer.theme.scrollbar * sizer.scale
    key = ("area", e)
    stamp = (w.text, inner.w, font, w.wrap)
    cached = state.caches.get(key)
    if cached is not None and cached[0] == stamp:
        lines, has_bar = cached[1], cached[2]
    else:
        lines = wrap(sizer.measure, w.text, font, inner.w if w.wrap else None)
        has_bar = len(lines) * line_h > inner.h
        if has_bar and w.wrap:
            lines = wrap(sizer.measure, w.text, font, max(inner.w - bar, 1.0))
        state.caches[key] = (stamp, lines, has_bar)
    view = Box(inner.x, inner.y, max(inner.w - (bar if has_bar else 0.0), 1.0), inner.h)
    return AreaView(view, lines, line_h, max(len(lines) * line_h - view.h, 0.0), font, has_bar)
