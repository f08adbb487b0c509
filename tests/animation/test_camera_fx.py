"""Camera effects: trauma shake bounded and decaying, zoom/move tweens, dead zone, look-ahead."""

from __future__ import annotations

import itertools
from typing import Any

import numpy as np
import pytest

from kge import App, BodyType, Camera, CameraShake, RigidBody, Transform, Tweens, ValidationError
from kge.animation.shake import noise
from kge.systems.animation import shake


def _app(setup: Any) -> App:
    return App(setup, headless=True, fixed_dt=0.02)


def test_noise_is_bounded_smooth_and_deterministic() -> None:
    ts = np.linspace(0, 50, 20001)
    v = np.array([noise(t, 3) for t in ts])
    assert np.abs(v).max() <= 1.0 and np.abs(v).max() > 0.5
    assert np.abs(np.diff(v)).max() < 0.05  # smooth: small steps for small dt
    assert [noise(t, 3) for t in ts[:50]] == list(v[:50])
    assert noise(1.3, 3) != noise(1.3, 4)


def test_shake_is_bounded_by_trauma_squared_and_decays_to_rest() -> None:
    def setup(world: Any) -> None:
        world.spawn(Camera(center=(5.0, 1.0)), CameraShake(decay=1.0, max_offset=(0.4, 0.2)))

    app = _app(setup)
    world = app.world
    cam = world.get(1, Camera)
    s = world.get(1, CameraShake)
    s.add(0.8)
    offsets = []
    trauma = []
    for _ in range(30):
        before = s.trauma
        app.step(1)
        ox, oy = cam.center[0] - 5.0, cam.center[1] - 1.0
        assert abs(ox) <= 0.4 * before**2 + 1e-12 and abs(oy) <= 0.2 * before**2 + 1e-12
        offsets.append(np.hypot(ox, oy))
        trauma.append(s.trauma)
    assert max(offsets) > 0.05  # it does shake
    assert all(b <= a for a, b in itertools.pairwise(trauma))  # decays
    assert s.trauma == pytest.approx(0.8 - 30 * 0.02)
    app.step(60)
    assert s.trauma == 0.0
    app.step(1)
    assert cam.center == pytest.approx((5.0, 1.0), abs=1e-12)  # back at rest, no drift


def test_shake_helper_adds_trauma_and_is_deterministic() -> None:
    runs = []
    for _ in range(2):
        app = _app(lambda world: world.insert_resource(Camera()))
        shake(app.world, 0.5)
        shake(app.world, 0.7)
        assert app.world.resource(CameraShake).trauma == 1.0
        path = []
        for _ in range(20):
            app.step(1)
            path.append(app.world.resource(Camera).center)
        runs.append(path)
    assert runs[0] == runs[1]
    with pytest.raises(ValidationError, match="amount must be >= 0"):
        shake(app.world, -0.1)


def test_zoom_to_and_move_to_are_eased_tweens_of_the_active_camera() -> None:
    app = _app(lambda world: world.spawn(Camera(center=(0.0, 0.0), zoom=1.0)))
    tweens = app.world.resource(Tweens)
    z = tweens.zoom_to(3.0, 0.4, ease="quad_in_out")
    m = tweens.move_to((2.0, -2.0), 0.4)
    app.step(10)  # 0.2 s: half-way, and in-out curves are at 0.5 there
    cam = app.world.get(1, Camera)
    assert cam.zoom == pytest.approx(2.0) and cam.center == pytest.approx((1.0, -1.0))
    app.step(10)
    assert z.done and m.done and cam.zoom == pytest.approx(3.0)


def test_follow_with_a_dead_zone_and_look_ahead() -> None:
    def setup(world: Any) -> None:
        world.spawn(Transform(0.0, 0.0), RigidBody(type=BodyType.KINEMATIC, velocity=(2.0, 0.0)))
        world.spawn(Camera(follow=1, dead_zone=(4.0, 2.0)))

    app = _app(setup)
    cam = app.world.get(2, Camera)
    app.step(45)  # body at x = 1.8: inside the dead zone's half width
    assert cam.center == (0.0, 0.0)
    app.step(55)  # x = 4: the camera keeps it on the zone's edge
    assert cam.center[0] == pytest.approx(4.0 - 2.0, abs=0.05)
    cam.look_ahead = 0.5
    app.step(1)  # aims 1 m ahead of the body
    x = app.world.get(1, Transform).x
    assert cam.center[0] == pytest.approx(x + 1.0 - 2.0, abs=1e-6)
    with pytest.raises(ValidationError, match=r"Camera.dead_zone\[0\] must be >= 0"):
        cam.dead_zone = (-1.0, 0.0)
