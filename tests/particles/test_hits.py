"""Physics hits spray sparks at the contact point, along the normal away from the surface."""

from __future__ import annotations

import numpy as np

from kge import App, Collider, RigidBody, Transform, World
from kge.components.particles import BurstOnHit, ParticleEmitter
from kge.components.shapes import Box, Circle
from kge.particles import Particles


def test_a_ball_hitting_the_ground_sprays_sparks_upwards() -> None:
    def setup(w: World) -> None:
        sparks = w.spawn(Transform(), ParticleEmitter(speed=3.0, spread=0.5, lifetime=5.0))
        w.spawn(
            Transform(0.0, -1.0),
            Collider(Box(10.0, 1.0), hit_threshold=1.0),
            BurstOnHit(sparks, count=15),
        )
        w.spawn(Transform(2.0, 3.0), RigidBody(), Collider(Circle(0.25), restitution=0.0))

    app = App(setup, headless=True)
    p = app.world.resource(Particles)
    sparks = next(e for e, _ in app.world.query(ParticleEmitter))
    for _ in range(120):
        app.step(1)
        if p.count(sparks):
            break
    assert p.count(sparks) == 15
    st = p.state(sparks)
    pos = p.positions(sparks)
    assert np.all(np.abs(pos[:, 0] - 2.0) < 0.3) and np.all(np.abs(pos[:, 1]) < 0.3)
    v = st.pool.vel[:15]
    assert np.all(v[:, 1] > 2.5), "sparks leave the ground upwards"


def test_contacts_mode_without_hit_threshold_respects_the_burst_threshold() -> None:
    def setup(w: World) -> None:
        sparks = w.spawn(Transform(), ParticleEmitter(lifetime=5.0))
        w.spawn(
            Transform(0.0, -1.0),
            Collider(Box(10.0, 1.0)),
            BurstOnHit(sparks, count=4, contacts=True, hit_threshold=50.0),
        )
        w.spawn(Transform(0.0, 1.0), RigidBody(), Collider(Circle(0.25)))
        w.spawn(Transform(3.0, 1.0), RigidBody(velocity=(0.0, -60.0)), Collider(Circle(0.25)))

    app = App(setup, headless=True)
    app.step(90)
    sparks = next(e for e, _ in app.world.query(ParticleEmitter))
    assert app.world.resource(Particles).count(sparks) == 4  # only the fast ball
