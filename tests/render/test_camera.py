"""Camera maths (pure), zoom clamping, bounds and follow (headless, no window needed)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from kge import App, Transform
from kge.components.camera import Camera
from kge.errors import ValidationError

finite = st.floats(-1e4, 1e4, allow_nan=False)


@given(finite, finite, finite, finite, st.floats(0.1, 10), st.floats(1, 500))
def test_world_to_screen_round_trips(px, py, cx, cy, zoom, ppm):
    cam = Camera(center=(cx, cy), pixels_per_meter=ppm, zoom=zoom)
    back = cam.screen_to_world(cam.world_to_screen((px, py), (640, 480)), (640, 480))
    assert back == pytest.approx((px, py), abs=1e-6 * (1 + abs(px) + abs(py)))


def test_world_y_is_up_and_centre_is_mid_window():
    cam = Camera(center=(10.0, 5.0))
    assert cam.world_to_screen((10.0, 5.0), (800, 600)) == (400.0, 300.0)
    assert cam.world_to_screen((10.0, 6.0), (800, 600))[1] > 300.0


def test_zoom_is_clamped_and_nan_refused():
    cam = Camera()
    cam.zoom = 0.01
    assert cam.zoom == 0.1
    cam.zoom = 1e6
    assert cam.zoom == 10.0
    with pytest.raises(ValidationError, match="Camera.zoom"):
        cam.zoom = math.nan
    with pytest.raises(ValidationError, match="Camera.bounds"):
        Camera(bounds=(0, 0, -1, 1))


def test_bounds_keep_the_view_inside_the_level():
    cam = Camera(pixels_per_meter=10, bounds=(0.0, 0.0, 100.0, 50.0))
    cam.track((-20.0, 49.0), dt=1 / 60, viewport=(200, 100))  # view is 20 m x 10 m
    assert cam.center == pytest.approx((10.0, 45.0))


def _follow_app(smoothing):
    state = {}

    def scene(world):
        state["target"] = world.spawn(Transform(3.0, -2.0))
        world.spawn(Camera(follow=state["target"], smoothing=smoothing))

    app = App(scene, headless=True)  # CameraFollow is a default system
    return app, state["target"]


def test_follow_snaps_without_smoothing():
    app, target = _follow_app(0.0)
    app.step(1)
    ((_, (cam,)),) = app.world.query(Camera)
    assert cam.center == pytest.approx((3.0, -2.0))
    app.world.get(target, Transform).x = 7.0
    app.step(1)
    assert cam.center == pytest.approx((7.0, -2.0))
    app.close()


def test_follow_with_smoothing_converges_frame_rate_independently():
    app, _ = _follow_app(0.2)
    ((_, (cam,)),) = app.world.query(Camera)
    app.step(6)  # 0.1 s: 1 - exp(-0.5) of the way
    assert cam.center[0] == pytest.approx(3.0 * (1 - math.exp(-0.5)), rel=1e-6)
    app.step(120)
    assert cam.center == pytest.approx((3.0, -2.0), abs=1e-3)
    app.close()
