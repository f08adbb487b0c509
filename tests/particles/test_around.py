"""Radial and tangential acceleration and orbits about the emitter's origin."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

from kge import App, Transform, ValidationError, World
from kge.components.particles import EmitCircle, ParticleEmitter
from kge.particles import Particles

DT = 1.0 / 60.0


def _positions(em: ParticleEmitter, steps: int, at: tuple[float, float] = (2.0, 3.0)
               ) -> tuple[App, np.ndarray]:
    def scene(world: World) -> None:
        world.spawn(Transform(*at), em)

    app = App(scene, headless=True)
    app.step(steps)
    e = next(e for e, _ in app.world.query(ParticleEmitter))
    return app, app.world.resource(Particles).positions(e)


def test_radial_acceleration_slows_a_ring_about_the_offset_origin() -> None:
    em = ParticleEmitter(burst=12, speed=4.0, spread=2 * math.pi, lifetime=10.0,
                         offset=(1.0, 0.0), radial_acceleration=-3.0, seed=3)  # fmt: skip
    n = 60
    _, p = _positions(em, 1 + n)  # born, then n steps
    rel = p - np.array([3.0, 3.0])  # the entity at (2, 3) plus the offset
    r = np.hypot(rel[:, 0], rel[:, 1])
    # the first step leaves the centre (no direction there yet), then -3 m/s^2 outward
    expected = n * 4.0 * DT - 3.0 * DT * DT * (n - 1) * n / 2
    np.testing.assert_allclose(r, expected, rtol=1e-4)
    _, q = _positions(ParticleEmitter(burst=12, speed=4.0, spread=2 * math.pi,
                                          lifetime=10.0, offset=(1.0, 0.0), seed=3), 1 + n)
    dirs = np.arctan2(rel[:, 1], rel[:, 0])
    qrel = q - np.array([3.0, 3.0])
    np.testing.assert_allclose(dirs, np.arctan2(qrel[:, 1], qrel[:, 0]), atol=1e-5)  # radial


def test_tangential_acceleration_swirls_counter_clockwise() -> None:
    for sign in (1.0, -1.0):
        em = ParticleEmitter(burst=16, speed=1.0, spread=2 * math.pi, lifetime=10.0,
                             tangential_acceleration=4.0 * sign, seed=1)  # fmt: skip
        app, p = _positions(em, 1 + 30, at=(0.0, 0.0))
        e = next(e for e, _ in app.world.query(ParticleEmitter))
        st = app.world.resource(Particles).states[e]
        vel = st.pool.data[2:4, : st.pool.count].T
        cross = p[:, 0] * vel[:, 1] - p[:, 1] * vel[:, 0]  # angular momentum about the origin
        assert np.all(np.sign(cross) == sign), cross


def test_an_orbit_turns_resting_particles_round_the_origin() -> None:
    em = ParticleEmitter(burst=20, speed=0.0, shape=EmitCircle(1.5, edge=True), lifetime=10.0,
                         orbit=math.pi, seed=2)  # fmt: skip
    app, before = _positions(em, 1)
    app.step(30)  # half a second at pi rad/s: a quarter turn
    e = next(e for e, _ in app.world.query(ParticleEmitter))
    after = app.world.resource(Particles).positions(e)
    rel = before - np.array([2.0, 3.0])
    turned = np.stack([-rel[:, 1], rel[:, 0]], axis=1) + np.array([2.0, 3.0])
    np.testing.assert_allclose(after, turned, atol=1e-4)


@pytest.mark.parametrize("field", ["radial_acceleration", "tangential_acceleration", "orbit"])
def test_bad_values_are_refused(field: str) -> None:
    bad: dict[str, Any] = {field: float("nan")}
    with pytest.raises(ValidationError, match=field):
        ParticleEmitter(**bad)
    bad[field] = 1e12
    with pytest.raises(ValidationError, match=field):
        ParticleEmitter(**bad)
    em = ParticleEmitter()
    with pytest.raises(ValidationError, match=field):
        setattr(em, field, float("inf"))
    assert getattr(em, field) == 0.0
