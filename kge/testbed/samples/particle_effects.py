"""Particle effect samples: turbulence and attractors, flipbooks, sub-emitters, trails."""

from __future__ import annotations

import numpy as np

from kge.components import Name, Transform
from kge.components.particle_turbulence import ParticleTurbulence
from kge.components.particles import (
    Blend,
    EmitCircle,
    EmitLine,
    ParticleAttractor,
    ParticleEmitter,
)
from kge.particles import Particles
from kge.testbed.registry import sample
from kge.testbed.samples.build import named
from kge.world import World


def _live(app, name: str) -> np.ndarray:  # type: ignore[no-untyped-def]
    return app.world.resource(Particles).positions(named(app.world, name)[0])


@sample("Particles", "Turbulence And Attractors", help="Left: smoke rises through a curl-noise "
        "field and billows. Right: a sheet of sparks drifts past a black hole (falloff 2) and "
        "a repulsor that parts the stream.", camera=(0.0, 3.0, 1.0))
def turbulence_and_attractors(world: World) -> None:
    world.spawn(Transform(-4.0, 0.0), Name("smoke"), ParticleEmitter(
        rate=160.0, speed=(0.6, 1.0), spread=0.4, lifetime=(3.0, 4.0), drag=0.6,
        acceleration=(0.0, 0.5), shape=EmitCircle(0.3), size=(0.15, 0.6),
        color=((220, 220, 230), (120, 120, 140)), opacity=(200, 0), seed=2,
    ), ParticleTurbulence(strength=2.5, frequency=0.7, speed=0.4, seed=5))  # fmt: skip
    world.spawn(Transform(1.0, 3.0), Name("stream"), ParticleEmitter(
        rate=300.0, speed=2.0, direction=0.0, lifetime=3.5, shape=EmitLine((0.0, -2.5), (0.0, 2.5)),
        size=0.08, color=((255, 220, 120), (120, 200, 255)), blend=Blend.ADDITIVE, seed=3,
    ))  # fmt: skip
    world.spawn(Transform(4.0, 4.2), Name("black hole"),
                ParticleAttractor(strength=30.0, radius=2.5, falloff=2.0))
    world.spawn(Transform(4.0, 1.8), Name("repulsor"),
                ParticleAttractor(strength=-20.0, radius=1.2, falloff=1.0))


@turbulence_and_attractors.claim
def _smoke_billows_and_the_stream_parts(app) -> None:  # type: ignore[no-untyped-def]
    st = app.world.resource(Particles).state(named(app.world, "smoke")[0])
    sideways = st.pool.vel[: st.pool.count, 0]
    # a 0.4 rad cone with drag alone keeps the sideways speeds within about 0.05 m/s
    assert st.pool.count > 300 and sideways.std() > 0.1, "turbulence stirs the column"
    stream = _live(app, "stream")
    near = np.hypot(stream[:, 0] - 4.0, stream[:, 1] - 1.8)
    assert near.min() > 0.3, "the repulsor keeps a hole in the stream"
    hole = np.hypot(stream[:, 0] - 4.0, stream[:, 1] - 4.2)
    assert (hole < 0.5).sum() > 5, "the black hole gathers sparks"
