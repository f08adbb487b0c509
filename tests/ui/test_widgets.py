"""UI widgets headless: clicks, focus, typing, sliders, dropdowns, lists, events, hooks."""

from __future__ import annotations

from typing import Any

from kge import App, Behaviour, Input, Key, Mod, Mouse, Script, World
from kge.components.ui import (
    Button,
    Dropdown,
    Panel,
    ScrollList,
    Slider,
    TextInput,
    Toggle,
    UINode,
)
from kge.systems.ui import focus
from kge.ui import ButtonClicked, TextSubmitted, ValueChanged
from kge.ui.interact import UIState

SIZE = (400, 300)


class Clicks(Script):
    def __init__(self) -> None:
        self.clicks: list[Any] = []
        self.changes: list[Any] = []

    def on_click(self, event: ButtonClicked) -> None:
        self.clicks.append(event)

    def on_value_changed(self, event: ValueChanged) -> None:
        self.changes.append(event.value)


class Game(Script):
    """The game under the UI: counts the clicks it gets."""

    def __init__(self) -> None:
        self.downs = 0
        self.pressed = 0

    def on_mouse_down(self, event: Any) -> None:
        self.downs += 1

    def on_update(self, dt: float) -> None:
        self.pressed += self.world.resource(Input).mouse_pressed(Mouse.LEFT)


def menu(world: World, hooks: Clicks, game: Game) -> None:
    world.spawn(Behaviour(game))
    col = world.spawn(
        UINode(width=200, layout="column", padding=10, spacing=10, align="stretch"), Panel()
    )
    world.spawn(UINode(parent=col, height=40), Button("Play"), Behaviour(hooks))
    world.spawn(UINode(parent=col, height=40), Button("Off", disabled=True))
    world.spawn(UINode(parent=col, height=30), Toggle(False, "Sound"))
    world.spawn(UINode(parent=col, height=24), Slider(0, 10, 5, step=1))
    world.spawn(UINode(parent=col), TextInput("", max_length=8))


def make() -> tuple[App, Clicks, Game]:
    hooks, game = Clicks(), Game()
    app = App(menu, headless=True, size=SIZE, hooks=hooks, game=game)
    app.step()
    return app, hooks, game


def entity_of(app: App, kind: type) -> int:
    return next(e for e, _ in app.world.query(kind))


def focused(st: UIState) -> int:
    assert st.focused is not None
    return st.focused


def centre(app: App, e: int) -> tuple[float, float]:
    return app.world.resource(UIState).layout.boxes[e].center


def test_click_on_a_button_emits_its_event_and_hook_and_the_game_never_sees_it() -> None:
    app, hooks, game = make()
    play = next(e for e, (b,) in app.world.query(Button) if b.text == "Play")
    app.input.click(at=centre(app, play))
    app.step()
    assert app.world.events(ButtonClicked) == [ButtonClicked(play, "Play")]
    assert [c.entity for c in hooks.clicks] == [play]
    assert game.downs == 0 and game.pressed == 0
    app.step()
    assert app.world.events(ButtonClicked) == []  # per frame
    app.input.click(at=(5, 5))  # outside the UI: the game gets it
    app.step()
    assert game.downs == 1 and game.pressed == 1 and len(hooks.clicks) == 1


def test_press_then_release_elsewhere_is_not_a_click_and_disabled_buttons_do_nothing() -> None:
    app, hooks, _ = make()
    play = next(e for e, (b,) in app.world.query(Button) if b.text == "Play")
    off = next(e for e, (b,) in app.world.query(Button) if b.text == "Off")
    app.input.mouse_down(at=centre(app, play))
    app.step()
    assert app.world.resource(UIState).state_of(play) == "pressed"
    app.input.mouse_up(at=(5, 5))
    app.step()
    app.input.click(at=centre(app, off))
    app.step()
    assert hooks.clicks == [] and app.world.resource(UIState).state_of(off) == "disabled"
    app.input.move_mouse(*centre(app, play))
    app.step()
    assert app.world.resource(UIState).state_of(play) == "hover"


def test_keyboard_focus_navigation_skips_disabled_widgets_and_enter_clicks() -> None:
    app, hooks, _ = make()
    st = app.world.resource(UIState)
    order = []
    for _ in range(5):
        app.input.press(Key.TAB)
        app.step()
        app.input.release(Key.TAB)
        w = st.layout.widget[focused(st)]
        order.append(getattr(w, "text", type(w).__name__) or type(w).__name__)
    # "Off" is disabled: skipped; the fifth Tab wraps around
    assert order == ["Play", "Sound", "Slider", "TextInput", "Play"]
    assert st.focused == next(e for e, (b,) in app.world.query(Button) if b.text == "Play")
    app.input.press(Key.TAB, Mod.SHIFT)
    app.step()
    app.input.release(Key.TAB)
    assert app.world.try_get(focused(st), TextInput) is not None
    app.input.press(Key.UP)
    app.step()
    app.input.release(Key.UP)
    assert app.world.try_get(focused(st), Slider) is not None
    app.input.press(Key.RIGHT)
    app.step()
    app.input.release(Key.RIGHT)
    assert app.world.get(focused(st), Slider).value == 6
    focus(app.world, next(e for e, (b,) in app.world.query(Button) if b.text == "Play"))
    app.input.press(Key.ENTER)
    app.step()
    assert len(hooks.clicks) == 1


def test_gamepad_focus_navigation_and_activation() -> None:
    app, hooks, _ = make()
    pad = app.input.connect_gamepad()
    st = app.world.resource(UIState)

    def tap(button: str) -> None:
        pad.press(button)
        app.step()
        pad.release(button)
        app.step()

    tap("dpdown")  # nothing focused: focus the first widget
    play = focused(st)
    assert app.world.get(play, Button).text == "Play"
    tap("dpdown")
    toggle = focused(st)
    assert app.world.try_get(toggle, Toggle) is not None
    tap("a")
    assert app.world.get(toggle, Toggle).value is True
    tap("dpdown")
    tap("dpleft")
    assert app.world.get(focused(st), Slider).value == 4
    tap("dpup")
    tap("dpup")
    tap("a")
    assert [c.entity for c in hooks.clicks] == [play]


def test_typing_editing_selection_paste_max_length_and_submit() -> None:
    app, _, game = make()
    field = entity_of(app, TextInput)
    ti = app.world.get(field, TextInput)
    app.input.click(at=centre(app, field))
    app.step()
    assert app.world.resource(UIState).focused == field
    app.input.press(Key.H)
    app.input.type_text("Hello")
    app.step()
    app.input.release(Key.H)
    assert ti.text == "Hello" and ti.caret == 5
    assert not app.input.pressed(Key.H)  # the field took the key from the game
    for k in (Key.BACKSPACE, Key.LEFT, Key.LEFT):
        app.input.press(k)
        app.step()
        app.input.release(k)
    assert ti.text == "Hell" and ti.caret == 2
    app.input.press(Key.END, Mod.SHIFT)  # select "ll"
    app.step()
    app.input.release(Key.END)
    assert ti.selection == (2, 4)
    app.input.press(Key.C, Mod.CTRL)
    app.step()
    app.input.release(Key.C)
    assert app.world.resource(UIState).clipboard == "ll"
    app.input.type_text("y")  # replaces the selection
    app.step()
    assert ti.text == "Hey"
    app.world.resource(UIState).clipboard = "-world!!"
    app.input.press(Key.V, Mod.CTRL)
    app.step()
    app.input.release(Key.V)
    assert ti.text == "Hey-worl"  # cut to max_length 8
    app.input.type_text("more")
    app.step()
    assert ti.text == "Hey-worl"
    app.input.press(Key.A, Mod.CTRL)
    app.step()
    app.input.release(Key.A)
    app.input.type_text("ok")
    app.input.press(Key.ENTER)
    app.step()
    assert app.world.events(TextSubmitted) == [TextSubmitted(field, "ok")]
    assert game.downs == 0


def test_slider_drag_toggle_click_and_value_events() -> None:
    app, _, _ = make()
    s = entity_of(app, Slider)
    box = app.world.resource(UIState).layout.boxes[s]
    app.input.mouse_down(at=(box.x + 1, box.center[1]))
    app.step()
    assert app.world.get(s, Slider).value == 0
    app.input.move_mouse(box.right - 1, box.center[1])
    app.step()
    assert app.world.get(s, Slider).value == 10
    app.input.move_mouse(box.center[0], box.center[1])
    app.step()
    assert app.world.get(s, Slider).value == 5
    assert app.world.events(ValueChanged) == [ValueChanged(s, 5.0, 10.0)]
    app.input.mouse_up()
    app.step()
    t = entity_of(app, Toggle)
    app.input.click(at=centre(app, t))
    app.step()
    assert app.world.get(t, Toggle).value is True
    assert app.world.events(ValueChanged) == [ValueChanged(t, True, False)]


def _lists(world: World) -> None:
    world.spawn(
        UINode(anchor="top", offset=(0, -10), width=150, height=30), Dropdown(["A", "B", "C"])
    )
    world.spawn(
        UINode(anchor="bottom", offset=(0, 10), width=150, height=100),
        ScrollList([f"row {i}" for i in range(20)], row_height=25),
    )


def test_dropdown_opens_picks_and_closes() -> None:
    app = App(_lists, headless=True, size=SIZE)
    app.step()
    d = entity_of(app, Dropdown)
    dd = app.world.get(d, Dropdown)
    app.input.click(at=centre(app, d))
    app.step()
    assert dd.open
    box = app.world.resource(UIState).layout.boxes[d]
    app.input.click(at=(box.center[0], box.y - 2.5 * box.h))  # third option
    app.step()
    assert not dd.open and dd.selected == 2 and dd.value == "C"
    assert app.world.events(ValueChanged) == [ValueChanged(d, 2, 0)]


def test_scroll_list_scrolls_with_the_wheel_and_selects_rows() -> None:
    app = App(_lists, headless=True, size=SIZE)
    app.step()
    e = entity_of(app, ScrollList)
    lst = app.world.get(e, ScrollList)
    box = app.world.resource(UIState).layout.boxes[e]
    app.input.move_mouse(*box.center)
    app.input.scroll_by(0, -2)  # wheel down: two rows
    app.step()
    assert lst.scroll == 50
    assert app.input.scroll == (0.0, 0.0)
    app.input.click(at=(box.center[0], box.top - 10))  # the first visible row is row 2
    app.step()
    assert lst.selected == 2
    app.input.scroll_by(0, -100)
    app.step()
    assert lst.scroll == 20 * 25 - 100  # never past the end


def test_value_and_text_hooks_run_on_the_widget_entity() -> None:
    seen: list[tuple[str, Any]] = []

    class Field(Script):
        def on_value_changed(self, event: ValueChanged) -> None:
            seen.append(("changed", event.value))

        def on_text_submitted(self, event: TextSubmitted) -> None:
            seen.append(("submitted", event.text))

    def scene(world: World) -> None:
        world.spawn(UINode(width=200), TextInput(max_length=10), Behaviour(Field()))

    app = App(scene, headless=True, size=SIZE)
    field = entity_of(app, TextInput)
    focus(app.world, field)
    app.input.type_text("ok")
    app.step()
    app.input.press(Key.ENTER)
    app.step()
    assert seen == [("changed", "ok"), ("submitted", "ok")]
