"""Text on screen and in the world: fonts, layout, baking and measuring (pyglet side).

* :func:`measure` lays text out exactly as it will be drawn and returns the
  :class:`~kge.text.layout.TextLayout`: the box, each line's box and baseline,
  whether overflow cut anything and how much ``shrink`` shrank it;
* :class:`~kge.render.text.sprite.TextSprite` draws laid-out text in any pyglet batch
  (the Text component and UI labels use it);
* :func:`add_font_file` registers a font file's face (any weight and slant);
  :func:`register_bitmap_font` makes a :class:`~kge.text.bitmap.BitmapFont` usable by
  name; a family that exists nowhere gives a :class:`~kge.text.fonts.FontWarning`.

>>> from kge.render.text import measure
>>> box = measure("Hello\\nworld", size=12)
>>> len(box.lines), box.lines[0].text, box.lines[1].text
(2, 'Hello', 'world')
"""

from __future__ import annotations

import os
from typing import Any

from kge.components.text import TextStyle
from kge.errors import ValidationError
from kge.render.text.fonts import FALLBACK_FAMILIES, ICONS, FontBook, WorldFaces, book
from kge.render.text.raster import TextRaster
from kge.render.text.sprite import TextSprite
from kge.text.bitmap import BitmapFont
from kge.text.fontfile import FaceInfo
from kge.text.fonts import FONTS, FontWarning
from kge.text.layout import Line, TextLayout, layout
from kge.text.markup import spans_of


def add_font_file(path: str | os.PathLike[str] | bytes) -> FaceInfo:
    """Register a font file (or its bytes): its face is usable by family name, with the
    weight and slant it has (a Light Italic file is the family's light italic)."""
    if isinstance(path, bytes):
        return FONTS.register(path, f"<{len(path)} bytes #{hash(path) & 0xFFFF:04x}>")
    where = os.fspath(path)
    with open(where, "rb") as f:
        return FONTS.register(f.read(), where)


def register_bitmap_font(name: str, font: BitmapFont) -> None:
    """Make ``font`` usable as family ``name`` (``Text(font=name)``)."""
    FONTS.register_bitmap(name, font)


def register_icon(name: str, image: Any) -> None:
    """Make ``image`` (a PixelImage, an asset name...) usable as ``[img]name[/img]``."""
    if not isinstance(name, str) or not name:
        raise ValidationError(f"register_icon: the name must be a non-empty str, got {name!r}")
    ICONS[name] = image


_measurer: dict[int, WorldFaces] = {}


def faces_for(world: Any = None) -> WorldFaces:
    """The face source text of ``world`` uses (its asset store for images)."""
    from kge.render.textures import TextureCache

    key = id(world)
    found = _measurer.get(key)
    if found is None or found.textures.world is not world:
        found = _measurer[key] = WorldFaces(TextureCache(world))
    return found


def measure(text: str, style: TextStyle | None = None, *, world: Any = None,
            **fields: Any) -> TextLayout:  # fmt: skip
    """Lay ``text`` out in ``style`` (or a style from ``fields``) as it would be drawn.

    Sizes are in the text's pixels (screen pixels for HUD and UI). Needs the fonts,
    so it opens a headless GL context when no window exists yet.
    """
    from kge.render.setup import gl_context

    if style is None:
        style = TextStyle(**fields)
    elif fields:
        style = style.replace(**fields)
    gl_context()
    return layout(spans_of(text, style.markup), style, faces_for(world))


__all__ = [
    "FALLBACK_FAMILIES",
    "BitmapFont",
    "FaceInfo",
    "FontBook",
    "FontWarning",
    "Line",
    "TextLayout",
    "TextRaster",
    "TextSprite",
    "TextStyle",
    "add_font_file",
    "book",
    "faces_for",
    "measure",
    "register_bitmap_font",
    "register_icon",
]
