"""Line layout: styled spans into lines and placed glyphs, for any font source.

The layout works in *em* metrics (advances, kerning, ascent, descent and line
height as fractions of the font size), so a text laid out at 16 px and at 32 px
has exactly the same line breaks and a box exactly twice as big: zooming world
text re-rasterises it without moving a word. Units out are pixels of the text's
own space (screen pixels, or font pixels at zoom 1 for world text), y up, origin
at the bottom-left of the box.

What it does, in order:

1. **shape**: each character gets the first face of its style's chain that has it
   (the fallbacks), an advance (plus kerning with the previous character of the
   same face, plus ``letter_spacing``); ``"\\n"`` ends a paragraph, ``"\\t"`` is four
   spaces, other control characters and zero-width joiners take no room and draw
   nothing (never a missing-glyph box);
2. **break**: greedy lines at most ``width`` wide, breaking after spaces, hyphens
   and around CJK ideographs; a word longer than the line breaks between letters;
   trailing spaces hang past the edge;
3. **stack**: each line box is its tallest font's line height times
   ``line_spacing``, with the baseline in the middle of the leading (the CSS model);
4. **overflow**: lines past ``max_lines`` or ``height`` are dropped (``clip``), or the
   last kept line ends with an ellipsis (``ellipsis``), or the whole text is laid
   out again smaller until it fits (``shrink``, a binary search on the size);
5. **align**: lines sit left, centred, right or justified in the box, and the block
   sits top, centre or bottom in it (``valign``).

>>> from kge.components.text import TextStyle
>>> from kge.text.markup import Span
>>> src = MonoSource()                      # every glyph 0.5 em wide
>>> out = layout([Span("hello world")], TextStyle(size=12, width=40), src)
>>> [line.text for line in out.lines], out.width
(['hello', 'world'], 40.0)
>>> out.lines[0].width                      # 5 glyphs of 8 px (12 pt = 16 px)
40.0
"""

from __future__ import annotations

import math
import unicodedata
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Protocol

from kge.components.text import TextOverflow, TextStyle
from kge.text.markup import Span

RGBA = tuple[int, int, int, int]
ELLIPSIS = "\u2026"
_ZERO_WIDTH = frozenset("\u200c\u200d\u2060\ufeff\u00ad") | frozenset(
    chr(c) for c in range(0xFE00, 0xFE10)
)
_NEWLINES = frozenset("\n\u2028\u2029\x0b\x0c\x85")
_SPACES = frozenset(" \u3000\u1680\u2000\u2001\u2002\u2003\u2004\u2005\u2006\u2008\u2009\u200a")
_BREAK_AFTER = frozenset("-\u2010\u2013\u2014/")
_TAB_SPACES = 4
#: smallest size ``overflow="shrink"`` goes down to, as a share of the style's size
MIN_SHRINK = 0.05


class Face(Protocol):
    """One font face's metrics in em units (``size`` pixels per em)."""

    @property
    def ascent(self) -> float:
        """Height above the baseline, em (> 0)."""

    @property
    def descent(self) -> float:
        """Depth below the baseline, em (< 0)."""

    @property
    def line_height(self) -> float:
        """Distance between baselines at line spacing 1, em."""

    def has(self, ch: str) -> bool:
        """Whether the face draws ``ch`` (else a fallback face is tried)."""

    def advance(self, ch: str) -> float:
        """Pen advance of ``ch``, em."""

    def kerning(self, left: str, right: str) -> float:
        """Extra advance between ``left`` and ``right``, em (usually <= 0)."""


class FaceSource(Protocol):
    """Where faces come from: a chain (primary first, then fallbacks) per style."""

    def faces(self, family: str | None, weight: int, italic: bool) -> Sequence[Face]:
        """The faces to try for a character of this style, best first (never empty)."""

    def icon_size(self, name: str) -> tuple[float, float] | None:
        """The natural pixel size of an inline image, or None if unknown."""


@dataclass(slots=True)
class PlacedGlyph:
    """A character (or inline image) at its place: pen ``x`` and ``baseline``, y up."""

    char: str
    face: Face | None
    size: float  #: font pixels per em
    x: float
    baseline: float
    color: RGBA
    #: (name, width px, height px) of an inline image; ``char`` is "" then
    icon: tuple[str, float, float] | None = None
    #: the icon's bottom edge (y up), for images
    bottom: float = 0.0


@dataclass(slots=True)
class Line:
    """A laid-out line: its box (x, y bottom, width, height), baseline and text."""

    x: float
    y: float
    width: float
    height: float
    baseline: float
    text: str


@dataclass(slots=True)
class TextLayout:
    """The result: the box, its lines and glyphs, and what overflow did."""

    width: float
    height: float
    lines: list[Line] = field(default_factory=list)
    glyphs: list[PlacedGlyph] = field(default_factory=list)
    #: some text was dropped (clip, ellipsis, max_lines)
    truncated: bool = False
    #: size factor ``overflow="shrink"`` applied (1: none)
    scale: float = 1.0
    content_width: float = 0.0
    content_height: float = 0.0


@dataclass(slots=True)
class _Item:
    ch: str
    face: Face | None
    size: float
    advance: float
    color: RGBA
    asc: float
    desc: float
    lh: float
    space: bool = False
    brk: bool = False
    draw: bool = True
    icon: tuple[str, float, float] | None = None


@dataclass(slots=True)
class _RawLine:
    items: list[_Item]
    asc: float
    desc: float
    lh: float
    ends_paragraph: bool
    width: float = 0.0


def _is_cjk(ch: str) -> bool:
    o = ord(ch)
    return (
        0x2E80 <= o <= 0x9FFF
        or 0xAC00 <= o <= 0xD7AF
        or 0xF900 <= o <= 0xFAFF
        or 0xFF00 <= o <= 0xFFEF
        or 0x20000 <= o <= 0x2FA1F
    )


class _Shaper:
    """Turns spans into paragraphs of items (see step 1 of the module docstring)."""

    def __init__(self, style: TextStyle, source: FaceSource, scale: float) -> None:
        self.style = style
        self.source = source
        self.scale = scale
        self.base_color: RGBA = style.color  # type: ignore[assignment]

    def base_metrics(self) -> tuple[float, float, float]:
        """(ascent, descent, line height) px of the base style, for empty lines."""
        face = self.source.faces(self.style.font, int(self.style.weight), self.style.italic)[0]
        size = self.style.pixel_size * self.scale
        return face.ascent * size, face.descent * size, face.line_height * size

    def shape(self, spans: Sequence[Span]) -> list[list[_Item]]:
        st = self.style
        paragraphs: list[list[_Item]] = [[]]
        spacing = st.letter_spacing * self.scale
        for span in spans:
            family = span.font if span.font is not None else st.font
            weight = span.weight if span.weight is not None else int(st.weight)
            italic = span.italic if span.italic is not None else st.italic
            size = (span.size if span.size is not None else st.size) * 4.0 / 3.0 * self.scale
            color = span.color if span.color is not None else self.base_color
            chain = self.source.faces(family, weight, italic)
            if span.icon is not None:
                paragraphs[-1].append(self._icon(span.icon, chain[0], size, color))
                continue
            text = span.text.replace("\r\n", "\n").replace("\r", "\n")
            for ch in text:
                if ch in _NEWLINES:
                    paragraphs.append([])
                    continue
                para = paragraphs[-1]
                face = next((f for f in chain if f.has(ch)), chain[0])
                asc, desc, lh = face.ascent * size, face.descent * size, face.line_height * size
                if ch == "\t":
                    adv = face.advance(" ") * size * _TAB_SPACES + spacing
                    para.append(_Item(" ", face, size, adv, color, asc, desc, lh,
                                      space=True, brk=True, draw=False))  # fmt: skip
                    continue
                if ch == "\u200b":  # zero-width space: a break opportunity, no room
                    para.append(_Item("", face, size, 0.0, color, asc, desc, lh,
                                      brk=True, draw=False))  # fmt: skip
                    continue
                if ch in _ZERO_WIDTH or unicodedata.category(ch) in ("Cc", "Cf", "Cs"):
                    continue
                adv = face.advance(ch) * size
                if para and para[-1].face is face and para[-1].size == size and para[-1].draw:
                    para[-1].advance += face.kerning(para[-1].ch, ch) * size
                cjk = _is_cjk(ch)
                if cjk and para:
                    para[-1].brk = True
                space = ch in _SPACES
                item = _Item(ch, face, size, adv + spacing, color, asc, desc, lh, space,
                             space or cjk or ch in _BREAK_AFTER)  # fmt: skip
                para.append(item)
        return paragraphs

    def _icon(
        self, icon: tuple[str, float, float], face: Face, size: float, color: RGBA
    ) -> _Item:
        name, w, h = icon
        if w <= 0 or h <= 0:
            natural = self.source.icon_size(name) or (size, size)
            h = size
            w = natural[0] * h / max(natural[1], 1e-9)
        else:
            w, h = w * self.scale, h * self.scale
        # centred on the middle of the capitals: about 0.35 em above the baseline
        mid = 0.35 * size
        asc, desc = max(mid + h / 2, face.ascent * size), min(mid - h / 2, face.descent * size)
        return _Item("", face, size, w, color, asc, desc, max(asc - desc, face.line_height * size),
                     icon=(name, w, h))  # fmt: skip


def _line_of(items: list[_Item], ends: bool, base: tuple[float, float, float]) -> _RawLine:
    shown = items
    while shown and shown[-1].space:
        shown = shown[:-1]
    width = sum(i.advance for i in shown)
    if not items:
        return _RawLine([], base[0], base[1], base[2], ends, 0.0)
    asc = max(i.asc for i in items)
    desc = min(i.desc for i in items)
    lh = max(i.lh for i in items)
    return _RawLine(items, asc, desc, lh, ends, width)


def _break(para: list[_Item], width: float | None, base: tuple[float, float, float]
           ) -> list[_RawLine]:  # fmt: skip
    """Greedy line breaking of one paragraph (step 2)."""
    if width is None or not para:
        return [_line_of(para, True, base)]
    lines: list[_RawLine] = []
    start, n = 0, len(para)
    while start < n:
        x = 0.0
        last_break = -1
        i = start
        end = n
        while i < n:
            it = para[i]
            if not it.space and i > start and x + it.advance > width + 1e-6:
                end = last_break if last_break > start else i
                break
            x += it.advance
            if it.brk:
                last_break = i + 1
            i += 1
        lines.append(_line_of(para[start:end], end >= n, base))
        start = end
        while start < n and para[start].space:  # a wrapped line starts at a word
            start += 1
    return lines


def _ellipsize(line: _RawLine, width: float | None, shaper: _Shaper) -> None:
    """End ``line`` with an ellipsis, dropping characters until it fits ``width``."""
    items = list(line.items)
    last = items[-1] if items else None
    face = last.face if last is not None and last.face is not None else None
    if face is None:
        face = shaper.source.faces(shaper.style.font, int(shaper.style.weight),
                                   shaper.style.italic)[0]  # fmt: skip
    size = last.size if last is not None else shaper.style.pixel_size * shaper.scale
    color = last.color if last is not None else shaper.base_color
    glyph = ELLIPSIS if face.has(ELLIPSIS) else "..."
    dots = [
        _Item(c, face, size, face.advance(c) * size, color, face.ascent * size,
              face.descent * size, face.line_height * size)
        for c in glyph
    ]  # fmt: skip
    room = sum(d.advance for d in dots)
    def too_wide() -> bool:
        return width is not None and sum(i.advance for i in items) + room > width + 1e-6

    while items and (items[-1].space or too_wide()):
        items.pop()
    new = _line_of(items + dots, line.ends_paragraph, (line.asc, line.desc, line.lh))
    line.items, line.width = new.items, new.width
    line.asc, line.desc, line.lh = new.asc, new.desc, new.lh


def _stack(lines: list[_RawLine], spacing: float) -> list[tuple[float, float]]:
    """(top, baseline) of each line from the top of the block, downwards (step 3)."""
    out = []
    y = 0.0
    for ln in lines:
        box = ln.lh * spacing
        half_leading = (box - (ln.asc - ln.desc)) / 2
        out.append((y, y + half_leading + ln.asc))
        y += box
    return out


def _lay(spans: Sequence[Span], style: TextStyle, source: FaceSource, scale: float
         ) -> tuple[list[_RawLine], bool, bool]:  # fmt: skip
    """Lines at ``scale``: (lines kept, truncated, broke inside a word)."""
    shaper = _Shaper(style, source, scale)
    base = shaper.base_metrics()
    width = style.width if style.wrap else None
    lines: list[_RawLine] = []
    split_word = False
    for para in shaper.shape(spans):
        got = _break(para, width, base)
        for ln in got[:-1]:
            if ln.items and not ln.items[-1].brk and not ln.items[-1].space:
                split_word = True
        lines.extend(got)
    limit = style.max_lines if style.max_lines is not None else len(lines)
    if style.height is not None and style.overflow != "visible":
        fit, y = 0, 0.0
        for ln in lines:
            y += ln.lh * style.line_spacing
            if y > style.height + 1e-6 and fit > 0:
                break
            fit += 1
        limit = min(limit, max(fit, 1))
    truncated = len(lines) > limit
    if truncated:
        lines = lines[:limit]
        if style.overflow == "ellipsis":
            _ellipsize(lines[-1], style.width, shaper)
    if style.overflow == "ellipsis" and style.width is not None:
        for ln in lines:
            if ln.width > style.width + 1e-6:
                _ellipsize(ln, style.width, shaper)
                truncated = True
    return lines, truncated, split_word


def _fits(lines: list[_RawLine], truncated: bool, split_word: bool, style: TextStyle) -> bool:
    if truncated or split_word:
        return False
    if style.width is not None and any(ln.width > style.width + 1e-6 for ln in lines):
        return False
    height = sum(ln.lh * style.line_spacing for ln in lines)
    return style.height is None or height <= style.height + 1e-6


def layout(spans: Sequence[Span], style: TextStyle, source: FaceSource) -> TextLayout:
    """Lay ``spans`` out in ``style`` with faces from ``source`` (see the module docstring)."""
    scale = 1.0
    if style.overflow == "shrink":
        probe = style.replace(overflow=TextOverflow.VISIBLE)
        if not _fits(*_lay(spans, probe, source, 1.0), style):
            lo, hi = max(MIN_SHRINK, 1.0 / max(style.size, 1.0)), 1.0
            for _ in range(12):  # the largest size that fits, to 0.1 %
                mid = math.sqrt(lo * hi)
                if _fits(*_lay(spans, probe, source, mid), style):
                    lo = mid
                else:
                    hi = mid
            scale = lo
        lines, truncated, _ = _lay(spans, style.replace(overflow=TextOverflow.CLIP), source, scale)
    else:
        lines, truncated, _ = _lay(spans, style, source, 1.0)
    return _place(lines, truncated, scale, style)


def _place(lines: list[_RawLine], truncated: bool, scale: float, style: TextStyle) -> TextLayout:
    """Boxes and glyph positions, y up from the box's bottom-left (step 5)."""
    stacked = _stack(lines, style.line_spacing)
    content_h = sum(ln.lh * style.line_spacing for ln in lines)
    content_w = max((ln.width for ln in lines), default=0.0)
    box_w = style.width if style.width is not None else content_w
    box_h = style.height if style.height is not None else content_h
    free = box_h - content_h
    if free < 0 and style.overflow != "visible":
        free = 0.0  # clipped text keeps its first lines in view
    top = {"top": 0.0, "center": free / 2, "bottom": free}[style.valign]
    out = TextLayout(box_w, box_h, truncated=truncated, scale=scale,
                     content_width=content_w, content_height=content_h)  # fmt: skip
    for ln, (line_top, baseline_down) in zip(lines, stacked, strict=True):
        extra = box_w - ln.width
        x0 = {"left": 0.0, "center": extra / 2, "right": extra, "justify": 0.0}[style.align]
        gap = 0.0
        if style.align == "justify" and not ln.ends_paragraph and extra > 0:
            inner = _inner_spaces(ln.items)
            gap = extra / inner if inner else 0.0
        baseline = box_h - (top + baseline_down)
        box_top = box_h - (top + line_top)
        lh = ln.lh * style.line_spacing
        width = ln.width + (gap * _inner_spaces(ln.items) if gap else 0.0)
        last_shown = len(ln.items)
        while last_shown and ln.items[last_shown - 1].space:
            last_shown -= 1
        text = "".join(i.ch for i in ln.items[:last_shown])
        out.lines.append(Line(x0, box_top - lh, width, lh, baseline, text))
        x = x0
        for k, it in enumerate(ln.items):
            if it.icon is not None:
                mid = baseline + 0.35 * it.size
                out.glyphs.append(PlacedGlyph("", it.face, it.size, x, baseline, it.color,
                                              it.icon, mid - it.icon[2] / 2))  # fmt: skip
            elif it.draw and not it.space and it.ch:
                out.glyphs.append(PlacedGlyph(it.ch, it.face, it.size, x, baseline, it.color))
            x += it.advance
            if it.space and gap and k < last_shown:
                x += gap
    return out


def _inner_spaces(items: list[_Item]) -> int:
    end = len(items)
    while end and items[end - 1].space:
        end -= 1
    start = 0
    while start < end and items[start].space:
        start += 1
    return sum(1 for i in items[start:end] if i.space)


class MonoFace:
    """A made-up monospaced face (tests and doctests): every glyph ``width`` em wide."""

    ascent = 0.8
    descent = -0.2
    line_height = 1.2

    def __init__(self, width: float = 0.5, missing: str = "") -> None:
        self.width = width
        self.missing = frozenset(missing)

    def has(self, ch: str) -> bool:
        return ch not in self.missing

    def advance(self, ch: str) -> float:
        return self.width

    def kerning(self, left: str, right: str) -> float:
        return 0.0


class MonoSource:
    """A :class:`FaceSource` of :class:`MonoFace` (no font files, no GL)."""

    def __init__(self, width: float = 0.5) -> None:
        self.face = MonoFace(width)

    def faces(self, family: str | None, weight: int, italic: bool) -> Sequence[Face]:
        return (self.face,)

    def icon_size(self, name: str) -> tuple[float, float] | None:
        return None
