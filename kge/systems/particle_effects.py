"""``ParticleEffectsPlugin``: the particle feature systems (in the default plugins).

* :class:`~kge.systems.particle_turbulence.ParticleTurbulenceSystem` runs just before
  the particle update (its field accelerates the particles the update integrates);
* :class:`ParticleEffectsSystem` runs just after it (UPDATE stage, ``EFFECTS`` set):
  it gives the particles born this frame their flipbook start frames.
"""

from __future__ import annotations

from kge.components.particle_flipbook import ParticleFlipbook
from kge.components.particle_stretch import ParticleStretch
from kge.components.particle_turbulence import ParticleTurbulence
from kge.components.particles import ParticleEmitter
from kge.components.tracked import validate_writes
from kge.particles import flipbook
from kge.particles.emitter import Particles
from kge.plugin import Plugin
from kge.schedule import Stage, System, SystemSet
from kge.systems.particle_turbulence import ParticleTurbulenceSystem
from kge.systems.particles import ParticlesPlugin, ParticleSystem
from kge.world import World


class ParticleEffectsSystem(System):
    """What happens to particles after each update: see the module docstring."""

    stage = Stage.UPDATE
    in_set = SystemSet.EFFECTS
    after = (ParticleSystem,)

    def attach(self, world: World) -> None:
        super().attach(world)
        self.particles = world.try_resource(Particles) or world.insert_resource(Particles(world))

    def process(self, dt: float) -> None:
        particles = self.particles
        for e, (fb, em) in self.world.query(ParticleFlipbook, ParticleEmitter):
            st = particles.state(e)
            fs = flipbook.state(st, e if em.seed is None else em.seed)
            flipbook.start_new(st, fs, fb.count, fb.random_start)


class ParticleEffectsPlugin(Plugin):
    """Turbulence, flipbooks, stretched particles, sub-emitters and trails: the systems
    (on top of ``ParticlesPlugin``); a bad write to one of their components names its
    entity."""

    requires = (ParticlesPlugin,)

    def build(self, world: World) -> None:
        world.add_system(ParticleTurbulenceSystem())
        world.add_system(ParticleEffectsSystem())
        for kind in (ParticleTurbulence, ParticleFlipbook, ParticleStretch):
            validate_writes(world, kind)
