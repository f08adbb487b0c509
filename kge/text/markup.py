"""Rich-text markup: BBCode-style tags into styled spans.

Tags (nest freely; every tag but ``[img]`` needs its closing ``[/tag]``):

========================  ============================================================
``[b]...[/b]``            bold (weight 700)
``[i]...[/i]``            italic
``[weight=light]``        any weight: a name (``thin`` .. ``black``) or 100..900
``[color=#ff8800]``       ``#rgb``, ``#rrggbb``, ``#rrggbbaa``, a name (``red``...) or
                          ``r,g,b[,a]``
``[size=24]``             font size in points
``[font=DejaVu Serif]``   another family (or font file)
``[img]coin.png[/img]``   an inline image, as tall as the line's font; ``[img=20x16]``
                          sets its size in pixels
``[lb]`` / ``[rb]``       a literal ``[`` / ``]``
========================  ============================================================

A tag that is unknown, unclosed or closed out of order raises a ``ValidationError``
naming it, so a typo shows at the call, not as odd text on screen.

>>> [(s.text, s.weight, s.color) for s in parse("a [b]b[/b] [color=#f00]c[/color]")]
[('a ', None, None), ('b', 700, None), (' ', None, None), ('c', None, (255, 0, 0, 255))]
>>> parse("[img=8x8]coin.png[/img] x")[0].icon
('coin.png', 8.0, 8.0)
>>> plain("[b]Gold[/b]: 3 [lb]max[rb]")
'Gold: 3 [max]'
>>> parse("[b]oops")
Traceback (most recent call last):
...
kge.errors.ValidationError: markup: [b] is never closed
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace

from kge.components.text import MAX_FONT_SIZE, WEIGHTS
from kge.errors import ValidationError

#: colour names the ``[color=...]`` tag knows
COLORS: dict[str, tuple[int, int, int, int]] = {
    "white": (255, 255, 255, 255), "black": (0, 0, 0, 255), "red": (230, 40, 40, 255),
    "green": (60, 200, 80, 255), "blue": (60, 110, 240, 255), "yellow": (250, 220, 50, 255),
    "orange": (255, 150, 30, 255), "cyan": (40, 220, 230, 255), "magenta": (230, 60, 220, 255),
    "purple": (150, 80, 220, 255), "pink": (255, 140, 190, 255), "gray": (150, 150, 150, 255),
    "grey": (150, 150, 150, 255), "brown": (140, 90, 50, 255), "gold": (255, 200, 40, 255),
    "transparent": (0, 0, 0, 0),
}  # fmt: skip

_TAG = re.compile(r"\[(/?)([a-z]+)(?:=([^\]]*))?\]")


@dataclass(slots=True, frozen=True)
class Span:
    """A run of text with the style changes its tags made (None: the base style's)."""

    text: str
    color: tuple[int, int, int, int] | None = None
    size: float | None = None
    font: str | None = None
    weight: int | None = None
    italic: bool | None = None
    #: an inline image: (image name, width px or 0, height px or 0); ``text`` is empty
    icon: tuple[str, float, float] | None = None


def parse_color(value: str) -> tuple[int, int, int, int]:
    """``#rgb``, ``#rrggbb``, ``#rrggbbaa``, a name or ``r,g,b[,a]`` as RGBA.

    >>> parse_color("#f80"), parse_color("10, 20, 30")
    ((255, 136, 0, 255), (10, 20, 30, 255))
    """
    v = value.strip().lower()
    if v in COLORS:
        return COLORS[v]
    if v.startswith("#") and len(v) in (4, 7, 9):
        digits = v[1:]
        try:
            if len(digits) == 3:
                r, g, b = (int(c * 2, 16) for c in digits)
                return (r, g, b, 255)
            parts = [int(digits[i : i + 2], 16) for i in range(0, len(digits), 2)]
        except ValueError:
            parts = []
        if len(parts) in (3, 4):
            return (parts[0], parts[1], parts[2], parts[3] if len(parts) == 4 else 255)
    if "," in v:
        try:
            nums = [int(p) for p in v.split(",")]
        except ValueError:
            nums = []
        if len(nums) in (3, 4) and all(0 <= n <= 255 for n in nums):
            return (nums[0], nums[1], nums[2], nums[3] if len(nums) == 4 else 255)
    raise ValidationError(
        f"markup: [color={value}] is not a colour (#rgb, #rrggbb, #rrggbbaa, r,g,b or a name: "
        f"{', '.join(sorted(COLORS))})"
    )


def _size(value: str) -> float:
    try:
        v = float(value)
    except ValueError:
        v = float("nan")
    if not 0.0 < v <= MAX_FONT_SIZE:
        raise ValidationError(f"markup: [size={value}] must be in (0, {MAX_FONT_SIZE:g}] points")
    return v


def _weight(value: str) -> int:
    key = value.strip().lower()
    if key in WEIGHTS:
        return WEIGHTS[key]
    try:
        w = int(key)
    except ValueError:
        w = 0
    if not 1 <= w <= 1000:
        raise ValidationError(f"markup: [weight={value}] must be 1..1000 or a weight name")
    return w


def _icon_size(value: str | None) -> tuple[float, float]:
    if not value:
        return (0.0, 0.0)
    m = re.fullmatch(r"\s*(\d+(?:\.\d+)?)\s*x\s*(\d+(?:\.\d+)?)\s*", value)
    if m is None or not 0 < float(m.group(1)) <= 4096 or not 0 < float(m.group(2)) <= 4096:
        raise ValidationError(f"markup: [img={value}] must be WIDTHxHEIGHT pixels, e.g. 16x16")
    return (float(m.group(1)), float(m.group(2)))


def _apply(span: Span, tag: str, value: str | None) -> Span:
    """``span``'s style with the opening ``tag`` applied."""
    needs_value = tag in ("color", "size", "font", "weight")
    if needs_value and not value:
        raise ValidationError(f"markup: [{tag}] needs a value, e.g. [{tag}=...]")
    if tag == "b":
        return replace(span, weight=700)
    if tag == "i":
        return replace(span, italic=True)
    if tag == "color":
        return replace(span, color=parse_color(value or ""))
    if tag == "size":
        return replace(span, size=_size(value or ""))
    if tag == "font":
        return replace(span, font=(value or "").strip())
    if tag == "weight":
        return replace(span, weight=_weight(value or ""))
    raise ValidationError(
        f"markup: unknown tag [{tag}] (known: b, i, color, size, font, weight, img, lb, rb)"
    )


def parse(source: str) -> list[Span]:
    """The spans of ``source`` in order; adjacent text of one style is one span."""
    spans: list[Span] = []
    stack: list[tuple[str, Span]] = []
    current = Span("")
    pos = 0
    buf: list[str] = []

    def flush() -> None:
        text = "".join(buf)
        buf.clear()
        if text:
            if spans and spans[-1].icon is None and replace(spans[-1], text="") == current:
                spans[-1] = replace(spans[-1], text=spans[-1].text + text)
            else:
                spans.append(replace(current, text=text))

    for m in _TAG.finditer(source):
        if m.start() < pos:  # inside an [img]...[/img] already taken
            continue
        buf.append(source[pos : m.start()])
        pos = m.end()
        closing, tag, value = m.group(1) == "/", m.group(2), m.group(3)
        if tag in ("lb", "rb") and not closing:
            buf.append("[" if tag == "lb" else "]")
            continue
        if tag == "img" and not closing:
            end = source.find("[/img]", pos)
            if end < 0:
                raise ValidationError("markup: [img] is never closed (write [img]name[/img])")
            name = source[pos:end].strip()
            if not name:
                raise ValidationError("markup: [img][/img] names no image")
            w, h = _icon_size(value)
            flush()
            spans.append(replace(current, text="", icon=(name, w, h)))
            pos = end + len("[/img]")
            continue
        flush()
        if closing:
            if not stack or stack[-1][0] != tag:
                expected = f"[/{stack[-1][0]}]" if stack else "no closing tag"
                raise ValidationError(f"markup: [/{tag}] closes nothing open (expected {expected})")
            current = stack.pop()[1]
            continue
        stack.append((tag, current))
        current = _apply(current, tag, value)
    buf.append(source[pos:])
    flush()
    if stack:
        raise ValidationError(f"markup: [{stack[-1][0]}] is never closed")
    return spans


def plain(source: str) -> str:
    """The text of ``source`` without its tags (inline images dropped)."""
    return "".join(s.text for s in parse(source))


def spans_of(text: str, markup: bool) -> list[Span]:
    """``text`` as spans: parsed when ``markup`` is on, else one span of the base style."""
    return parse(text) if markup else [Span(text)]
