"""Font files made at test time (fontTools): faces with any weight and slant, drawn as boxes.

Each glyph is a set of rectangles in font units (1000 per em), so a test can tell
from the pixels which face drew a character.
"""

from __future__ import annotations

import io
from typing import Any

from fontTools.fontBuilder import FontBuilder
from fontTools.pens.ttGlyphPen import TTGlyphPen

Rects = list[tuple[int, int, int, int]]

#: a full block from the baseline to the cap height: unmistakable in pixels
BLOCK: Rects = [(50, 0, 650, 700)]
#: a hollow frame
FRAME: Rects = [(50, 0, 650, 100), (50, 600, 650, 700), (50, 0, 150, 700), (550, 0, 650, 700)]


def _glyph(rects: Rects) -> Any:
    pen = TTGlyphPen(None)
    for x0, y0, x1, y1 in rects:
        pen.moveTo((x0, y0))
        pen.lineTo((x0, y1))
        pen.lineTo((x1, y1))
        pen.lineTo((x1, y0))
        pen.closePath()
    return pen.glyph()


def make_font(family: str, style: str = "Regular", weight: int = 400, italic: bool = False,
              glyphs: dict[str, Rects] | None = None, advance: int = 700) -> bytes:  # fmt: skip
    """The bytes of a TrueType font: ``glyphs`` maps characters to rectangles."""
    glyphs = {"A": BLOCK, "B": FRAME} if glyphs is None else glyphs
    names = {ch: f"g{ord(ch):04x}" for ch in glyphs}
    order = [".notdef", "space", *names.values()]
    fb = FontBuilder(1000, isTTF=True)
    fb.setupGlyphOrder(order)
    fb.setupCharacterMap({32: "space", **{ord(ch): n for ch, n in names.items()}})
    drawn = {".notdef": _glyph([(50, 0, 450, 700), (100, 50, 400, 650)]), "space": _glyph([])}
    drawn.update({names[ch]: _glyph(rects) for ch, rects in glyphs.items()})
    fb.setupGlyf(drawn)
    fb.setupHorizontalMetrics({n: (advance if n != "space" else 300, 0) for n in order})
    fb.setupHorizontalHeader(ascent=800, descent=-200)
    fb.setupNameTable({"familyName": family, "styleName": style,
                       "typographicFamily": family, "typographicSubfamily": style})  # fmt: skip
    selection = 0x01 if italic else (0x20 if weight >= 700 else 0x40)
    fb.setupOS2(usWeightClass=weight, fsSelection=selection, sTypoAscender=800,
                sTypoDescender=-200, usWinAscent=800, usWinDescent=200)  # fmt: skip
    fb.setupPost(italicAngle=-12 if italic else 0)
    fb.updateHead(macStyle=(0x2 if italic else 0) | (0x1 if weight >= 700 else 0))
    out = io.BytesIO()
    fb.save(out)
    return out.getvalue()
