"""The mouse pointer's look (``app.cursor``): set headless, applied by the window loop."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from PIL import Image

from kge import App, KgeError, ValidationError
from kge.cursor import Cursor, apply
from kge.render.window import connect, disconnect


class Recorder:
    """A window that records what it was asked to do with the pointer."""

    def __init__(self) -> None:
        self.calls: list[tuple[str, Any]] = []

    def set_exclusive_mouse(self, on: bool) -> None:
        self.calls.append(("exclusive", on))

    def set_mouse_visible(self, on: bool) -> None:
        self.calls.append(("visible", on))

    def set_mouse_cursor(self, cursor: Any) -> None:
        self.calls.append(("cursor", cursor))


def test_bad_cursor_settings_are_refused_at_the_call_and_change_nothing() -> None:
    cursor = Cursor()
    for bad in ({"visible": "no"}, {"locked": 1}, {"image": 3}, {"image": ""},
                {"hotspot": (1.5, 0)}, {"hotspot": (0,)}, {"hotspot": (0, -2)}):
        with pytest.raises(KgeError, match="Cursor"):
            cursor.set(**bad)
    with pytest.raises(ValidationError):
        cursor.set(visible=False, hotspot=(-1, 0))  # one bad value: nothing changes
    assert cursor == Cursor()


def test_hide_lock_and_an_image_cursor_reach_the_window(tmp_path: Path) -> None:
    import pyglet

    Image.new("RGBA", (16, 12), (255, 0, 0, 255)).save(tmp_path / "aim.png")
    window = Recorder()
    cursor = Cursor()
    cursor.hide()
    apply(cursor, window, pyglet.image.load)
    assert window.calls == [("exclusive", False), ("visible", False), ("cursor", None)]
    window.calls.clear()
    cursor.set(visible=True, locked=True)
    apply(cursor, window, pyglet.image.load)
    assert window.calls[:2] == [("exclusive", True), ("visible", False)]  # captured: hidden
    window.calls.clear()
    cursor.set(locked=False, image=str(tmp_path / "aim.png"), hotspot=(3, 2))
    apply(cursor, window, pyglet.image.load)
    made = window.calls[-1][1]
    assert isinstance(made, pyglet.window.ImageMouseCursor)
    assert (made.hot_x, made.hot_y) == (3, 12 - 1 - 2)  # pyglet counts from the bottom
    cursor.set(hotspot=(16, 0))
    with pytest.raises(ValidationError, match="outside the 16x12 image"):
        apply(cursor, window, pyglet.image.load)


def test_the_window_loop_applies_a_changed_cursor_once(make_app: Any) -> None:
    from kge.render.setup import ensure_renderer

    app: App = make_app(lambda world: None)
    window = ensure_renderer(app).window
    seen: list[bool] = []
    window.set_mouse_visible = seen.append
    connect(app, window)
    app._running = True

    def draw() -> None:
        window.dispatch_event("on_draw")
        window.dispatch_events()  # outside pyglet's loop, window events are queued

    try:
        draw()
        assert seen == [] and app.frame_count == 1  # unchanged: the window is left alone
        app.cursor.hide()
        draw()
        draw()
        assert seen == [False]  # applied once, on the frame after the change
    finally:
        disconnect(window)
