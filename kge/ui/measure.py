"""Measuring text: advances, caret positions, hit-testing a click, eliding and wrapping.

Layout, caret placement and drawing all measure through one :class:`TextMeasure`
(the ``measure`` of the world's :class:`~kge.ui.state.UIState`), so a click lands
on the character drawn under it. Headless, :class:`TableMeasure` reads DejaVu Sans
advances from a table (pyglet's default font on Debian; no font renderer needed);
once a frame is drawn the renderer installs a measure that asks the real font
(:mod:`kge.render.ui_text`). Every helper here works with either.

Sizes are points, as in pyglet (1 pt = 96/72 pixels):

>>> m = TableMeasure()
>>> font = Font(size=12)
>>> width(m, "Hello", font)              # pyglet draws it 40 px wide too
40.0
>>> positions(m, "Hello", font)
[0.0, 12.0, 22.0, 26.0, 30.0, 40.0]
>>> index_at(m, "Hello", font, 20.0)    # a click 20 px in: the caret goes before "l"
2
>>> elide(m, "Hello world", font, 40.0)
'He…'
>>> [("Hello world, hi"[a:b]) for a, b in wrap(m, "Hello world, hi", font, 80.0)]
['Hello ', 'world, hi']
"""

from __future__ import annotations

import bisect
import math
import unicodedata
from collections.abc import Callable, Mapping
from itertools import accumulate
from typing import NamedTuple, Protocol

from kge.ui import font_metrics as fm

POINT = 96.0 / 72.0  #: pixels per point (pyglet's 96 dpi)
ELLIPSIS = "…"


class Font(NamedTuple):
    """Which font text is measured and drawn with (``name`` None: the default)."""

    name: str | None = None
    size: float = 16.0  #: points
    bold: bool = False
    italic: bool = False


class Advances(dict[str, float]):
    """A font's advances by character, each measured once (on first use) by ``fn``."""

    __slots__ = ("fn",)

    def __init__(self, fn: Callable[[str], float]) -> None:
        super().__init__()
        self.fn = fn

    def __missing__(self, ch: str) -> float:
        v = self[ch] = self.fn(ch)
        return v


class TextMeasure(Protocol):
    """What the UI needs to know of a font."""

    def advances(self, font: Font) -> Mapping[str, float]:
        """Pixels the pen moves after drawing each character (0 for control characters):
        ``advances(font)[ch]``, measured once per character and kept."""
        ...

    def line_height(self, font: Font) -> float:
        """Pixels from one line's top to the next one's."""
        ...

    def ascent(self, font: Font) -> float:
        """Pixels from a line's top to its baseline."""
        ...


def is_control(ch: str) -> bool:
    """A character that is never drawn (C0/C1 controls, DEL); newlines break lines."""
    o = ord(ch)
    return o < 0x20 or 0x7F <= o < 0xA0


class TableMeasure:
    """Advances from the DejaVu Sans table (regular and bold; italic measures as regular),
    rounded to whole pixels per glyph as a hinting renderer does."""

    def __init__(self) -> None:
        self._fonts: dict[Font, Advances] = {}

    def advances(self, font: Font) -> Advances:
        got = self._fonts.get(font)
        if got is None:
            size, bold = font.size, font.bold
            got = self._fonts[font] = Advances(lambda ch: _table_advance(ch, size, bold))
        return got

    def line_height(self, font: Font) -> float:
        px = font.size * POINT
        return self.ascent(font) + float(math.ceil(-fm.DESCENT * px / fm.UNITS_PER_EM))

    def ascent(self, font: Font) -> float:
        return float(math.ceil(fm.ASCENT * font.size * POINT / fm.UNITS_PER_EM))


def _table_advance(ch: str, size: float, bold: bool) -> float:
    if is_control(ch):
        return 0.0
    table = fm.BOLD if bold else fm.REGULAR
    units = table.get(ord(ch))
    if units is None:
        if unicodedata.combining(ch):
            return 0.0
        wide = unicodedata.east_asian_width(ch) in ("W", "F")
        units = fm.UNITS_PER_EM if wide else round(fm.UNITS_PER_EM * 0.6)
    return float(round(units * size * POINT / fm.UNITS_PER_EM))


def width(m: TextMeasure, text: str, font: Font) -> float:
    """The width of one line of ``text`` in pixels."""
    return float(sum(map(m.advances(font).__getitem__, text)))


def positions(m: TextMeasure, text: str, font: Font) -> list[float]:
    """x of every caret position 0..len(text), from the start of the line."""
    return list(accumulate(map(m.advances(font).__getitem__, text), initial=0.0))


def index_at(m: TextMeasure, text: str, font: Font, x: float) -> int:
    """The caret position nearest to ``x`` pixels from the line's start (a click)."""
    xs = positions(m, text, font)
    i = bisect.bisect_left(xs, x)
    if i <= 0:
        return 0
    if i >= len(xs):
        return len(text)
    return i if xs[i] - x < x - xs[i - 1] else i - 1


def elide(m: TextMeasure, text: str, font: Font, max_width: float) -> str:
    """``text`` cut to fit ``max_width`` pixels, ending in an ellipsis when cut.

    Only the characters that fit are measured, so a 100,000-character label costs
    what its visible part does.
    """
    adv = m.advances(font)
    room = max_width
    x = 0.0
    for i, ch in enumerate(text):
        x += adv[ch]
        if x > room:
            keep = room - adv[ELLIPSIS]
            cut = 0
            y = 0.0
            for j in range(i):
                y += adv[text[j]]
                if y > keep:
                    break
                cut = j + 1
            return text[:cut] + ELLIPSIS if keep >= 0 else ""
    return text


def visible(text: str) -> str:
    """``text`` without the characters that are never drawn (controls; newlines too)."""
    if text.isprintable():
        return text
    return "".join(ch for ch in text if not is_control(ch))


def wrap(m: TextMeasure, text: str, font: Font, max_width: float | None) -> list[tuple[int, int]]:
    """Line spans ``(start, end)`` of ``text``: broken at newlines and, when
    ``max_width`` is given, before a word that would pass it (a word longer than a
    line is broken between characters). Spaces stay at the end of their line; the
    newline itself belongs to no span."""
    lines: list[tuple[int, int]] = []
    adv = m.advances(font)
    start = 0
    n = len(text)
    while True:
        nl = text.find("\n", start)
        end = n if nl < 0 else nl
        if max_width is None:
            lines.append((start, end))
        else:
            _wrap_line(text, start, end, max_width, adv, lines)
        if nl < 0:
            return lines
        start = nl + 1


def _wrap_line(text: str, start: int, end: int, max_width: float,
               adv: Mapping[str, float], lines: list[tuple[int, int]]) -> None:  # fmt: skip
    line = start
    x = 0.0
    brk = -1  # index after the last space on this line
    i = start
    while i < end:
        ch = text[i]
        w = adv[ch]
        if ch == " ":
            brk = i + 1
            x += w
            i += 1
            continue
        if x + w > max_width and i > line:
            cut = brk if brk > line else i
            lines.append((line, cut))
            line = cut
            brk = -1
            x = sum(adv[c] for c in text[line:i])
            continue
        x += w
        i += 1
    lines.append((line, end))
