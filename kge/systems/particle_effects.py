"""``ParticleEffectsPlugin``: the particle feature systems (in the default plugins).

* :class:`~kge.systems.particle_turbulence.ParticleTurbulenceSystem` runs just before
  the particle update (its field accelerates the particles the update integrates);
* :class:`ParticleEffectsSystem` runs just after it (UPDATE stage, ``EFFECTS`` set):
  sub-emitters fire at the births, collisions and deaths of their parents' particles
  (in entity order, at most :data:`GENERATIONS` generations of a chain per frame; a
  parent despawned this frame, a finished one-shot, still fires for its last
  deaths), then the particles born this frame get their flipbook start frames, and
  trails sample their particles' positions into their ring buffers.
"""

from __future__ import annotations

from kge.components.particle_flipbook import ParticleFlipbook
from kge.components.particle_stretch import ParticleStretch
from kge.components.particle_subemitters import ParticleSubEmitters
from kge.components.particle_trail import ParticleTrail, TrailMode
from kge.components.particle_turbulence import ParticleTurbulence
from kge.components.particles import ParticleEmitter
from kge.components.tracked import validate_writes
from kge.errors import ValidationError, where
from kge.particles import flipbook, subemit, trails
from kge.particles.emitter import EmitterState, Particles
from kge.plugin import Plugin
from kge.schedule import Stage, System, SystemSet
from kge.systems.particle_turbulence import ParticleTurbulenceSystem
from kge.systems.particles import ParticlesPlugin, ParticleSystem
from kge.world import World

#: generations of a sub-emitter chain (sparks whose births spawn sparks) run per frame;
#: later ones run on the next frame
GENERATIONS = 4

Parent = tuple[EmitterState, ParticleEmitter, ParticleSubEmitters]


class ParticleEffectsSystem(System):
    """What happens to particles after each update: see the module docstring."""

    stage = Stage.UPDATE
    in_set = SystemSet.EFFECTS
    after = (ParticleSystem,)

    def attach(self, world: World) -> None:
        super().attach(world)
        self.particles = world.try_resource(Particles) or world.insert_resource(Particles(world))
        #: the parents of the last frame (a despawned one still fires its last deaths)
        self.parents: dict[int, Parent] = {}

    def process(self, dt: float) -> None:
        self._sub_emit()
        particles = self.particles
        for e, (fb, em) in self.world.query(ParticleFlipbook, ParticleEmitter):
            st = particles.state(e)
            fs = flipbook.state(st, e if em.seed is None else em.seed)
            flipbook.start_new(st, fs, fb.count, fb.random_start)
        for e, (trail, _em) in self.world.query(ParticleTrail, ParticleEmitter):
            if trail.mode is TrailMode.PARTICLE:
                st = particles.state(e)
                trails.record(st, trails.state(st, trail.points), trail.duration, dt)


    def _sub_emit(self) -> None:
        world, particles = self.world, self.particles
        now: dict[int, Parent] = {}
        for e, (subs, em) in world.query(ParticleSubEmitters, ParticleEmitter):
            now[e] = (particles.state(e), em, subs)
        order = sorted(now)
        for e, (st, em, subs) in self.parents.items():
            if e in now:
                continue
            if e in particles.states:  # the component went: stop recording
                st.pool.watch = False
                st.pool.hits, st.pool.deaths = [], []
            else:  # despawned: its last events fire once
                now[e] = (st, em, subs)
                order.append(e)
        self.parents = {e: p for e, p in now.items() if e in particles.states}
        for _ in range(GENERATIONS):
            born = 0
            for e in order:
                st, em, subs = now[e]
                events = subemit.take_events(st, em, subs)
                for sub in subs.emitters:
                    rows = events.get(sub.on)
                    if rows is not None:
                        born += subemit.fire(particles, world, sub.emitter, sub.count,
                                             sub.inherit_velocity, rows)  # fmt: skip
            order = [e for e in order if e in self.parents]
            if not born:
                break


def _check_subemitters(world: World, entity: int | None, subs: ParticleSubEmitters) -> None:
    """Each sub-emitter must be a live world-space emitter."""
    for i, sub in enumerate(subs.emitters):
        field = f"emitters[{i}].emitter"
        em = world.try_get(sub.emitter, ParticleEmitter) if world.exists(sub.emitter) else None
        if em is None:
            raise ValidationError(f"{where(entity, 'ParticleSubEmitters', field)}: entity "
                                  f"{sub.emitter} is not a ParticleEmitter")  # fmt: skip
        if em.space == "local":
            raise ValidationError(f"{where(entity, 'ParticleSubEmitters', field)}: entity "
                                  f"{sub.emitter}'s emitter is in local space; sub-emitters "
                                  "spray in the world (ParticleSpace.WORLD)")  # fmt: skip


class ParticleEffectsPlugin(Plugin):
    """Turbulence, flipbooks, stretched particles, sub-emitters and trails: the systems
    (on top of ``ParticlesPlugin``); a bad write to one of their components names its
    entity."""

    requires = (ParticlesPlugin,)

    def build(self, world: World) -> None:
        world.add_system(ParticleTurbulenceSystem())
        world.add_system(ParticleEffectsSystem())
        world.validator(ParticleSubEmitters,
                        lambda entity, subs: _check_subemitters(world, entity, subs))
        for kind in (ParticleTurbulence, ParticleFlipbook, ParticleStretch, ParticleSubEmitters,
                     ParticleTrail):  # fmt: skip
            validate_writes(world, kind)
