"""Keyframe timelines: property tracks over time, calls and sounds on time, loops, events."""

from __future__ import annotations

import itertools
from typing import Any

import numpy as np
import pytest

from kge import Behaviour, Camera, Script, Sprite, Transform, World
from kge.animation.events import TimelineFinished
from kge.components.timeline import Calls, Keys, Sounds, Timeline, TimelinePlayer
from kge.errors import ComponentTypeError, ValidationError
from kge.schedule import Stage
from kge.systems.animation import AnimationPlugin
from kge.systems.behaviour import BehaviourPlugin
from kge.systems.timeline import Timelines
from tests.animation.conftest import centre_colour

DT = 0.1


class Log(Script):
    def __init__(self) -> None:
        self.calls: list[tuple[Any, ...]] = []
        self.ended: list[str] = []

    def hit(self, *args: Any) -> None:
        self.calls.append(("hit", *args))

    def on_timeline_end(self, event: TimelineFinished) -> None:
        self.ended.append(event.name)


def _world() -> World:
    w = World()
    w.add_plugins(BehaviourPlugin(), AnimationPlugin())
    return w


def _run(w: World, steps: int, dt: float = DT) -> None:
    for _ in range(steps):
        w.schedule.run(Stage.UPDATE, dt)


def test_linear_step_and_cubic_tracks_over_time() -> None:
    w = _world()
    tl = Timeline([
        Keys(Transform, "x", [(0.0, 0.0), (1.0, 10.0), (2.0, 0.0)]),
        Keys(Transform, "y", [(0.0, 0.0), (0.5, 4.0), (1.5, -4.0)], interp="step"),
        Keys(Transform, "angle", [(0.0, 0.0), (1.0, 1.0), (2.0, 4.0)], interp="cubic"),
    ])
    e = w.spawn(Transform(), TimelinePlayer({"move": tl}))
    t = w.get(e, Transform)
    xs, ys, angles = [], [], []
    for _ in range(21):
        _run(w, 1)
        xs.append(round(t.x, 9))
        ys.append(t.y)
        angles.append(t.angle)
    times = [(k + 1) * DT for k in range(21)]
    assert xs == [round(10 * s if s <= 1 else max(10 * (2 - s), 0.0), 9) for s in times]
    assert ys == [0.0 if s < 0.5 - 1e-9 else 4.0 if s < 1.5 - 1e-9 else -4.0 for s in times]
    # the cubic passes through its keys, rises monotonically here, and holds after the end
    assert angles[9] == pytest.approx(1.0) and angles[19] == pytest.approx(4.0)
    assert all(b >= a for a, b in itertools.pairwise(angles))
    assert angles[4] != pytest.approx(0.5)  # not a straight line: the slope bends
    assert w.resource(Timelines).finished(e)


def test_vectors_colours_ints_and_held_values() -> None:
    w = _world()
    tl = Timeline([
        Keys(Sprite, "tint", [(0.0, (255, 0, 0)), (1.0, (0, 0, 255))]),
        Keys(Sprite, "opacity", [(0.0, 0), (1.0, 255)]),
        Keys(Sprite, "visible", [(0.0, False), (0.3, True)], interp="step"),
    ])
    e = w.spawn(Transform(), Sprite("x.png"), TimelinePlayer({"in": tl}))
    s = w.get(e, Sprite)
    _run(w, 5)
    assert s.tint == (128, 0, 128) and s.opacity == 128 and s.visible is True
    assert all(isinstance(v, int) for v in s.tint) and isinstance(s.opacity, int)


def test_calls_fire_once_per_crossing_even_in_a_long_frame_and_each_lap() -> None:
    w = _world()
    log = Log()
    tl = Timeline([Calls([(0.0, "hit", "start"), (0.25, "hit", 1), (0.75, "hit", 2)])],
                  length=1.0, loop=True)
    e = w.spawn(Behaviour(log), TimelinePlayer({"loop": tl}))
    _run(w, 1, 0.5)
    assert log.calls == [("hit", "start"), ("hit", 1)]
    _run(w, 1, 2.0)  # two laps in one frame: 0.75, 0, 0.25, 0.75, 0, 0.25 in order
    assert log.calls[2:] == [("hit", 2), ("hit", "start"), ("hit", 1), ("hit", 2),
                             ("hit", "start"), ("hit", 1)]
    assert w.resource(Timelines).time(e) == pytest.approx(0.5)
    assert not log.ended  # a loop never finishes


def test_end_event_hook_pause_seek_stop_speed_and_backwards() -> None:
    w = _world()
    log = Log()
    tl = Timeline([Keys(Transform, "x", [(0.0, 0.0), (1.0, 1.0)]),
                   Calls([(0.5, "hit", "mid")])])
    e = w.spawn(Transform(), Behaviour(log), TimelinePlayer({"go": tl}))
    player, t = w.get(e, TimelinePlayer), w.get(e, Transform)
    _run(w, 3)
    player.pause()
    _run(w, 5)
    assert t.x == pytest.approx(0.3) and log.calls == []
    player.seek(0.8)  # a seek jumps over the call without firing it
    player.resume()
    _run(w, 1)
    assert t.x == pytest.approx(0.9) and log.calls == []
    _run(w, 2)
    assert t.x == 1.0 and log.ended == ["go"]
    assert [type(ev) for ev in w.events(TimelineFinished)] == [TimelineFinished]
    player.speed = -2.0
    player.play()  # backwards from the end
    _run(w, 3)
    assert t.x == pytest.approx(0.4) and log.calls == [("hit", "mid")]
    player.stop()
    _run(w, 1)
    assert t.x == 0.0 and not w.resource(Timelines).finished(e)


def test_a_sound_track_plays_its_sounds_on_time() -> None:
    from kge import App
    from kge.sound import tone

    beep = tone(440.0, 0.05)
    played: list[Any] = []

    def setup(world: World) -> None:
        from kge.audio.resource import Audio

        audio = world.resource(Audio)
        real = audio.play
        audio.play = lambda s, **kw: played.append((s, kw)) or real(s, **kw)  # type: ignore
        world.spawn(TimelinePlayer({"s": Timeline([Sounds([(0.1, beep), (0.3, beep)],
                                                          volume=0.5)])}))

    app = App(setup, headless=True, fixed_dt=0.05)
    app.step(4)
    assert len(played) == 1 and played[0][1] == {"volume": 0.5, "bus": "sfx"}
    app.step(4)
    assert len(played) == 2
    app.close()


def test_bad_timelines_are_refused_at_the_call() -> None:
    with pytest.raises(ValidationError, match="times must increase"):
        Keys(Transform, "x", [(0.5, 1.0), (0.5, 2.0)])
    with pytest.raises(ValidationError, match="Transform has no field 'z'"):
        Keys(Transform, "z", [(0.0, 1.0)])
    with pytest.raises(ValidationError, match="not a number"):
        Keys(Sprite, "visible", [(0.0, True), (1.0, False)])
    with pytest.raises(ValidationError, match="opacity"):
        Keys(Sprite, "opacity", [(0.0, 0), (1.0, 300)])
    with pytest.raises(ValidationError, match="keys\\[0\\] time"):
        Keys(Transform, "x", [(float("nan"), 1.0)])
    with pytest.raises(ValidationError, match="interp"):
        Keys(Transform, "x", [(0.0, 1.0)], interp="bouncy")
    with pytest.raises(ValidationError, match="method name"):
        Calls([(0.0, "__init__")])
    with pytest.raises(ValidationError, match="shorter than its last key"):
        Timeline([Keys(Transform, "x", [(0.0, 0.0), (2.0, 1.0)])], length=1.0)
    with pytest.raises(ComponentTypeError, match="Timeline.tracks"):
        Timeline(Keys(Transform, "x", [(0.0, 0.0)]))  # type: ignore[arg-type]


def test_a_track_the_entity_cannot_take_is_refused_naming_it() -> None:
    w = _world()
    tl = Timeline([Keys(Sprite, "opacity", [(0.0, 0), (1.0, 255)])])
    calls = Timeline([Calls([(0.2, "jump")])])
    e = w.spawn(Transform(), Behaviour(Log()), TimelinePlayer({"idle": Timeline(
        [Keys(Transform, "x", [(0.0, 0.0)])]), "fade": tl, "jump": calls}))
    player = w.get(e, TimelinePlayer)
    _run(w, 1)
    with pytest.raises(ValidationError, match=f"entity {e}.*'fade'.*has no Sprite"):
        player.play("fade")
    with pytest.raises(ValidationError, match="no such method"):
        player.play("jump")
    with pytest.raises(ValidationError, match="unknown timeline 'nope'"):
        player.play("nope")
    assert player.current == "idle"
    bad = w.spawn(Transform(), TimelinePlayer({"fade": tl}))
    with pytest.raises(ValidationError, match=f"entity {bad}.*has no Sprite"):
        _run(w, 1)


def test_many_players_share_one_sampling_pass() -> None:
    w = _world()
    tl = Timeline([Keys(Transform, "x", [(0.0, 0.0), (1.0, 1.0)])], loop=True)
    es = [w.spawn(Transform(), TimelinePlayer({"a": tl}, speed=0.5 + 0.1 * i))
          for i in range(20)]
    _run(w, 3)
    xs = np.array([w.get(e, Transform).x for e in es])
    expected = np.array([(0.3 * (0.5 + 0.1 * i)) % 1.0 for i in range(20)])
    assert np.allclose(xs, expected)
    w.despawn(es[3])
    _run(w, 1)
    assert w.get(es[4], Transform).x == pytest.approx((0.4 * 0.9) % 1.0)


def test_a_timeline_fades_a_sprite_in_on_screen(make_app: Any) -> None:
    from kge.render.images import solid

    tl = Timeline([Keys(Sprite, "opacity", [(0.0, 0), (1.0, 255)])])

    def setup(world: World) -> None:
        world.insert_resource(Camera(pixels_per_meter=16))
        world.spawn(Transform(), Sprite(solid(8, 8, (255, 255, 255)), size=(3.0, 3.0)),
                    TimelinePlayer({"in": tl}))

    app = make_app(setup, fixed_dt=0.05)
    app.step(10)
    r, g, b = centre_colour(app)
    assert abs(r - 128) <= 2 and r == g == b
    app.step(10)
    assert centre_colour(app) == (255, 255, 255)
