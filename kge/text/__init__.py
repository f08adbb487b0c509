"""Text layout without a GL context: rich-text markup and line layout.

* :mod:`kge.text.markup`: ``[b]``, ``[color=...]``, ``[img]`` tags into styled spans;
* :mod:`kge.text.layout`: spans into lines and placed glyphs (wrapping, alignment,
  line spacing, overflow by clipping, ellipsis or shrinking), from any font source
  that gives em metrics (:class:`kge.text.layout.Face`).

The pyglet side (font files and faces, rasterising, the Text component's drawing,
:func:`kge.render.text.measure`) lives in :mod:`kge.render.text`.
"""

from kge.text.layout import Face, FaceSource, Line, PlacedGlyph, TextLayout, layout
from kge.text.markup import Span, parse, plain

__all__ = [
    "Face",
    "FaceSource",
    "Line",
    "PlacedGlyph",
    "Span",
    "TextLayout",
    "layout",
    "parse",
    "plain",
]
