"""The pyglet side of kge: windows, textures, batches and the draw loop.

Nothing in this package is imported by ``import kge``. ``App.render()``,
``App.screenshot()`` and ``App.run()`` import :mod:`kge.render.setup` /
:mod:`kge.render.window` on first use, and only those (and the modules they
pull in) touch ``pyglet.gl`` and ``pyglet.window``. A few modules here are pure
(``images``, ``geometry``, ``projection``, ``poses``) so they can be tested and
used without a GL context.

How a frame is drawn (see :class:`kge.systems.render.RenderSystem`):

1. components that changed since the last frame (tracked writes) update their
   pyglet objects (texture region, colour, size, layer);
2. every drawn entity's pose is blended between the last two fixed steps by
   ``alpha`` (:mod:`kge.render.poses`), in one numpy pass;
3. positions and rotations are written straight into the batch's vertex
   buffers with numpy (:mod:`kge.render.bulk`), not one ``Sprite.update`` each;
4. the camera becomes the window's view matrix (:mod:`kge.render.projection`),
   so vertex data stays in metres and zooming rewrites nothing;
5. one ``Batch.draw()``: layer groups draw in ``(layer, order)`` order.
"""

import os as _os
import sys as _sys


def _select_backend() -> None:
    """With no display, pick pyglet's EGL (headless) backend before GL is first loaded.

    pyglet decides between X11/Wayland and EGL when ``pyglet.window`` is first
    imported, and cannot switch afterwards; doing it here means any module of
    this package can be imported on a bare machine (CI, doctests).

    pyglet checks for a GL error after *every* GL call unless told not to (a Python
    call and a ``glGetError`` each: a few milliseconds a frame with lights and post
    effects); kge turns that off unless ``PYGLET_DEBUG_GL=1`` asks for it (the test
    suite does).
    """
    if "pyglet.gl" not in _sys.modules and "PYGLET_DEBUG_GL" not in _os.environ:
        import pyglet

        pyglet.options["debug_gl"] = False
    if "pyglet.window" in _sys.modules:
        return
    from kge.platform import has_display

    if not has_display():
        import pyglet

        pyglet.options["headless"] = True


_select_backend()
