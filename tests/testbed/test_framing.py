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


@pytest.mark.parametrize("slug", ["box-pile", "rain", "hello-world", "pyramid"])
def test_the_contact_sheet_shows_every_moving_body_large(slug: str) -> None:
    """The showcase frames a sample after it ran: its bodies, not the empty top of its box."""
    from kge import Collider, RigidBody
    from kge.components.rigidbody import BodyType
    from kge.testbed.cli import make_app
    from kge.testbed.framing import collider_bounds
    from kge.testbed.showcase import frame_sample

    size = (640, 400)
    sample = get_sample(slug)
    app = make_app(sample, size)
    app.step(120)
    frame_sample(app, sample, label=False)
    cam = app.world.resource(Camera)
    corners = []
    for e, (col, rb) in app.world.query(Collider, RigidBody):
        if rb.type is BodyType.DYNAMIC:
            box = collider_bounds(app.world, e, col)
            assert box is not None
            for corner in ((box[0], box[1]), (box[2], box[3])):
                sx, sy = cam.world_to_screen(corner, size)
                assert -1 <= sx <= size[0] + 1 and -1 <= sy <= size[1] - 24 + 1, (slug, e)
                corners.append((sx, sy))
    assert corners
    xs, ys = [c[0] for c in corners], [c[1] for c in corners]
    # the bodies fill a fair part of the tile (the empty top of a 40 x 80 m box does not)
    assert max(xs) - min(xs) > 0.25 * size[0] or max(ys) - min(ys) > 0.25 * (size[1] - 24)
    app.close()
