"""Small pyglet pieces of the UI renderer: scissor clipping and nine-patch slicing."""

from __future__ import annotations

import functools
from typing import Any

import pyglet
from pyglet import gl

from kge.ui.layout import Box


class ClipGroup(pyglet.graphics.Group):
    """Draws its children only inside ``box`` (window pixels: a scroll view's viewport, a
    text field's inside). Clip groups nest: the inner one's box is already cut to the
    outer one's, and leaving it restores the outer scissor."""

    def __init__(self, order: int = 0, parent: pyglet.graphics.Group | None = None) -> None:
        super().__init__(order=order, parent=parent)
        self.box: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)
        self.scale = 1.0  #: framebuffer pixels per window pixel (HiDPI)

    def apply(self) -> None:
        x, y, w, h = self.box
        k = self.scale
        x0, y0 = round(x * k), round(y * k)
        gl.glEnable(gl.GL_SCISSOR_TEST)
        gl.glScissor(x0, y0, max(round((x + w) * k) - x0, 0), max(round((y + h) * k) - y0, 0))

    def set_state(self) -> None:
        self.apply()

    def unset_state(self) -> None:
        outer = self.parent
        while outer is not None and not isinstance(outer, ClipGroup):
            outer = outer.parent
        if outer is not None:
            outer.apply()
        else:
            gl.glDisable(gl.GL_SCISSOR_TEST)

    def __eq__(self, other: object) -> bool:
        return self is other

    def __hash__(self) -> int:
        return id(self)


def nine_patch(image: Any, box: Box, border: float) -> list[tuple[Any, Box]]:
    """The nine (texture region, target box) pieces of a nine-patch image over ``box``.

    Corners keep ``border`` source pixels at their size; edges stretch along one
    axis and the middle along both. A box smaller than two borders shrinks them.
    """
    tex = image.get_texture()
    iw, ih = tex.width, tex.height
    b = int(min(border, iw / 2, ih / 2))
    bx = min(float(b), box.w / 2)
    by = min(float(b), box.h / 2)
    src_x = (0, b, iw - b, iw)
    src_y = (0, b, ih - b, ih)
    dst_x = (box.x, box.x + bx, box.right - bx, box.right)
    dst_y = (box.y, box.y + by, box.top - by, box.top)
    out = []
    for j in range(3):
        for i in range(3):
            sw, sh = src_x[i + 1] - src_x[i], src_y[j + 1] - src_y[j]
            dw, dh = dst_x[i + 1] - dst_x[i], dst_y[j + 1] - dst_y[j]
            if sw <= 0 or sh <= 0 or dw <= 0 or dh <= 0:
                continue
            region = _region(tex, src_x[i], src_y[j], sw, sh)
            out.append((region, Box(dst_x[i], dst_y[j], dw, dh)))
    return out


@functools.lru_cache(maxsize=256)
def _region(tex: Any, x: int, y: int, w: int, h: int) -> Any:
    """One region object per piece, so the sprites showing it are not rebuilt each frame."""
    return tex.get_region(x, y, w, h)
