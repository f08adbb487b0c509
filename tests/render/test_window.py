"""The windowed loop, driven headless: the clock advances the App, events reach Input."""

from __future__ import annotations

import pytest

from kge import App, Transform
from kge.components.debug import DebugDraw
from kge.components.sprite import Sprite
from kge.keys import Key, Mouse
from kge.render.images import solid
from kge.render.window import connect, disconnect, run_windowed

from .conftest import SIZE


def scene(world):
    world.spawn(Transform(), Sprite(solid(2, 2, (255, 0, 0))))


def test_run_windowed_advances_and_draws_then_stops():
    app = App(scene, headless=True, size=SIZE)
    run_windowed(app, frames=5)
    assert app.frame_count >= 5
    assert not app.running
    app.close()


def test_window_events_feed_input_and_debug_toggles(make_app):
    app = make_app(scene)
    from kge.render.setup import ensure_renderer

    window = ensure_renderer(app).window
    app.render()
    connect(app, window)

    def send(name, *args):
        window.dispatch_event(name, *args)
        window.dispatch_events()  # outside pyglet's loop, window events are queued

    try:
        send("on_key_press", Key.SPACE, 0)
        assert app.input.pressed(Key.SPACE)
        send("on_mouse_press", SIZE[0] // 2 + 64, SIZE[1] // 2, Mouse.LEFT, 0)
        assert app.input.mouse_held(Mouse.LEFT)
        assert app.input.mouse_world == pytest.approx((1.0, 0.0))  # default camera: 64 px/m
        send("on_mouse_scroll", 0, 0, 0.0, 2.0)
        assert app.input.scroll == (0.0, 2.0)
        send("on_key_press", Key.F1, 0)
        app.advance(1 / 60)  # the press reaches the game in the frame's input stage
        assert app.world.resource(DebugDraw).enabled
        send("on_key_release", Key.F1, 0)
        send("on_key_press", Key.F1, 0)
        app.advance(1 / 60)
        assert not app.world.resource(DebugDraw).enabled
        send("on_deactivate")
        assert not app.input.held(Key.SPACE)
    finally:
        disconnect(window)
