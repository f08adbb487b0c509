"""Radio groups, tabs, spin boxes, colour pickers and long dropdowns: mouse, keyboard, gamepad."""

from __future__ import annotations

import pytest

from kge import App, Key, Mod, World
from kge.components.ui import (
    Button,
    ColorPicker,
    Dropdown,
    RadioGroup,
    SpinBox,
    Tabs,
    UINode,
)
from kge.errors import ComponentTypeError, ValidationError
from kge.testing import box_of, click, find, focus, press, type_text
from kge.ui import geometry as geo
from kge.ui.events import ValueChanged
from kge.ui.state import UIState

SIZE = (640, 480)


def form(world: World) -> None:
    col = world.spawn(UINode(anchor="top_left", offset=(10, -10), width=300, layout="column",
                             padding=10, spacing=8, align="stretch"))  # fmt: skip
    world.spawn(UINode(parent=col), RadioGroup(["Low", "Medium", "High"], 1))
    world.spawn(UINode(parent=col), SpinBox(2.0, min=0, max=5, step=0.5, suffix=" m"))
    tabs = world.spawn(UINode(parent=col, height=90), Tabs(["Audio", "Video", "Keys"]))
    for name in ("Mute", "Fullscreen", "Rebind"):
        world.spawn(UINode(parent=tabs, height=30), Button(name))
    world.spawn(UINode(parent=col, height=120), ColorPicker((255, 0, 0, 255)))


def _app() -> App:
    app = App(form, headless=True, size=SIZE)
    app.step()
    return app


def _changes(app: App) -> list[ValueChanged]:
    return app.world.events(ValueChanged)


def test_radio_group_by_click_and_arrows_moving_on_past_its_ends() -> None:
    app = _app()
    radio = click(app, "High")
    w = app.world.get(radio, RadioGroup)
    assert w.selected == 2 and w.value == "High"
    assert _changes(app) == [ValueChanged(radio, 2, 1)]
    press(app, Key.UP)
    assert w.selected == 1
    press(app, Key.UP)
    press(app, Key.UP)  # past the first option: the focus moves on (wraps to the last widget)
    assert w.selected == 0 and app.world.resource(UIState).focused != radio
    focus(app, radio)
    pad = app.input.connect_gamepad()
    pad.press("a")  # a gamepad's A steps through the options
    app.step()
    assert w.selected == 1


def test_tabs_show_only_the_selected_page_and_switch_by_click_keys_and_shoulders() -> None:
    app = _app()
    assert find(app, "Mute") and not _shown(app, "Fullscreen")
    tabs = click(app, "Video")
    w = app.world.get(tabs, Tabs)
    assert w.selected == 1 and _shown(app, "Fullscreen") and not _shown(app, "Mute")
    assert _changes(app) == [ValueChanged(tabs, 1, 0)]
    press(app, Key.RIGHT)  # the bar has the focus: arrows switch
    assert w.selected == 2
    focus(app, "Rebind")  # focus inside a page: Ctrl+Tab / Ctrl+Shift+Tab switch
    press(app, Key.TAB, Mod.CTRL)
    assert w.selected == 0
    pad = app.input.connect_gamepad()
    pad.press("leftshoulder")
    app.step()
    assert w.selected == 2
    box = box_of(app, "Rebind")
    bar = app.world.resource(UIState).layout.tab_bar[tabs]
    assert box.top <= bar.y + 1e-6  # the page sits under the bar


def _shown(app: App, text: str) -> bool:
    from kge.ui.current import current_layout

    lay = current_layout(app.world)
    return any(getattr(lay.widget.get(e), "text", None) == text for e in lay.order)


def test_spin_box_buttons_keys_wheel_drag_and_typing() -> None:
    app = _app()
    world = app.world
    spin = next(e for e, _ in world.query(SpinBox))
    w = world.get(spin, SpinBox)
    minus, field, plus = geo.spin_parts(box_of(app, spin))
    app.input.click(at=plus.center)
    app.step()
    assert w.value == 2.5 and _changes(app) == [ValueChanged(spin, 2.5, 2.0)]
    app.input.click(at=minus.center)
    app.step()
    assert w.value == 2.0
    press(app, Key.RIGHT)
    press(app, Key.RIGHT)
    assert w.value == 3.0
    app.input.move_mouse(*field.center)
    app.input.scroll_by(0, -1)  # focused and under the pointer: the wheel steps it
    app.step()
    assert w.value == 2.5
    # drag sideways on the number: a step per 4 px (drag_speed 0), clamped at max
    app.input.mouse_down(at=field.center)
    app.step()
    app.input.move_mouse(field.center[0] + 20, field.center[1])
    app.step()
    assert w.value == 5.0  # 2.5 + 20 px * 0.125 = 5.0
    app.input.move_mouse(field.center[0] + 400, field.center[1])
    app.step()
    app.input.mouse_up()
    app.step()
    assert w.value == 5.0 and spin not in app.world.resource(UIState).spin  # a drag: no typing
    click(app, spin)  # a click without a drag: type a value
    assert spin in app.world.resource(UIState).spin
    press(app, Key.A, Mod.CTRL)
    type_text(app, "1.3")
    press(app, Key.ENTER)
    assert w.value == 1.5  # to the nearest step
    click(app, spin)
    type_text(app, "abc")  # only number characters are typed
    assert app.world.resource(UIState).spin[spin].text == "1.5"
    press(app, Key.ESCAPE)
    assert w.value == 1.5 and spin not in app.world.resource(UIState).spin


def test_spin_box_refused_text_keeps_the_value_and_bounds_may_be_open() -> None:
    app = _app()
    spin = next(e for e, _ in app.world.query(SpinBox))
    click(app, spin)
    press(app, Key.A, Mod.CTRL)
    type_text(app, "--")
    press(app, Key.ENTER)
    assert app.world.get(spin, SpinBox).value == 2.0
    open_ended = SpinBox(1e9)  # an inspector's field: no bounds
    assert open_ended.min == -float("inf") and open_ended.text() == "1000000000"
    assert SpinBox(2.4, rounded=True).value == 2.0
    with pytest.raises(ValidationError, match="nan"):
        SpinBox(min=float("nan"))
    with pytest.raises(ValidationError, match="min"):
        SpinBox(min=3, max=1)


def test_colour_picker_by_mouse_and_by_keys() -> None:
    app = _app()
    world = app.world
    cp = next(e for e, _ in world.query(ColorPicker))
    w = world.get(cp, ColorPicker)
    parts = geo.picker_parts(box_of(app, cp), True)
    sv, hue, alpha = parts["sv"], parts["hue"], parts["alpha"]
    app.input.click(at=(sv.x + 1, sv.top - 1))  # left top: white
    app.step()
    assert all(c >= 250 for c in w.color[:3])
    app.input.click(at=(sv.right - 1, sv.y + 1))  # right bottom: black
    app.step()
    assert all(c <= 5 for c in w.color[:3])
    app.input.mouse_down(at=(sv.right - 1, sv.top - 1))  # full colour, then drag the hue
    app.step()
    app.input.mouse_up()
    app.step()
    app.input.click(at=(hue.center[0], hue.y + hue.h / 3))  # a third up the bar: green
    app.step()
    r, g, b, a = w.color
    assert g > 240 and r < 20 and b < 20 and a == 255
    app.input.click(at=(alpha.center[0], alpha.y + alpha.h / 2))
    app.step()
    assert w.color[3] == pytest.approx(128, abs=2)
    changes = _changes(app)
    assert changes and changes[-1].value == w.color
    # keys: Left/Right change the active part (hue first), Enter picks the next part
    focus(app, cp)
    press(app, Key.RIGHT)
    assert w.color[:3] != (0, 255, 0)
    press(app, Key.ENTER)  # saturation
    for _ in range(20):
        press(app, Key.LEFT)
    assert max(w.color[:3]) - min(w.color[:3]) <= 2  # no saturation left: a grey


def test_a_long_dropdown_scrolls_its_list_and_opens_upwards_near_the_bottom() -> None:
    options = [f"Level {i}" for i in range(40)]

    def scene(world: World) -> None:
        world.spawn(UINode(anchor="bottom", offset=(0, 20), width=200, height=30),
                    Dropdown(options, 0, max_rows=6))  # fmt: skip

    app = App(scene, headless=True, size=SIZE)
    app.step()
    d = next(e for e, _ in app.world.query(Dropdown))
    w = app.world.get(d, Dropdown)
    click(app, d)
    assert w.open
    box = box_of(app, d)
    lst, rows, up = geo.dropdown_list(box, len(options), w.max_rows, SIZE[1])
    assert up and rows == 6 and lst.y == box.top  # no room below: it opens upwards
    assert _shown_options(app, d) == options[:6]
    app.input.move_mouse(*lst.center)
    app.input.scroll_by(0, -3)
    app.step()
    assert _shown_options(app, d) == options[3:9]
    for _ in range(10):
        press(app, Key.DOWN)
    assert w.selected == 10 and _shown_options(app, d) == options[5:11]  # kept in view
    click(app, "Level 7")
    assert w.selected == 7 and not w.open


def _shown_options(app: App, d: int) -> list[str]:
    st = app.world.resource(UIState)
    w = app.world.get(d, Dropdown)
    rows = geo.dropdown_rows(st.layout.boxes[d], len(w.options), w.max_rows, SIZE[1],
                             st.dropdown_first.get(d, 0))  # fmt: skip
    return [w.options[i] for i, _ in rows]


def test_pickers_refuse_out_of_range_selections_and_follow_shrinking_items() -> None:
    with pytest.raises(ValidationError, match="not an index of its 3 options"):
        RadioGroup(["a", "b", "c"], 3)
    t = Tabs(["a", "b"])
    with pytest.raises(ValidationError, match="selected -1"):
        t.selected = -1
    r = RadioGroup(["a", "b", "c"], 2)
    r.options.pop()
    assert r.selected == 1
    r.options.clear()
    assert r.selected == -1 and r.value is None
    with pytest.raises(ComponentTypeError, match="must be a str"):
        r.options.append(7)  # type: ignore[arg-type]
    assert r.options == []
