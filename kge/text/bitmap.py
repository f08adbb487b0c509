"""Bitmap fonts: glyphs cut from an image (pixel-art text), usable by name like any family.

A :class:`BitmapFont` is a sheet of equal cells, one character per cell, row by row
from the top-left. Register it under a family name and use that name in ``Text.font``
or ``TextStyle.font``; its em is the cell height, so ``size`` in points of
``cell_height * 3/4`` (or a whole multiple of it) draws it pixel for pixel. Glyphs are
sampled with nearest filtering: crisp at whole-number scales.

>>> from kge.render.images import solid
>>> font = BitmapFont(solid(40, 8), "ABCDI", cell=(8, 8), baseline=1, widths={"I": 4})
>>> face = BitmapFace(font)
>>> face.has("A"), face.has("z"), face.advance("A"), face.advance("I"), face.descent
(True, False, 1.125, 0.625, -0.125)
>>> font.cell_rect("C", 40, 8)
(16, 0, 8, 8)
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from kge.errors import ValidationError


@dataclass(slots=True, frozen=True)
class BitmapFont:
    """Glyphs in ``image``: ``chars`` in cells of ``cell`` = (w, h) pixels, row by row.

    ``baseline`` is the baseline's height in pixels above the cell's bottom;
    ``widths`` the advance of characters narrower than a cell; ``spacing`` the pixels
    between glyphs; ``line_height`` the pixels between lines (default: cell height + 1).
    """

    image: Any
    chars: str
    cell: tuple[int, int]
    baseline: int = 0
    widths: Mapping[str, int] = field(default_factory=dict)
    spacing: int = 1
    line_height: int | None = None

    def __post_init__(self) -> None:
        w, h = self.cell
        if not (isinstance(w, int) and isinstance(h, int)) or w < 1 or h < 1:
            raise ValidationError(f"BitmapFont.cell must be (w >= 1, h >= 1) ints, got {self.cell}")
        if not self.chars or len(set(self.chars)) != len(self.chars):
            raise ValidationError("BitmapFont.chars must list each character once")
        if not 0 <= self.baseline < h:
            raise ValidationError(f"BitmapFont.baseline must be in 0..{h - 1}, got {self.baseline}")
        for ch, width in self.widths.items():
            if ch not in self.chars or not 0 <= width <= 4 * w:
                raise ValidationError(f"BitmapFont.widths[{ch!r}] = {width} is not usable")

    def cell_rect(self, ch: str, image_width: int, image_height: int) -> tuple[int, int, int, int]:
        """The (x, y, w, h) of ``ch``'s cell, y from the image's bottom (GL order)."""
        w, h = self.cell
        columns = max(image_width // w, 1)
        i = self.chars.index(ch)
        col, row = i % columns, i // columns
        if (row + 1) * h > image_height:
            raise ValidationError(
                f"BitmapFont: character {ch!r} is in row {row}, outside the "
                f"{image_width}x{image_height} image"
            )
        return (col * w, image_height - (row + 1) * h, w, h)


class BitmapFace:
    """A :class:`BitmapFont`'s metrics in em (em = the cell height)."""

    def __init__(self, font: BitmapFont) -> None:
        self.font = font
        h = float(font.cell[1])
        self.ascent = (h - font.baseline) / h
        self.descent = -font.baseline / h
        self.line_height = (font.line_height or font.cell[1] + 1) / h
        self._chars = frozenset(font.chars)

    def has(self, ch: str) -> bool:
        return ch in self._chars or ch == " "

    def advance(self, ch: str) -> float:
        w = self.font.widths.get(ch, self.font.cell[0])
        return (w + self.font.spacing) / self.font.cell[1]

    def kerning(self, left: str, right: str) -> float:
        return 0.0
