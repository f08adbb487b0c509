"""Particle attractors: world-space particles within the radius are pulled in."""

from __future__ import annotations

import numpy as np
import pytest

from kge import (
    App,
    ParticleAttractor,
    ParticleEmitter,
    Particles,
    Transform,
    ValidationError,
    World,
)
from kge.components.particles import ParticleSpace


def _run(attractor: ParticleAttractor | None, space: ParticleSpace = ParticleSpace.WORLD,
         steps: int = 31) -> np.ndarray:
    def scene(world: World) -> None:
        world.spawn(Transform(0.0, 0.0), ParticleEmitter(burst=10, speed=0.0, lifetime=10.0,
                                                         space=space, seed=1))  # fmt: skip
        if attractor is not None:
            world.spawn(Transform(2.0, 0.0), attractor)

    app = App(scene, headless=True)
    app.step(steps)
    return app.world.resource(Particles).positions(1)


def test_particles_fall_towards_an_attractor_in_range() -> None:
    p = _run(ParticleAttractor(strength=8.0, radius=4.0))
    dt = 1 / 60
    # resting at the origin, 2 m away: pulled at 8 x (1 - 2/4) = 4 m/s^2, growing as they near
    assert np.all(p[:, 0] > 4.0 * dt * dt * 30 * 31 / 2 * 0.99) and np.allclose(p[:, 1], 0.0)
    assert np.all(p[:, 0] < 2.0)


def test_out_of_range_disabled_and_local_emitters_are_not_pulled() -> None:
    assert np.allclose(_run(ParticleAttractor(strength=8.0, radius=1.5)), 0.0)
    assert np.allclose(_run(ParticleAttractor(strength=8.0, radius=4.0, enabled=False)), 0.0)
    assert np.allclose(_run(ParticleAttractor(strength=8.0, radius=4.0),
                            space=ParticleSpace.LOCAL), 0.0)  # fmt: skip
    pushed = _run(ParticleAttractor(strength=-8.0, radius=4.0))
    assert np.all(pushed[:, 0] < -0.05)


def test_bad_attractors_are_refused() -> None:
    with pytest.raises(ValidationError, match="radius"):
        ParticleAttractor(radius=0.0)
    with pytest.raises(ValidationError, match="strength"):
        ParticleAttractor(strength=float("nan"))
    a = ParticleAttractor()
    with pytest.raises(ValidationError, match="radius"):
        a.radius = -1.0
    assert a.radius == 5.0
