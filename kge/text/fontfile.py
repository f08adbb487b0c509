"""Read a TrueType/OpenType font's family, style, weight and slant without a font engine.

Text is styled by *family* ("DejaVu Sans") plus weight and slant, while a file holds
one *face* (a Light Italic, a Bold). Reading the ``name``, ``OS/2`` and ``head``
tables ourselves tells which face a file is, headless, without GL or FreeType, so a
file whose face is not Regular is used as what it is instead of silently falling
back to another font.

>>> face_info(b"not a font") is None
True
"""

from __future__ import annotations

import struct
from dataclasses import dataclass


@dataclass(slots=True, frozen=True)
class FaceInfo:
    """What a font file holds: ``family`` (typographic), ``style`` ("Light Italic"),
    ``weight`` (100..900) and ``italic``."""

    family: str
    style: str
    weight: int
    italic: bool
    full_name: str = ""


def _tables(data: bytes) -> dict[bytes, tuple[int, int]]:
    base = 0
    if data[:4] == b"ttcf":  # a collection: its first font
        (base,) = struct.unpack_from(">I", data, 12)
    (count,) = struct.unpack_from(">H", data, base + 4)
    out = {}
    for i in range(count):
        tag, _, offset, length = struct.unpack_from(">4sIII", data, base + 12 + 16 * i)
        out[tag] = (offset, length)
    return out


def _names(data: bytes, offset: int) -> dict[int, str]:
    _, count, string_offset = struct.unpack_from(">HHH", data, offset)
    found: dict[int, str] = {}
    for i in range(count):
        platform, _, language, name_id, length, str_off = struct.unpack_from(
            ">HHHHHH", data, offset + 6 + 12 * i
        )
        if name_id not in (1, 2, 4, 16, 17) or name_id in found:
            continue
        start = offset + string_offset + str_off
        raw = data[start : start + length]
        if platform in (0, 3):
            found[name_id] = raw.decode("utf-16-be", errors="replace")
        elif platform == 1 and language == 0:
            found[name_id] = raw.decode("latin-1")
    return found


def face_info(data: bytes) -> FaceInfo | None:
    """The face a font file holds, or None when ``data`` is not a font."""
    try:
        tables = _tables(data)
        if b"name" not in tables:
            return None
        names = _names(data, tables[b"name"][0])
        family = names.get(16) or names.get(1)
        if not family:
            return None
        style = names.get(17) or names.get(2) or "Regular"
        weight, italic = 400, False
        if b"OS/2" in tables:
            os2 = tables[b"OS/2"][0]
            (weight,) = struct.unpack_from(">H", data, os2 + 4)
            (selection,) = struct.unpack_from(">H", data, os2 + 62)
            italic = bool(selection & 0x1 or selection & 0x200)
        elif b"head" in tables:
            (mac_style,) = struct.unpack_from(">H", data, tables[b"head"][0] + 44)
            weight = 700 if mac_style & 0x1 else 400
            italic = bool(mac_style & 0x2)
        lowered = style.lower()
        italic = italic or "italic" in lowered or "oblique" in lowered
        return FaceInfo(family, style, min(max(int(weight), 1), 1000), italic,
                        names.get(4, f"{family} {style}"))  # fmt: skip
    except (struct.error, IndexError):
        return None


def family_name(data: bytes) -> str | None:
    """The family (name id 16, else 1) of the first font in ``data``, or None."""
    info = face_info(data)
    return None if info is None else info.family
