"""App.restore carries what the game layer is running: tweens go on from where they
were, live particles keep flying (one-shot bursts do not fire again) and animators keep
their clip time. Each restored run is compared with the same game run without one."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from kge import Animations, Animator, App, Clip, Sprite, Transform, Tweens, World
from kge.components.particles import ParticleEmitter
from kge.particles import Particles
from tests.animation.conftest import strip

SHEET = strip([(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 255)])


def twin_runs(scene: Callable[[World], None], before: int, after: int,
              read: Callable[[App], Any]) -> tuple[Any, Any]:
    """``read`` after ``before + after`` steps, plain and with a restore in between."""
    plain = App(scene, headless=True)
    plain.step(before + after)
    restored = App(scene, headless=True)
    restored.step(before)
    restored.restore(restored.world.snapshot())
    restored.step(after)
    return read(plain), read(restored)


def tweened(world: World) -> None:
    e = world.spawn(Transform(0.0, 0.0))
    world.resource(Tweens).to(e, Transform, "x", 10.0, 1.0, ease="quad_in_out")


def test_a_running_tween_goes_on_from_where_it_was() -> None:
    plain, restored = twin_runs(tweened, 25, 20, lambda app: app.world.get(1, Transform).x)
    assert 0.0 < plain < 10.0
    assert restored == plain
    app = App(tweened, headless=True)
    app.step(25)
    app.restore(app.world.snapshot())
    app.step(1)
    assert len(app.world.resource(Tweens)) == 1  # still running in the restored world
    app.step(60)
    assert app.world.get(1, Transform).x == 10.0 and len(app.world.resource(Tweens)) == 0


def sparks(world: World) -> None:
    world.spawn(Transform(0.0, 0.0), ParticleEmitter(
        rate=0.0, burst=40, speed=3.0, spread=6.28, lifetime=3.0, acceleration=(0.0, -2.0),
        seed=7))  # fmt: skip
    world.spawn(Transform(3.0, 0.0), ParticleEmitter(rate=30.0, speed=1.0, lifetime=1.0, seed=3))


def particles_of(app: App) -> list[np.ndarray]:
    p = app.world.resource(Particles)
    return [p.positions(e) for e, _ in sorted(app.world.query(ParticleEmitter))]


def test_live_particles_keep_flying_and_a_burst_does_not_fire_again() -> None:
    plain, restored = twin_runs(sparks, 20, 15, particles_of)
    assert len(restored[0]) == 40, "the one-shot burst fired once, before the restore"
    for a, b in zip(plain, restored, strict=True):
        np.testing.assert_array_equal(a, b)


def animated(world: World) -> None:
    clip = Clip.grid(SHEET, (4, 1), duration=0.2)
    world.spawn(Transform(), Sprite(SHEET, size=(1.0, 1.0)), Animator({"walk": clip}))


def test_an_animator_keeps_its_clip_time() -> None:
    def frames(app: App) -> list[int]:
        anims, out = app.world.resource(Animations), []
        for _ in range(12):
            out.append(anims.frame(1))
            app.step()
        return out

    plain, restored = twin_runs(animated, 17, 0, frames)
    assert plain == restored
    assert plain[0] != 0, "mid-clip when restored: a restart would show frame 0"
