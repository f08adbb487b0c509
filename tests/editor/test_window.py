"""The editor window driven headless with simulated mouse and keys."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from kge import (
    App,
    Button,
    Circle,
    Collider,
    ColorPicker,
    Key,
    Label,
    Mod,
    Mouse,
    RevoluteJoint,
    RigidBody,
    ScrollView,
    SpinBox,
    Sprite,
    TextInput,
    Time,
    Transform,
    TreeView,
)
from kge.components.drawables import Rect
from kge.editor.app import Editor, editor_app
from kge.testing import box_of, click, double_click, drag, focus, scroll
from kge.ui.interact import UIState

from .test_model import LEVEL


@pytest.fixture
def editor(tmp_path: Path) -> tuple[App, Editor]:
    path = tmp_path / "level.scene.toml"
    path.write_text(LEVEL)
    app, ed = editor_app(path, headless=True, hot_reload=False)
    app.step()
    return app, ed


def button(app: App, text: str) -> int:
    return next(e for e, (b,) in app.world.query(Button) if b.text == text)


def click_button(app: App, text: str) -> None:
    app.input.click(at=box_of(app, button(app, text)).center)
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


def _replace_text(app: App, text: str) -> None:
    """In the focused field: select all (Ctrl+A), type ``text`` and press Enter."""
    app.input.press(Key.A, Mod.CTRL)
    app.input.release(Key.A)
    app.input.type_text(text)
    app.input.press(Key.ENTER)
    app.step()
    app.input.release(Key.ENTER)


def test_inspector_edit_undo_redo_by_keys(editor: tuple[App, Editor]) -> None:
    app, ed = editor
    app.input.click(at=screen_of(ed, "Crate"))
    app.step()
    app.step()  # the new inspector rows are laid out
    widget = next(w for w, (_, c, f, _) in ed.widgets.items() if c is Collider and f == "density")
    app.input.click(at=box_of(app, widget).center)
    app.step()
    _replace_text(app, "2.5")
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
    app.input.click(at=box_of(app, search).center)
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


def named(ed: Editor, name: str) -> int:
    return next(e for e in ed.model.entities() if ed.model.name(e) == name)


def test_the_hierarchy_is_a_tree_whose_row_drops_reparent(editor: tuple[App, Editor]) -> None:
    app, ed = editor
    tree = app.world.get(ed.tree, TreeView)
    assert [(it.text, it.parent) for it in tree.items] == [
        ("Ground", None), ("Crate", None), ("hinge", None)]  # fmt: skip
    before = ed.model.text()
    crate, ground = named(ed, "Crate"), named(ed, "Ground")
    drag(app, "Ground", "Crate")  # the middle of the Crate row: inside it (a compound part)
    app.step()
    assert ed.model.parent(ground) == crate and len(ed.model.undo_stack) == 1
    assert {it.text: it.parent for it in tree.items}["Ground"] == crate  # shown under it
    assert crate in tree.expanded  # a row that gains children opens
    assert [it.text for it in tree.items] == ["Crate", "Ground", "hinge"]
    ed.model.undo()
    assert ed.model.text() == before
    app.step()
    assert {it.text: it.parent for it in tree.items}["Ground"] is None
    drag(app, "Crate", "Ground")  # a static collider cannot carry the crate: refused
    app.step()
    assert ed.model.parent(crate) is None and "RigidBody" in ed.message
    assert ed.model.text() == before


def test_a_collider_dropped_on_a_body_in_the_tree_becomes_its_part(
    editor: tuple[App, Editor]
) -> None:
    app, ed = editor
    part = ed.model.create(Transform(2.0, 2.0), Collider(Circle(0.2)), name="Bumper")
    app.step()
    app.step()
    crate = named(ed, "Crate")
    drag(app, "Bumper", "Crate")
    app.step()
    assert ed.model.world.get(part, Collider).body == crate
    assert ed.model.parent(part) == crate
    assert ed.model.name(ed.rows[ed.rows.index(crate) + 1]) == "Bumper"  # shown under it


def test_a_tree_row_click_selects_and_a_double_click_frames_it(
    editor: tuple[App, Editor]
) -> None:
    app, ed = editor
    click(app, "Ground")
    assert ed.model.selection == [named(ed, "Ground")]
    assert app.world.get(ed.tree, TreeView).selected == named(ed, "Ground")
    zoom = ed.model.camera.zoom
    double_click(app, "Crate")
    assert ed.model.selection == [named(ed, "Crate")] and ed.model.camera.zoom != zoom


def select(app: App, ed: Editor, name: str) -> int:
    """Select ``name`` and let the inspector build and lay out its rows."""
    entity = named(ed, name)
    ed.model.select(entity)
    app.step()
    app.step()
    return entity


def _field(ed: Editor, ctype: type, name: str) -> int:
    return next(w for w, (_, c, f, _) in ed.widgets.items() if c is ctype and f == name)


def test_number_fields_are_spin_boxes_and_a_drag_is_one_undo_step(
    editor: tuple[App, Editor]
) -> None:
    app, ed = editor
    crate = select(app, ed, "Crate")
    widget = _field(ed, Collider, "density")
    assert app.world.get(widget, SpinBox).value == 1.0
    angle = app.world.get(_field(ed, Transform, "angle"), SpinBox)
    assert angle.value == 0.0 and angle.drag_speed == 0.5  # degrees
    start = box_of(app, widget).center
    app.input.mouse_down(at=start)
    app.step()
    for i in range(1, 6):
        app.input.move_mouse(start[0] + 10 * i, start[1])
        app.step()
        assert ed.model.world.get(crate, Collider).density == pytest.approx(1.0 + 0.2 * i)
        assert not ed.model.undo_stack  # live: the undo step comes with the release
    app.input.mouse_up(at=(start[0] + 50, start[1]))
    app.step()
    assert ed.model.world.get(crate, Collider).density == pytest.approx(2.0)
    assert len(ed.model.undo_stack) == 1 and ed.model.dirty
    ed.model.undo()
    assert ed.model.world.get(crate, Collider).density == 1.0 and not ed.model.dirty


def test_colour_fields_are_colour_pickers_and_a_drag_is_one_undo_step(
    editor: tuple[App, Editor]
) -> None:
    app, ed = editor
    tile = ed.model.create(Transform(0.0, 0.0), Rect(1.0, 1.0, color=(200, 40, 40, 255)),
                           name="Tile")  # fmt: skip
    steps = len(ed.model.undo_stack)
    app.step()
    app.step()
    widget = _field(ed, Rect, "color")
    assert app.world.get(widget, ColorPicker).color == (200, 40, 40, 255)
    box = box_of(app, widget)
    app.input.mouse_down(at=(box.x + 10, box.top - 10))  # the square's bright top left
    app.step()
    app.input.move_mouse(box.x + 12, box.y + 10)  # down: darker
    app.step()
    app.input.mouse_up(at=(box.x + 12, box.y + 10))
    app.step()
    color = ed.model.world.get(tile, Rect).color
    assert color != (200, 40, 40, 255) and max(color[:3]) < 100 and color[-1] == 255
    assert len(ed.model.undo_stack) == steps + 1
    ed.model.undo()
    assert ed.model.world.get(tile, Rect).color == (200, 40, 40, 255)


def test_the_inspector_scrolls_and_keeps_its_place_across_edits(
    editor: tuple[App, Editor]
) -> None:
    app, ed = editor
    crate = select(app, ed, "Crate")
    view = app.world.get(ed.inspector, ScrollView)
    scroll(app, ed.inspector, -4)  # the wheel down
    assert view.scroll[1] > 0
    where = view.scroll
    ed.model.set_field(crate, Collider, "density", 3.0)  # the rows are rebuilt
    app.step()
    app.step()
    assert view.scroll == where


def test_the_status_line_marks_unsaved_changes_after_edits_undo_and_save(
    editor: tuple[App, Editor]
) -> None:
    app, ed = editor

    def status() -> str:
        app.step()
        return app.world.get(ed.status, Label).text

    assert "*" not in status()
    crate = named(ed, "Crate")
    ed.model.set_field(crate, Transform, "x", 4.0)
    assert "level.scene.toml *" in status()
    ed.model.undo()
    assert "*" not in status()
    ed.model.redo()
    assert "*" in status()
    ed.model.save()
    assert "*" not in status()


def test_vector_fields_are_two_spin_boxes_each_changing_its_component(
    editor: tuple[App, Editor]
) -> None:
    app, ed = editor
    crate = select(app, ed, "Crate")
    x, y = (w for w, (_, c, f, _) in ed.widgets.items() if c is RigidBody and f == "velocity")
    assert app.world.get(x, SpinBox).value == 0.0 and app.world.get(y, SpinBox).value == 0.0
    click(app, y)  # a click without a drag: type a value
    app.input.type_text("-3.5")
    app.input.press(Key.ENTER)
    app.step()
    app.input.release(Key.ENTER)
    assert ed.model.world.get(crate, RigidBody).velocity == (0.0, -3.5)
    app.step()
    x = next(w for w, (_, c, f, k) in ed.widgets.items()
             if c is RigidBody and f == "velocity" and k.index == 0)  # fmt: skip
    drag(app, x, (box_of(app, x).center[0] + 50, box_of(app, x).center[1]))
    app.step()
    assert ed.model.world.get(crate, RigidBody).velocity == pytest.approx((1.0, -3.5))
    assert len(ed.model.undo_stack) == 2
    ed.model.undo()
    assert ed.model.world.get(crate, RigidBody).velocity == (0.0, -3.5)


def test_rotate_and_paint_tools_by_mouse(editor: tuple[App, Editor]) -> None:
    app, ed = editor
    crate = next(e for e in ed.model.entities() if ed.model.name(e) == "Crate")
    click_button(app, "Rotate")
    cx, cy = screen_of(ed, "Crate")
    k = ed.model.camera.pixels_per_meter * ed.model.camera.zoom
    app.input.mouse_down(Mouse.LEFT, at=(cx + 0.3 * k, cy))  # on the crate, to its right
    app.step()
    app.input.move_mouse(cx, cy + 0.3 * k)  # a quarter turn around it
    app.step()
    app.input.mouse_up(Mouse.LEFT)
    app.step()
    assert ed.model.world.get(crate, Transform).angle == pytest.approx(3.14159265 / 2)
    click_button(app, "Paint")
    start = ed.to_screen((1.0, 3.5))
    app.input.mouse_down(Mouse.LEFT, at=start)
    app.step()
    app.input.move_mouse(start[0] + 2.0 * k, start[1])
    app.step()
    app.input.mouse_up(Mouse.LEFT)
    app.step()
    painted = [e for e in ed.model.entities() if ed.model.world.has(e, Transform)
               and ed.model.world.get(e, Transform).y == 3.5]
    assert len(painted) == 5  # 1.0 .. 3.0 every 0.5 m
    assert ed.model.undo() and len(ed.model.entities()) == 3


def _close_button(app: App) -> None:
    """The window manager's close button: pyglet's on_close on the App's (EGL) window."""
    from kge.render.setup import ensure_renderer
    from kge.render.window import connect, disconnect

    window = ensure_renderer(app).window
    connect(app, window)
    try:
        window.dispatch_event("on_close")
        window.dispatch_events()  # outside pyglet's loop, window events are queued
    finally:
        disconnect(window)


def test_closing_the_window_with_unsaved_changes_asks_first(editor: tuple[App, Editor]) -> None:
    app, ed = editor
    app.render()  # the window the close button belongs to
    app._running = True  # as inside App.run: quit() is what ends it
    crate = next(e for e in ed.model.entities() if ed.model.name(e) == "Crate")
    ed.model.set_field(crate, Transform, "x", 5.0)
    _close_button(app)
    app.step()
    assert ed.dialog_kind == "unsaved" and app.running  # asked; the editor stays open
    app.step()  # laid out
    click_button(app, "Cancel")
    assert ed.dialog_kind == "" and app.running and ed.model.dirty
    assert app.world.name == "editor"  # still editing, the change still there
    assert ed.model.world.get(crate, Transform).x == 5.0
    _close_button(app)
    app.step()
    app.step()
    click_button(app, "Discard")
    assert not app.running  # discarded: the App's loop ends, the file is untouched
    assert ed.model.path is not None and "x = 5.0" not in ed.model.path.read_text()


def test_closing_the_window_can_save_and_quits_at_once_when_clean(
    editor: tuple[App, Editor]
) -> None:
    app, ed = editor
    app._running = True
    app.request_close()  # what the window's on_close calls
    app.step()
    assert not app.running and ed.dialog_kind == ""  # nothing to save: no question
    app._running = True
    crate = next(e for e in ed.model.entities() if ed.model.name(e) == "Crate")
    ed.model.set_field(crate, Transform, "x", 7.0)
    click_button(app, "Play")  # closing while playing stops play, then asks
    app.request_close()
    app.advance(1 / 60)
    assert not ed.playing and ed.dialog_kind == "unsaved" and app.running
    app.step()
    save = next(e for e in ed.dialog if app.world.has(e, Button)
                and app.world.get(e, Button).text == "Save")  # the dialog's, not the toolbar's
    app.input.click(at=box_of(app, save).center)
    app.step()
    assert not app.running and not ed.model.dirty
    assert ed.model.path is not None and "x = 7.0" in ed.model.path.read_text()


def test_an_app_quits_on_close_unless_told_otherwise() -> None:
    from kge import CloseRequested

    app = App(lambda w: None, headless=True)
    app._running = True
    app.request_close()
    assert not app.running  # the default: the close button ends the game
    app._running, app.quit_on_close = True, False
    app.request_close()
    assert app.running and len(app.world.events(CloseRequested)) == 1
    app.close()


def _mouse_drag(app: App, ed: Editor, start: tuple[float, float], end: tuple[float, float]
                ) -> None:
    """Press at world point ``start``, move to ``end`` in three frames, release there."""
    a, b = ed.to_screen(start), ed.to_screen(end)
    app.input.mouse_down(Mouse.LEFT, at=a)
    app.step()
    for t in (0.33, 0.66, 1.0):
        app.input.move_mouse(a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t)
        app.step()
    app.input.mouse_up(Mouse.LEFT, at=b)
    app.step()


def _one_undo_step(ed: Editor, before: str) -> None:
    """The last tool use was one undo step: undo gives back ``before``, redo the edit."""
    after = ed.model.text()
    assert after != before
    assert ed.model.undo() and ed.model.text() == before
    assert ed.model.redo() and ed.model.text() == after


def test_scale_shape_anchor_and_prefab_tools_by_mouse(
    editor: tuple[App, Editor], tmp_path: Path
) -> None:
    from kge import Box

    from .test_model import PREFABS

    app, ed = editor
    m = ed.model
    crate = named(ed, "Crate")
    click_button(app, "Scale")
    before = m.text()
    _mouse_drag(app, ed, (1.25, 2.0), (1.5, 2.0))  # twice as far from the crate's centre
    assert m.selection == [crate]
    box = m.world.get(crate, Collider).shape
    assert isinstance(box, Box) and (box.half_width, box.half_height) == pytest.approx((1, 1))
    _one_undo_step(ed, before)
    m.undo()
    click_button(app, "Shape")
    before = m.text()
    _mouse_drag(app, ed, (1.5, 2.5), (2.0, 3.0))  # the box's corner handle, snapped
    assert m.world.get(crate, Collider).shape == Box(1.0, 1.0)
    _one_undo_step(ed, before)
    click_button(app, "Anchor")
    hinge = named(ed, "hinge")
    m.select(hinge)  # a joint has no position to click: chosen in the hierarchy
    app.step()
    before = m.text()
    _mouse_drag(app, ed, (1.0, 2.5), (0.5, 3.0))
    assert m.world.get(hinge, RevoluteJoint).anchor == (0.5, 3.0)
    _one_undo_step(ed, before)
    shutil.copy(PREFABS / "wheel.prefab.toml", tmp_path / "wheel.prefab.toml")
    m.select(None)  # with nothing selected the inspector offers the prefab files
    ed.inspector_dirty = True
    app.step()
    click_button(app, "Prefab")
    assert ed.prefab is not None and ed.prefab.endswith("wheel.prefab.toml")
    before = m.text()
    assert ed.in_viewport(ed.to_screen((3.0, 3.0)))
    app.input.click(at=ed.to_screen((3.0, 3.0)))
    app.step()
    assert 'prefab = "wheel.prefab.toml"' in m.text() and "at = [3.0, 3.0" in m.text()
    _one_undo_step(ed, before)


def test_inspector_toggles_lists_references_assets_and_component_buttons(
    editor: tuple[App, Editor], tmp_path: Path
) -> None:
    from PIL import Image

    from kge import BodyType, Dropdown

    app, ed = editor
    m = ed.model
    for name in ("barrel.png", "crate.png"):
        Image.new("RGBA", (4, 4), (255, 0, 0, 255)).save(tmp_path / name)
    crate = select(app, ed, "Crate")
    steps = len(m.undo_stack)
    click(app, _field(ed, RigidBody, "bullet"))  # a boolean: a toggle
    assert m.world.get(crate, RigidBody).bullet is True
    app.step()
    click(app, _field(ed, RigidBody, "type"))  # an enum: a list of its members
    assert app.world.get(_field(ed, RigidBody, "type"), Dropdown).open
    click(app, "KINEMATIC")
    assert m.world.get(crate, RigidBody).type == BodyType.KINEMATIC
    app.step()
    hinge = select(app, ed, "hinge")
    widget = _field(ed, RevoluteJoint, "body_a")  # an entity reference: the scene's ids
    assert "ground" in app.world.get(widget, Dropdown).options
    click(app, widget)
    click(app, "ground")
    assert m.world.get(hinge, RevoluteJoint).body_a == named(ed, "Ground")
    assert len(m.undo_stack) == steps + 3
    crate = select(app, ed, "Crate")
    assert ed.add_choice is not None and ed.add_button is not None
    choice = app.world.get(ed.add_choice, Dropdown)  # the Add list: kge's types and the game's
    choice.selected = choice.options.index("Sprite")
    scroll(app, ed.inspector, -40)  # the Add row is at the bottom of the inspector
    click(app, ed.add_button)
    assert m.world.has(crate, Sprite), ed.message  # with the first image of the folder
    assert m.world.get(crate, Sprite).image == str(tmp_path / "barrel.png")
    app.step()
    widget = _field(ed, Sprite, "image")  # an asset path: the files beside the scene
    assert "crate.png" in app.world.get(widget, Dropdown).options
    focus(app, widget)  # scrolls it into view
    click(app, widget)
    click(app, "crate.png")
    assert m.world.get(crate, Sprite).image == str(tmp_path / "crate.png")
    assert 'image = "crate.png"' in m.text()  # saved relative to the scene
    app.step()
    remove = next(b for b, (e, c) in ed.remove_buttons.items() if c is Sprite)
    focus(app, remove)
    click(app, remove)  # the x beside a component's name
    assert not m.world.has(crate, Sprite)
    assert len(m.undo_stack) == steps + 6
    for _ in range(6):
        m.undo()
    assert m.text() == LEVEL_TEXT(ed)


def LEVEL_TEXT(ed: Editor) -> str:
    from .test_model import LEVEL

    app = App(lambda w: None, headless=True)
    path = ed.model.path
    assert path is not None
    path.with_name("fresh.scene.toml").write_text(LEVEL)
    from kge.editor import EditorModel

    return EditorModel(app.world, path.with_name("fresh.scene.toml")).text()


def test_rename_duplicate_new_and_the_view_buttons(editor: tuple[App, Editor]) -> None:
    from kge import Name
    from kge.components.debug import DebugDraw

    app, ed = editor
    m = ed.model
    crate = select(app, ed, "Crate")
    assert ed.name_box is not None
    click(app, ed.name_box)
    _replace_text(app, "Barrel")
    assert m.world.get(crate, Name).value == "Barrel"
    app.world.resource(UIState).focused = None
    click_button(app, "Duplicate")
    assert [m.name(e) for e in m.entities()].count("Barrel") == 2
    click_button(app, "New")
    assert len(m.entities()) == 5 and len(m.undo_stack) == 3
    click_button(app, "Undo")
    click_button(app, "Undo")
    click_button(app, "Redo")
    assert len(m.entities()) == 4 and len(m.undo_stack) == 2
    snap = m.snap
    click_button(app, "Grid")
    assert m.snap is not snap
    overlay = ed.edit_world.resource(DebugDraw).enabled
    click_button(app, "Physics")
    assert ed.edit_world.resource(DebugDraw).enabled is not overlay
    cam = m.camera
    zoom, centre = cam.zoom, cam.center
    where = ed.to_screen((0.0, 0.0))
    app.input.move_mouse(*where)
    app.input.scroll_by(0.0, 2.0)  # the wheel zooms at the pointer
    app.step()
    assert cam.zoom == pytest.approx(zoom * 1.15 ** 2)
    assert ed.to_world(where) == pytest.approx((0.0, 0.0))
    app.input.mouse_down(Mouse.RIGHT, at=where)  # a right drag pans
    app.step()
    app.input.move_mouse(where[0] + 100, where[1])
    app.step()
    app.input.mouse_up(Mouse.RIGHT)
    app.step()
    assert cam.center[0] < centre[0]
    click_button(app, "Frame")
    assert m.selection and cam.center != centre
