"""Input actions beyond polling: chords, triggers as buttons, a radial dead zone, hold
duration, double taps, buffering, combos, and action events and hooks."""

from __future__ import annotations

import math

import pytest

from kge import (
    ActionPressed,
    ActionReleased,
    App,
    Behaviour,
    InputMap,
    Key,
    Mouse,
    Script,
    Transform,
    UnknownActionError,
    ValidationError,
    World,
)
from kge.input import Input


def _app() -> App:
    return App(lambda world: None, headless=True)


def _tap(app: App, key: int, frames_between: int = 1) -> None:
    app.input.press(key)
    app.step(1)
    app.input.release(key)
    app.step(frames_between)


# -- chords -----------------------------------------------------------------------------------
def test_a_chord_fires_only_with_its_modifiers_held_on_either_side() -> None:
    inp = Input()
    actions = InputMap(inp)
    actions.bind("save", "key:ctrl+S")
    actions.bind("redo", "key:SHIFT+CTRL+Z", "mouse:ALT+RIGHT")
    assert actions.bindings("redo") == ["key:CTRL+SHIFT+Z", "mouse:ALT+RIGHT"]
    inp.press(Key.S)
    assert not actions.pressed("save") and not actions.held("save")
    inp.end_frame()
    inp.release(Key.S)
    inp.press(Key.RCTRL)
    inp.press(Key.S)
    assert actions.pressed("save") and actions.held("save")
    inp.end_frame()
    inp.release(Key.RCTRL)
    assert not actions.held("save")  # the modifier went up: the chord is not held
    inp.release(Key.S)
    assert actions.released("save")
    inp.end_frame()
    inp.press(Key.LCTRL)
    inp.press(Key.Z)
    assert not actions.pressed("redo")  # SHIFT is missing
    inp.press(Key.LSHIFT)
    assert actions.held("redo")
    inp.mouse_down(Mouse.RIGHT)
    inp.press(Key.LALT)
    assert actions.pressed("redo")


@pytest.mark.parametrize(
    ("binding", "message"),
    [("key:HYPER+S", "unknown modifier 'HYPER'"), ("key:CTRL+", "a chord ends with a key"),
     ("key:CTRL+NOPE", "unknown key 'NOPE'"), ("mouse:CTRL+MIDDLEST", "mouse buttons")],
)  # fmt: skip
def test_a_bad_chord_is_refused_at_the_call(binding: str, message: str) -> None:
    actions = InputMap(Input())
    with pytest.raises(ValidationError, match=message):
        actions.bind("save", binding)
    assert actions.actions == []


# -- triggers and sticks ------------------------------------------------------------------------
def test_a_trigger_is_a_button_with_hysteresis_and_still_an_axis() -> None:
    inp = Input()
    pad = inp.connect_gamepad()
    actions = InputMap(inp)
    actions.bind("fire", "pad:righttrigger")
    actions.bind_axis("throttle", positive=[], stick="pad:righttrigger", dead_zone=0.0)
    pad.move("righttrigger", 0.45)
    assert not actions.held("fire")
    pad.move("righttrigger", 0.6)
    assert actions.pressed("fire") and actions.held("fire")
    assert actions.axis("throttle") == pytest.approx(0.6)
    inp.end_frame()
    pad.move("righttrigger", 0.45)  # between the two thresholds: still down, no new press
    assert actions.held("fire") and not actions.pressed("fire")
    pad.move("righttrigger", 0.3)
    assert actions.released("fire") and not actions.held("fire")
    assert inp.pad_held("righttrigger") is False


def test_a_radial_dead_zone_keeps_the_stick_direction() -> None:
    inp = Input()
    pad = inp.connect_gamepad()
    actions = InputMap(inp)
    actions.bind_axis("mx", stick="pad:leftx", dead_zone=0.2)
    actions.bind_axis("my", stick="pad:lefty", dead_zone=0.2)
    actions.bind_vector("cross", "mx", "my")
    actions.bind_vector("round", "mx", "my", dead_zone=0.2)
    pad.move("leftx", 0.7)
    pad.move("lefty", 0.1)
    x, y = actions.vector("cross")
    assert y == 0.0  # per axis: the small y is cut away, the push snaps to the axis
    x, y = actions.vector("round")
    assert y / x == pytest.approx(0.1 / 0.7)  # radial: the direction is kept
    assert math.hypot(x, y) == pytest.approx((math.hypot(0.7, 0.1) - 0.2) / 0.8)
    pad.move("leftx", 0.14)
    pad.move("lefty", 0.14)  # inside the circle (0.198)
    assert actions.vector("round") == (0.0, 0.0)
    pad.move("leftx", 1.0)
    pad.move("lefty", 1.0)
    assert math.hypot(*actions.vector("round")) == pytest.approx(1.0)
    with pytest.raises(ValidationError, match="dead_zone must be in"):
        actions.bind_vector("bad", "mx", "my", dead_zone=1.5)


# -- over time ---------------------------------------------------------------------------------
def test_hold_duration_is_real_time_and_the_release_event_carries_it() -> None:
    app = _app()
    app.actions.bind("charge", Key.C)
    app.time_scale = 0.25  # slow motion does not slow the player's fingers
    app.input.press(Key.C)
    app.step(30)
    assert app.actions.held_for("charge") == pytest.approx(29 / 60)
    app.input.release(Key.C)
    app.step(1)
    released = app.world.events(ActionReleased)
    assert [e.action for e in released] == ["charge"]
    assert released[0].held_for == pytest.approx(30 / 60)
    assert app.actions.held_for("charge") == 0.0


def test_double_tap_within_the_window_and_not_after_it() -> None:
    app = _app()
    app.actions.bind("dash", Key.D)
    _tap(app, Key.D, frames_between=5)
    app.input.press(Key.D)
    app.step(1)
    assert app.actions.double_tapped("dash")
    assert [e.taps for e in app.world.events(ActionPressed)] == [2]
    app.input.release(Key.D)
    app.step(30)  # half a second: too slow
    app.input.press(Key.D)
    app.step(1)
    assert not app.actions.double_tapped("dash")
    assert [e.taps for e in app.world.events(ActionPressed)] == [1]
    app.actions.tap_window = 0.6
    app.input.release(Key.D)
    app.step(30)
    app.input.press(Key.D)
    app.step(1)
    assert app.actions.double_tapped("dash")
    with pytest.raises(ValidationError, match="tap_window"):
        app.actions.tap_window = -1.0


def test_a_buffered_jump_lands_when_the_player_can_jump() -> None:
    jumps: list[int] = []

    class Player(Script):
        grounded_at = 6  # frames until the player lands

        def on_fixed_update(self, dt: float) -> None:
            actions = self.world.resource(InputMap)
            frame = self.world.resource(App).frame_count
            if frame >= self.grounded_at and actions.buffered("jump"):
                actions.consume("jump")
                jumps.append(frame)

    app = App(lambda w: w.spawn(Transform(), Behaviour(Player())), headless=True)
    app.actions.bind("jump", Key.SPACE)
    app.step(2)
    app.input.press(Key.SPACE)  # pressed 4 frames before landing (67 ms)
    app.step(1)
    app.input.release(Key.SPACE)
    app.step(10)
    assert jumps == [6]  # jumped on landing, once: the press was consumed
    app.input.press(Key.SPACE)
    app.step(1)
    app.input.release(Key.SPACE)
    assert jumps == [6, 13]
    assert not app.actions.buffered("jump")
    app.actions.bind("dash", Key.D)  # nothing consumes it
    app.input.press(Key.D)
    app.step(1)
    app.input.release(Key.D)
    app.step(5)
    assert app.actions.buffered("dash")
    app.step(7)  # 0.2 s after the press it has run out
    assert not app.actions.buffered("dash") and app.actions.buffered("dash", window=0.25)
    with pytest.raises(ValidationError, match="window"):
        app.actions.buffered("dash", window=float("nan"))


def test_a_combo_needs_its_order_and_its_time() -> None:
    app = _app()
    for name, key in (("down", Key.S), ("right", Key.D), ("punch", Key.J), ("jump", Key.K)):
        app.actions.bind(name, key)
    app.actions.bind_combo("fireball", "down", "right", "punch", within=0.5)
    seen: list[ActionPressed] = []
    app.actions.on_pressed("fireball", seen.append)
    for key in (Key.S, Key.D, Key.K):  # a jump in between does not break it
        _tap(app, key, frames_between=3)
    app.input.press(Key.J)
    app.step(1)
    assert app.actions.combo("fireball") and len(seen) == 1
    assert "fireball" in [e.action for e in app.world.events(ActionPressed)]
    app.input.release(Key.J)
    app.step(1)
    assert not app.actions.combo("fireball")
    for key in (Key.D, Key.S, Key.J):  # wrong order
        _tap(app, key)
    assert len(seen) == 1
    for key in (Key.S, Key.D):
        _tap(app, key, frames_between=20)  # too slow: 0.7 s
    _tap(app, Key.J)
    assert len(seen) == 1
    with pytest.raises(UnknownActionError, match="kick"):
        app.actions.bind_combo("x", "down", "kick")
    with pytest.raises(ValidationError, match="two or more"):
        app.actions.bind_combo("x", "down")
    with pytest.raises(ValidationError, match="an action has that name"):
        app.actions.bind_combo("punch", "down", "right")


def test_hooks_and_events_reach_game_code_in_order() -> None:
    log: list[str] = []

    class Reader(Script):
        def on_update(self, dt: float) -> None:
            for ev in self.world.events(ActionPressed, ActionReleased):
                log.append(f"script {type(ev).__name__} {ev.action}")

    app = App(lambda w: w.spawn(Transform(), Behaviour(Reader())), headless=True)
    app.actions.bind("jump", Key.SPACE)
    app.actions.on_pressed("jump", lambda ev: log.append(f"hook pressed {ev.action}"))
    hook = app.actions.on_released("jump", lambda ev: log.append(f"hook released {ev.held_for}"))
    _tap(app, Key.SPACE, frames_between=1)
    assert log == ["hook pressed jump", "script ActionPressed jump",
                   f"hook released {1 / 60}", "script ActionReleased jump"]  # fmt: skip
    app.actions.remove_hook("jump", hook)
    log.clear()
    _tap(app, Key.SPACE)
    assert log == ["hook pressed jump", "script ActionPressed jump", "script ActionReleased jump"]
    with pytest.raises(UnknownActionError, match="jmup"):
        app.actions.on_pressed("jmup", print)
    with pytest.raises(ValidationError, match="needs a function"):
        app.actions.on_pressed("jump", "not a function")  # type: ignore[arg-type]


def test_a_paused_game_still_sees_action_events() -> None:
    app = _app()
    app.actions.bind("pause_menu", Key.ESCAPE)
    app.paused = True
    app.input.press(Key.ESCAPE)
    app.advance(1 / 60)
    assert [e.action for e in app.world.events(ActionPressed)] == ["pause_menu"]


def test_combos_and_radial_vectors_save_and_load() -> None:
    actions = InputMap(Input())
    actions.bind("a", Key.A)
    actions.bind("b", "key:CTRL+B")
    actions.bind_axis("x", stick="pad:leftx")
    actions.bind_vector("v", "x", "x", dead_zone=0.25)
    actions.bind_combo("ab", "a", "b", within=0.4)
    data = actions.to_data()
    assert data["combos"] == {"ab": {"steps": ["a", "b"], "within": 0.4}}
    assert data["vectors"] == {"v": ["x", "x", 0.25]}
    again = InputMap(Input())
    again.load_data(data)
    assert again.to_data() == data
    with pytest.raises(ValidationError, match="malformed"):
        again.load_data({**data, "combos": {"ab": {"within": 1}}})
    assert again.to_data() == data  # unchanged


def test_a_scene_change_starts_holds_afresh() -> None:
    app = _app()
    app.actions.bind("charge", Key.C)
    app.input.press(Key.C)
    app.step(10)
    app.push_scene(lambda world: None)
    app.step(1)
    assert app.actions.held_for("charge") == 0.0
    assert isinstance(app.world, World)
