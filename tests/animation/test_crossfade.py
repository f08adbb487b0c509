"""Cross-fades between clips: the weight over time, the outgoing clip running on, pixels."""

from __future__ import annotations

from typing import Any

import pytest

from kge import Animations, Animator, Camera, Clip, Sprite, Transform, Transition, World
from kge.errors import ValidationError
from kge.schedule import Stage
from kge.systems.animation import AnimationPlugin
from tests.animation.conftest import centre_colour, strip

DT = 0.05


def _world(sheet: Any, **kwargs: Any) -> tuple[World, int, Animator]:
    red = Clip.grid(sheet, (4, 1), frames=[0])
    walk = Clip.grid(sheet, (4, 1), frames=[1, 2], duration=0.1)  # green, blue
    w = World()
    w.add_plugins(AnimationPlugin())
    e = w.spawn(Animator({"red": red, "walk": walk}, **kwargs))
    return w, e, w.get(e, Animator)


def test_the_weight_climbs_over_the_fade_and_the_outgoing_clip_runs_on(sheet: Any) -> None:
    w, e, anim = _world(sheet)
    anims = w.resource(Animations)
    w.schedule.run(Stage.UPDATE, DT)
    anim.play("walk")
    for _ in range(3):  # walk shows green, blue, green...
        w.schedule.run(Stage.UPDATE, DT)
    anim.play("red", fade=0.2)
    seen = []
    for _ in range(5):
        fade = anims.crossfade(e)
        seen.append(None if fade is None else (fade.clip, fade.frame, round(fade.weight, 6)))
        w.schedule.run(Stage.UPDATE, DT)
    # walk was at 0.15 s (frame 1); it runs on at 0.2 (frame 0), 0.25, 0.3 (frame 1)...
    assert seen == [
        ("walk", 1, 0.0), ("walk", 0, 0.25), ("walk", 0, 0.5), ("walk", 1, 0.75), None,
    ]
    assert anims.clip(e) == "red" and anims.frame(e) == 0


def test_a_cut_has_no_fade_and_a_paused_animator_holds_it(sheet: Any) -> None:
    w, e, anim = _world(sheet)
    anims = w.resource(Animations)
    w.schedule.run(Stage.UPDATE, DT)
    anim.play("walk")
    w.schedule.run(Stage.UPDATE, DT)
    assert anims.crossfade(e) is None
    anim.play("red", fade=0.5)
    w.schedule.run(Stage.UPDATE, DT)
    anim.pause()
    for _ in range(4):
        w.schedule.run(Stage.UPDATE, DT)
    fade = anims.crossfade(e)
    assert fade is not None and fade.weight == pytest.approx(0.1)
    anim.play("walk")  # a new play without fade cuts at once
    w.schedule.run(Stage.UPDATE, DT)
    assert anims.crossfade(e) is None


def test_transitions_fade_on_a_condition(sheet: Any) -> None:
    trs = (Transition("red", "walk", when="moving", fade=0.1),)
    w, e, anim = _world(sheet, transitions=trs)
    anims = w.resource(Animations)
    w.schedule.run(Stage.UPDATE, DT)
    anim.set("moving", True)
    w.schedule.run(Stage.UPDATE, DT)
    fade = anims.crossfade(e)
    assert anim.current == "walk" and fade is not None
    assert (fade.clip, fade.weight) == ("red", pytest.approx(0.5))
    w.schedule.run(Stage.UPDATE, DT)
    assert anims.crossfade(e) is None


@pytest.mark.parametrize("bad", [-0.1, float("nan"), float("inf"), "0.2", 1e9])
def test_bad_fades_are_refused_at_the_call(sheet: Any, bad: Any) -> None:
    _, _, anim = _world(sheet)
    with pytest.raises((ValidationError, TypeError), match="fade"):
        anim.play("walk", fade=bad)
    assert anim.current == "red" and anim.fade == 0.0
    with pytest.raises((ValidationError, TypeError), match="Transition.fade"):
        Transition("red", "walk", fade=bad)


def test_a_cross_fade_blends_the_two_frames_pixels(make_app: Any) -> None:
    sheet = strip([(255, 0, 0), (0, 0, 255)])
    clips = {"red": Clip.grid(sheet, (2, 1), frames=[0]),
             "blue": Clip.grid(sheet, (2, 1), frames=[1])}

    def setup(world: World) -> None:
        world.insert_resource(Camera(pixels_per_meter=16))
        world.spawn(Transform(0.0, 0.0), Sprite(sheet, size=(3.0, 3.0)), Animator(clips))

    app = make_app(setup, fixed_dt=DT)
    assert centre_colour(app) == (255, 0, 0)
    anim = app.world.get(1, Animator)
    anim.play("blue", fade=0.2)
    app.step(1)  # the fade starts at weight 0 and the frame advances to 0.25
    r, g, b = centre_colour(app)
    assert abs(r - 191) <= 2 and g == 0 and abs(b - 64) <= 2
    app.step(1)
    r, g, b = centre_colour(app)
    assert abs(r - 128) <= 2 and g == 0 and abs(b - 128) <= 2
    app.step(3)
    assert centre_colour(app) == (0, 0, 255)
