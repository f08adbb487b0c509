"""``App.run()`` with a display: a pyglet window driving the App.

pyglet's loop redraws the window 60 times a second (or at the display's vsync);
each ``on_draw`` runs one game frame with the real time since the previous one
(:meth:`App.advance`: the App's accumulator turns it into fixed steps) and
renders it. Window events feed the :class:`~kge.input.Input` resource. kge key and button codes are
pyglet's, so events pass through untranslated.

Keys the window itself handles: F11 toggles fullscreen. F1 (the physics debug view)
and F2 (the stats overlay) are ordinary input, handled by the render plugin's
:class:`~kge.systems.render.DebugKeys` system, so one path serves windows and tests.
Losing focus releases every held key, so nothing stays stuck. Gamepads join
through :mod:`kge.render.gamepads` (pyglet's controller API, with hot-plug).
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from kge.components.resolution import Resolution
from kge.cursor import apply as apply_cursor
from kge.keys import Key

if TYPE_CHECKING:
    from kge.app import App


def connect(app: App, window: Any, frames: int | None = None) -> None:
    """Wire ``window`` events to ``app`` (separate from the loop so it can be tested).

    The handlers go on a frame of their own on the window's handler stack, which
    :func:`disconnect` pops.
    """
    import pyglet

    window.push_handlers()  # a fresh frame: @window.event below fills it
    inp = app.input
    state = {"count": 0, "last": time.perf_counter(), "cursor": 0}
    #: keys pressed whose first text motion (pyglet sends one with the press) is still due
    first_motion: set[int] = set()

    def screen(x: float, y: float) -> tuple[float, float]:
        """Window pixels -> the game's screen pixels (design pixels with a Resolution)."""
        res = app.world.try_resource(Resolution) if app._stack else None
        if res is None:
            return (x, y)
        return res.to_design((x, y), (window.width, window.height))

    @window.event
    def on_draw() -> None:
        # One game frame per drawn frame: advance by the real time since the last
        # one (the App's accumulator turns it into fixed steps), then draw.
        now = time.perf_counter()
        dt, state["last"] = now - state["last"], now
        if not app._running or not app._stack:
            pyglet.app.exit()
            return
        app.advance(dt)
        if app.cursor.version != state["cursor"]:  # the game changed the pointer's look
            state["cursor"] = app.cursor.version
            apply_cursor(app.cursor, window, _image_loader(app))
        state["count"] += 1
        if frames is not None and state["count"] >= frames:
            app.quit()
        if app._stack:
            app.render()

    @window.event
    def on_key_press(symbol: int, modifiers: int) -> bool | None:
        if symbol == Key.F11:
            window.set_fullscreen(not window.fullscreen)
            return True
        inp.press(symbol, modifiers)  # F1 / F2: the render plugin's DebugKeys system
        first_motion.add(symbol)
        return True  # keep pyglet's default Escape-closes-window out of the game's way

    def motion(code: int) -> None:
        # arrows, PageUp/PageDown, Backspace and Delete arrive again as text
        # motions while held: after the first (the press itself), each is the system's
        # auto-repeat, which text fields follow (word and clipboard motions are codes < 9)
        if code < 9:
            return
        if code in first_motion:
            first_motion.discard(code)
        else:
            inp.repeat_key(code, inp.modifiers)

    @window.event
    def on_text_motion(code: int) -> None:
        motion(code)

    @window.event
    def on_text_motion_select(code: int) -> None:
        motion(code)

    @window.event
    def on_key_release(symbol: int, modifiers: int) -> None:
        first_motion.discard(symbol)
        inp.release(symbol, modifiers)

    @window.event
    def on_text(text: str) -> None:
        inp.type_text(text)

    @window.event
    def on_mouse_press(x: int, y: int, button: int, modifiers: int) -> None:
        inp.mouse_down(button, screen(x, y), modifiers)

    @window.event
    def on_mouse_release(x: int, y: int, button: int, modifiers: int) -> None:
        inp.mouse_up(button, screen(x, y), modifiers)

    @window.event
    def on_mouse_motion(x: int, y: int, dx: int, dy: int) -> None:
        inp.move_mouse(*screen(x, y))

    @window.event
    def on_mouse_drag(x: int, y: int, dx: int, dy: int, buttons: int, modifiers: int) -> None:
        inp.move_mouse(*screen(x, y))

    @window.event
    def on_mouse_scroll(x: int, y: int, scroll_x: float, scroll_y: float) -> None:
        inp.scroll_by(scroll_x, scroll_y)

    @window.event
    def on_deactivate() -> None:
        inp.reset()

    @window.event
    def on_resize(width: int, height: int) -> None:
        app.size = (int(width), int(height))  # cameras clamp to bounds with the real size

    @window.event
    def on_close() -> bool:
        app.request_close()  # quits, or asks the top scene (app.quit_on_close = False)
        return True  # the window closes when the App's loop ends, not before


def _image_loader(app: App) -> Callable[[str], Any]:
    def load(name: str) -> Any:
        from kge.assets import assets_for

        return assets_for(app.world).image(name)

    return load


def disconnect(window: Any) -> None:
    """Take :func:`connect`'s handlers off ``window`` (a pooled window outlives its App:
    a handler left on it would still drive a closed App in the next event loop)."""
    window.pop_handlers()


def run_windowed(
    app: App,
    frames: int | None = None,
    screenshot: str | None = None,
    prepare: Callable[[App, Any], None] | None = None,
) -> None:
    """Open a window of ``app.size`` and run until it closes, ``app.quit()`` or ``frames``.

    ``screenshot`` saves the last frame as a PNG while the window still exists.
    """
    import pyglet

    from kge.render.setup import configure_headless, create_window, ensure_renderer, release

    configure_headless(app.headless)
    window = create_window(app.size[0], app.size[1], caption=app.title, resizable=True, vsync=True)
    if prepare is not None:
        prepare(app, window)  # the render plugin: renderer + drawing systems
    else:
        ensure_renderer(app, window)
    connect(app, window, frames)
    from kge.render.gamepads import GamepadBridge

    pads = GamepadBridge(app.input)
    pads.start()
    app._running = True
    queued = pyglet.window.Window._enable_event_queue
    try:
        pyglet.app.run(1 / 60)
    finally:
        if screenshot:
            app.screenshot(screenshot)
        pyglet.clock.unschedule(pyglet.app.event_loop._redraw_windows)
        pyglet.window.Window._enable_event_queue = queued  # see setup.create_window
        app._running = False
        pads.stop()
        release(app)
