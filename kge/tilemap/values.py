"""Reading values of Tiled documents: numbers with bounds, colours, properties.

Every helper names the file and the field in its error, and applies Tiled's
default when a file (often an older one) leaves the field out.

>>> color("#80ff0000", "m.tmx", "tintcolor")
(255, 0, 0, 128)
>>> color("ff00ff", "m.tmx", "trans")
(255, 0, 255, 255)
>>> number({"width": "3"}, "width", "m.tmx", "map", minimum=1)
3
"""

from __future__ import annotations

import math
from typing import Any

from kge.tilemap.errors import TilemapError

RE_SAVE = "re-save it in Tiled 1.9 or later"


def number(
    d: dict[str, Any],
    key: str,
    where: str,
    what: str,
    default: Any = None,
    *,
    minimum: float | None = None,
    integer: bool = True,
    since: str = "",
) -> Any:
    """``d[key]`` as an int (or float), checked; a missing key gives ``default``.

    With no default a missing key is refused, naming the Tiled version that
    writes it (``since``) and the fix.
    """
    raw = d.get(key)
    if raw is None:
        if default is None:
            written = (
                f"Tiled {since} and later write it" if since else "every Tiled version writes it"
            )
            raise TilemapError(f"{where}: {what} has no {key!r} ({written}); {RE_SAVE}")
        return default
    try:
        value = float(raw) if not isinstance(raw, (int, float)) else raw
        if isinstance(value, bool):
            raise ValueError
        if integer:
            if isinstance(value, float) and (not math.isfinite(value) or value != int(value)):
                raise ValueError
            value = int(value)
        elif not math.isfinite(value):
            raise ValueError
    except (ValueError, TypeError, OverflowError):
        raise TilemapError(f"{where}: {what}: {key} = {raw!r} is not a finite number") from None
    if minimum is not None and value < minimum:
        raise TilemapError(f"{where}: {what}: {key} = {value} is below {minimum:g}")
    return value


def color(raw: Any, where: str, what: str) -> tuple[int, int, int, int]:
    """Tiled's ``#AARRGGBB`` / ``#RRGGBB`` (``#`` optional) as (r, g, b, a)."""
    text = str(raw).strip().lstrip("#")
    try:
        if len(text) == 6:
            return (int(text[0:2], 16), int(text[2:4], 16), int(text[4:6], 16), 255)
        if len(text) == 8:
            a, r, g, b = (int(text[i : i + 2], 16) for i in (0, 2, 4, 6))
            return (r, g, b, a)
    except ValueError:
        pass
    raise TilemapError(f"{where}: {what} {raw!r} is not a colour (#rrggbb or #aarrggbb)")


def flag(d: dict[str, Any], key: str, default: bool) -> bool:
    v = d.get(key)
    if v is None:
        return default
    if isinstance(v, str):
        return v.strip().lower() not in ("0", "false", "")
    return bool(v)


def properties(items: Any, where: str) -> dict[str, Any]:
    """Tiled's property list as a dict of Python values (ints, floats, bools, strings)."""
    out: dict[str, Any] = {}
    for p in items or []:
        if not isinstance(p, dict) or "name" not in p:
            raise TilemapError(f"{where}: a property is not {{name, type, value}}: {p!r}")
        ptype, value = p.get("type", "string"), p.get("value")
        try:
            if ptype == "int" or ptype == "object":
                value = int(float(value)) if value not in (None, "") else 0
            elif ptype == "float":
                value = float(value) if value not in (None, "") else 0.0
            elif ptype == "bool":
                value = value if isinstance(value, bool) else str(value).lower() == "true"
            elif value is None:
                value = ""
        except (ValueError, TypeError, OverflowError):
            raise TilemapError(
                f"{where}: property {p['name']!r}: {value!r} is not a {ptype}"
            ) from None
        out[str(p["name"])] = value
    return out
