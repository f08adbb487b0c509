"""The TOML side: a canonical writer, and the line of every table and key for errors.

Reading is the standard library's ``tomllib`` (data only: TOML has no way to
name code). Writing is here because the output must be canonical, so that save,
load, save gives the same bytes: one key per line in field order, floats by
``repr`` (which reads back to the same double), strings with TOML's escapes,
short arrays inline and long ones one item per line.

>>> print(value([1.5, "a\\"b", True, {"type": "Box", "half_width": 1.0}]))
[1.5, "a\\"b", true, { type = "Box", half_width = 1.0 }]
>>> key("draw.Rect"), key("body_a")
('"draw.Rect"', 'body_a')
>>> idx = LineIndex('[[entity]]\\nid = "a"\\n[entity.Collider]\\ndensity = -1.0\\n')
>>> idx.line(("entity", 0, "Collider", "density")), idx.line(("entity", 0, "Sprite"))
(4, 1)
"""

from __future__ import annotations

import math
import re
from typing import Any

#: arrays whose one-line form is longer than this are written one item per line
WIDE = 88

_BARE = re.compile(r"^[A-Za-z0-9_-]+$")
_ESCAPES = {'"': '\\"', "\\": "\\\\", "\b": "\\b", "\t": "\\t", "\n": "\\n", "\f": "\\f",
            "\r": "\\r"}


def string(s: str) -> str:
    """A TOML basic string."""
    out = []
    for ch in s:
        esc = _ESCAPES.get(ch)
        if esc is not None:
            out.append(esc)
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append(f"\\u{ord(ch):04X}")
        else:
            out.append(ch)
    return '"' + "".join(out) + '"'


def key(k: str) -> str:
    """A bare key when TOML allows one, else a quoted one."""
    return k if _BARE.match(k) else string(k)


def value(v: Any, indent: str = "") -> str:
    """The TOML text of a plain value (bool, int, float, str, list/tuple, dict)."""
    if v is True:
        return "true"
    if v is False:
        return "false"
    if isinstance(v, int):
        return str(int(v))
    if isinstance(v, float):
        if not math.isfinite(v):
            raise ValueError(f"non-finite number {v!r}")
        return repr(v)
    if isinstance(v, str):
        return string(v)
    if isinstance(v, dict):
        if not v:
            return "{}"
        return "{ " + ", ".join(f"{key(k)} = {value(x)}" for k, x in v.items()) + " }"
    if isinstance(v, list | tuple):
        one_line = "[" + ", ".join(value(x) for x in v) + "]"
        if len(one_line) + len(indent) <= WIDE or len(v) < 2:
            return one_line
        inner = indent + "    "
        rows = "".join(f"{inner}{value(x, inner)},\n" for x in v)
        return "[\n" + rows + indent + "]"
    raise TypeError(f"not a TOML value: {type(v).__name__}")


def header(path: tuple[str, ...], array: bool = False) -> str:
    text = ".".join(key(p) for p in path)
    return f"[[{text}]]" if array else f"[{text}]"


# -- where things are: the line of each table header and key ---------------------------
_KEY_PART = re.compile(r'\s*(?:([A-Za-z0-9_-]+)|"((?:[^"\\]|\\.)*)"|\'([^\']*)\')\s*')


def _parse_keys(text: str) -> tuple[list[str], str] | None:
    """Split a dotted key at the start of ``text``: (parts, rest after the key)."""
    parts: list[str] = []
    pos = 0
    while True:
        m = _KEY_PART.match(text, pos)
        if m is None or m.end() == pos:
            return None
        bare, basic, literal = m.groups()
        parts.append(bare if bare is not None else basic if basic is not None else literal or "")
        pos = m.end()
        if pos < len(text) and text[pos] == ".":
            pos += 1
            continue
        return parts, text[pos:]


def _depth_change(text: str) -> tuple[int, str | None]:
    """Net change of [ / { nesting over ``text`` outside strings and comments, and the
    multi-line string delimiter still open at its end (None when none is)."""
    depth, i, n = 0, 0, len(text)
    while i < n:
        ch = text[i]
        if text.startswith('"""', i) or text.startswith("'''", i):
            delim = text[i:i + 3]
            end = text.find(delim, i + 3)
            if end < 0:
                return depth, delim
            i = end + 3
            continue
        if ch == '"':
            i += 1
            while i < n and text[i] != '"':
                i += 2 if text[i] == "\\" else 1
        elif ch == "'":
            end = text.find("'", i + 1)
            i = n if end < 0 else end
        elif ch == "#":
            break
        elif ch in "[{":
            depth += 1
        elif ch in "]}":
            depth -= 1
        i += 1
    return depth, None


class LineIndex:
    """Line numbers (1-based) of the tables and keys of a TOML text, by path.

    A path walks the parsed document: table names, then the index inside an array
    of tables (``("entity", 3, "Collider", "density")``). :meth:`line` returns the
    line of the longest known prefix, so a field inside an inline table points at
    its key's line and an unknown path at its table.
    """

    def __init__(self, text: str) -> None:
        self._lines: dict[tuple[Any, ...], int] = {}
        counts: dict[tuple[str, ...], int] = {}
        current: tuple[Any, ...] = ()
        depth = 0
        open_string: str | None = None
        for number, raw in enumerate(text.splitlines(), start=1):
            if open_string is not None:  # inside a multi-line string
                if open_string in raw:
                    open_string = None
                continue
            if depth > 0:  # inside a multi-line array
                change, open_string = _depth_change(raw)
                depth += change
                continue
            line = raw.strip()
            if not line or line.startswith("#"):
                continue
            if line.startswith("[["):
                parsed = _parse_keys(line[2:])
                if parsed is not None:
                    names = tuple(parsed[0])
                    counts[names] = counts.get(names, -1) + 1
                    current = (*self._indexed(names, counts), counts[names])
                    self._lines.setdefault(current, number)
                continue
            if line.startswith("["):
                parsed = _parse_keys(line[1:])
                if parsed is not None:
                    current = self._indexed(tuple(parsed[0]), counts)
                    self._lines.setdefault(current, number)
                continue
            parsed = _parse_keys(line)
            if parsed is None or not parsed[1].lstrip().startswith("="):
                continue
            path = current + tuple(parsed[0])
            self._lines.setdefault(path, number)
            change, open_string = _depth_change(parsed[1].lstrip()[1:])
            depth = max(change, 0)

    @staticmethod
    def _indexed(names: tuple[str, ...], counts: dict[tuple[str, ...], int]) -> tuple[Any, ...]:
        """``names`` with the current index inserted after every array-of-tables prefix."""
        out: list[Any] = []
        for i, name in enumerate(names):
            out.append(name)
            prefix = names[: i + 1]
            if prefix in counts and i < len(names) - 1:
                out.append(counts[prefix])
        return tuple(out)

    def line(self, path: tuple[Any, ...]) -> int | None:
        for n in range(len(path), 0, -1):
            found = self._lines.get(tuple(path[:n]))
            if found is not None:
                return found
        return None
