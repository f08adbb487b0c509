"""Clips played backwards: a negative animator speed (frames, loop wrap, the end of a
``once`` clip at its start, frame events as the playhead crosses them going back)."""

from __future__ import annotations

from typing import Any

from kge import (
    AnimationEvent,
    AnimationFinished,
    Animator,
    App,
    Clip,
    Loop,
    Sprite,
    Transform,
    World,
)
from kge.systems.animation import Animations

DT = 0.05


def _app(sheet: Any, clip: Clip, speed: float) -> App:
    def setup(world: World) -> None:
        world.spawn(Transform(), Sprite(sheet, size=(1.0, 1.0)),
                    Animator({"walk": clip}, speed=speed))  # fmt: skip

    return App(setup, headless=True, fixed_dt=DT)


def _frames(app: App, steps: int) -> list[int]:
    anims = app.world.resource(Animations)
    out = []
    for _ in range(steps):
        app.step(1)
        out.append(anims.frame(1))
    return out


def test_a_loop_plays_backwards_and_wraps_at_the_start(sheet: Any) -> None:
    clip = Clip.grid(sheet, (4, 1), duration=0.1)
    forward = _frames(_app(sheet, clip, 1.0), 16)[::2]
    backward = _frames(_app(sheet, clip, -1.0), 16)[::2]
    assert forward == [0, 1, 2, 3, 0, 1, 2, 3]
    assert backward == [3, 2, 1, 0, 3, 2, 1, 0]
    faster = _frames(_app(sheet, clip, -2.0), 8)
    assert faster == [3, 2, 1, 0, 3, 2, 1, 0]


def test_a_once_clip_ends_at_its_start_going_back(sheet: Any) -> None:
    clip = Clip.grid(sheet, (4, 1), duration=0.1, loop=Loop.HOLD)
    app = _app(sheet, clip, -1.0)
    frames = []
    ended = []
    for _ in range(12):
        app.step(1)
        frames.append(app.world.resource(Animations).frame(1))
        ended += app.world.events(AnimationFinished)
    assert frames[::2] == [3, 2, 1, 0, 0, 0]
    assert len(ended) == 1


def test_frame_events_fire_backwards_in_reverse_order(sheet: Any) -> None:
    clip = Clip.grid(sheet, (4, 1), duration=0.1, events={0: "start", 2: "footstep"})
    app = _app(sheet, clip, -1.0)
    log: list[tuple[int, str]] = []
    for step in range(16):
        app.step(1)
        log += [(step, e.name) for e in app.world.events(AnimationEvent)]
    # the playhead runs 0.4 -> 0 and wraps: it crosses 0.2 (footstep) then 0.0 (start)
    assert [name for _, name in log][:4] == ["footstep", "start", "footstep", "start"]
    steps = [s for s, _ in log]
    assert steps == sorted(steps) and steps[1] - steps[0] == 4
    app2 = _app(sheet, clip, -1.0)
    app2.world.get(1, Animator).speed = -40.0  # a whole lap and a half in one frame
    app2.step(1)
    names = [e.name for e in app2.world.events(AnimationEvent)]
    assert names[:2] == ["footstep", "start"]
