"""Where the game's screen lands in the framebuffer: design resolution, letterbox, DPI.

The *canvas* is the game's screen in screen pixels (design pixels with a
:class:`~kge.components.resolution.Resolution`, else the window's size). Cameras,
screen-space text and UI draw in canvas pixels; :func:`canvas_of` says where the
canvas sits in the framebuffer and how many framebuffer pixels a canvas pixel
covers (a high-DPI window or a scaled design resolution), so text and the light
map are made at the real pixel size. In ``"integer"`` mode the canvas is drawn into
a design-sized texture first (:class:`IntegerCanvas`) and magnified with nearest
filtering.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from pyglet import gl

from kge.components.resolution import Resolution
from kge.render.glutil import FULLSCREEN_VS, new_texture, program


@dataclass(slots=True)
class Canvas:
    """The canvas of one frame."""

    size: tuple[int, int]  #: canvas (design) pixels
    rect: tuple[int, int, int, int]  #: where it is drawn: framebuffer pixels
    scale: tuple[float, float]  #: framebuffer pixels per canvas pixel, x and y
    framebuffer: tuple[int, int]  #: the window's framebuffer size
    resolution: Resolution | None = None

    @property
    def pixel_scale(self) -> float:
        """Framebuffer pixels per canvas pixel (the smaller axis)."""
        return min(self.scale)

    @property
    def integer(self) -> bool:
        return self.resolution is not None and self.resolution.mode == "integer"

    def sub_rect(self, fraction: tuple[float, float, float, float]) -> tuple[int, int, int, int]:
        """A viewport given as fractions of the canvas, in framebuffer pixels."""
        x, y, w, h = self.rect
        fx, fy, fw, fh = fraction
        x0, y0 = round(x + fx * w), round(y + fy * h)
        x1, y1 = round(x + (fx + fw) * w), round(y + (fy + fh) * h)
        return (x0, y0, max(x1 - x0, 1), max(y1 - y0, 1))


def canvas_of(world: Any, window: Any) -> Canvas:
    """The canvas of ``world`` drawn in ``window`` this frame."""
    w, h = int(window.width), int(window.height)
    fw, fh = (int(v) for v in window.get_framebuffer_size())
    res = world.try_resource(Resolution)
    if res is None:
        return Canvas((w, h), (0, 0, fw, fh), (fw / max(w, 1), fh / max(h, 1)), (fw, fh))
    if res.mode == "integer":  # drawn 1:1 into a design-sized texture, magnified after
        return Canvas(res.size, (0, 0, res.width, res.height), (1.0, 1.0), (fw, fh), res)
    x, y, cw, ch = res.fit((fw, fh))
    rect = (round(x), round(y), max(round(cw), 1), max(round(ch), 1))
    return Canvas(res.size, rect, (cw / res.width, ch / res.height), (fw, fh), res)


_BLIT_FS = """#version 150 core
in vec2 uv;
out vec4 frag;
uniform sampler2D src;
void main() { frag = texture(src, uv); }
"""


class IntegerCanvas:
    """The design-sized texture of ``"integer"`` mode, and its magnified copy to the window."""

    def __init__(self) -> None:
        self.texture: Any = None

    def target(self, size: tuple[int, int]) -> Any:
        tex = self.texture
        if tex is None or (tex.width, tex.height) != size:
            if tex is not None:
                tex.delete()
            tex = self.texture = new_texture(size[0], size[1], linear=False)
        return tex

    def present(self, canvas: Canvas) -> None:
        """Draw the texture into the window, scaled by a whole number, centred."""
        from kge.render.glutil import fullscreen

        res = canvas.resolution
        assert res is not None and self.texture is not None
        x, y, w, h = res.fit(canvas.framebuffer)
        gl.glViewport(int(x), int(y), round(w), round(h))
        prog = program("kge-canvas-blit", FULLSCREEN_VS, _BLIT_FS)
        prog.use()
        gl.glDisable(gl.GL_BLEND)
        gl.glActiveTexture(gl.GL_TEXTURE0)
        gl.glBindTexture(self.texture.target, self.texture.id)
        fullscreen(prog)
        prog.stop()
        gl.glViewport(0, 0, *canvas.framebuffer)

    def close(self) -> None:
        if self.texture is not None:
            self.texture.delete()
            self.texture = None
