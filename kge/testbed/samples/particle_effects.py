"""Particle effect samples: turbulence and attractors, flipbooks, sub-emitters, trails."""

from __future__ import annotations

import math

import numpy as np

from kge.components import Name, Transform
from kge.components.particle_flipbook import ParticleFlipbook
from kge.components.particle_stretch import ParticleStretch
from kge.components.particle_subemitters import ParticleSubEmitters, SubEmitEvent, SubEmitter
from kge.components.particle_trail import ParticleTrail, TrailMode
from kge.components.particle_turbulence import ParticleTurbulence
from kge.components.particles import (
    Blend,
    EmitBox,
    EmitCircle,
    EmitLine,
    ParticleAttractor,
    ParticleCollision,
    ParticleEmitter,
)
from kge.particles import Particles, flipbook
from kge.render.images import PixelImage, from_array
from kge.testbed.registry import sample
from kge.testbed.samples.build import named, static_box
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


def flame_sheet(cell: int = 16) -> PixelImage:
    """A 4 x 2 sheet of a soft flame that grows, then shrinks and cools (generated)."""
    sheet = np.zeros((2 * cell, 4 * cell, 4), np.uint8)
    ys, xs = np.mgrid[0:cell, 0:cell] + 0.5
    for i in range(8):
        row, col = divmod(i, 4)
        grow = 0.45 + 0.45 * math.sin(math.pi * (i + 0.5) / 8)
        r = np.hypot((xs - cell / 2) / grow, (ys - cell * 0.6) / (grow * 1.3)) / (cell / 2)
        alpha = np.clip(1.0 - r, 0.0, 1.0)
        heat = 1.0 - i / 10
        tile = sheet[row * cell : (row + 1) * cell, col * cell : (col + 1) * cell]
        tile[..., 0] = 255
        tile[..., 1] = np.uint8(200 * heat)
        tile[..., 2] = np.uint8(60 * heat * heat)
        tile[..., 3] = np.rint(alpha * 255).astype(np.uint8)
    return from_array(sheet)


@sample("Particles", "Flipbook And Stretch", help="Left: a fire of animated flame sprites "
        "(a generated 4 x 2 sheet, each particle from a random frame at 12 fps). Right: sparks "
        "drawn stretched along their velocity, longer the faster they fly.",
        camera=(0.0, 3.0, 1.0))
def flipbook_and_stretch(world: World) -> None:
    world.spawn(Transform(-3.5, 0.5), Name("fire"), ParticleEmitter(
        rate=40.0, speed=(0.6, 1.2), spread=0.5, lifetime=(0.8, 1.4), shape=EmitBox(1.0, 0.2),
        size=(0.9, 1.3, 0.6), opacity=(0, 255, 255, 0), texture=flame_sheet(),
        blend=Blend.ADDITIVE, seed=7,
    ), ParticleFlipbook(4, 2, fps=12.0, random_start=True))  # fmt: skip
    world.spawn(Transform(3.5, 0.5), Name("sparks"), ParticleEmitter(
        rate=120.0, speed=(3.0, 9.0), spread=1.2, lifetime=(0.6, 1.0), acceleration=(0.0, -9.8),
        size=0.06, flat=True, color=((255, 255, 200), (255, 120, 20)), blend=Blend.ADDITIVE,
        seed=8,
    ), ParticleStretch(speed_scale=0.05, max_length=0.6))  # fmt: skip


@flipbook_and_stretch.claim
def _flames_flicker_out_of_step(app) -> None:  # type: ignore[no-untyped-def]
    st = app.world.resource(Particles).state(named(app.world, "fire")[0])
    n = st.pool.count
    starts = st.pool.data[st.extras[flipbook.KEY]["row"], :n]
    assert n > 20 and len(set(starts.tolist())) >= 6, "random start frames"


@sample("Particles", "Fireworks And Splashes", help="Left: rockets leave a trail of embers "
        "(sub-emitter on birth) and burst into 80 sparks where they die (on death, inheriting "
        "30% of the rocket's velocity). Right: rain splashes where it hits the ground (on "
        "collision).", camera=(0.0, 3.0, 1.0))
def fireworks_and_splashes(world: World) -> None:
    sparks = world.spawn(Transform(), Name("sparks"), ParticleEmitter(
        emitting=False, speed=(2.0, 4.0), spread=2 * math.pi, lifetime=(0.8, 1.2), drag=1.2,
        acceleration=(0.0, -2.5), size=(0.1, 0.03), color=((255, 240, 160), (255, 60, 120)),
        blend=Blend.ADDITIVE, max_particles=4000, seed=2,
    ))  # fmt: skip
    embers = world.spawn(Transform(), Name("embers"), ParticleEmitter(
        emitting=False, speed=(0.0, 0.3), spread=2 * math.pi, lifetime=(0.3, 0.5), size=0.05,
        color=((255, 180, 80),), opacity=(200, 0), blend=Blend.ADDITIVE, max_particles=2000,
        seed=3,
    ))  # fmt: skip
    world.spawn(Transform(-4.0, -1.0), Name("rockets"), ParticleEmitter(
        rate=1.5, speed=(8.0, 9.5), spread=0.5, lifetime=(0.9, 1.1), acceleration=(0.0, -5.0),
        rate_per_meter=0.0, size=0.12, color=((255, 255, 255),), seed=1,
    ), ParticleSubEmitters(
        SubEmitter(sparks, SubEmitEvent.DEATH, count=80, inherit_velocity=0.3),
        SubEmitter(embers, SubEmitEvent.BIRTH, count=1),
    ))  # fmt: skip
    static_box(world, 4.0, -1.5, 3.0, 0.5, name="ground")
    splash = world.spawn(Transform(), Name("splash"), ParticleEmitter(
        emitting=False, speed=(0.8, 1.6), direction=math.pi / 2, spread=1.6, lifetime=0.35,
        acceleration=(0.0, -9.8), size=0.05, color=((180, 200, 255),), max_particles=3000,
        collide=ParticleCollision.DIE, seed=4,
    ))  # fmt: skip
    world.spawn(Transform(4.0, 6.0), Name("rain"), ParticleEmitter(
        rate=60.0, speed=6.0, direction=-math.pi / 2, lifetime=2.0, shape=EmitBox(5.0, 0.1),
        size=0.04, color=((170, 190, 255),), collide=ParticleCollision.DIE, seed=5,
    ), ParticleSubEmitters(SubEmitter(splash, SubEmitEvent.COLLISION, count=4)),
        ParticleStretch(speed_scale=0.05))  # fmt: skip


@fireworks_and_splashes.claim
def _rockets_burst_and_rain_splashes(app) -> None:  # type: ignore[no-untyped-def]
    particles = app.world.resource(Particles)
    burst = particles.state(named(app.world, "sparks")[0])
    assert burst.born >= 80 and burst.born % 80 == 0, burst.born
    rockets = particles.state(named(app.world, "rockets")[0])
    assert particles.state(named(app.world, "embers")[0]).born == rockets.born
    drops = particles.positions(named(app.world, "splash")[0])
    assert len(drops) > 20 and drops[:, 1].min() > -1.1, "splashes start on the ground"


@sample("Particles", "Trails And Ribbons", help="Left: comets with tapering, cooling trails "
        "(0.4 s of path in 12 samples each, ring buffers in numpy). Right: a ribbon joins a "
        "stream of particles rising through a turbulence field.", camera=(0.0, 3.0, 1.0))
def trails_and_ribbons(world: World) -> None:
    world.spawn(Transform(-4.0, 0.0), Name("comets"), ParticleEmitter(
        rate=12.0, speed=(6.0, 8.0), spread=0.8, direction=1.25, lifetime=(1.4, 1.8),
        acceleration=(0.0, -6.0), size=0.18, color=((255, 240, 180),), blend=Blend.ADDITIVE,
        seed=11,
    ), ParticleTrail(duration=0.4, points=12, width=(0.16, 0.0),
                     color=((255, 200, 80), (255, 40, 0)), opacity=(255, 0)))  # fmt: skip
    world.spawn(Transform(3.5, 0.0), Name("stream"), ParticleEmitter(
        rate=40.0, speed=1.5, lifetime=3.0, size=0.0, seed=12,
    ), ParticleTurbulence(strength=2.0, frequency=0.5, speed=0.3, seed=1),
        ParticleTrail(mode=TrailMode.RIBBON, width=(0.35, 0.05), color=((80, 200, 255),),
                      opacity=(255, 40)))  # fmt: skip


@trails_and_ribbons.claim
def _trails_lie_behind_their_comets(app) -> None:  # type: ignore[no-untyped-def]
    from kge.particles import trails

    st = app.world.resource(Particles).state(named(app.world, "comets")[0])
    lines = trails.polylines(st, st.extras[trails.KEY])
    old = st.pool.age[: st.pool.count] > 0.5
    vel = st.pool.vel[: st.pool.count][old]
    back = (lines[:, old, 0] - lines[:, old, -1]).T  # head minus tail: along the flight
    assert old.sum() > 3 and np.all(np.sum(back * vel, axis=1) > 0)
