"""The inspector's widgets: which one a field gets, and how its text reads back.

=================  ==============================================================
field              widget
=================  ==============================================================
bool               a Toggle
enum               a Dropdown of the member names
entity reference   a Dropdown of the scene's entity ids ("-" for none)
asset path         a Dropdown of the files next to the scene (the file picker)
number             a SpinBox: drag it sideways, the wheel, +/-, or click and type
angle              the same, in degrees (``angle``, ``*_angle`` fields)
colour             a ColorPicker (``color``, ``tint``, ``*_color``: 3 or 4 of 0..255)
2D vector          two SpinBoxes, x and y
numbers            a text field of comma-separated numbers ("1.5, 2, 3")
anything else      a text field holding the value as TOML (a shape, a filter)
=================  ==============================================================
"""

from __future__ import annotations

import enum
import math
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from kge.scenefile import default_registry
from kge.scenefile.codec import Decoder, Encoder, Source
from kge.scenefile.errors import SceneFileError, Where
from kge.scenefile.paths import AssetPaths
from kge.scenefile.registry import TypeInfo
from kge.scenefile.toml import value as toml_value

IMAGE_SUFFIXES = (".png", ".jpg", ".jpeg", ".gif", ".bmp")
SOUND_SUFFIXES = (".wav", ".ogg", ".mp3", ".flac")


@dataclass(slots=True)
class FieldKind:
    """How the inspector shows one field."""

    widget: str  #: "toggle", "choice", "number", "angle", "colour", "vector", "numbers",
    #: "text", "toml"
    choices: tuple[str, ...] = ()
    index: int = -1  #: a vector's component shown by this widget (0: x, 1: y)


def is_angle(name: str) -> bool:
    return name == "angle" or name.endswith("_angle") or name in ("direction", "spread", "cone")


def is_colour(name: str, value: Any) -> bool:
    """A colour field: named like one, holding 3 (RGB) or 4 (RGBA) integers in 0..255."""
    named = name in ("color", "colour", "tint") or name.endswith(("_color", "_colour"))
    return named and isinstance(value, tuple) and len(value) in (3, 4) and all(
        isinstance(v, int) and not isinstance(v, bool) and 0 <= v <= 255 for v in value
    )


def kind_of(info: TypeInfo, name: str, value: Any, entity_keys: list[str],
            assets: list[str]) -> FieldKind:
    hint_enum = _enum_of(info.hint(name))
    if name in info.entity_fields:
        return FieldKind("choice", ("-", *entity_keys))
    if name in info.asset_fields:
        return FieldKind("choice", ("-", *assets))
    if isinstance(value, bool):
        return FieldKind("toggle")
    if hint_enum is not None:
        return FieldKind("choice", tuple(m.name for m in hint_enum))
    if isinstance(value, int | float):
        if not math.isfinite(value):
            return FieldKind("toml")  # a SpinBox holds finite numbers only; inf is typed
        return FieldKind("angle" if is_angle(name) else "number")
    if is_colour(name, value):
        return FieldKind("colour")
    if isinstance(value, tuple) and value and all(
        isinstance(v, int | float) and not isinstance(v, bool) for v in value
    ):
        finite = all(math.isfinite(v) for v in value)
        return FieldKind("vector" if len(value) == 2 and finite else "numbers")
    if isinstance(value, str):
        return FieldKind("text")
    return FieldKind("toml")


def _enum_of(hint: Any) -> type[enum.Enum] | None:
    from kge.scenefile.codec import _enum_hint

    return _enum_hint(hint)


def show(kind: FieldKind, value: Any, folder: Path, key_of: Any) -> str:
    """The text (or choice) a widget shows for ``value``."""
    if kind.widget == "angle":
        return f"{math.degrees(value):.6g}"
    if kind.widget == "number":
        return f"{value:.6g}" if isinstance(value, float) else str(value)
    if kind.widget in ("numbers", "vector"):
        return ", ".join(f"{v:.6g}" if isinstance(v, float) else str(v) for v in value)
    if kind.widget == "text":
        return str(value)
    if kind.widget == "choice":
        if value is None:
            return "-"
        if isinstance(value, enum.Enum):
            return value.name
        if isinstance(value, int):
            return str(key_of(value))
        return AssetPaths(folder).relative(Path(value)) if Path(str(value)).is_absolute() else \
            str(value)
    if kind.widget == "toggle":
        return "true" if value else "false"
    if kind.widget == "colour":
        return ", ".join(str(v) for v in value)
    encoder = Encoder(default_registry(), AssetPaths(folder), lambda e, w: key_of(e))
    return toml_value(encoder.value(value, Where(), 0))


def parse(kind: FieldKind, text: str, info: TypeInfo, name: str, current: Any, folder: Path,
          entity_of: Any) -> Any:
    """The field value for what was typed or chosen (raises a clear error when it is not)."""
    where = Where(component=info.name, field=name)
    text = text.strip()
    if kind.widget in ("number", "angle"):
        try:
            v = float(text)
        except ValueError:
            raise SceneFileError(where, f"{text!r} is not a number") from None
        if kind.widget == "angle":
            v = math.radians(v)
        return int(v) if isinstance(current, int) and v.is_integer() else v
    if kind.widget in ("numbers", "vector", "colour"):
        try:
            parts = tuple(float(p) for p in text.replace("(", "").replace(")", "").split(","))
        except ValueError:
            raise SceneFileError(where, f"{text!r} is not numbers separated by commas") from None
        if current and all(isinstance(c, int) for c in current):
            return tuple(int(p) for p in parts)
        return parts
    if kind.widget == "text":
        return text
    if kind.widget == "toggle":
        return text == "true"
    if kind.widget == "choice":
        if text == "-":
            return None
        if name in info.entity_fields:
            return entity_of(text)
        if name in info.asset_fields:
            return AssetPaths(folder).load(text, where)
        enum_cls = _enum_of(info.hint(name))
        return enum_cls[text] if enum_cls is not None else text
    try:
        raw = tomllib.loads(f"v = {text}")["v"]
    except tomllib.TOMLDecodeError as exc:
        raise SceneFileError(where, f"not a value: {exc}") from None
    decoder = Decoder(default_registry(), Source(None, None, AssetPaths(folder)),
                      lambda k, w: entity_of(k))
    return decoder.value(raw, info.hint(name), where, 0)


def asset_files(folder: Path | None, limit: int = 400) -> list[str]:
    """Image and sound files under the scene's folder (the asset picker's choices)."""
    if folder is None or not folder.is_dir():
        return []
    out = []
    for p in sorted(folder.rglob("*")):
        if p.suffix.lower() in IMAGE_SUFFIXES + SOUND_SUFFIXES and p.is_file():
            out.append(p.relative_to(folder).as_posix())
            if len(out) >= limit:
                break
    return out
