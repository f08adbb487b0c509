"""Read a TrueType/OpenType font's family name without loading a font engine.

pyglet text is styled by *family name* ("DejaVu Sans"), not by file, and
``pyglet.font.add_file`` does not say which family a file provides. Reading the
``name`` table ourselves lets ``assets.font("ui.ttf")`` return the family to put
in a ``Text`` component, and it works headless, without GL or FreeType.
"""

from __future__ import annotations

import struct


def family_name(data: bytes) -> str | None:
    """The family (name id 16, else 1) of the first font in ``data``, or None.

    >>> family_name(b"not a font") is None
    True
    """
    try:
        base = 0
        if data[:4] == b"ttcf":  # a collection: use its first font
            (base,) = struct.unpack_from(">I", data, 12)
        (num_tables,) = struct.unpack_from(">H", data, base + 4)
        for i in range(num_tables):
            tag, _, offset, _ = struct.unpack_from(">4sIII", data, base + 12 + 16 * i)
            if tag == b"name":
                return _family_from_name_table(data, offset)
    except struct.error:
        return None
    return None


def _family_from_name_table(data: bytes, offset: int) -> str | None:
    _, count, string_offset = struct.unpack_from(">HHH", data, offset)
    found: dict[int, str] = {}
    for i in range(count):
        platform, _, language, name_id, length, str_off = struct.unpack_from(
            ">HHHHHH", data, offset + 6 + 12 * i
        )
        if name_id not in (1, 16) or name_id in found:
            continue
        start = offset + string_offset + str_off
        raw = data[start : start + length]
        if platform in (0, 3):
            found[name_id] = raw.decode("utf-16-be", errors="replace")
        elif platform == 1 and language == 0:
            found[name_id] = raw.decode("latin-1")
    return found.get(16) or found.get(1)
