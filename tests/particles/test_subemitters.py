"""Sub-emitters: particles born at the births, collisions and deaths of other particles."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

from kge import App, Collider, EmitCircle, ParticleEmitter, Particles, Transform, World
from kge.components.particle_subemitters import ParticleSubEmitters, SubEmitEvent, SubEmitter
from kge.components.particles import ParticleCollision, ParticleSpace
from kge.components.shapes import Box
from kge.errors import ComponentTypeError, ValidationError

DT = 1.0 / 60.0


def _child(world: World, **fields: Any) -> int:
    em = {"emitting": False, "speed": 0.0, "lifetime": 10.0, "max_particles": 20_000, "seed": 2,
          **fields}  # fmt: skip
    return world.spawn(Transform(), ParticleEmitter(**em))


def _app(scene: Any) -> tuple[App, Particles]:
    app = App(scene, headless=True)
    return app, app.world.resource(Particles)


def test_each_death_sprays_count_particles_where_the_parent_died() -> None:
    def scene(world: World) -> None:
        sparks = _child(world)
        world.spawn(Transform(3.0, 1.0), ParticleEmitter(
            burst=6, speed=0.0, lifetime=0.5, shape=EmitCircle(2.0), seed=1),
            ParticleSubEmitters(SubEmitter(sparks, SubEmitEvent.DEATH, count=7)))  # fmt: skip

    app, p = _app(scene)
    app.step(1)
    homes = p.positions(2).copy()
    app.step(29)
    assert p.count(1) == 0 and p.count(2) == 6  # not dead yet
    app.step(1)
    assert p.count(2) == 0 and p.count(1) == 6 * 7
    got = p.positions(1)
    np.testing.assert_allclose(got, np.repeat(homes, 7, axis=0), atol=1e-5)


def test_a_despawned_one_shot_parent_still_fires_for_its_last_deaths() -> None:
    def scene(world: World) -> None:
        sparks = _child(world, speed=(2.0, 3.0), spread=2 * math.pi)
        world.spawn(Transform(), ParticleEmitter(burst=5, speed=8.0, spread=0.5, lifetime=1.0,
                                                 one_shot=True, seed=1),
                    ParticleSubEmitters(SubEmitter(sparks, SubEmitEvent.DEATH, count=40)))

    app, p = _app(scene)
    app.step(70)
    assert not app.world.exists(2), "the finished one-shot rocket despawned"
    assert p.count(1) == 5 * 40


def test_inherit_velocity_adds_a_share_of_the_event_particle_s_velocity() -> None:
    def scene(world: World) -> None:
        trail = _child(world, speed=1.0, direction=math.pi / 2)
        world.spawn(Transform(), ParticleEmitter(burst=3, speed=4.0, direction=0.0, lifetime=0.25,
                                                 seed=1),
                    ParticleSubEmitters(SubEmitter(trail, SubEmitEvent.DEATH, count=2,
                                                   inherit_velocity=0.5)))  # fmt: skip

    app, p = _app(scene)
    app.step(20)
    vel = p.state(1).pool.vel[: p.count(1)]
    assert len(vel) == 6
    np.testing.assert_allclose(vel, np.tile([2.0, 1.0], (6, 1)), atol=1e-5)


def test_collisions_spray_at_the_contact_and_births_follow_the_parent() -> None:
    def scene(world: World) -> None:
        world.spawn(Transform(0.0, -0.5), Collider(Box(5.0, 0.5)))
        splash = _child(world, lifetime=0.2)
        trail = _child(world, lifetime=0.2, seed=3)
        world.spawn(Transform(0.0, 2.0), ParticleEmitter(
            rate=60.0, speed=0.0, lifetime=5.0, acceleration=(0.0, -9.8),
            collide=ParticleCollision.BOUNCE, bounciness=0.2, shape=EmitCircle(1.0), seed=1),
            ParticleSubEmitters(SubEmitter(splash, SubEmitEvent.COLLISION, count=3),
                                SubEmitter(trail, SubEmitEvent.BIRTH, count=2)))  # fmt: skip

    app, p = _app(scene)
    app.step(50)
    drops = p.state(4)
    assert p.state(3).born == 2 * drops.born  # two per birth, every frame
    splashes = p.state(2)
    assert splashes.born > 0 and splashes.born % 3 == 0
    ys = p.positions(2)[:, 1]
    assert np.all(np.abs(ys) < 0.2), ys  # at the floor's top (y = 0), within a grid cell


def test_events_and_pools_are_bounded_even_for_a_chain_feeding_itself() -> None:
    def scene(world: World) -> None:
        kids = _child(world, max_particles=500)
        world.spawn(Transform(), ParticleEmitter(burst=300, speed=0.0, lifetime=0.1, seed=1),
                    ParticleSubEmitters(SubEmitter(kids, SubEmitEvent.DEATH, count=4),
                                        max_events=50))  # fmt: skip
        chain = world.spawn(Transform(), ParticleEmitter(burst=1, speed=1.0, lifetime=0.05,
                                                         spread=2 * math.pi, max_particles=3000,
                                                         seed=4))  # fmt: skip
        world.add(chain, ParticleSubEmitters(SubEmitter(chain, SubEmitEvent.DEATH, count=3)))

    app, p = _app(scene)
    app.step(20)
    assert p.count(1) == 50 * 4  # 300 deaths, 50 taken in their frame
    assert p.state(2).extras["subemitters"]["dropped"] == 250
    app.step(120)
    chain = p.state(3)
    assert 0 < chain.pool.count <= 3000  # 3^n, capped by max_particles, never more
    born = chain.born
    app.step(3)  # a generation: at most max_events (1000) deaths taken a frame, 3 each
    assert chain.born - born <= 3 * 1000 * 3
    assert chain.extras["subemitters"]["dropped"] > 0


def test_the_same_scene_sprays_the_same_particles() -> None:
    def scene(world: World) -> None:
        sparks = _child(world, speed=(1.0, 4.0), spread=2 * math.pi, lifetime=(0.2, 0.6))
        world.spawn(Transform(), ParticleEmitter(rate=40.0, speed=(3.0, 6.0), spread=1.0,
                                                 lifetime=(0.3, 0.8), seed=1),
                    ParticleSubEmitters(SubEmitter(sparks, SubEmitEvent.DEATH, count=12,
                                                   inherit_velocity=0.3)))  # fmt: skip

    def run() -> np.ndarray:
        app, p = _app(scene)
        app.step(90)
        st = p.state(1)
        return st.pool.data[:, : st.pool.count].copy()

    first = run()
    assert first.shape[1] > 100 and np.array_equal(first, run())
    plain = App(scene, headless=True)
    plain.step(90)
    restored = App(scene, headless=True)
    restored.step(40)
    restored.restore(restored.world.snapshot())
    restored.step(50)
    a, b = plain.world.resource(Particles).state(1).pool, restored.world.resource(Particles).state(
        1).pool  # fmt: skip
    assert np.array_equal(a.data[:, : a.count], b.data[:, : b.count])


@pytest.mark.parametrize(("make", "message"), [
    (lambda: SubEmitter(1, count=-1), "SubEmitter.count must be in 0..100000"),
    (lambda: SubEmitter(1, inherit_velocity=20.0), "SubEmitter.inherit_velocity must be in"),
    (lambda: SubEmitter(1, inherit_velocity=float("nan")), "SubEmitter.inherit_velocity must be"),
    (lambda: SubEmitter(1, on="touch"), "SubEmitter.on must be one of"),  # type: ignore[arg-type]
    (lambda: SubEmitter(-3), "SubEmitter.emitter"),
    (lambda: ParticleSubEmitters(3),  # type: ignore[arg-type]
     r"ParticleSubEmitters.emitters\[0\] must be a SubEmitter"),
    (lambda: ParticleSubEmitters(max_events=-1), "ParticleSubEmitters.max_events must be in"),
])  # fmt: skip
def test_bad_sub_emitters_are_refused_at_the_call(make: Any, message: str) -> None:
    with pytest.raises((ValidationError, ComponentTypeError), match=message):
        make()


def test_a_sub_emitter_that_is_no_world_space_emitter_is_refused_at_the_spawn() -> None:
    app = App(lambda world: None, headless=True)
    world = app.world
    plain = world.spawn(Transform())
    local = world.spawn(Transform(), ParticleEmitter(space=ParticleSpace.LOCAL))
    count = len(list(world.entities()))
    for target, why in ((99, "is not a ParticleEmitter"), (plain, "is not a ParticleEmitter"),
                        (local, "local space")):  # fmt: skip
        with pytest.raises(ValidationError,
                           match=rf"ParticleSubEmitters.emitters\[0\].emitter: entity {target}.*{why}"):
            world.spawn(Transform(), ParticleEmitter(), ParticleSubEmitters(SubEmitter(target)))
    assert len(list(world.entities())) == count
    parent = world.spawn(Transform(), ParticleEmitter(), ParticleSubEmitters())
    subs = world.get(parent, ParticleSubEmitters)
    with pytest.raises(ValidationError, match=rf"entity {parent}, ParticleSubEmitters.emitters"):
        subs.emitters = (SubEmitter(local),)
    assert subs.emitters == ()
