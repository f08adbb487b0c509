"""Drawing scene transitions over the frame (see :mod:`kge.transitions` for the timing).

The render frontend calls :func:`draw_transition` after every visible world is drawn.
Fades cover the window with the transition colour at ``active.cover``; the other
kinds draw a picture of the old scene (the App asks the frontend for one,
:func:`take_picture`, just before it changes the scene) faded, shifted or cut.
"""

from __future__ import annotations

from typing import Any

import pyglet
from pyglet import gl

from kge.render.setup import Renderer
from kge.transition_shaders import Shaded
from kge.transitions import ActiveTransition, Wipe


def take_picture(renderer: Renderer) -> Any:
    """The window's current frame as a texture (the old scene of a transition)."""
    renderer.window.switch_to()
    buffer = pyglet.image.get_buffer_manager().get_color_buffer()
    return buffer.get_image_data().get_texture()


def draw_transition(renderer: Renderer, active: ActiveTransition, background: Any) -> None:
    """Draw ``active`` over what the window shows now (window pixels, view reset)."""
    window = renderer.window
    window.view = pyglet.math.Mat4()
    w, h = renderer.size
    tr = active.transition
    if isinstance(tr, Shaded):  # Iris, ShaderTransition: kge/render/transition_shaders.py
        from kge.render.transition_shaders import draw_shaded

        draw_shaded(active, window.get_framebuffer_size())
        return
    if tr.needs_picture:
        if not active.swapped or active.picture is None:
            return  # the old scene is still on screen, or nothing was drawn to picture
        _draw_picture(renderer, active, w, h)
    cover = active.cover
    if cover > 0.0:
        a = round(255 * cover)
        rect = pyglet.shapes.Rectangle(0, 0, w, h, color=(*tr.color, a))
        rect.draw()


def _draw_picture(renderer: Renderer, active: ActiveTransition, w: int, h: int) -> None:
    pic = active.picture
    sx, sy = active.shift
    sprite = pyglet.sprite.Sprite(pic, 0, 0)
    sprite.scale_x = w / max(pic.width, 1)
    sprite.scale_y = h / max(pic.height, 1)
    sprite.opacity = round(255 * active.picture_alpha)
    if isinstance(active.transition, Wipe):
        # the picture stays put; a scissor keeps only the part the edge has not passed
        fw, fh = renderer.window.get_framebuffer_size()
        kx, ky = fw / w, fh / h
        x0, x1 = (sx * w, w) if sx >= 0 else (0.0, w * (1 + sx))
        y0, y1 = (sy * h, h) if sy >= 0 else (0.0, h * (1 + sy))
        gl.glEnable(gl.GL_SCISSOR_TEST)
        gl.glScissor(int(x0 * kx), int(y0 * ky), max(int((x1 - x0) * kx), 0),
                     max(int((y1 - y0) * ky), 0))  # fmt: skip
        try:
            sprite.draw()
        finally:
            gl.glDisable(gl.GL_SCISSOR_TEST)
    else:
        sprite.position = (sx * w, sy * h, 0)
        sprite.draw()
    sprite.delete()
