"""The editor window driven headless with simulated mouse and keys."""

from __future__ import annotations

from pathlib import Path

import pytest

from kge import App, Button, Collider, Key, Mod, Mouse, RevoluteJoint, TextInput, Time, Transform
from kge.editor.app import Editor, editor_app
from kge.ui.interact import UIState

from .test_model import LEVEL


@pytest.fixture
def editor(tmp_path: Path) -> tuple[App, Editor]:
    path = tmp_path / "level.scene.toml"
    path.write_text(LEVEL)
    app, ed = editor_app(path, headless=True, hot_reload=False)
    app.step()
    return app, ed


def box_of(app: App, entity: int) -> object:
    return app.world.resource(UIState).layout.boxes[entity]


def button(app: App, text: str) -> int:
    return next(e for e, (b,) in app.world.query(Button) if b.text == text)


def click_button(app: App, text: str) -> None:
    app.input.click(at=box_of(app, button(app, text)).center)  # type: ignore[attr-defined]
    app.advance(1 / 60)  # a real frame: respects the pause


def screen_of(ed: Editor, name: str) -> tuple[float, float]:
    e = next(x for x in ed.model.entities() if ed.model.name(x) == name)
    return ed.to_screen(ed.model.world_pose(e)[:2])


def test_opens_clean_and_selects_with_a_click(editor: tuple[App, Editor]) -> None:
    app, ed = editor
    assert not ed.model.dirty
    app.input.click(at=screen_of(ed, "Crate"))
    app.step()
    assert [ed.model.name(e) for e in ed.model.selection] == ["Crate"]
    # the inspector shows the crate's components, one widget per field
    fields = {(c.__name__, f) for _, c, f, _ in ed.widgets.values()}
    assert ("Collider", "density") in fields and ("Transform", "angle") in fields
    # shift-click adds to the selection
    app.input.click(at=screen_of(ed, "Ground"), modifiers=Mod.SHIFT)
    app.step()
    assert len(ed.model.selection) == 2


def test_inspector_edit_undo_redo_by_keys(editor: tuple[App, Editor]) -> None:
    app, ed = editor
    app.input.click(at=screen_of(ed, "Crate"))
    app.step()
    app.step()  # the new inspector rows are laid out
    widget = next(w for w, (_, c, f, _) in ed.widgets.items() if c is Collider and f == "density")
    app.input.click(at=box_of(app, widget).center)  # type: ignore[attr-defined]
    app.step()
    app.input.press(Key.A, Mod.CTRL)
    app.input.release(Key.A)
    app.input.type_text("2.5")
    app.input.press(Key.ENTER)
    app.step()
    app.input.release(Key.ENTER)
    crate = ed.model.selection[0]
    assert ed.model.world.get(crate, Collider).density == 2.5 and ed.model.dirty
    app.world.resource(UIState).focused = None  # keys go to the editor, not the field
    app.input.press(Key.LCTRL)
    app.input.press(Key.Z, Mod.CTRL)
    app.step()
    assert ed.model.world.get(crate, Collider).density == 1.0
    app.input.release(Key.Z)
    app.step()
    app.input.press(Key.Y, Mod.CTRL)
    app.step()
    assert ed.model.world.get(crate, Collider).density == 2.5
    app.input.release(Key.Y)
    app.input.release(Key.LCTRL)


def test_move_tool_drag_is_one_undo_step(editor: tuple[App, Editor]) -> None:
    app, ed = editor
    click_button(app, "Move")
    assert ed.tool == "move"
    start = screen_of(ed, "Crate")
    app.input.mouse_down(Mouse.LEFT, at=start)
    app.step()
    k = ed.model.camera.pixels_per_meter * ed.model.camera.zoom
    for i in range(1, 5):
        app.input.move_mouse(start[0] + i * 0.5 * k, start[1])
        app.step()
    app.input.mouse_up(Mouse.LEFT)
    app.step()
    crate = ed.model.selection[0]
    assert ed.model.world.get(crate, Transform).x == 3.0  # 1 + 4 x 0.5 m
    assert len(ed.model.undo_stack) == 1
    ed.model.undo()
    assert ed.model.world.get(crate, Transform).x == 1.0


def test_play_runs_the_scene_and_stop_restores_the_edit_exactly(
    editor: tuple[App, Editor]
) -> None:
    app, ed = editor
    before = ed.model.text()
    click_button(app, "Play")
    assert ed.playing and app.world.name == "play bar"
    play_world = app.worlds[-2]
    for _ in range(60):
        app.advance(1 / 60)
    (joint,) = [j for _, (j,) in play_world.query(RevoluteJoint)]
    assert joint.anchor is None  # physics ran and resolved the hinge
    time = play_world.resource(Time)
    click_button(app, "Pause")
    steps = time.step
    app.advance(1 / 60)
    assert time.step == steps
    click_button(app, "Step")  # the next frame runs one step, then it holds again
    app.advance(1 / 60)
    assert time.step == steps + 1
    app.advance(1 / 60)
    assert time.step == steps + 1
    click_button(app, "Stop")
    assert not ed.playing and ed.model.text() == before
    assert app.world.name == "editor"


def test_save_and_the_unsaved_changes_prompt(editor: tuple[App, Editor]) -> None:
    app, ed = editor
    crate = next(e for e in ed.model.entities() if ed.model.name(e) == "Crate")
    ed.model.set_field(crate, Transform, "x", 5.0)
    app.input.press(Key.Q, Mod.CTRL)
    app.input.press(Key.LCTRL)
    app.step()
    app.input.release(Key.Q)
    app.input.release(Key.LCTRL)
    assert ed.dialog_kind == "unsaved"
    app.step()  # laid out
    click_button(app, "Cancel")
    assert ed.dialog_kind == "" and ed.model.dirty
    app.input.press(Key.LCTRL)
    app.input.press(Key.S, Mod.CTRL)
    app.step()
    app.input.release(Key.S)
    app.input.release(Key.LCTRL)
    assert not ed.model.dirty
    assert ed.model.path is not None and "x = 5.0" in ed.model.path.read_text()
    click_button(app, "Save as")
    app.step()
    field = next(e for e in ed.dialog if app.world.has(e, TextInput))
    target = ed.model.path.parent / "copy.scene.toml"
    app.world.get(field, TextInput).text = str(target)
    save = next(e for e in ed.dialog if app.world.has(e, Button)
                and app.world.get(e, Button).text == "Save")
    app.input.click(at=app.world.resource(UIState).layout.boxes[save].center)
    app.step()
    assert target.exists() and ed.model.path == target


def test_hierarchy_search_and_delete_key(editor: tuple[App, Editor]) -> None:
    app, ed = editor
    search = ed.search_box
    app.input.click(at=box_of(app, search).center)  # type: ignore[attr-defined]
    app.step()
    app.input.type_text("gro")
    app.step()
    app.step()
    assert [ed.model.name(e) for e in ed.rows] == ["Ground"]
    app.world.resource(UIState).focused = None
    app.input.click(at=screen_of(ed, "Crate"))
    app.step()
    app.input.press(Key.DELETE)
    app.step()
    assert "Crate" not in [ed.model.name(e) for e in ed.model.entities()]
