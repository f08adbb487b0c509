"""Particle samples: a fountain, explosions, sparks on hits, a smoke trail, 10,000 particles."""

from __future__ import annotations

import math

import numpy as np

from kge.components import Behaviour, Name, Script, Transform
from kge.components.collider import Collider
from kge.components.particles import (
    Blend,
    BurstOnHit,
    EmitBox,
    EmitCircle,
    ParticleCollision,
    ParticleEmitter,
)
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box
from kge.particles import Particles
from kge.testbed.registry import sample
from kge.testbed.samples.build import ball, named, static_box
from kge.world import World


def _live(app, name: str) -> np.ndarray:  # type: ignore[no-untyped-def]
    """World positions of the particles of the emitter named ``name``."""
    return app.world.resource(Particles).positions(named(app.world, name)[0])


@sample("Particles", "Fountain", help="Water arcs up, falls under gravity and bounces off the "
        "basin: 300 particles a second, colour and alpha over life.", camera=(0.0, 4.0, 1.0))
def fountain(world: World, rate: float = 300.0) -> None:
    static_box(world, 0.0, -0.5, 6.0, 0.5, name="basin")
    world.spawn(Transform(0.0, 0.2), Name("fountain"), ParticleEmitter(
        rate=rate, lifetime=(2.0, 2.6), speed=(7.0, 8.5), spread=0.35, acceleration=(0.0, -9.8),
        size=(0.12, 0.2), color=((200, 230, 255), (60, 120, 255)), opacity=(255, 230, 0),
        collide=ParticleCollision.BOUNCE, bounciness=0.3, shape=EmitCircle(0.1), max_particles=2000,
        seed=3,
    ))  # fmt: skip


@fountain.claim
def _water_stays_above_the_basin(app) -> None:  # type: ignore[no-untyped-def]
    pts = _live(app, "fountain")
    assert len(pts) > 400, f"only {len(pts)} live drops"
    assert pts[:, 1].min() > -0.05, "a drop sank into the basin"
    assert pts[:, 1].max() > 2.0, "the jet rises"


class _Exploder(Script):
    """Every ``period`` seconds, a one-shot explosion at the next spot."""

    def __init__(self, period: float = 1.0) -> None:
        self.period = period
        self.timer = 0.0
        self.count = 0

    def on_update(self, dt: float) -> None:
        self.timer -= dt
        if self.timer > 0:
            return
        self.timer = self.period
        x = (-4.0, 0.0, 4.0)[self.count % 3]
        self.count += 1
        self.world.spawn(Transform(x, 4.0), Name("explosion"), ParticleEmitter(
            burst=250, lifetime=(0.4, 0.9), speed=(2.0, 9.0), drag=2.5, size=(0.25, 0.05),
            color=((255, 255, 200), (255, 160, 40), (200, 40, 0)), opacity=(255, 0),
            one_shot=True, spread=2 * math.pi, blend=Blend.ADDITIVE, seed=self.count,
        ))  # fmt: skip
        self.world.spawn(Transform(x, 4.0), Name("smoke"), ParticleEmitter(
            burst=60, lifetime=(1.0, 1.6), speed=(0.5, 2.0), drag=1.0, size=(0.3, 1.2),
            acceleration=(0.0, 1.0), color=((90, 90, 90), (40, 40, 40)), opacity=(153, 0),
            one_shot=True, spread=2 * math.pi, seed=1000 + self.count,
        ))  # fmt: skip


@sample("Particles", "Explosion", help="A one-shot blast every second: an additive flash and a "
        "smoke puff, each an entity that despawns itself when its particles are gone.",
        camera=(0.0, 4.0, 1.0))
def explosion(world: World) -> None:
    static_box(world, 0.0, -0.5, 8.0, 0.5, name="ground")
    world.spawn(Name("exploder"), Behaviour(_Exploder()))


@explosion.claim
def _one_shots_clean_up(app) -> None:  # type: ignore[no-untyped-def]
    world = app.world
    script = world.get(named(world, "exploder")[0], Behaviour).script
    assert script.count >= 5
    # each blast lives < 1.6 s: at most two generations exist at any time
    assert len(named(world, "explosion")) <= 2 and len(named(world, "smoke")) <= 2


@sample("Particles", "Sparks On Hits", help="Balls rain onto the floor; every impact sprays "
        "sparks from the contact point along the contact normal (BurstOnHit).",
        camera=(0.0, 3.0, 1.0))
def sparks_on_hits(world: World, balls: int = 12) -> None:
    sparks = world.spawn(Name("sparks"), Transform(), ParticleEmitter(
        speed=(2.0, 6.0), spread=1.6, lifetime=(0.3, 0.7), acceleration=(0.0, -9.8),
        size=(0.08, 0.02), color=((255, 255, 180), (255, 120, 0)), blend=Blend.ADDITIVE,
        collide=ParticleCollision.BOUNCE, bounciness=0.4, max_particles=3000, seed=5,
    ))  # fmt: skip
    floor = static_box(world, 0.0, -0.5, 8.0, 0.5, name="floor")
    world.add(floor, BurstOnHit(sparks, count=40))
    world.get(floor, Collider).hit_threshold = 2.0
    for i in range(balls):
        ball(world, -5.5 + i, 3.0 + 1.3 * (i % 4), 0.25, restitution=0.6)


@sparks_on_hits.claim
def _impacts_made_sparks(app) -> None:  # type: ignore[no-untyped-def]
    st = app.world.resource(Particles).state(named(app.world, "sparks")[0])
    assert st.bursts >= 12, f"only {st.bursts} impacts made sparks"
    assert st.born == 40 * st.bursts - st.pool.dropped


class _Orbit(Script):
    """Drives a kinematic body round a circle (velocity, so physics moves it)."""

    def __init__(self, radius: float, speed: float) -> None:
        self.radius, self.speed, self.t = radius, speed, 0.0

    def on_fixed_update(self, dt: float) -> None:
        self.t += dt
        w = self.speed / self.radius
        rb = self.get(RigidBody)
        rb.velocity = (-self.speed * math.sin(w * self.t), self.speed * math.cos(w * self.t))
        rb.angular_velocity = w


@sample("Particles", "Smoke Trail", help="A body circling at 6 m/s leaves a smoke trail: "
        "20 puffs per metre travelled that grow, rise and fade.", camera=(0.0, 4.0, 1.0))
def smoke_trail(world: World) -> None:
    static_box(world, 0.0, -0.5, 8.0, 0.5, name="ground")
    world.spawn(Transform(3.0, 4.0, math.pi / 2), Name("smoker"),
                RigidBody(type=BodyType.KINEMATIC), Collider(Box(0.3, 0.15)),
                Behaviour(_Orbit(3.0, 6.0)), ParticleEmitter(
        rate_per_meter=20.0, lifetime=(1.2, 1.8), speed=(0.1, 0.4), spread=2 * math.pi,
        acceleration=(0.0, 0.6), drag=0.8, size=(0.15, 0.7), color=((200, 200, 200), (90, 90, 90)),
        opacity=(178, 0), offset=(-0.35, 0.0), max_particles=1500, seed=9,
    ))  # fmt: skip


@smoke_trail.claim
def _the_trail_follows_the_path(app) -> None:  # type: ignore[no-untyped-def]
    pts = _live(app, "smoker")
    assert len(pts) > 100
    r = np.hypot(pts[:, 0], pts[:, 1] - 4.0)
    assert np.median(np.abs(r - 3.0)) < 0.6, "puffs lie along the 3 m circle"
    assert np.ptp(pts[:, 0]) > 3.0, "the trail stretches along the path"


@sample("Particles", "Stress 10000", help="10,000 live particles bouncing in a box: one "
        "vectorised update and one vertex upload per emitter per frame.", camera=(0.0, 5.0, 0.7))
def stress(world: World, count: int = 10_000) -> None:
    for x, y, hw, hh in ((0.0, -0.5, 8.0, 0.5), (-8.5, 5.0, 0.5, 6.0), (8.5, 5.0, 0.5, 6.0)):
        static_box(world, x, y, hw, hh)
    for i, x in enumerate((-4.0, 0.0, 4.0, 0.0)):
        world.spawn(Transform(x, 6.0 if i < 3 else 9.0), Name("stress"), ParticleEmitter(
            rate=count / 4 / 2.0, lifetime=2.0, speed=(2.0, 6.0), spread=2 * math.pi,
            acceleration=(0.0, -9.8), size=0.08, color=((255, 200, 80), (80, 160, 255)),
            collide=ParticleCollision.BOUNCE, bounciness=0.7, shape=EmitBox(1.0, 1.0), prewarm=2.0,
            max_particles=count // 4 + 200, seed=20 + i,
        ))  # fmt: skip


@stress.claim
def _ten_thousand_inside_the_box(app) -> None:  # type: ignore[no-untyped-def]
    particles = app.world.resource(Particles)
    assert 9_500 <= particles.total() <= 10_300, particles.total()
    for e in named(app.world, "stress"):
        pts = particles.positions(e)
        assert pts[:, 1].min() > -0.05 and np.abs(pts[:, 0]).max() < 8.05


@sample("Particles", "Vortex And Orbit", help="Left: sparks born on a ring are pulled in and "
        "swirled (radial and tangential acceleration). Right: a ring of resting particles "
        "orbits its centre at half a turn a second.", camera=(0.0, 2.0, 1.0))
def vortex_and_orbit(world: World) -> None:
    world.spawn(Transform(-4.0, 2.0), Name("vortex"), ParticleEmitter(
        rate=200.0, speed=(0.2, 0.5), spread=2 * math.pi, lifetime=(1.5, 2.0),
        shape=EmitCircle(2.5, edge=True), radial_acceleration=-5.0,
        tangential_acceleration=2.0, blend=Blend.ADDITIVE, size=(0.12, 0.04),
        color=((140, 90, 255), (40, 200, 255)), seed=5,
    ))  # fmt: skip
    world.spawn(Transform(4.0, 2.0), Name("orbit"), ParticleEmitter(
        burst=48, emitting=True, speed=0.0, lifetime=1e6, shape=EmitCircle(2.0, edge=True),
        orbit=math.pi, size=0.15, color=((255, 210, 80),), seed=6,
    ))  # fmt: skip


@vortex_and_orbit.claim
def _the_ring_keeps_its_radius_and_the_vortex_pulls_in(app) -> None:  # type: ignore[no-untyped-def]
    ring = _live(app, "orbit") - np.array([4.0, 2.0])
    assert len(ring) == 48
    radius = np.hypot(ring[:, 0], ring[:, 1])
    assert np.allclose(radius, 2.0, atol=1e-2), radius.min()
    swirl = _live(app, "vortex") - np.array([-4.0, 2.0])
    assert len(swirl) > 100 and np.median(np.hypot(swirl[:, 0], swirl[:, 1])) < 2.5
