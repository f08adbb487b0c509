"""Touch points and gestures from injected touch sequences: tap, double tap, drag and
two-finger pan, pinch, rotate; as polled state, world events and actions; mouse
emulation; edges per fixed step; bad input refused at the call."""

from __future__ import annotations

import math

import pytest

from kge import (
    ActionPressed,
    App,
    Behaviour,
    DragGesture,
    InputMap,
    Mouse,
    PinchGesture,
    RotateGesture,
    Script,
    TapGesture,
    TouchPoint,
    Transform,
    World,
)
from kge.errors import KgeError, ValidationError
from kge.input import Input


def _events(inp: Input, kind: type) -> list:
    return [e for e in inp.touch.events if isinstance(e, kind)]


def _frame(inp: Input, dt: float = 1 / 60) -> None:
    inp.end_frame()
    inp.touch.advance(dt)


# -- touch points -----------------------------------------------------------------------------
def test_touch_points_carry_id_phase_pixels_and_world_metres() -> None:
    inp = Input(screen_to_world=lambda p: (p[0] / 50.0, p[1] / 50.0))
    inp.touch_down(7, (100, 50))
    [p] = inp.touches()
    assert (p.id, p.phase, p.screen, p.world, p.start) == (
        7,
        "began",
        (100, 50),
        (2.0, 1.0),
        (100, 50),
    )
    _frame(inp)
    assert inp.touches()[0].phase == "moved"  # down since an earlier frame
    inp.touch_move(7, (150, 50))
    assert inp.touches()[0].world == (3.0, 1.0)
    inp.touch_down(2, (10, 10))
    assert [t.id for t in inp.touches()] == [2, 7]
    _frame(inp)
    inp.touch_up(7)
    ended = [t for t in inp.touches() if t.id == 7]
    assert ended[0].phase == "ended" and not ended[0].down() and ended[0].screen == (150, 50)
    phases = [(e.id, e.phase) for e in _events(inp, TouchPoint)]
    assert phases == [(7, "ended")]
    _frame(inp)
    assert [t.id for t in inp.touches()] == [2]


def test_a_muted_input_shows_no_touches_and_no_gestures() -> None:
    inp = Input()
    inp.touch_down(0, (0, 0))
    inp.touch_up(0)
    with inp.muted():
        assert inp.touches() == [] and not inp.gesture_pressed("tap")
    assert inp.gesture_pressed("tap")


# -- taps -------------------------------------------------------------------------------------
def test_a_quick_still_touch_is_a_tap_pressed_and_released_never_held() -> None:
    inp = Input()
    inp.touch_down(0, (100, 100))
    _frame(inp, 0.1)
    inp.touch_up(0, (104, 103))  # within the slop
    assert inp.gesture_pressed("tap") and inp.gesture_released("tap")
    assert not inp.gesture_held("tap") and not inp.gesture_pressed("double_tap")
    assert _events(inp, TapGesture) == [TapGesture((104.0, 103.0), (104.0, 103.0), 1)]
    _frame(inp)
    assert not inp.gesture_pressed("tap")


def test_a_long_press_a_moved_finger_or_two_fingers_are_not_taps() -> None:
    inp = Input()
    inp.touch_down(0, (100, 100))
    _frame(inp, 0.35)  # longer than TAP_TIME
    inp.touch_up(0)
    assert not inp.gesture_pressed("tap")
    _frame(inp)
    inp.touch_down(0, (100, 100))
    inp.touch_move(0, (115, 100))  # beyond TAP_SLOP, even if it comes back
    inp.touch_move(0, (100, 100))
    inp.touch_up(0)
    assert not inp.gesture_pressed("tap")
    _frame(inp)
    inp.touch_down(0, (100, 100))
    inp.touch_down(1, (200, 100))
    inp.touch_up(1)
    inp.touch_up(0)
    assert not inp.gesture_pressed("tap") and _events(inp, TapGesture) == []


def test_a_second_tap_soon_and_near_is_a_double_tap() -> None:
    inp = Input()
    taps = []
    for gap, at in (
        (0.0, (50, 50)),
        (0.2, (60, 55)),
        (0.2, (60, 55)),
        (0.5, (60, 55)),
        (0.1, (200, 55)),
    ):
        _frame(inp, gap)
        inp.touch_down(0, at)
        inp.touch_up(0)
        taps.append((_events(inp, TapGesture)[0].taps, inp.gesture_pressed("double_tap")))
    # second: double; third: triple (not another double); after 0.5 s: single; far: single
    assert taps == [(1, False), (2, True), (3, False), (1, False), (1, False)]


def test_the_tap_thresholds_are_settable() -> None:
    inp = Input()
    inp.touch.tap_time = 1.0
    inp.touch_down(0, (0, 0))
    _frame(inp, 0.8)
    inp.touch_up(0)
    assert inp.gesture_pressed("tap")


# -- drag and pan -----------------------------------------------------------------------------
def test_a_drag_begins_past_the_slop_and_sums_its_deltas_per_frame() -> None:
    inp = Input(screen_to_world=lambda p: (p[0] / 50.0, p[1] / 50.0))
    inp.touch_down(0, (100, 100))
    inp.touch_move(0, (105, 100))
    assert not inp.gesture_held("drag") and inp.drag_delta() == (0.0, 0.0)
    inp.touch_move(0, (120, 100))
    assert inp.gesture_pressed("drag") and inp.gesture_held("drag")
    inp.touch_move(0, (130, 90))
    assert inp.drag_delta() == (30.0, -10.0)  # from where the finger came down
    assert inp.drag_delta(world=True) == pytest.approx((0.6, -0.2))
    assert [e.phase for e in _events(inp, DragGesture)] == ["began", "moved"]
    _frame(inp)
    assert inp.drag_delta() == (0.0, 0.0) and inp.gesture_held("drag")
    inp.touch_up(0, (140, 90))
    assert [(e.phase, e.delta) for e in _events(inp, DragGesture)] == [
        ("moved", (10.0, 0.0)),
        ("ended", (0.0, 0.0)),
    ]
    assert inp.gesture_released("drag") and not inp.gesture_held("drag")
    assert not inp.gesture_pressed("tap")


def test_two_fingers_moving_together_pan_without_pinch_or_rotate() -> None:
    inp = Input()
    inp.touch_down(0, (100, 100))
    inp.touch_down(1, (200, 100))
    for step in range(1, 4):
        inp.touch_move(0, (100, 100 + 10 * step))
        inp.touch_move(1, (200, 100 + 10 * step))
    drags = _events(inp, DragGesture)
    assert drags and all(d.fingers == 2 for d in drags)
    assert inp.drag_delta() == (0.0, 30.0)
    assert not inp.gesture_held("pinch") and not inp.gesture_held("rotate")
    assert inp.pinch_scale() == 1.0 and inp.rotation_delta() == 0.0


def test_a_second_finger_ends_a_one_finger_drag_so_the_centre_never_jumps() -> None:
    inp = Input()
    inp.touch_down(0, (100, 100))
    inp.touch_move(0, (150, 100))
    inp.touch_down(1, (300, 300))  # the centre is now far away: no jump in the drag
    assert [e.phase for e in _events(inp, DragGesture)] == ["began", "ended"]
    assert inp.drag_delta() == (50.0, 0.0)


# -- pinch and rotate -------------------------------------------------------------------------
def test_a_pinch_reports_its_scale_and_per_frame_factor() -> None:
    inp = Input()
    inp.touch_down(0, (100, 100))
    inp.touch_down(1, (200, 100))
    inp.touch_move(1, (205, 100))  # within PINCH_SLOP
    assert not inp.gesture_held("pinch") and inp.pinch_scale() == 1.0
    inp.touch_move(1, (250, 100))
    assert inp.gesture_pressed("pinch") and inp.pinch_scale() == pytest.approx(1.5)
    _frame(inp)
    inp.touch_move(1, (300, 100))
    assert inp.pinch_scale() == pytest.approx(200 / 150)
    [ev] = _events(inp, PinchGesture)
    assert ev.phase == "moved" and ev.scale == pytest.approx(2.0) and ev.center == (200.0, 100.0)
    _frame(inp)
    inp.touch_move(0, (200, 100))  # closing back to the start's distance
    assert inp.pinch_scale() == pytest.approx(0.5)
    _frame(inp)
    inp.touch_move(0, (150, 100))  # two moves in one frame: their factors multiply
    inp.touch_move(0, (100, 100))
    assert inp.pinch_scale() == pytest.approx(2.0)
    inp.touch_move(0, (200, 100))
    inp.touch_up(0)
    [*_, end] = _events(inp, PinchGesture)
    assert end.phase == "ended" and end.scale == pytest.approx(1.0)
    assert inp.gesture_released("pinch") and not inp.gesture_held("pinch")


def test_a_two_finger_turn_reports_counter_clockwise_radians_wrapping_at_pi() -> None:
    inp = Input()
    inp.touch_down(0, (0, 0))
    inp.touch_down(1, (100, 0))
    inp.touch_move(1, (0, 100))  # a quarter turn counter-clockwise
    assert inp.gesture_pressed("rotate")
    assert inp.rotation_delta() == pytest.approx(math.pi / 2)
    assert not inp.gesture_held("pinch")  # same distance: no pinch
    _frame(inp)
    for deg in range(100, 271, 10):  # on through pi (180 deg) to 270 deg
        a = math.radians(deg)
        inp.touch_move(1, (100 * math.cos(a), 100 * math.sin(a)))
    assert inp.rotation_delta() == pytest.approx(math.radians(180))
    [*_, last] = _events(inp, RotateGesture)
    assert last.angle == pytest.approx(math.radians(270))  # whole turns count, no wrap
    _frame(inp)
    inp.touch_move(1, (-100, 0))  # back clockwise to 180 deg
    assert inp.rotation_delta() == pytest.approx(-math.pi / 2)
    inp.touch_up(1)
    [*_, end] = _events(inp, RotateGesture)
    assert end.phase == "ended" and end.angle == pytest.approx(math.pi)


def test_two_fingers_on_one_pixel_never_make_nan() -> None:
    inp = Input()
    inp.touch_down(0, (50, 50))
    inp.touch_down(1, (50, 50))
    inp.touch_move(1, (50, 80))
    inp.touch_move(0, (50, 80))
    for ev in _events(inp, PinchGesture) + _events(inp, RotateGesture):
        assert math.isfinite(ev.scale if isinstance(ev, PinchGesture) else ev.angle)
        assert math.isfinite(ev.delta)
    assert math.isfinite(inp.pinch_scale()) and math.isfinite(inp.rotation_delta())


# -- through the App: events, actions, fixed steps ---------------------------------------------
class _Recorder(Script):
    def on_start(self) -> None:
        self.seen: list[object] = []

    def on_update(self, dt: float) -> None:
        for kind in (TapGesture, DragGesture, PinchGesture, ActionPressed):
            self.seen += self.world.events(kind)


def test_gestures_reach_the_world_as_events_and_bound_actions() -> None:
    rec = _Recorder()
    app = App(lambda world: world.spawn(Transform(), Behaviour(rec)), headless=True)
    app.actions.bind("zoom_in", "touch:double_tap")
    app.actions.bind("zoom", "touch:pinch")
    app.step()
    for _ in range(2):
        app.input.touch_down(0, (300, 200))
        app.step()
        app.input.touch_up(0)
        app.step()
    taps = [e for e in rec.seen if isinstance(e, TapGesture)]
    assert [t.taps for t in taps] == [1, 2]
    assert [e.action for e in rec.seen if isinstance(e, ActionPressed)] == ["zoom_in"]
    app.input.touch_down(0, (100, 100))
    app.input.touch_down(1, (200, 100))
    app.input.touch_move(1, (300, 100))
    assert app.actions.pressed("zoom")
    app.step()
    assert [e.phase for e in rec.seen if isinstance(e, PinchGesture)] == ["began"]
    assert app.actions.held("zoom")
    assert app.actions.to_data()["actions"]["zoom"] == ["touch:pinch"]


def test_fixed_step_code_sees_a_tap_once_even_with_two_steps_in_a_frame() -> None:
    seen: list[int] = []

    class Fixed(Script):
        def on_fixed_update(self, dt: float) -> None:
            if self.world.resource(Input).gesture_pressed("tap"):
                seen.append(self.world.resource(Input).touch.fingers.__len__())

    app = App(lambda world: world.spawn(Transform(), Behaviour(Fixed())), headless=True)
    app.step()
    app.input.touch_down(0, (10, 10))
    app.input.touch_up(0)
    app.advance(2 / 60 + 1e-6)  # two fixed steps in this frame
    app.advance(1 / 60)
    assert seen == [0]


def test_a_scene_change_lifts_every_finger() -> None:
    app = App(lambda world: None, headless=True)
    app.step()
    app.input.touch_down(0, (10, 10))
    app.replace_scene(lambda world: None)
    app.step()
    assert app.input.touches() == []


# -- mouse emulation --------------------------------------------------------------------------
def test_the_mouse_is_touch_zero_only_when_the_game_opts_in() -> None:
    inp = Input()
    inp.click(Mouse.LEFT, at=(40, 40))
    assert inp.touches() == [] and not inp.gesture_pressed("tap")
    inp.end_frame()
    inp.emulate_touch_from_mouse = True
    inp.click(Mouse.RIGHT, at=(40, 40))
    assert inp.touches() == []  # only the left button touches
    inp.click(Mouse.LEFT, at=(40, 40))
    assert inp.gesture_pressed("tap") and [t.id for t in inp.touches()] == [0]
    inp.end_frame()
    inp.move_mouse(200, 200)  # hovering is not touching
    assert inp.touches() == []
    inp.mouse_down(Mouse.LEFT)
    inp.move_mouse(260, 200)
    assert inp.gesture_held("drag") and inp.drag_delta() == (60.0, 0.0)
    inp.mouse_up(Mouse.LEFT)
    assert inp.gesture_released("drag")


# -- bad input --------------------------------------------------------------------------------
@pytest.mark.parametrize("bad_id", [-1, True, 1.5, "0", None])
def test_a_bad_touch_id_is_refused_at_the_call(bad_id: object) -> None:
    inp = Input()
    with pytest.raises(ValidationError, match="touch id"):
        inp.touch_down(bad_id, (0, 0))  # type: ignore[arg-type]
    assert inp.touch.fingers == {} and inp.touch.events == []


@pytest.mark.parametrize("bad_at", [(math.nan, 0), (0, math.inf), (1, 2, 3), "ab", 5])
def test_a_bad_position_is_refused_and_changes_nothing(bad_at: object) -> None:
    inp = Input()
    inp.touch_down(0, (10, 10))
    with pytest.raises(KgeError, match="Input.touch_move"):
        inp.touch_move(0, bad_at)  # type: ignore[arg-type]
    with pytest.raises(KgeError, match="Input.touch_down"):
        inp.touch_down(1, bad_at)  # type: ignore[arg-type]
    assert [(t.id, t.screen) for t in inp.touches()] == [(0, (10, 10))]


def test_touch_sequences_out_of_order_are_refused() -> None:
    inp = Input()
    inp.touch_down(0, (10, 10))
    with pytest.raises(ValidationError, match="touch 0 is already down"):
        inp.touch_down(0, (20, 20))
    with pytest.raises(ValidationError, match=r"touch 3 is not down \(down: 0\)"):
        inp.touch_move(3, (20, 20))
    with pytest.raises(ValidationError, match="touch 3 is not down"):
        inp.touch_up(3)
    assert len(inp.touch.events) == 1


def test_unknown_gestures_are_refused_in_queries_and_bindings() -> None:
    inp = Input()
    with pytest.raises(ValidationError, match="unknown gesture 'swipe'; gestures are tap"):
        inp.gesture_pressed("swipe")
    actions = InputMap(inp)
    with pytest.raises(ValidationError, match="unknown gesture 'swipe'"):
        actions.bind("x", "touch:swipe")
    assert actions.actions == []


def test_a_world_without_an_app_can_read_touch_events() -> None:
    world = World()
    inp = Input()
    inp.touch_down(0, (0, 0))
    inp.touch_up(0)
    inp.touch.deliver(world.emit)
    assert [type(e).__name__ for e in world.events(TouchPoint)] == ["TouchPoint", "TouchPoint"]
    assert len(world.events(TapGesture)) == 1
