"""Turbulence: a seeded, deterministic curl-noise field over an emitter's particles."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from kge import App, EmitCircle, ParticleEmitter, Particles, Transform, ValidationError, World
from kge.components.particle_turbulence import ParticleTurbulence
from kge.errors import ComponentTypeError
from kge.particles.turbulence import curl, gradient, value

DT = 1.0 / 60.0


def test_the_gradient_is_the_noise_s_derivative_and_the_curl_has_no_divergence() -> None:
    rng = np.random.default_rng(0)
    x, y = rng.uniform(-30, 30, 500), rng.uniform(-30, 30, 500)
    h = 1e-5
    gx, gy = gradient(x, y, 0.37, 3)
    np.testing.assert_allclose(gx, (value(x + h, y, 0.37, 3) - value(x - h, y, 0.37, 3)) / (2 * h),
                               atol=1e-5)  # fmt: skip
    np.testing.assert_allclose(gy, (value(x, y + h, 0.37, 3) - value(x, y - h, 0.37, 3)) / (2 * h),
                               atol=1e-5)  # fmt: skip
    h = 1e-3
    p = np.stack([x, y], 1)

    def field(dx: float, dy: float) -> np.ndarray:
        return curl(p + np.array([dx, dy]), 1.0, 1.0, 0.0, 3).astype(float)

    div = (field(h, 0)[:, 0] - field(-h, 0)[:, 0] + field(0, h)[:, 1] - field(0, -h)[:, 1]) / (2 * h)
    assert np.abs(div).max() < 2e-2 and np.abs(field(0, 0)).max() > 0.3  # swirls, no sinks


def test_speed_changes_the_field_over_time_and_zero_keeps_it() -> None:
    p = np.random.default_rng(1).uniform(-5, 5, (100, 2))
    assert np.array_equal(curl(p, 0.0, 1.0, 0.0, 1), curl(p, 9.0, 1.0, 0.0, 1))
    assert not np.allclose(curl(p, 0.0, 1.0, 2.0, 1), curl(p, 0.4, 1.0, 2.0, 1))


def _app(turbulence: ParticleTurbulence | None, steps: int, seed: int = 1) -> App:
    def scene(world: World) -> None:
        extra: tuple[Any, ...] = () if turbulence is None else (turbulence,)
        world.spawn(Transform(1.0, 2.0), ParticleEmitter(
            burst=300, speed=0.0, lifetime=100.0, shape=EmitCircle(3.0), seed=seed), *extra)

    app = App(scene, headless=True)
    app.step(steps)
    return app


def _pool(app: App) -> Any:
    return app.world.resource(Particles).state(1).pool


def test_one_frame_adds_strength_times_the_curl_to_each_velocity() -> None:
    tb = ParticleTurbulence(strength=6.0, frequency=0.8, speed=0.5, seed=9)
    app = _app(tb, 1)  # born at rest
    pool = _pool(app)
    before = pool.pos[: pool.count].copy()
    app.step(1)  # the field at the clock's time (one frame in), then integrated
    expected = 6.0 * DT * curl(before, DT, 0.8, 0.5, 9)
    np.testing.assert_allclose(pool.vel[: pool.count], expected, rtol=1e-5, atol=1e-7)
    np.testing.assert_allclose(pool.pos[: pool.count], before + expected * DT, atol=1e-6)


def test_turbulence_moves_resting_particles_and_off_or_zero_does_not() -> None:
    moved = _pool(_app(ParticleTurbulence(strength=4.0), 60))
    speeds = np.hypot(*moved.vel[: moved.count].T)
    assert speeds.mean() > 0.3 and np.ptp(speeds) > 0.1  # each its own way
    for tb in (None, ParticleTurbulence(strength=0.0), ParticleTurbulence(enabled=False)):
        still = _pool(_app(tb, 60))
        assert not still.vel[: still.count].any()


def test_the_same_seed_gives_the_same_particles_another_seed_others() -> None:
    def run(seed: int) -> np.ndarray:
        p = _pool(_app(ParticleTurbulence(strength=4.0, seed=seed), 40))
        return p.data[:, : p.count].copy()

    assert np.array_equal(run(2), run(2))
    assert not np.array_equal(run(2), run(3))


def test_a_restored_snapshot_continues_the_same_field() -> None:
    tb = ParticleTurbulence(strength=5.0, speed=2.0)
    plain = _app(tb, 50)
    restored = _app(ParticleTurbulence(strength=5.0, speed=2.0), 20)
    restored.restore(restored.world.snapshot())
    restored.step(30)
    a, b = _pool(plain), _pool(restored)
    assert np.array_equal(a.data[:, : a.count], b.data[:, : b.count])


@pytest.mark.parametrize(("field", "bad", "message"), [
    ("strength", float("nan"), "ParticleTurbulence.strength must be finite"),
    ("strength", 1e9, "ParticleTurbulence.strength must be within"),
    ("frequency", 0.0, "ParticleTurbulence.frequency must be > 0"),
    ("frequency", 1e4, "ParticleTurbulence.frequency must be <= 1000"),
    ("speed", -1.0, "ParticleTurbulence.speed must be >= 0"),
    ("seed", -1, "ParticleTurbulence.seed must be in"),
    ("seed", 1.5, "ParticleTurbulence.seed must be an int"),
])  # fmt: skip
def test_bad_turbulence_is_refused_at_the_call(field: str, bad: Any, message: str) -> None:
    refused = (ValidationError, ComponentTypeError)
    with pytest.raises(refused, match=message):
        ParticleTurbulence(**{field: bad})
    app = _app(ParticleTurbulence(), 1)
    tb = app.world.get(1, ParticleTurbulence)
    before = getattr(tb, field)
    with pytest.raises(refused, match=f"entity 1, {message}"):
        setattr(tb, field, bad)
    assert getattr(tb, field) == before
