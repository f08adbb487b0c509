"""The shooter's particles: enemies trail exhaust, kills explode and clean up after themselves."""

import numpy as np
import shooter  # examples/shooter.py

from kge import Mouse, Transform
from kge.particles import Particles
from kge.testbed.samples.build import named
from tests.games.test_shooter import screen, start


def test_enemies_trail_exhaust_and_kills_explode() -> None:
    app = start()
    while not named(app.world, "enemy"):
        app.step()
    enemy = named(app.world, "enemy")[0]
    app.step(30)
    particles = app.world.resource(Particles)
    trail = particles.positions(enemy)
    assert len(trail) > 3, "a flying enemy leaves exhaust"
    t = app.world.get(enemy, Transform)
    assert np.all(np.hypot(trail[:, 0] - t.x, trail[:, 1] - t.y) < 1.5)
    explosions = 0
    for _ in range(60 * 8):
        enemies = named(app.world, "enemy")
        if enemies:
            t = app.world.get(enemies[0], Transform)
            app.input.move_mouse(*screen(app, (t.x, t.y)))
            if not app.input.mouse_held(Mouse.LEFT):
                app.input.mouse_down(Mouse.LEFT)
        app.step()
        booms = named(app.world, "sparks")
        if booms:
            explosions = len(booms)
            app.step()
            assert particles.count(booms[0]) == 60
            break
    assert explosions, "killing an enemy spawns an explosion"
    app.input.mouse_up(Mouse.LEFT)
    app.step(60)
    assert not app.world.exists(booms[0]), "a spent explosion despawns itself"


def test_the_explosion_helper_is_a_one_shot() -> None:
    app = start()
    e = shooter.explosion(app.world, (1.0, 2.0))
    app.step(1)
    assert app.world.resource(Particles).count(e) == 60
    app.step(60)
    assert not app.world.exists(e)
