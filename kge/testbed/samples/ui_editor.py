"""The widgets an editor is built from: a scene tree whose rows drag to reparent, an
inspector of number fields that drag to change, a colour picker, a file path field, a
script editor."""

from __future__ import annotations

from typing import Any

from kge.components import Behaviour, Script
from kge.components.ui import (
    Button,
    ColorPicker,
    Label,
    SpinBox,
    Tabs,
    TextArea,
    TextInput,
    TreeItem,
    TreeView,
    UINode,
)
from kge.testbed.registry import sample
from kge.testbed.samples.ui_parts import Status, column, root_area, tip
from kge.ui.dialogs import message_box
from kge.ui.events import ButtonClicked, Dropped, TreeDrop
from kge.world import World

SCENE = [
    TreeItem("level", "Level"), TreeItem("player", "Player", "level"),
    TreeItem("sprite", "Sprite", "player"), TreeItem("camera", "Camera", "level"),
    TreeItem("lights", "Lights", "level"), TreeItem("sun", "Sun", "lights"),
    TreeItem("ui", "HUD"),
]  # fmt: skip


def reparent(tree: TreeView, drop: TreeDrop) -> None:
    """Apply a row drop to the tree's items: inside a row (its last child), or before or
    after it (its sibling)."""
    items = [it for it in tree.items if it.id != drop.item]
    moved = next(it for it in tree.items if it.id == drop.item)
    target = next((it for it in items if it.id == drop.target), None)
    if target is None:  # below the last row: a root at the end
        items.append(TreeItem(moved.id, moved.text, None, moved.icon))
    elif drop.where == "inside":
        items.append(TreeItem(moved.id, moved.text, target.id, moved.icon))
        tree.expanded = tree.expanded | {target.id}
    else:
        at = items.index(target) + (1 if drop.where == "after" else 0)
        items.insert(at, TreeItem(moved.id, moved.text, target.parent, moved.icon))
    tree.items = items


class _Editor(Script):
    """Row drops reparent; Browse opens a message box (the testbed has no file dialog)."""

    def __init__(self, tree: int) -> None:
        self.tree = tree

    def on_update(self, dt: float) -> None:
        for drop in self.world.events(Dropped):
            if drop.target == self.tree and isinstance(drop.payload, TreeDrop):
                reparent(self.world.get(self.tree, TreeView), drop.payload)
        for click in self.world.events(ButtonClicked):
            if click.text == "Browse…":
                message_box(self.world, "The testbed has no file browser: type a path.",
                            title="Browse")  # fmt: skip


def _field(world: World, parent: int, name: str, widget: Any) -> int:
    row = world.spawn(UINode(parent=parent, layout="row", spacing=8, align="center"))
    world.spawn(UINode(parent=row, width=70), Label(name, align="left"))
    return world.spawn(UINode(parent=row, grow=1, height=32), widget)


@sample("UI", "Editor Widgets",
        help="Drag tree rows to reparent; drag number fields sideways; pick a colour.")
def editor_widgets(world: World) -> None:
    root = root_area(world)
    left = column(world, parent=root, anchor="left", offset=(16, 0), width=260)
    world.spawn(UINode(parent=left), Label("Scene", size=20, align="left"))
    tree = world.spawn(UINode(parent=left, height=260),
                       TreeView(SCENE, expanded={"level", "player"}, draggable=True))  # fmt: skip
    middle = column(world, parent=root, anchor="center", offset=(-10, 0), width=330)
    world.spawn(UINode(parent=middle), Label("Inspector", size=20, align="left"))
    tip(world, _field(world, middle, "x", SpinBox(1.5, step=0.1, suffix=" m")),
        "Drag sideways to change, or click and type")  # fmt: skip
    _field(world, middle, "y", SpinBox(-2.0, step=0.1, suffix=" m"))
    _field(world, middle, "angle", SpinBox(0, -180, 180, 1, rounded=True, suffix="°"))
    world.spawn(UINode(parent=middle, height=170), ColorPicker((46, 196, 182, 255)))
    path = world.spawn(UINode(parent=middle, layout="row", spacing=6))
    world.spawn(UINode(parent=path, grow=1, shrink=1), TextInput("assets/player.png"))
    world.spawn(UINode(parent=path, width=120, height=34), Button("Browse…"))
    right = column(world, parent=root, anchor="right", offset=(-16, 0), width=330)
    tabs = world.spawn(UINode(parent=right, height=300), Tabs(["Script", "Notes"]))
    world.spawn(UINode(parent=tabs, padding=6), TextArea(
        "class Player(Script):\n    def on_update(self, dt):\n        ...\n", tab_size=4))
    world.spawn(UINode(parent=tabs, padding=6), TextArea("Notes about this level."))
    status = world.spawn(UINode(parent=root, anchor="bottom", offset=(0, 16)), Label(""))
    world.spawn(Behaviour(Status(status)))
    world.spawn(Behaviour(_Editor(tree)))


@editor_widgets.claim
def _rows_drag_to_reparent_and_fields_drag_to_change(app: Any) -> None:
    from kge.ui.driving import box_of, drag

    world = app.world
    tree = next(e for e, _ in world.query(TreeView))
    drag(app, "Camera", "Sprite")
    app.step()
    parents = {it.id: it.parent for it in world.get(tree, TreeView).items}
    assert parents["camera"] == "sprite"
    spin = next(e for e, (s,) in world.query(SpinBox) if s.suffix == " m")
    before = world.get(spin, SpinBox).value
    b = box_of(app, spin)
    app.input.mouse_down(at=b.center)
    app.step()
    app.input.move_mouse(b.center[0] + 40, b.center[1])
    app.step()
    app.input.mouse_up()
    app.step()
    assert world.get(spin, SpinBox).value > before
