"""``ParticleTurbulenceSystem``: curl-noise turbulence on emitters' particles.

Runs in the UPDATE stage's ``EFFECTS`` set just before
:class:`~kge.systems.particles.ParticleSystem`: for each emitter entity with an
enabled :class:`~kge.components.particle_turbulence.ParticleTurbulence` it adds
``strength x curl x dt`` to the velocities of all live particles at once (one
numpy pass, :func:`kge.particles.turbulence.curl`); the particle system then
integrates them with the emitter's own forces. The field's clock is kept in the
emitter's running state, so snapshots and restores continue the same field.
"""

from __future__ import annotations

import numpy as np

from kge.components.particle_turbulence import ParticleTurbulence
from kge.components.particles import ParticleEmitter
from kge.particles.emitter import Particles
from kge.particles.turbulence import curl
from kge.schedule import Stage, System, SystemSet
from kge.systems.particles import ParticleSystem
from kge.world import World

#: the key of the field's clock in ``EmitterState.extras``
CLOCK = "turbulence"


class ParticleTurbulenceSystem(System):
    """Adds each turbulent emitter's noise acceleration to its particles' velocities."""

    stage = Stage.UPDATE
    in_set = SystemSet.EFFECTS
    before = (ParticleSystem,)

    def attach(self, world: World) -> None:
        super().attach(world)
        self.particles = world.try_resource(Particles) or world.insert_resource(Particles(world))

    def process(self, dt: float) -> None:
        if dt <= 0.0:
            return
        particles = self.particles
        for e, (tb, _em) in self.world.query(ParticleTurbulence, ParticleEmitter):
            if not tb.enabled:
                continue
            st = particles.state(e)
            t = st.extras.get(CLOCK, 0.0)
            st.extras[CLOCK] = t + dt
            pool = st.pool
            n = pool.count
            if n == 0 or tb.strength == 0.0:
                continue
            acc = curl(pool.pos[:n], t, tb.frequency, tb.speed, tb.seed)
            acc *= np.float32(tb.strength * dt)
            pool.data[2:4, :n] += acc.T
