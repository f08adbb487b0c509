"""Particle trails: position history in ring buffers, strips and ribbons."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from kge import App, ParticleEmitter, Particles, Transform, ValidationError, World
from kge.components.particle_trail import ParticleTrail, TrailMode
from kge.errors import ComponentTypeError
from kge.particles import trails

DT = 1.0 / 60.0


def _app(trail: ParticleTrail, steps: int, **emitter: Any) -> tuple[App, Any]:
    def scene(world: World) -> None:
        world.spawn(Transform(1.0, 2.0), ParticleEmitter(**{
            "burst": 3, "speed": 3.0, "direction": 0.0, "lifetime": 10.0, "seed": 1,
            **emitter}), trail)  # fmt: skip

    app = App(scene, headless=True)
    app.step(steps)
    return app, app.world.resource(Particles).state(1)


def test_a_trail_holds_where_the_particle_was_newest_first() -> None:
    # 6 points over 0.1 s: a sample every 1/60 s, i.e. every frame
    app, st = _app(ParticleTrail(duration=0.1, points=6), 1)
    ts = st.extras[trails.KEY]
    lines = trails.polylines(st, ts)
    assert lines.shape == (2, 3, 7)  # x and y planes, 3 particles, the head and 6 samples
    np.testing.assert_allclose(lines[:, :, 1:], np.repeat(lines[:, :, :1], 6, axis=2), atol=1e-6)
    app.step(3)
    lines = trails.polylines(st, ts)
    x = lines[0, 0]  # moving +x at 3 m/s from x = 1: now 3 frames on
    np.testing.assert_allclose(x[:5], 1.0 + 3.0 * DT * np.array([3, 3, 2, 1, 0]), atol=1e-5)
    np.testing.assert_allclose(x[5:], 1.0, atol=1e-6)  # not filled yet: the birth point
    app.step(10)
    x = trails.polylines(st, ts)[0, 0]
    np.testing.assert_allclose(np.diff(x[1:]), -3.0 * DT, atol=1e-5)  # one frame apart


def test_samples_are_spaced_by_duration_over_points_of_game_time() -> None:
    _, st = _app(ParticleTrail(duration=0.5, points=5), 1 + 60)
    x = trails.polylines(st, st.extras[trails.KEY])[0, 0]
    gaps = -np.diff(x[1:])
    np.testing.assert_allclose(gaps, 3.0 * 0.1, atol=3.0 * DT + 1e-5)  # 0.1 s apart
    assert x[0] - x[-1] <= 3.0 * 0.6 + 1e-4  # the trail covers at most duration + one sample


def test_rings_follow_their_particles_when_others_die() -> None:
    _, st = _app(ParticleTrail(duration=0.1, points=4), 30, burst=0, rate=60.0,
                   lifetime=(0.2, 0.4), speed=(1.0, 4.0))  # fmt: skip
    lines = trails.polylines(st, st.extras[trails.KEY])
    speeds = np.hypot(*st.pool.vel[: st.pool.count].T)
    # each row's history lies behind its own particle, along its own velocity
    back = lines[0, :, 0] - lines[0, :, 2]
    old = st.pool.age[: st.pool.count] > 3 * DT  # the newest have no two samples yet
    assert old.sum() > 10
    np.testing.assert_allclose(back[old], speeds[old] * 2 * DT, atol=1e-4)


def test_a_ribbon_runs_from_the_youngest_particle_to_the_oldest() -> None:
    _, st = _app(ParticleTrail(mode=TrailMode.RIBBON), 20, burst=0, rate=60.0)
    x = trails.ribbon(st)[0, 0]
    assert len(x) == st.pool.count
    assert np.all(np.diff(x) > 0)  # older ones flew further along +x


def test_strips_are_as_wide_as_asked_across_the_line() -> None:
    line = np.array([[[0.0, 0.0, 0.0]], [[0.0, 1.0, 2.0]]], np.float32)  # x, y planes
    edges = trails.strip(line, np.array([0.4, 0.2, 0.0], np.float32))[0].reshape(-1, 2)
    np.testing.assert_allclose(edges[:, 0], [-0.2, 0.2, -0.1, 0.1, 0.0, 0.0], atol=1e-6)
    np.testing.assert_allclose(edges[:, 1], [0, 0, 1, 1, 2, 2], atol=1e-6)


def test_a_restored_snapshot_keeps_the_trails() -> None:
    def scene(world: World) -> None:
        world.spawn(Transform(), ParticleEmitter(rate=30.0, speed=(1.0, 3.0), spread=2.0,
                                                 lifetime=0.7, seed=3), ParticleTrail())

    plain = App(scene, headless=True)
    plain.step(50)
    restored = App(scene, headless=True)
    restored.step(25)
    restored.restore(restored.world.snapshot())
    restored.step(25)
    a = plain.world.resource(Particles).state(1)
    b = restored.world.resource(Particles).state(1)
    assert np.array_equal(trails.polylines(a, a.extras[trails.KEY]),
                          trails.polylines(b, b.extras[trails.KEY]))  # fmt: skip


@pytest.mark.parametrize(("field", "bad", "message"), [
    ("points", 1, "ParticleTrail.points must be in 2..64"),
    ("points", 65, "ParticleTrail.points must be in 2..64"),
    ("duration", 0.0, "ParticleTrail.duration must be > 0"),
    ("duration", float("inf"), "ParticleTrail.duration must be finite"),
    ("width", -0.1, "ParticleTrail.width must be >= 0"),
    ("width", (0.1, float("nan")), r"ParticleTrail.width\[1\] must be finite"),
    ("color", (300, 0, 0), r"ParticleTrail.color\[0\] must be an int in 0..255"),
    ("opacity", 400, "ParticleTrail.opacity must be in"),
    ("mode", "comet", "ParticleTrail.mode must be one of"),
])  # fmt: skip
def test_bad_trails_are_refused_at_the_call(field: str, bad: Any, message: str) -> None:
    refused = (ValidationError, ComponentTypeError)
    with pytest.raises(refused, match=message):
        ParticleTrail(**{field: bad})
    app, _ = _app(ParticleTrail(), 1)
    trail = app.world.get(1, ParticleTrail)
    before = getattr(trail, field)
    with pytest.raises(refused, match=f"entity 1, {message}"):
        setattr(trail, field, bad)
    assert getattr(trail, field) == before
