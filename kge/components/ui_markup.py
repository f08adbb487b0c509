"""The markup of :class:`~kge.components.ui_text.RichText`: BBCode-style tags, as Godot's
RichTextLabel reads them.

``[b]bold[/b]``, ``[i]italic[/i]``, ``[color=#ff8800]orange[/color]`` (``#rgb``,
``#rrggbb`` or ``#rrggbbaa``), ``[size=24]big[/size]`` (points); tags nest and each
closes the innermost open one of its name. ``[[`` is a literal ``[``. Text is cut
into runs of one look:

>>> [(r.text, r.bold, r.color) for r in parse("a [b]bold [color=#f00]red[/color][/b]!")]
[('a ', False, None), ('bold ', True, None), ('red', True, (255, 0, 0, 255)), ('!', False, None)]
>>> parse("x [blink]")
Traceback (most recent call last):
...
kge.errors.ValidationError: RichText.markup: unknown tag [blink] at character 2 (tags: b, i, ...
"""

from __future__ import annotations

from dataclasses import dataclass

from kge.components.color import Color
from kge.errors import ValidationError

TAGS = ("b", "i", "color", "size")


@dataclass(slots=True, frozen=True)
class Run:
    """A stretch of text of one look (None: the widget's own colour or size)."""

    text: str
    bold: bool = False
    italic: bool = False
    color: Color | None = None
    size: float | None = None


def _color(value: str, where: str) -> Color:
    h = value.lstrip("#")
    if len(h) == 3:
        h = "".join(c * 2 for c in h)
    if len(h) not in (6, 8) or not value.startswith("#"):
        raise ValidationError(f"{where}: colour {value!r} must be #rgb, #rrggbb or #rrggbbaa")
    try:
        parts = [int(h[i : i + 2], 16) for i in range(0, len(h), 2)]
    except ValueError:
        raise ValidationError(f"{where}: colour {value!r} is not hexadecimal") from None
    if len(parts) == 3:
        parts.append(255)
    return (parts[0], parts[1], parts[2], parts[3])


def _size(value: str, where: str) -> float:
    try:
        v = float(value)
    except ValueError:
        raise ValidationError(f"{where}: size {value!r} is not a number") from None
    if not 0 < v <= 1000:
        raise ValidationError(f"{where}: size {value!r} must be in (0, 1000] points")
    return v


def parse(markup: str, owner: str = "RichText") -> list[Run]:
    """The runs of ``markup`` (see the module docstring); bad tags raise ValidationError."""
    where = f"{owner}.markup"
    runs: list[Run] = []
    stack: list[tuple[str, object]] = []
    buf: list[str] = []

    def look() -> Run:
        bold = any(t == "b" for t, _ in stack)
        italic = any(t == "i" for t, _ in stack)
        color = next((v for t, v in reversed(stack) if t == "color"), None)
        size = next((v for t, v in reversed(stack) if t == "size"), None)
        return Run("", bold, italic, color, size)  # type: ignore[arg-type]

    def flush() -> None:
        if buf:
            r = look()
            runs.append(Run("".join(buf), r.bold, r.italic, r.color, r.size))
            buf.clear()

    i, n = 0, len(markup)
    while i < n:
        ch = markup[i]
        if ch != "[":
            buf.append(ch)
            i += 1
            continue
        if markup.startswith("[[", i):
            buf.append("[")
            i += 2
            continue
        end = markup.find("]", i)
        if end < 0:
            raise ValidationError(f"{where}: '[' at character {i} is not closed (write [[ for '[')")
        body = markup[i + 1 : end]
        closing = body.startswith("/")
        name, _, value = body.lstrip("/").partition("=")
        if name not in TAGS:
            raise ValidationError(
                f"{where}: unknown tag [{body}] at character {i} (tags: b, i, color=#rrggbb, "
                "size=points)"
            )
        flush()
        if closing:
            for k in range(len(stack) - 1, -1, -1):
                if stack[k][0] == name:
                    del stack[k]
                    break
            else:
                raise ValidationError(f"{where}: [/{name}] at character {i} closes no [{name}]")
        elif name == "color":
            stack.append((name, _color(value, where)))
        elif name == "size":
            stack.append((name, _size(value, where)))
        else:
            if value:
                raise ValidationError(f"{where}: [{name}] takes no value (at character {i})")
            stack.append((name, None))
        i = end + 1
    flush()
    return runs


def plain(markup: str) -> str:
    """The text of ``markup`` without its tags."""
    return "".join(r.text for r in parse(markup))
