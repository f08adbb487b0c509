"""Small drawn glyphs of the default theme: a check mark, arrow heads, a checkerboard."""

from __future__ import annotations

from typing import TYPE_CHECKING

from kge.ui.layout import Box

if TYPE_CHECKING:
    from kge.render.ui import Canvas

Color = tuple[int, ...]  #: RGBA (themes and components always hold four channels)


def check_mark(c: Canvas, square: Box, color: Color, dz: int = 3) -> None:
    """A drawn check mark: two round-capped strokes."""
    s = square.w
    x, y = square.x, square.y
    th = max(s * 0.13, 1.5)
    a = (x + 0.24 * s, y + 0.52 * s)
    m = (x + 0.43 * s, y + 0.31 * s)
    z = (x + 0.77 * s, y + 0.72 * s)
    c.line("tick1", a, m, th, color, dz)
    c.line("tick2", m, z, th, color, dz)


def chevron(c: Canvas, part: object, cx: float, cy: float, size: float, color: Color,
            direction: str = "down", dz: int = 4, own: bool = False) -> None:  # fmt: skip
    """A drawn arrow head (dropdowns, tree rows), ``size`` pixels across."""
    h = size / 2
    q = size / 4
    th = max(size * 0.16, 1.5)
    if direction == "down":
        pts = ((cx - h, cy + q), (cx, cy - q), (cx + h, cy + q))
    elif direction == "up":
        pts = ((cx - h, cy - q), (cx, cy + q), (cx + h, cy - q))
    elif direction == "right":
        pts = ((cx - q, cy + h), (cx + q, cy), (cx - q, cy - h))
    else:
        pts = ((cx + q, cy + h), (cx - q, cy), (cx + q, cy - h))
    c.line((part, 0), pts[0], pts[1], th, color, dz, own)
    c.line((part, 1), pts[1], pts[2], th, color, dz, own)


def checker(c: Canvas, part: str, b: Box) -> None:
    """A grey checkerboard under see-through colours."""
    c.rect((part, "bg"), b, (200, 200, 200, 255), 2)
    cell = max(min(b.w, b.h) / 2, 4.0)
    k = 0
    y = b.y
    row = 0
    while y < b.top - 0.5 and k < 64:
        x = b.x + (cell if row % 2 else 0.0)
        while x < b.right - 0.5 and k < 64:
            c.rect((part, k), Box(x, y, min(cell, b.right - x), min(cell, b.top - y)),
                   (150, 150, 150, 255), 2)  # fmt: skip
            k += 1
            x += 2 * cell
        y += cell
        row += 1
