"""Long play: the clip table and the tween rows hold what is alive, not what ever was.

A game that spawns entities with clips of their own (an enemy with its own walk cycle,
a one-off explosion) must not grow the animation tables without bound, and after
everything is despawned they return to their empty size."""

from __future__ import annotations

from typing import Any

from kge import Animations, Animator, App, Camera, Clip, Sprite, Transform, Tweens, World
from tests.animation.conftest import COLOURS, centre_colour


def _spawn_with_own_clip(world: World, sheet: Any, k: int) -> int:
    # a new Clip object each time: what a game making clips per entity does
    clip = Clip.grid(sheet, (4, 1), duration=0.05 + 0.001 * (k % 7))
    return world.spawn(Transform(0.0, 0.0), Sprite(sheet, size=(3.0, 3.0)),
                       Animator({"walk": clip}))


def test_clips_of_despawned_entities_leave_the_table(sheet: Any) -> None:
    app = App(lambda world: None, headless=True)
    world = app.world
    alive: list[int] = []
    largest = 0
    for k in range(3000):
        alive.append(_spawn_with_own_clip(world, sheet, k))
        if len(alive) > 100:
            world.despawn(alive.pop(0))
        app.step()
        largest = max(largest, len(world.resource(Animations).table))
    # 3,000 clips were registered; the table never held much more than the 100 alive
    assert largest <= 2 * 100 + 32 + 1
    for e in alive:
        world.despawn(e)
    app.step()
    assert len(world.resource(Animations).table) == 0


def test_compaction_keeps_every_animator_on_its_frame(make_app: Any, sheet: Any) -> None:
    def scene(world: World) -> None:
        world.insert_resource(Camera(pixels_per_meter=16))
        world.spawn(Transform(0.0, 0.0), Sprite(sheet, size=(3.0, 3.0)),
                    Animator({"walk": Clip.grid(sheet, (4, 1), duration=0.2)}))

    app = make_app(scene, fixed_dt=0.05)
    anims = app.world.resource(Animations)
    hidden: list[int] = []
    seen = []
    for step in range(40):
        # churn far away: many short-lived entities with their own clips
        for _ in range(8):
            hidden.append(_spawn_with_own_clip(app.world, sheet, step))
            app.world.get(hidden[-1], Transform).x = 500.0
        while len(hidden) > 4:
            app.world.despawn(hidden.pop(0))
        seen.append((anims.frame(1), centre_colour(app)))
        app.step()
    # the first entity's walk went on through every compaction: frame k*0.05 of 0.2 s frames
    frames = [int((k * 0.05 + 1e-9) / 0.2) % 4 for k in range(40)]
    assert [f for f, _ in seen] == frames
    assert [c for _, c in seen] == [COLOURS[f] for f in frames]
    assert len(anims.table) <= 2 * 5 + 32


def test_finished_tweens_leave_the_table() -> None:
    app = App(lambda world: None, headless=True)
    world = app.world
    tweens = world.resource(Tweens)
    alive: list[int] = []
    largest = 0
    for k in range(2000):
        e = world.spawn(Transform(0.0, 0.0))
        tweens.to(e, Transform, "x", 1.0, 0.1 + 0.01 * (k % 5))
        alive.append(e)
        if len(alive) > 40:
            world.despawn(alive.pop(0))
        app.step()
        largest = max(largest, tweens.rows)
    assert largest <= 2 * 40 + 32 + 1
    app.step(30)  # every tween has ended
    assert len(tweens) == 0 and tweens.rows == 0
