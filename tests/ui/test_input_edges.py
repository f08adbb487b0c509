"""Input edges per fixed step, actions, gamepads (simulated and through the pyglet bridge)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from kge import App, Behaviour, Input, Key, Mouse, Script, World
from kge.actions import InputMap, UnknownActionError
from kge.errors import ValidationError
from kge.input import GamepadEvent


class Counter(Script):
    def __init__(self) -> None:
        self.fixed = 0
        self.update = 0
        self.fixed_released = 0
        self.action_fixed = 0
        self.action_update = 0

    def on_fixed_update(self, dt: float) -> None:
        inp = self.world.resource(Input)
        self.fixed += inp.pressed(Key.SPACE)
        self.fixed_released += inp.released(Key.SPACE)
        self.action_fixed += self.world.resource(InputMap).pressed("jump")

    def on_update(self, dt: float) -> None:
        self.update += self.world.resource(Input).pressed(Key.SPACE)
        self.action_update += self.world.resource(InputMap).pressed("jump")


def _app() -> tuple[App, Counter]:
    probe = Counter()

    def scene(world: World) -> None:
        world.spawn(Behaviour(probe))

    app = App(scene, headless=True)
    app.actions.bind("jump", Key.SPACE, "pad:a")
    return app, probe


@pytest.mark.parametrize("hz", [30, 60, 144])
@pytest.mark.parametrize("press_frame", range(7))
def test_a_press_is_seen_once_by_fixed_and_once_by_update_code(hz: int, press_frame: int) -> None:
    app, probe = _app()
    steps_total = 0
    for frame in range(40):
        if frame == press_frame:
            app.input.press(Key.SPACE)
        if frame == press_frame + 3:
            app.input.release(Key.SPACE)
        steps_total += app.advance(1.0 / hz)
    assert steps_total > 0
    assert (probe.fixed, probe.update) == (1, 1)
    assert probe.fixed_released == 1
    assert (probe.action_fixed, probe.action_update) == (1, 1)


def test_at_30_hz_only_the_first_of_two_steps_sees_the_press() -> None:
    app, probe = _app()
    app.input.press(Key.SPACE)
    assert app.advance(1.0 / 30) == 2
    assert probe.fixed == 1 and probe.update == 1
    assert app.advance(1.0 / 30) == 2
    assert probe.fixed == 1 and probe.update == 1


def test_press_and_release_between_two_steps_are_both_seen_by_fixed_code() -> None:
    app, probe = _app()
    for _ in range(3):
        app.input.press(Key.SPACE)
        app.input.release(Key.SPACE)
        while app.advance(1.0 / 144) == 0:
            pass
    assert probe.fixed == 3 and probe.fixed_released == 3 and probe.update == 3


def test_mouse_and_pad_edges_follow_the_same_rule() -> None:
    seen: list[tuple[bool, bool]] = []

    class Probe(Script):
        def on_fixed_update(self, dt: float) -> None:
            inp = self.world.resource(Input)
            seen.append((inp.mouse_pressed(Mouse.LEFT), inp.pad_pressed("a")))

    def scene(world: World) -> None:
        world.spawn(Behaviour(Probe()))

    app = App(scene, headless=True)
    pad = app.input.connect_gamepad()
    app.input.click(Mouse.LEFT, at=(3, 4))
    pad.press("a")
    app.advance(1.0 / 30)
    assert seen == [(True, True), (False, False)]


# -- actions ---------------------------------------------------------------------------------
def _map() -> tuple[Input, InputMap]:
    inp = Input()
    m = InputMap(inp)
    m.bind("jump", Key.SPACE, "pad:a", "mouse:LEFT")
    m.bind_axis("move_x", negative=["key:A", Key.LEFT], positive=["key:D"], stick="pad:leftx")
    m.bind_axis("move_y", negative=["key:S"], positive=["key:W"], stick="pad:lefty")
    m.bind_vector("move", "move_x", "move_y")
    return inp, m


def test_actions_held_pressed_released_from_every_kind_of_binding() -> None:
    inp, m = _map()
    pad = inp.connect_gamepad()
    for down, up in (
        (lambda: inp.press(Key.SPACE), lambda: inp.release(Key.SPACE)),
        (lambda: pad.press("a"), lambda: pad.release("a")),
        (lambda: inp.mouse_down(Mouse.LEFT), lambda: inp.mouse_up(Mouse.LEFT)),
    ):
        down()
        assert m.pressed("jump") and m.held("jump") and not m.released("jump")
        inp.end_frame()
        assert not m.pressed("jump") and m.held("jump")
        up()
        assert m.released("jump") and not m.held("jump")
        inp.end_frame()


def test_axes_with_dead_zone_and_vectors() -> None:
    inp, m = _map()
    pad = inp.connect_gamepad()
    pad.move("leftx", 0.15)
    assert m.axis("move_x") == 0.0  # inside the 0.2 dead zone
    pad.move("leftx", 0.6)
    assert m.axis("move_x") == pytest.approx(0.5)  # (0.6 - 0.2) / 0.8
    pad.move("leftx", -1.0)
    assert m.axis("move_x") == -1.0
    pad.move("leftx", 0.0)
    inp.press(Key.D)
    inp.press(Key.W)
    x, y = m.vector("move")
    assert x == pytest.approx(2**-0.5) and y == pytest.approx(2**-0.5)  # diagonal not faster
    inp.press(Key.LEFT)
    assert m.axis("move_x") == 0.0


def test_rebinding_at_run_time_and_saving_as_data(tmp_path: Path) -> None:
    inp, m = _map()
    m.rebind("jump", "key:W")
    assert m.bindings("jump") == ["key:W"]
    inp.press(Key.SPACE)
    assert not m.pressed("jump")
    inp.end_frame()
    m.bind("jump", "pad:a")
    inp.press(Key.J)
    assert m.rebind_from_input("jump") == "key:J"
    assert m.bindings("jump") == ["key:J", "pad:a"]  # the pad binding stays
    path = tmp_path / "keys.json"
    m.save(path)
    assert json.loads(path.read_text())["actions"]["jump"] == ["key:J", "pad:a"]
    other = InputMap(Input())
    other.load(path)
    assert other.to_data() == m.to_data()
    assert other.bindings("jump") == ["key:J", "pad:a"]


def test_bad_bindings_and_unknown_actions_are_refused_and_change_nothing() -> None:
    inp, m = _map()
    before = m.to_data()
    with pytest.raises(UnknownActionError, match="did you mean 'jump'"):
        m.pressed("jmup")
    with pytest.raises(ValidationError, match="unknown key 'SPAEC'.*SPACE"):
        m.bind("fire", "key:SPACE", "key:SPAEC")
    with pytest.raises(ValidationError, match="unknown key code 99999"):
        m.bind("fire", 99999)
    with pytest.raises(ValidationError, match="unknown gamepad button 'z'"):
        m.bind("fire", "pad:z")
    with pytest.raises(ValidationError, match="dead_zone"):
        m.bind_axis("turn", stick="pad:rightx", dead_zone=1.5)
    with pytest.raises(ValidationError, match="not a gamepad axis"):
        m.bind_axis("turn", stick="pad:a")
    with pytest.raises(UnknownActionError):
        m.bind_vector("aim", "move_x", "nope")
    with pytest.raises(ValidationError):
        m.load_data({"actions": {"jump": ["key:NOPE"]}})
    with pytest.raises(ValidationError, match="malformed"):
        m.load_data({"actions": {"jump": ["key:A"]}, "vectors": {"v": 3}})
    assert m.to_data() == before
    with pytest.raises(ValidationError, match="not in"):
        inp.connect_gamepad().move("leftx", float("nan"))
    with pytest.raises(ValidationError, match="unknown gamepad axis"):
        inp.pad_axis_value("leftz")


# -- gamepads ----------------------------------------------------------------------------------
def test_hot_plug_several_pads_and_rumble() -> None:
    inp = Input()
    rumbles: list[tuple[float, float, float]] = []
    p0 = inp.connect_gamepad("one", rumble=lambda *a: rumbles.append(a))
    p1 = inp.connect_gamepad("two")
    assert (p0.index, p1.index) == (0, 1)
    p1.press("start")
    assert inp.pad_held("start", pad=1) and not inp.pad_held("start", pad=0)
    assert inp.pad_held("start")
    inp.disconnect_gamepad(1)
    assert not inp.pad_held("start") and inp.pad_released("start", pad=1)
    with pytest.raises(ValidationError, match="not connected"):
        p1.press("a")
    p2 = inp.connect_gamepad("three")
    assert p2.index == 1  # the freed slot is reused
    p0.rumble(0.5, 1.0, 0.2)
    assert rumbles == [(0.5, 1.0, 0.2)] and p0.last_rumble == (0.5, 1.0, 0.2)
    with pytest.raises(ValidationError):
        p0.rumble(2.0)
    kinds = [(e.kind, e.pad) for e in inp.events if isinstance(e, GamepadEvent)]
    assert kinds[:3] == [("connect", 0), ("connect", 1), ("down", 1)]


def test_gamepad_hooks_reach_behaviours() -> None:
    got: list[tuple[str, int, str]] = []

    class Probe(Script):
        def on_gamepad_down(self, event: GamepadEvent) -> None:
            got.append((event.kind, event.pad, event.button))

    app = App(lambda w: w.spawn(Behaviour(Probe())), headless=True)
    app.input.connect_gamepad().press("x")
    app.step()
    assert got == [("down", 0, "x")]


class FakeController:
    """pyglet's Controller interface, as far as the bridge uses it."""

    def __init__(self, name: str) -> None:
        self.name = name
        self.handlers: dict[str, Any] = {}
        self.rumbled: list[tuple[str, float, float]] = []
        self.opened = False

    def open(self) -> None:
        self.opened = True

    def push_handlers(self, **handlers: Any) -> None:
        self.handlers.update(handlers)

    def remove_handlers(self, **handlers: Any) -> None:
        self.handlers.clear()

    def rumble_play_weak(self, strength: float, duration: float) -> None:
        self.rumbled.append(("weak", strength, duration))

    def rumble_play_strong(self, strength: float, duration: float) -> None:
        self.rumbled.append(("strong", strength, duration))

    def fire(self, event: str, *args: Any) -> None:
        self.handlers[event](self, *args)


def test_pyglet_bridge_turns_controller_events_into_pad_input() -> None:
    from kge.render.gamepads import GamepadBridge

    inp = Input()
    bridge = GamepadBridge(inp)
    a, b = FakeController("pad A"), FakeController("pad B")
    bridge.connect(a)
    bridge.connect(b)
    assert a.opened and sorted(inp.gamepads) == [0, 1]
    b.fire("on_button_press", "a")
    assert inp.pad_pressed("a", pad=1) and not inp.pad_held("a", pad=0)
    a.fire("on_stick_motion", "leftstick", (0.5, -0.25))
    assert inp.gamepads[0].axes["leftx"] == 0.5 and inp.gamepads[0].axes["lefty"] == -0.25
    a.fire("on_trigger_motion", "righttrigger", 0.75)
    assert inp.pad_axis_value("righttrigger", pad=0) == 0.75
    a.fire("on_dpad_motion", (0.0, 1.0))
    assert inp.pad_pressed("dpup", pad=0)
    a.fire("on_dpad_motion", (0.0, 0.0))
    assert inp.pad_released("dpup", pad=0) and not inp.pad_held("dpup")
    a.fire("on_stick_motion", "rightstick", (float("nan"), 2.0))
    assert inp.gamepads[0].axes["rightx"] == 0.0 and inp.gamepads[0].axes["righty"] == 1.0
    inp.gamepads[0].rumble(0.3, 0.0, 0.5)
    assert a.rumbled == [("weak", 0.3, 0.5)]
    b.fire("on_button_release", "a")
    bridge.disconnect(b)
    assert sorted(inp.gamepads) == [0] and not b.handlers
