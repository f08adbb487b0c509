"""Create the window (or the offscreen one) once per App and hook rendering in.

The render plugin's frontend calls :func:`ensure_renderer` on the first
``App.render()`` and adds the drawing systems to every current and future scene
world of the App. Headless Apps get an EGL pbuffer window (``PYGLET_HEADLESS=1``,
Mesa llvmpipe on a bare machine); these are pooled by size and reused by later
Apps in the same process, so a test session opens one GL context, not one per test.

:func:`frame_pixels` reads the last frame back as a numpy array (tests),
:func:`save_color_buffer` saves it as a PNG (no PIL needed).
"""

from __future__ import annotations

import os
import sys
import weakref
from typing import TYPE_CHECKING, Any

import numpy as np

from kge.render.stats import FrameClock

if TYPE_CHECKING:
    from kge.host import Host

_renderers: weakref.WeakKeyDictionary[Any, Renderer] = weakref.WeakKeyDictionary()
_offscreen: dict[tuple[int, int], Any] = {}


def configure_headless(headless: bool) -> None:
    """pyglet must be told *before* its window module is first imported."""
    if headless and "pyglet.window" not in sys.modules:
        import pyglet

        pyglet.options["headless"] = True
        os.environ.setdefault("PYGLET_HEADLESS", "1")


class Renderer:
    """The window of one App, and its frame timing."""

    def __init__(self, app: Host, window: Any, owns_window: bool) -> None:
        self.app_ref = weakref.ref(app)
        self.window = window
        self.owns_window = owns_window
        self.clock = FrameClock()
        #: False while drawing a world over another (an overlay scene): no clearing
        self.clear = True

    @property
    def size(self) -> tuple[int, int]:
        return (int(self.window.width), int(self.window.height))

    def begin_frame(self, background: tuple[int, ...]) -> None:
        """Make the window current, fit viewport and projection, clear it."""
        import pyglet
        from pyglet import gl

        w = self.window
        w.switch_to()
        fw, fh = w.get_framebuffer_size()
        gl.glViewport(0, 0, int(fw), int(fh))
        w.projection = pyglet.math.Mat4.orthogonal_projection(0, w.width, 0, w.height, -255, 255)
        if self.clear:
            r, g, b = (c / 255.0 for c in background[:3])
            gl.glClearColor(r, g, b, 1.0)
            w.clear()


def create_window(width: int, height: int, **kwargs: Any) -> Any:
    """A pyglet window, safe to create even after ``pyglet.app.run()`` has returned.

    pyglet's loop switches windows to immediate event dispatch and leaves it so;
    a window created afterwards would then handle its first resize before its GL
    state exists. Creation is done with events queued, as before any loop ran.
    """
    import pyglet

    window_cls = pyglet.window.Window
    queued, window_cls._enable_event_queue = window_cls._enable_event_queue, True
    try:
        if "config" not in kwargs:
            try:
                return window_cls(width, height, config=frame_config(), **kwargs)
            except pyglet.window.NoSuchConfigException:
                pass  # a display without 8-bit RGBA and stencil: take its default
        return window_cls(width, height, **kwargs)
    finally:
        window_cls._enable_event_queue = queued


def frame_config() -> Any:
    """The GL framebuffer kge asks for: 8 bits per channel with alpha, and a stencil.

    Mesa's EGL hands out a 16-bit RGB565 surface by default, which bands gradients
    and turns greys purple in headless frames; every window asks for this instead.
    """
    from pyglet import gl

    config_cls: Any = gl.Config  # the platform's concrete class, chosen by pyglet at import
    return config_cls(
        red_size=8, green_size=8, blue_size=8, alpha_size=8, stencil_size=8,
        depth_size=0, double_buffer=True,
    )


def _new_window(app: Host) -> tuple[Any, bool]:
    configure_headless(app.headless)
    import pyglet

    size = app.size
    if app.headless or pyglet.options.get("headless"):
        win = _offscreen.get(size)
        if win is None:
            win = _offscreen[size] = create_window(size[0], size[1], visible=False)
        return win, False
    return create_window(size[0], size[1], caption=app.title, visible=False), True


def gl_context() -> Any:
    """A current GL context (fonts need one): the current window's, else a small hidden
    window's, made once (headless: an EGL pbuffer)."""
    from kge.platform import has_display

    configure_headless(not has_display())
    import pyglet

    ctx = pyglet.gl.current_context
    if ctx is not None:
        return ctx
    win = _offscreen.get((16, 16))
    if win is None:
        win = _offscreen[(16, 16)] = create_window(16, 16, visible=False)
    win.switch_to()
    return pyglet.gl.current_context


def renderer_for(app: Host) -> Renderer | None:
    return _renderers.get(app)


def ensure_renderer(app: Host, window: Any = None) -> Renderer:
    """The App's Renderer (its window), created on first call.

    The drawing systems are added by the render plugin's frontend, which calls this.
    """
    r = _renderers.get(app)
    if r is not None:
        return r
    if window is None:
        window, owns = _new_window(app)
    else:
        owns = True
    from kge.render.program_life import pin_programs

    pin_programs(getattr(window, "context", None))
    r = _renderers[app] = Renderer(app, window, owns)
    return r


def frame_pixels(app: Host) -> np.ndarray:
    """The current frame as an (height, width, 4) uint8 array, row 0 at the **bottom**.

    Indexing is ``pixels[y, x]`` in window pixels, the same coordinates as
    ``Camera.world_to_screen``.
    """
    import pyglet

    r = ensure_renderer(app)
    r.window.switch_to()
    data = pyglet.image.get_buffer_manager().get_color_buffer().get_image_data()
    raw = data.get_data("RGBA", data.width * 4)
    return np.frombuffer(raw, np.uint8).reshape(data.height, data.width, 4)


def save_color_buffer(app: Host, path: str) -> None:
    """Save what the App's window shows now as a PNG (``app.screenshot`` renders first)."""
    import pyglet

    r = ensure_renderer(app)
    r.window.switch_to()
    directory = os.path.dirname(os.path.abspath(path))
    os.makedirs(directory, exist_ok=True)
    pyglet.image.get_buffer_manager().get_color_buffer().save(path)


def release(app: Host) -> None:
    """Forget the App's renderer (closing a window it owns; pooled offscreen ones stay)."""
    r = _renderers.pop(app, None)
    if r is not None and r.owns_window:
        r.window.close()
