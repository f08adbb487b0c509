"""Scene flow as a game uses it: transitions started from a script's update play (not a
cut), scripts reach the App (push, replace, pop, quit), kge.run apps declare bindings."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from kge import App, Behaviour, InputMap, Key, Script, Transform, World
from kge.components.camera import Camera
from kge.components.color import RGBA
from kge.components.drawables import Rect
from kge.errors import ValidationError
from kge.transitions import Crossfade, Fade, Slide, Transition, Wipe

from .conftest import mask, pixels

RED: RGBA = (255, 0, 0, 255)
BLUE: RGBA = (0, 0, 255, 255)


def red_room(world: World) -> None:
    world.insert_resource(Camera(pixels_per_meter=20))  # 200 px window: red at x 40..79
    world.spawn(Transform(-2, 0), Rect(2.0, 2.0, color=RED))


def blue_room(world: World) -> None:
    world.insert_resource(Camera(pixels_per_meter=20))  # blue at x 120..159
    world.spawn(Transform(2, 0), Rect(2.0, 2.0, color=BLUE))


class Door(Script):
    """Leaves for the blue room with ``kind`` when the frame counter reaches ``at``."""

    def __init__(self, kind: Transition | None, at: int = 3, target: Any = None) -> None:
        self.kind, self.at, self.frames = kind, at, 0
        self.target = target or blue_room

    def on_update(self, dt: float) -> None:
        self.frames += 1
        if self.frames == self.at:
            self.app.replace_scene(self.target, transition=self.kind)


def room_with_door(world: World, door: Door) -> None:
    red_room(world)
    world.spawn(Behaviour(door))


def painted_room(world: World, door: Door) -> None:
    """A window-filling dark red room: every pixel tells the two rooms apart."""
    world.insert_resource(Camera(pixels_per_meter=20))
    world.spawn(Transform(0, 0), Rect(10.0, 8.0, color=(90, 0, 0, 255)))
    world.spawn(Transform(-2, 0), Rect(2.0, 2.0, color=RED), Behaviour(door))


def painted_blue(world: World) -> None:
    world.insert_resource(Camera(pixels_per_meter=20))
    world.spawn(Transform(0, 0), Rect(10.0, 8.0, color=(0, 0, 90, 255)))


@pytest.mark.parametrize("kind", [Crossfade(0.4), Slide(0.4, direction="left"),
                                  Wipe(0.4, direction="left")])  # fmt: skip
def test_a_picture_transition_started_in_on_update_plays_over_several_frames(
    make_app: Any, kind: Transition
) -> None:
    app = make_app(painted_room, door=Door(kind, target=painted_blue), fixed_dt=0.025)
    frames = []
    for _ in range(24):  # a window: one frame advanced, then drawn
        app.advance(0.025)
        frames.append(pixels(app).copy())
    # frame index 2 is the one whose update asked for the change: the old room is still
    # shown whole; then frames unlike both rooms (the old one fading, moving or cut
    # away over the new one), then only the new one: an animation, not a cut
    red = [int((px[..., 0] > 40).sum()) for px in frames]  # pixels showing some red
    blue = [int((px[..., 2] > 40).sum()) for px in frames]
    assert red[2] == 200 * 160 and blue[2] == 0
    old, new = frames[2], frames[-1]
    between = [i for i, px in enumerate(frames)
               if (px != old).any() and (px != new).any()]  # fmt: skip
    assert len(between) >= 8, between  # 0.4 s of 25 ms frames: most of them in between
    assert between == list(range(3, 3 + len(between)))  # from the frame after the request
    assert len(between) <= 16  # and done when it should be
    assert red[-1] == 0 and blue[-1] == 200 * 160 and app.transition is None


def test_crossfade_from_a_script_shows_the_old_room_fading(make_app: Any) -> None:
    app = make_app(room_with_door, door=Door(Crossfade(0.4)), fixed_dt=0.05)
    for _ in range(3):
        app.advance(0.05)
        pixels(app)
    app.advance(0.05)  # the first frame of the transition: the scene changes under it
    tr = app.transition
    assert tr is not None and tr.swapped and tr.picture is not None
    assert tr.picture_alpha == pytest.approx(0.957, abs=0.002)  # eased at t = 0.05 / 0.4
    px = pixels(app)
    # the old red square, mostly opaque, over the new blue one (blended, not a cut)
    reds = px[mask(px, (215, 0, 0), tol=30)]
    assert len(reds) > 1000
    blend = px[mask(px, (0, 0, 11), tol=6)]
    assert len(blend) > 500


def test_a_fade_started_in_on_update_starts_its_clock_on_the_next_frame() -> None:
    app = App(room_with_door, headless=True, door=Door(Fade(0.4), at=1), fixed_dt=0.05)
    first = app.world
    app.advance(0.05)  # the script asks for the fade during this frame
    assert app.transition is not None and app.transition.elapsed == 0.0
    covers = []
    for _ in range(8):
        app.advance(0.05)
        covers.append(round(app.transition.cover, 3) if app.transition else None)
    assert covers[:4] == [0.156, 0.5, 0.844, 1.0] and app.world is not first


def test_between_frames_a_picture_transition_also_plays(make_app: Any) -> None:
    app = make_app(red_room, fixed_dt=0.05)
    pixels(app)
    app.replace_scene(blue_room, transition=Crossfade(0.4))
    app.advance(0.05)  # no frame drawn in between: the picture is taken at the change
    px = pixels(app)
    assert app.transition is not None and app.transition.picture is not None
    assert mask(px, (215, 0, 0), tol=30).sum() > 1000


def test_headless_without_drawing_a_transition_still_changes_the_scene() -> None:
    app = App(room_with_door, headless=True, door=Door(Slide(0.3)), fixed_dt=0.05)
    first = app.world
    for _ in range(12):
        app.advance(0.05)
    assert app.world is not first and app.transition is None


# -- the App from scripts -----------------------------------------------------------------------
class Flow(Script):
    """Drives the scene stack from hooks, as a game does."""


    def on_update(self, dt: float) -> None:
        inp = self.app.input
        if inp.pressed(Key.P):
            self.app.push_scene(pause, overlay=True)
        elif inp.pressed(Key.N):
            self.app.replace_scene(level_two)
        elif inp.pressed(Key.Q):
            self.app.quit()


class Resume(Script):
    def on_update(self, dt: float) -> None:
        if self.app.input.pressed(Key.ESCAPE):
            self.app.pop_scene()


def level_one(world: World) -> None:
    world.spawn(Behaviour(Flow()))


def level_two(world: World) -> None:
    world.spawn(Behaviour(Flow()))


def pause(world: World) -> None:
    world.spawn(Behaviour(Resume()))


def _tap(app: App, key: int) -> None:
    app.input.press(key)
    app.step()
    app.input.release(key)
    app.step()


def test_scripts_push_pop_replace_and_quit_through_self_app() -> None:
    app = App(level_one, headless=True)
    assert [s.name for s in app.scenes] == ["level_one"]
    _tap(app, Key.P)
    assert [s.name for s in app.scenes] == ["level_one", "pause"]
    _tap(app, Key.ESCAPE)
    assert [s.name for s in app.scenes] == ["level_one"]
    _tap(app, Key.N)
    assert [s.name for s in app.scenes] == ["level_two"]
    app.input.press(Key.Q)
    app.run(frames=100)  # quit from the script stops the loop after that frame
    assert app.frame_count < 10


def test_script_app_outside_an_app_says_so() -> None:
    world = World()
    script = Flow()
    world.spawn(Behaviour(script))
    with pytest.raises(LookupError, match="not run by an App"):
        _ = script.app


# -- bindings for kge.run apps ---------------------------------------------------------------------
def _jumps(world: World) -> None:
    pass


def test_bindings_declared_as_a_dict_of_actions_and_axes() -> None:
    app = App(_jumps, headless=True, bindings={
        "jump": ["key:SPACE", "pad:a"], "fire": "key:F",
        "move_x": {"negative": ["key:A"], "positive": ["key:D"], "stick": "pad:leftx"},
    })  # fmt: skip
    assert app.actions.bindings("jump") == ["key:SPACE", "pad:a"]
    app.input.press(Key.D)
    assert app.actions.axis("move_x") == 1.0
    assert app.world.resource(InputMap) is app.actions


def test_bindings_from_a_json_file_a_function_and_to_data(tmp_path: Path) -> None:
    path = tmp_path / "controls.json"
    source = InputMap(App(_jumps, headless=True).input)
    source.bind("jump", "key:W")
    source.save(path)
    assert App(_jumps, headless=True, bindings=path).actions.bindings("jump") == ["key:W"]
    data = json.loads(path.read_text())
    assert App(_jumps, headless=True, bindings=data).actions.bindings("jump") == ["key:W"]
    app = App(_jumps, headless=True, bindings=lambda a: a.bind("dash", Key.LSHIFT))
    assert app.actions.bindings("dash") == ["key:LSHIFT"]


def test_bad_bindings_are_refused_naming_what_is_wrong() -> None:
    with pytest.raises(ValidationError, match="SPAEC"):
        App(_jumps, headless=True, bindings={"jump": ["key:SPAEC"]})
    with pytest.raises(ValidationError, match="unknown keys"):
        App(_jumps, headless=True, bindings={"move": {"negatve": ["key:A"]}})
    with pytest.raises(ValidationError, match="bindings must be"):
        App(_jumps, headless=True, bindings=[1, 2])  # type: ignore[arg-type]
