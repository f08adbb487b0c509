"""Particle emitters headless: kinematics, rates, caps, determinism, one-shots, game time."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kge import App, Behaviour, Collider, RigidBody, Script, Transform, ValidationError, World
from kge.components.particles import (
    EmitBox,
    EmitCircle,
    EmitCollider,
    EmitLine,
    ParticleBurst,
    ParticleCollision,
    ParticleEmitter,
    ParticleSpace,
)
from kge.components.shapes import Box
from kge.particles import Particles
from kge.systems.particles import ParticlesPlugin

DT = 1.0 / 60.0


def run(setup, steps: int) -> App:
    app = App(setup, headless=True)
    app.step(steps)
    return app


def one(app: App) -> int:
    return next(e for e, _ in app.world.query(ParticleEmitter))


def test_a_burst_follows_ballistics_exactly() -> None:
    em = ParticleEmitter(
        burst=5, speed=2.0, direction=0.0, acceleration=(0.0, -10.0), lifetime=10.0
    )

    app = run(lambda w: w.spawn(Transform(1.0, 3.0), em), 1 + 60)  # born, then 1 s
    p = app.world.resource(Particles).positions(one(app))
    assert p.shape == (5, 2)
    t = 60 * DT
    # semi-implicit Euler (velocity first), as the physics does: y = -g dt^2 n(n+1)/2
    fall = 10.0 * DT * DT * 60 * 61 / 2
    np.testing.assert_allclose(p[:, 0], 1.0 + 2.0 * t, atol=1e-4)
    np.testing.assert_allclose(p[:, 1], 3.0 - fall, atol=1e-4)


def test_particles_die_at_the_end_of_their_lifetime() -> None:
    app = run(lambda w: w.spawn(Transform(), ParticleEmitter(burst=10, lifetime=0.5)), 1 + 29)
    particles = app.world.resource(Particles)
    assert particles.count(one(app)) == 10
    app.step(2)
    assert particles.count(one(app)) == 0


def test_rate_per_second_emits_that_many() -> None:
    app = run(lambda w: w.spawn(Transform(), ParticleEmitter(rate=90.0, lifetime=5.0)), 120)
    assert app.world.resource(Particles).count(one(app)) == 180  # 90/s for 2 s


def test_rate_per_meter_follows_the_distance_travelled() -> None:
    class Move(Script):
        def on_update(self, dt: float) -> None:
            self.transform.x += 0.1

    def setup(w: World) -> None:
        w.spawn(Transform(), ParticleEmitter(rate_per_meter=20.0, lifetime=30.0), Behaviour(Move()))

    app = run(setup, 50)  # 5 m, the first 0.1 m before the emitter's first update
    n = app.world.resource(Particles).count(one(app))
    assert 97 <= n <= 98  # 4.9 m x 20 (less the fraction still carried)
    xs = app.world.resource(Particles).positions(one(app))[:, 0]
    assert xs.min() < 0.3 and xs.max() > 4.6, "births are spread along the path travelled"


def test_max_particles_drops_and_never_grows() -> None:
    app = run(
        lambda w: w.spawn(
            Transform(), ParticleEmitter(rate=6000.0, max_particles=100, lifetime=10.0)
        ),
        30,
    )
    st = app.world.resource(Particles).state(one(app))
    assert st.pool.count == 100 and st.pool.capacity == 100
    assert st.pool.dropped == 6000 // 2 - 100
    assert len(st.pool.pos) == 100


def test_same_seed_same_particles_other_seed_others() -> None:
    def positions(seed: int) -> np.ndarray:
        em = ParticleEmitter(
            rate=100.0,
            speed=(1.0, 3.0),
            spread=math.pi,
            lifetime=(0.5, 2.0),
            shape=EmitCircle(1.0),
            seed=seed,
        )
        app = run(lambda w: w.spawn(Transform(), em), 90)
        return app.world.resource(Particles).positions(one(app))

    a, b, c = positions(7), positions(7), positions(8)
    assert len(a) > 100
    np.testing.assert_array_equal(a, b)
    assert a.shape != c.shape or not np.array_equal(a, c)


def test_one_shot_despawns_its_entity_when_done() -> None:
    app = run(
        lambda w: w.spawn(Transform(), ParticleEmitter(burst=20, one_shot=True, lifetime=0.25)), 1
    )
    e = one(app)
    assert app.world.resource(Particles).count(e) == 20
    app.step(16)
    assert not app.world.exists(e)


def test_duration_stops_a_continuous_emitter() -> None:
    em = ParticleEmitter(rate=60.0, duration=0.5, lifetime=10.0)
    app = run(lambda w: w.spawn(Transform(), em), 120)
    assert app.world.resource(Particles).count(one(app)) == 30
    assert app.world.exists(one(app))


def test_prewarm_fills_the_emitter_before_the_first_frame() -> None:
    em = ParticleEmitter(rate=50.0, prewarm=2.0, lifetime=1.0, speed=1.0)
    app = run(lambda w: w.spawn(Transform(), em), 1)
    p = app.world.resource(Particles)
    assert 45 <= p.count(one(app)) <= 52  # a steady state: rate x lifetime
    assert p.positions(one(app))[:, 1].max() > 0.8


def test_pause_and_time_scale_are_game_time() -> None:
    app = App(
        lambda w: w.spawn(Transform(), ParticleEmitter(rate=60.0, lifetime=10.0)), headless=True
    )
    app.paused = True
    for _ in range(30):
        app.advance(DT)
    p = app.world.resource(Particles)
    assert p.count(one(app)) == 0
    app.paused = False
    app.time_scale = 0.5
    for _ in range(60):
        app.advance(DT)
    assert 29 <= p.count(one(app)) <= 31  # half a second of game time


def test_stop_start_burst_and_clear_from_code() -> None:
    app = run(lambda w: w.spawn(Transform(), ParticleEmitter(rate=60.0, burst=5, lifetime=9.0)), 1)
    p, e = app.world.resource(Particles), one(app)
    assert p.count(e) == 5 + 1
    p.stop(e)
    app.step(30)
    assert p.count(e) == 6
    p.burst(e, 7, position=(3.0, 4.0), direction=0.0)
    app.step(1)
    assert p.count(e) == 13
    assert np.sum(np.all(np.isclose(p.positions(e), (3.0, 4.0)), axis=1)) == 7
    p.start(e)  # the emitter's own burst fires again
    app.step(1)
    assert p.count(e) == 13 + 5 + 1
    p.clear(e)
    assert p.count(e) == 0


def test_burst_events_from_a_script_in_fixed_and_update() -> None:
    class Sparker(Script):
        def on_fixed_update(self, dt: float) -> None:
            self.world.emit(ParticleBurst(self.entity, 3))

        def on_update(self, dt: float) -> None:
            self.world.emit(ParticleBurst(self.entity, 1))

    def setup(w: World) -> None:
        w.spawn(Transform(), ParticleEmitter(lifetime=10.0), Behaviour(Sparker()))

    app = App(setup, headless=True)
    for _ in range(10):
        app.advance(2 * DT + 1e-9)  # two fixed steps per frame: none of their events is lost
    assert app.world.resource(Particles).count(one(app)) == 10 * (2 * 3 + 1)


@pytest.mark.parametrize(
    ("shape", "inside"),
    [
        (EmitBox(2.0, 1.0), lambda p: (np.abs(p[:, 0]) <= 1.0) & (np.abs(p[:, 1]) <= 0.5)),
        (EmitCircle(1.5, edge=True), lambda p: np.isclose(np.hypot(p[:, 0], p[:, 1]), 1.5)),
        (EmitLine((-1.0, 0.0), (1.0, 0.0)), lambda p: np.isclose(p[:, 1], 0.0)),
        (EmitCollider(), lambda p: (np.abs(p[:, 0] - 5.0) <= 0.5) & (np.abs(p[:, 1]) <= 2.0)),
    ],
)
def test_emission_shapes(shape, inside) -> None:
    em = ParticleEmitter(burst=500, speed=0.0, shape=shape)
    t = Transform(5.0, 0.0) if isinstance(shape, EmitCollider) else Transform()

    def setup(w: World) -> None:
        comps = [t, em]
        if isinstance(shape, EmitCollider):
            comps.append(Collider(Box(0.5, 2.0)))
        w.spawn(*comps)

    app = run(setup, 1)
    p = app.world.resource(Particles).positions(one(app))
    assert len(p) == 500 and inside(p).all()
    assert np.ptp(p[:, 0]) > 0.5  # spread out, not all at one point


def test_entity_angle_turns_direction_and_offset() -> None:
    em = ParticleEmitter(burst=1, speed=1.0, direction=0.0, offset=(1.0, 0.0), lifetime=5.0)
    app = run(lambda w: w.spawn(Transform(0.0, 0.0, math.pi / 2), em), 1 + 60)
    p = app.world.resource(Particles).positions(one(app))[0]
    np.testing.assert_allclose(p, (0.0, 2.0), atol=1e-4)


def test_inherit_velocity_and_drag() -> None:
    def setup(w: World) -> None:
        w.spawn(
            Transform(),
            RigidBody(velocity=(4.0, 0.0), gravity_scale=0.0),
            ParticleEmitter(burst=1, speed=0.0, inherit_velocity=0.5, drag=1.0, lifetime=9.0),
        )

    app = run(setup, 1)
    st = app.world.resource(Particles).state(one(app))
    assert st.pool.vel[0, 0] == pytest.approx(2.0)
    app.step(60)
    assert st.pool.vel[0, 0] == pytest.approx(2.0 * math.exp(-1.0), rel=1e-4)


def test_local_space_particles_move_with_the_entity() -> None:
    def setup(w: World) -> None:
        w.spawn(Transform(), ParticleEmitter(burst=3, speed=0.0, space=ParticleSpace.LOCAL, lifetime=9.0))

    app = run(setup, 1)
    e = one(app)
    app.world.get(e, Transform).x = 10.0
    app.step(1)
    np.testing.assert_allclose(app.world.resource(Particles).positions(e)[:, 0], 10.0)


@pytest.mark.parametrize("mode", [ParticleCollision.BOUNCE, ParticleCollision.DIE])
def test_collision_with_static_colliders(mode: ParticleCollision) -> None:
    def setup(w: World) -> None:
        w.spawn(Transform(0.0, -1.0), Collider(Box(10.0, 1.0)))  # top at y = 0
        w.spawn(Transform(0.0, 2.0), ParticleEmitter(
            burst=50, speed=0.0, acceleration=(0.0, -10.0), collide=mode, bounciness=0.5,
            lifetime=10.0, shape=EmitBox(4.0, 0.1)))  # fmt: skip

    app = run(setup, 60)
    p = app.world.resource(Particles)
    e = one(app)
    if mode == "die":
        assert p.count(e) == 0
    else:
        pos = p.positions(e)
        assert len(pos) == 50 and pos[:, 1].min() > -0.11, "nothing sinks into the ground"
        app.step(120)
        assert p.positions(e)[:, 1].min() > -0.11


def test_bounce_reflects_upwards() -> None:
    def setup(w: World) -> None:
        w.spawn(Transform(0.0, -1.0), Collider(Box(10.0, 1.0)))
        w.spawn(
            Transform(0.0, 1.0),
            ParticleEmitter(
                burst=1,
                speed=5.0,
                direction=-math.pi / 2,
                collide=ParticleCollision.BOUNCE,
                bounciness=1.0,
                lifetime=10.0,
            ),
        )

    app = run(setup, 16)  # 1 m at 5 m/s takes 12 frames
    st = app.world.resource(Particles).state(one(app))
    assert st.pool.vel[0, 1] > 4.0


def test_a_plugin_on_a_bare_world() -> None:
    w = World()
    w.add_plugins(ParticlesPlugin())
    e = w.spawn(Transform(), ParticleEmitter(burst=4))
    from kge.systems.particles import ParticleSystem

    sys = w.get_system(ParticleSystem)
    assert sys is not None
    sys.process(DT)
    assert w.resource(Particles).count(e) == 4


def test_the_old_names_alpha_and_rate_per_metre_still_work_deprecated() -> None:
    """alpha (0..1) became opacity (0-255, as Sprite.opacity); rate_per_metre became
    rate_per_meter (one spelling, as pixels_per_meter). Both old names convert, warning."""
    with pytest.warns(DeprecationWarning, match=r"alpha=\.\.\.\) is now opacity="):
        em = ParticleEmitter(alpha=(1.0, 0.5, 0.0))  # type: ignore[call-arg]
    assert em.opacity == (255.0, 127.5, 0.0)
    with pytest.warns(DeprecationWarning, match="ParticleEmitter.alpha is now"):
        assert em.alpha == (1.0, 0.5, 0.0)  # type: ignore[attr-defined]
    with pytest.warns(DeprecationWarning):
        em.alpha = 0.2
    assert em.opacity == (pytest.approx(51.0),)
    with pytest.warns(DeprecationWarning, match="rate_per_meter"):
        assert ParticleEmitter(rate_per_metre=3.0).rate_per_meter == 3.0  # type: ignore[call-arg]
    with pytest.warns(DeprecationWarning), pytest.raises(ValidationError, match="alpha"):
        ParticleEmitter(alpha=1.5)  # type: ignore[call-arg]  # still checked in its own unit
    with pytest.raises(TypeError, match="both alpha= and opacity="):
        ParticleEmitter(alpha=1.0, opacity=255)  # type: ignore[call-arg]
    # the same particles either way
    with pytest.warns(DeprecationWarning):
        old = ParticleEmitter(alpha=(0.9, 0.0), color=(255, 0, 0))  # type: ignore[call-arg]
    new = ParticleEmitter(opacity=(229.5, 0.0), color=(255, 0, 0))
    assert old == new
