"""Every sample is framed: what it builds is on screen, clear of the list and help,
and the car's camera follows the car."""

from __future__ import annotations

import pytest

from kge import App, Key, Transform
from kge.components.camera import Camera
from kge.components.debug import DebugDraw
from kge.testbed import all_samples, get_sample
from kge.testbed.app import HELP_HEIGHT, LIST_WIDTH, TestbedScene
from kge.testbed.framing import scene_bounds
from kge.testbed.registry import Sample
from kge.testbed.samples.build import named

SIZE = (1280, 720)


@pytest.mark.parametrize("sample", all_samples(), ids=lambda s: s.slug)
def test_the_sample_is_framed_beside_the_list_and_below_the_help(sample: Sample) -> None:
    app = App(TestbedScene(sample), headless=True, size=SIZE)
    if sample.camera is not None or sample.follow is not None:
        return  # the sample chose its own view (a 750 m row, a followed car...)
    bounds = scene_bounds(app.world)
    if bounds is None and sample.category == "UI":  # screen-space UI, no bodies to frame
        _ui_is_clear_of_the_list_and_help(app)
        return
    assert bounds is not None
    cam = app.world.resource(Camera)
    left, bottom = cam.world_to_screen((bounds[0], bounds[1]), SIZE)
    right, top = cam.world_to_screen((bounds[2], bounds[3]), SIZE)
    assert left >= LIST_WIDTH - 1 and right <= SIZE[0] + 1, (left, right)
    assert bottom >= -1 and top <= SIZE[1] - HELP_HEIGHT + 1, (bottom, top)
    # and it is not a speck: it fills a fair part of the free area
    assert (right - left) > 0.3 * (SIZE[0] - LIST_WIDTH) or (top - bottom) > 0.3 * (
        SIZE[1] - HELP_HEIGHT
    )


def _ui_is_clear_of_the_list_and_help(app: App) -> None:
    from kge.ui.interact import UIState

    app.step()
    boxes = app.world.resource(UIState).layout.boxes
    assert boxes
    for box in boxes.values():
        assert box.x >= LIST_WIDTH - 1 and box.top <= SIZE[1] - HELP_HEIGHT + 1, box


def test_the_car_camera_follows_the_car() -> None:
    app = App(TestbedScene(get_sample("car")), headless=True, size=SIZE)
    chassis = named(app.world, "chassis")[0]
    app.step(300)
    cam = app.world.resource(Camera)
    x = app.world.get(chassis, Transform).x
    assert x > 8.0
    sx, _ = cam.world_to_screen((x, 0.0), SIZE)
    assert abs(sx - SIZE[0] / 2) < 0.1 * SIZE[0]


def test_f1_from_a_real_window_toggles_debug_drawing_once() -> None:
    from kge.render.setup import ensure_renderer
    from kge.render.window import connect, disconnect

    app = App(TestbedScene(get_sample("hello-world")), headless=True, size=SIZE)
    app.render()
    window = ensure_renderer(app).window
    connect(app, window)
    assert app.world.resource(DebugDraw).enabled
    try:
        window.dispatch_event("on_key_press", Key.F1, 0)
        window.dispatch_events()
        app.advance(1 / 60)
        assert not app.world.resource(DebugDraw).enabled  # toggled once, not twice
        window.dispatch_event("on_key_release", Key.F1, 0)
        window.dispatch_event("on_key_press", Key.F1, 0)
        window.dispatch_events()
        app.advance(1 / 60)
        assert app.world.resource(DebugDraw).enabled
    finally:
        disconnect(window)
        app.close()
