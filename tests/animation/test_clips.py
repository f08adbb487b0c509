"""Sprite animation: the frame shown at time t, events, loop modes, game time, bad input."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from kge import (
    AnimationEvents,
    Animations,
    Animator,
    App,
    Behaviour,
    Camera,
    Clip,
    Loop,
    MissingComponentError,
    Script,
    Sprite,
    Transform,
    Transition,
    ValidationError,
    World,
    gif_clip,
)
from kge.systems.animation import AnimationPlugin
from tests.animation.conftest import COLOURS, centre_colour, write_gif

DT = 0.05


def _scene(sheet: Any, clip: Clip, extra: Any = None) -> Any:
    def setup(world: World) -> None:
        world.insert_resource(Camera(pixels_per_meter=16))
        comps = [Transform(0.0, 0.0), Sprite(sheet, size=(3.0, 3.0)), Animator({"walk": clip})]
        if extra is not None:
            comps.append(extra)
        world.spawn(*comps)

    return setup


def _frames(app: App, steps: int, entity: int = 1) -> list[int]:
    anims = app.world.resource(Animations)
    out = []
    for _ in range(steps):
        out.append(anims.frame(entity))
        app.step(1)
    return out


# -- pixels ---------------------------------------------------------------------------------
def test_the_frame_drawn_at_time_t_is_the_right_one(make_app: Any, sheet: Any) -> None:
    clip = Clip.grid(sheet, (4, 1), duration=0.2)  # 4 frames of 0.2 s, looping
    app = make_app(_scene(sheet, clip), fixed_dt=DT)
    seen = []
    for _ in range(20):  # 1.0 s: frames 0,0,0,0,1,1,1,1,2,...,3,0,0,0,0
        seen.append(centre_colour(app))
        app.step(1)
    expected = [COLOURS[int((k * DT + 1e-9) / 0.2) % 4] for k in range(20)]
    assert seen == expected


def test_per_frame_durations_flips_and_a_second_sprite_sharing_the_atlas(
    make_app: Any, sheet: Any
) -> None:
    clip = Clip.grid(sheet, (4, 1), frames=[3, 1], duration=[0.1, 0.3])

    def setup(world: World) -> None:
        world.insert_resource(Camera(pixels_per_meter=16))
        world.spawn(Transform(-1.0, 0.0), Sprite(sheet, size=(1.5, 1.5)), Animator({"a": clip}))
        still = Clip.grid(sheet, (4, 1), frames=[2], flip_x=True)
        world.spawn(Transform(1.0, 0.0), Sprite(sheet, size=(1.5, 1.5)), Animator({"b": still}))

    app = make_app(setup, fixed_dt=DT)
    from kge.render.setup import frame_pixels

    colours_left = []
    for _ in range(8):
        app.render()
        px = frame_pixels(app)
        colours_left.append(tuple(int(v) for v in px[32, 16, :3]))
        assert tuple(int(v) for v in px[32, 48, :3]) == COLOURS[2]
        app.step(1)
    white, green = COLOURS[3], COLOURS[1]
    assert colours_left == [white, white] + [green] * 6


def test_gif_frames_and_their_durations_come_from_the_file(make_app: Any, tmp_path: Path) -> None:
    path = write_gif(tmp_path / "blink.gif", [(255, 0, 0), (0, 0, 255)], [100, 300])
    clip = gif_clip(str(path))
    assert clip.durations == (0.1, 0.3)

    def setup(world: World) -> None:
        world.insert_resource(Camera(pixels_per_meter=16))
        world.spawn(Transform(), Sprite(str(path), size=(3.0, 3.0)), Animator({"blink": clip}))

    app = make_app(setup, fixed_dt=DT)
    seen = []
    for _ in range(10):
        seen.append(centre_colour(app))
        app.step(1)
    red, blue = (255, 0, 0), (0, 0, 255)
    assert seen == [red, red] + [blue] * 6 + [red, red]


def test_a_sprite_spawned_after_the_first_render_is_animated_too(make_app: Any, sheet: Any) -> None:
    app = make_app(lambda world: world.insert_resource(Camera(pixels_per_meter=16)), fixed_dt=DT)
    assert centre_colour(app) == (0, 0, 0)
    clip = Clip.grid(sheet, (4, 1), frames=[2, 0], duration=0.1)
    app.world.spawn(Transform(), Sprite(sheet, size=(3.0, 3.0)), Animator({"x": clip}))
    assert centre_colour(app) == COLOURS[2]
    app.step(2)
    assert centre_colour(app) == COLOURS[0]


# -- timing and events (headless) ---------------------------------------------------------------
def _world_app(sheet: Any, clip: Clip, extra: Any = None, **kw: Any) -> App:
    return App(_scene(sheet, clip, extra), headless=True, fixed_dt=DT, **kw)


def test_frame_events_fire_each_time_the_frame_is_entered(sheet: Any) -> None:
    clip = Clip.grid(sheet, (4, 1), duration=0.1, events={0: "start", 2: "footstep"})
    app = _world_app(sheet, clip)
    log: list[tuple[int, str]] = []
    for step in range(17):  # 0.85 s: frame 2 entered at 0.2 and 0.6
        app.step(1)
        log.extend((step, e.name) for e in app.world.resource(AnimationEvents).frame)
    assert log == [(0, "start"), (3, "footstep"), (7, "start"), (11, "footstep"), (15, "start")]


def test_a_long_frame_does_not_skip_events(sheet: Any) -> None:
    clip = Clip.grid(sheet, (4, 1), duration=0.1, events={2: "footstep"})
    app = _world_app(sheet, clip, time_scale=1.0)
    app.step(1)
    app.advance(0.25)  # a frame of 0.25 s: capped steps, update dt covers all of it
    names = [e.name for e in app.world.resource(AnimationEvents).frame]
    assert names == ["footstep"]


def test_loop_modes(sheet: Any) -> None:
    def run(loop: Loop) -> list[int]:
        clip = Clip.grid(sheet, (4, 1), duration=0.1, loop=loop)
        return _frames(_world_app(sheet, clip), 20)[1::2]  # every 0.1 s

    assert run(Loop.LOOP) == [0, 1, 2, 3, 0, 1, 2, 3, 0, 1]
    assert run(Loop.PING_PONG) == [0, 1, 2, 3, 2, 1, 0, 1, 2, 3]
    assert run(Loop.HOLD) == [0, 1, 2, 3, 3, 3, 3, 3, 3, 3]
    assert run(Loop.ONCE) == [0, 1, 2, 3, 0, 0, 0, 0, 0, 0]


class Listener(Script):
    def __init__(self) -> None:
        self.got: list[Any] = []

    def on_animation_event(self, event: Any) -> None:
        self.got.append(("event", event.name))

    def on_animation_end(self, event: Any) -> None:
        self.got.append(("end", event.clip))


def test_finished_event_hooks_queue_and_end_transition(sheet: Any) -> None:
    attack = Clip.grid(sheet, (4, 1), frames=[2, 3], duration=0.1, loop=Loop.ONCE,
                       events={1: "hit"})
    idle = Clip.grid(sheet, (4, 1), frames=[0], duration=0.1)
    rest = Clip.grid(sheet, (4, 1), frames=[1], duration=0.1, loop=Loop.HOLD)
    script = Listener()

    def setup(world: World) -> None:
        world.spawn(
            Transform(),
            Animator({"idle": idle, "attack": attack, "rest": rest}, current="attack",
                     transitions=(Transition("rest", "idle"),)),
            Behaviour(script),
        )

    app = App(setup, headless=True, fixed_dt=DT)
    anim = app.world.get(1, Animator)
    anim.queue("rest")
    app.step(12)
    assert script.got == [("event", "hit"), ("end", "attack"), ("end", "rest")]
    assert anim.current == "idle"
    finished = app.world.resource(AnimationEvents).finished
    assert finished == []  # per-frame lists: the end events were frames ago


def test_conditional_transition_switches_while_the_parameter_is_set(sheet: Any) -> None:
    idle = Clip.grid(sheet, (4, 1), frames=[0])
    run = Clip.grid(sheet, (4, 1), frames=[1, 2])
    trs = (Transition("idle", "run", when="moving"), Transition("run", "idle", when="still"))
    w = World()
    w.add_plugins(AnimationPlugin())
    e = w.spawn(Animator({"idle": idle, "run": run}, transitions=trs))
    from kge.schedule import Stage

    w.schedule.run(Stage.UPDATE, 0.05)
    anim = w.get(e, Animator)
    assert anim.current == "idle"
    anim.set("moving", True)
    w.schedule.run(Stage.UPDATE, 0.05)
    assert anim.current == "run"
    anim.set("moving", False)
    anim.set("still", True)
    w.schedule.run(Stage.UPDATE, 0.05)
    assert anim.current == "idle"


def test_game_time_scale_pause_and_single_step(sheet: Any) -> None:
    clip = Clip.grid(sheet, (4, 1), duration=0.1)
    app = _world_app(sheet, clip, time_scale=0.5)
    anims = app.world.resource(Animations)
    for _ in range(4):
        app.advance(DT)  # 0.2 s real = 0.1 s game
    assert anims.frame(1) == 1
    app.paused = True
    for _ in range(10):
        app.advance(DT)
    assert anims.frame(1) == 1
    app.single_step()
    app.advance(DT)  # one fixed step of game time: 0.15 s
    app.single_step()
    app.advance(DT)  # 0.2 s
    assert anims.frame(1) == 2


def test_play_pause_stop_speed_and_determinism(sheet: Any) -> None:
    clip = Clip.grid(sheet, (4, 1), duration=0.1)
    a, b = _world_app(sheet, clip), _world_app(sheet, clip)
    for app in (a, b):
        anim = app.world.get(1, Animator)
        anim.speed = 2.0
        app.step(3)  # 0.15 s x 2 = frame 3
        assert app.world.resource(Animations).frame(1) == 3
        anim.pause()
        app.step(5)
        assert app.world.resource(Animations).frame(1) == 3
        anim.resume()
        anim.play("walk")  # restart
        app.step(1)
        assert app.world.resource(Animations).frame(1) == 1
        anim.stop()
        app.step(4)
        assert app.world.resource(Animations).frame(1) == 0
    assert a.world.resource(Animations).state.time.tolist() == \
        b.world.resource(Animations).state.time.tolist()


# -- bad input --------------------------------------------------------------------------------------
def test_bad_clips_are_refused_at_the_call(sheet: Any) -> None:
    with pytest.raises(ValidationError, match="frame 9 is outside the 4x1 sheet"):
        Clip.grid(sheet, (4, 1), frames=[0, 9])
    with pytest.raises(ValidationError, match="at least one frame"):
        Clip.images([])
    with pytest.raises(ValidationError, match=r"Clip.duration must be > 0, got 0.0"):
        Clip.grid(sheet, (4, 1), duration=0)
    with pytest.raises(ValidationError, match=r"Clip.duration\[1\] must be > 0, got -0.1"):
        Clip.grid(sheet, (4, 1), frames=[0, 1], duration=[0.1, -0.1])
    with pytest.raises(ValidationError, match="loop must be one of"):
        Clip.grid(sheet, (4, 1), loop="forever")


def test_unknown_clip_names_leave_the_world_unchanged(sheet: Any) -> None:
    clip = Clip.grid(sheet, (4, 1))
    app = _world_app(sheet, clip)
    anim = app.world.get(1, Animator)
    before = (anim.current, anim.serial, list(anim.queued))
    with pytest.raises(ValidationError, match="entity 1, Animator.play: unknown clip 'run'"):
        anim.play("run")
    with pytest.raises(ValidationError, match="unknown clip 'jump'"):
        anim.queue("jump")
    assert (anim.current, anim.serial, list(anim.queued)) == before
    with pytest.raises(ValidationError, match="Animator.current: unknown clip 'fly'"):
        app.world.spawn(Animator({"walk": clip}, current="fly"))
    assert len(app.world) == 1
    with pytest.raises(ValidationError, match="Animator.speed must be finite"):
        anim.speed = float("nan")
    assert anim.speed == 1.0
    with pytest.raises(ValidationError, match="entity 1, Animator.current: unknown clip 'x'"):
        anim.current = "x"
    with pytest.raises(ValidationError, match="the new clips lack the current clip 'walk'"):
        anim.clips = {"other": clip}
    assert anim.current == "walk" and list(anim.clips) == ["walk"]
    with pytest.raises(MissingComponentError, match="entity 99 has no Animator"):
        app.world.resource(Animations).frame(99)


def test_image_list_clips_and_flips_draw_the_right_pixels(make_app: Any) -> None:
    import numpy as np

    from kge.render.images import PixelImage, solid
    from kge.render.setup import frame_pixels

    arr = np.zeros((8, 8, 4), np.uint8)
    arr[:, :4] = (255, 0, 0, 255)  # left half red, right half blue
    arr[:, 4:] = (0, 0, 255, 255)
    halves = PixelImage(8, 8, arr.tobytes())
    plain = Clip.images([halves, solid(8, 8, (0, 255, 0))], duration=0.1)
    mirrored = Clip.images([halves], flip_x=True)

    def setup(world: World) -> None:
        world.insert_resource(Camera(pixels_per_meter=16))
        world.spawn(Transform(-1.0, 0.0), Sprite(halves, size=(1.5, 1.5)),
                    Animator({"a": plain}))
        world.spawn(Transform(1.0, 0.0), Sprite(halves, size=(1.5, 1.5)),
                    Animator({"m": mirrored}))

    app = make_app(setup, fixed_dt=DT)
    app.render()
    px = frame_pixels(app)

    def at(x: int) -> tuple[int, ...]:
        return tuple(int(v) for v in px[32, x, :3])

    assert at(11) == (255, 0, 0) and at(21) == (0, 0, 255)  # left sprite as drawn
    assert at(43) == (0, 0, 255) and at(53) == (255, 0, 0)  # right sprite mirrored
    app.step(2)
    app.render()
    px = frame_pixels(app)
    assert at(11) == (0, 255, 0) and at(21) == (0, 255, 0)  # the second image


def test_tags_make_one_clip_per_range(sheet: Any) -> None:
    clips = Clip.tags(sheet, (4, 1), {"idle": (0, 0), "run": (1, 3)}, fps=10)
    assert [len(c.frames) for c in clips.values()] == [1, 3]
    assert [f.index for f in clips["run"].frames] == [1, 2, 3]
    with pytest.raises(ValidationError, match=r"Clip.tags\['bad'\]: last frame 0 < first 2"):
        Clip.tags(sheet, (4, 1), {"bad": (2, 0)})
    with pytest.raises(ValidationError, match="frame 4 is outside the 4x1 sheet"):
        Clip.tags(sheet, (4, 1), {"far": (3, 4)})


def test_bad_gifs_are_refused_with_the_file_named(tmp_path: Path) -> None:
    with pytest.raises(ValidationError, match="cannot read the file"):
        gif_clip(str(tmp_path / "missing.gif"))
    png = tmp_path / "still.png"
    from PIL import Image

    Image.new("RGB", (4, 4)).save(png)
    with pytest.raises(ValidationError, match="the file is a PNG, not a GIF"):
        gif_clip(str(png))
    (tmp_path / "junk.gif").write_bytes(b"not an image")
    with pytest.raises(ValidationError, match="not an image Pillow can read"):
        gif_clip(str(tmp_path / "junk.gif"))


def test_playing_a_clip_not_yet_played_after_frames_were_drawn(make_app: Any, sheet: Any) -> None:
    """play() of a clip the animator has not played yet, after rendering: the clip table's
    arrays are rebuilt before the frame is drawn (it indexed stale arrays: IndexError)."""
    clips = {
        "idle": Clip.grid(sheet, (4, 1), frames=[0], duration=0.1),
        "run": Clip.grid(sheet, (4, 1), frames=[1, 2, 3, 2], duration=0.1),
        "jump": Clip.grid(sheet, (4, 1), frames=[3], duration=0.1),
    }

    def setup(world: World) -> None:
        world.spawn(Transform(), Sprite(sheet, size=(1, 1)), Animator(clips))

    app = make_app(setup, fixed_dt=DT)
    assert centre_colour(app) == COLOURS[0]
    app.step(1)
    app.world.get(1, Animator).play("run")
    app.step(1)
    assert centre_colour(app) == COLOURS[1]
    app.world.get(1, Animator).play("jump")
    assert centre_colour(app) == COLOURS[3]
