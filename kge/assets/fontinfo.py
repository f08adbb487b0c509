"""Read a TrueType/OpenType font's family name without loading a font engine.

pyglet text is styled by *family name* ("DejaVu Sans"), not by file, and
``pyglet.font.add_file`` does not say which family a file provides. Reading the
``name`` table ourselves lets ``assets.font("ui.ttf")`` return the family to put
in a ``Text`` component, and it works headless, without GL or FreeType. The file
reader (family, style, weight, slant) is :mod:`kge.text.fontfile`.

>>> family_name(b"not a font") is None
True
"""

from __future__ import annotations

from kge.text.fontfile import face_info, family_name

__all__ = ["face_info", "family_name"]
