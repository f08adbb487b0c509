"""Modal dialogs and message boxes, tooltips, and drag and drop (mouse, keyboard, gamepad)."""

from __future__ import annotations

from typing import Any

from kge import App, Behaviour, Input, Key, Mod, Mouse, Script, World
from kge.components.ui import (
    Button,
    Dialog,
    Draggable,
    DropTarget,
    Label,
    Panel,
    Tooltip,
    UINode,
)
from kge.testing import box_of, click, drag, focus, press
from kge.ui.dialogs import confirm, message_box
from kge.ui.events import (
    ButtonClicked,
    DialogClosed,
    DragCancelled,
    DragStarted,
    Dropped,
)
from kge.ui.state import UIState

from .conftest import pixels

SIZE = (400, 300)


class Game(Script):
    def __init__(self) -> None:
        self.downs = 0
        self.closed: list[DialogClosed] = []

    def on_mouse_down(self, event: Any) -> None:
        self.downs += 1


def menu(world: World, game: Game) -> None:
    world.spawn(Behaviour(game))
    col = world.spawn(UINode(anchor="left", offset=(10, 0), width=120, layout="column",
                             spacing=6, align="stretch"))  # fmt: skip
    world.spawn(UINode(parent=col, height=30), Button("Quit"))
    world.spawn(UINode(parent=col, height=30), Button("Other"))


def test_a_confirm_dialog_is_modal_and_closes_with_its_buttons_result() -> None:
    game = Game()
    app = App(menu, headless=True, size=SIZE, game=game)
    app.step()
    dialog = confirm(app.world, "Quit the game?", ok="Quit now", title="Quit")
    app.step()
    st = app.world.resource(UIState)
    assert app.world.get(st.focused, Button).text == "Quit now"  # type: ignore[arg-type]
    other = box_of(app, "Other")
    app.input.click(at=other.center)  # behind the dialog: taken, reaches nothing
    app.step()
    assert app.world.events(ButtonClicked) == [] and game.downs == 0
    app.input.click(at=(5, 5))  # outside every widget: the game does not get it either
    app.step()
    assert game.downs == 0
    for _ in range(4):  # Tab stays inside the dialog
        press(app, Key.TAB)
        assert st.layout.dialog.get(st.focused) == dialog  # type: ignore[arg-type]
    click(app, "Cancel")
    assert app.world.events(DialogClosed) == [DialogClosed(dialog, 0, "Cancel")]
    app.step()
    assert not app.world.exists(dialog) and not any(
        b.text == "Cancel" for _, (b,) in app.world.query(Button))  # fmt: skip
    app.input.click(at=other.center)  # the menu works again
    app.step()
    assert app.world.events(ButtonClicked)[0].text == "Other"


def test_escape_or_gamepad_b_cancels_a_dialog_and_on_dialog_closed_runs() -> None:
    seen: list[DialogClosed] = []

    class Answer(Script):
        def on_dialog_closed(self, event: DialogClosed) -> None:
            seen.append(event)

    app = App(menu, headless=True, size=SIZE, game=Game())
    app.step()
    d = message_box(app.world, "Saved.", ("OK",))
    app.world.add(d, Behaviour(Answer()))
    app.step()
    press(app, Key.ESCAPE)
    assert seen == [DialogClosed(d, -1, "")]
    d2 = message_box(app.world, "Again", ("OK",))
    app.step()
    pad = app.input.connect_gamepad()
    pad.press("b")
    app.step()
    assert not app.world.exists(d2) or app.world.get(d2, Dialog) is None


def test_a_kept_dialog_hides_instead_of_going_and_non_modal_ones_let_clicks_through() -> None:
    app = App(menu, headless=True, size=SIZE, game=Game())
    app.step()
    d = app.world.spawn(UINode(anchor="top_right", width=150, layout="column", padding=8),
                        Dialog("Tools", modal=False, keep=True))  # fmt: skip
    from kge.components.ui import DialogButton

    app.world.spawn(UINode(parent=d, height=30), Button("Close"), DialogButton(3))
    app.step()
    click(app, "Other")  # not modal: the rest of the UI works
    assert app.world.events(ButtonClicked)[0].text == "Other"
    click(app, "Close")
    assert app.world.events(DialogClosed) == [DialogClosed(d, 3, "Close")]
    app.step()
    assert app.world.exists(d) and not app.world.get(d, UINode).visible


def tips(world: World) -> None:
    world.spawn(UINode(anchor="center", width=100, height=30), Button("Save"),
                Tooltip("Save the game (Ctrl+S)", delay=0.5))  # fmt: skip
    world.spawn(UINode(anchor="bottom", width=100, height=30), Button("Load"))


def test_a_tooltip_shows_after_its_delay_under_the_pointer_or_the_focus(make_app: Any) -> None:
    app = make_app(tips, size=SIZE, fixed_dt=0.1)
    app.step()
    st = app.world.resource(UIState)
    save = box_of(app, "Save")
    app.input.move_mouse(*save.center)
    app.step(4)  # 0.4 s
    assert not st.tip.shown
    app.step(2)
    assert st.tip.shown
    px = pixels(app)
    from kge.render.ui import OVERLAY, drawer_for

    drawn = drawer_for(app.world).owned.get(OVERLAY, set())
    assert (OVERLAY, "tiptext") in drawn and (px[..., :3].sum(-1) > 0).any()
    app.input.move_mouse(*box_of(app, "Load").center)  # moving away hides it
    app.step()
    assert not st.tip.shown
    pixels(app)
    assert (OVERLAY, "tiptext") not in drawer_for(app.world).owned.get(OVERLAY, set())
    app.input.move_mouse(1, 1)
    focus(app, "Save")  # keyboard users get it too
    app.step(6)
    assert st.tip.shown and st.tip.entity == next(
        e for e, (b,) in app.world.query(Button) if b.text == "Save")  # fmt: skip


class Drops(Script):
    def __init__(self) -> None:
        self.got: list[Dropped] = []

    def on_drop(self, event: Dropped) -> None:
        self.got.append(event)


def inventory(world: World, hooks: Drops) -> None:
    row = world.spawn(UINode(width=360, height=60, layout="row", spacing=10))
    world.spawn(UINode(parent=row, width=80, height=50), Button("Sword"),
                Draggable(payload="sword", kind="item"))  # fmt: skip
    world.spawn(UINode(parent=row, width=80, height=50), Panel(), Label("Bag"),
                DropTarget(accepts=("item",)), Behaviour(hooks))  # fmt: skip
    world.spawn(UINode(parent=row, width=80, height=50), Panel(), Label("Spells"),
                DropTarget(accepts=("spell",)))  # fmt: skip


def test_mouse_drag_and_drop_onto_a_target_taking_the_kind() -> None:
    hooks = Drops()
    app = App(inventory, headless=True, size=SIZE, hooks=hooks)
    app.step()
    sword = drag(app, "Sword", "Bag")
    bag = next(e for e, (lbl,) in app.world.query(Label) if lbl.text == "Bag")
    assert [(d.source, d.target, d.payload, d.kind) for d in hooks.got] == [
        (sword, bag, "sword", "item")]  # fmt: skip
    assert app.world.events(ButtonClicked) == []  # a drag is not a click
    drag(app, "Sword", "Spells")  # a target that does not take items
    assert app.world.events(DragCancelled) == [DragCancelled(sword, "sword")]
    assert len(hooks.got) == 1


def test_a_small_move_is_still_a_click_and_the_game_never_sees_the_drag() -> None:
    app = App(inventory, headless=True, size=SIZE, hooks=Drops())
    app.step()
    b = box_of(app, "Sword")
    app.input.mouse_down(at=b.center)
    app.step()
    app.input.move_mouse(b.center[0] + 3, b.center[1])  # under the 6 px threshold
    app.step()
    app.input.mouse_up()
    app.step()
    assert [e.text for e in app.world.events(ButtonClicked)] == ["Sword"]
    assert not app.world.resource(Input).mouse_pressed(Mouse.LEFT)


def test_keyboard_and_gamepad_drag_and_drop() -> None:
    hooks = Drops()
    app = App(inventory, headless=True, size=SIZE, hooks=hooks)
    app.step()
    focus(app, "Sword")
    press(app, Key.SPACE, Mod.CTRL)  # pick it up: the nearest target that takes it is chosen
    st = app.world.resource(UIState)
    assert st.drag is not None and st.drag.keyboard
    press(app, Key.ENTER)
    assert len(hooks.got) == 1 and st.drag is None
    pad = app.input.connect_gamepad()
    for button in ("x", "b"):  # pick up, cancel
        pad.press(button)
        app.step()
        pad.release(button)
        app.step()
    assert st.drag is None and len(hooks.got) == 1
    pad.press("x")
    app.step()
    assert app.world.events(DragStarted)
