"""Dialogs, tooltips and drag and drop: an inventory whose items drag into bags that take
their kind, a confirm dialog and a message box."""

from __future__ import annotations

from typing import Any

from kge.components import Behaviour, Script
from kge.components.ui import Button, Draggable, DropTarget, Label, Panel, UINode
from kge.testbed.registry import sample
from kge.testbed.samples.ui_parts import Status, column, root_area, tip
from kge.ui.dialogs import confirm, message_box
from kge.ui.events import ButtonClicked, DialogClosed, Dropped
from kge.world import World

ITEMS = (("Sword", "weapon"), ("Shield", "weapon"), ("Fire", "spell"), ("Frost", "spell"))


class _Bags(Script):
    """A drop moves the item's button into the bag; the dialog buttons open dialogs."""

    def on_update(self, dt: float) -> None:
        world = self.world
        for drop in world.events(Dropped):
            world.get(drop.source, UINode).parent = drop.target
        for click in world.events(ButtonClicked):
            if click.text == "Confirm…":
                confirm(world, "Throw every item away?", ok="Throw away", title="Confirm")
            elif click.text == "Message…":
                message_box(world, "Saved.", title="Message")
        for closed in world.events(DialogClosed):
            if closed.text == "Throw away":
                for e, (d,) in world.query(Draggable):
                    world.despawn(e)
                    del d


def _bag(world: World, parent: int, name: str, accepts: tuple[str, ...]) -> int:
    node = UINode(parent=parent, width=220, height=170, layout="column", padding=8, spacing=6,
                  align="stretch")  # fmt: skip
    bag = world.spawn(node, Panel(), DropTarget(accepts=accepts))
    world.spawn(UINode(parent=bag), Label(name, align="left"))
    return bag


@sample("UI", "Dialogs and Drag",
        help="Drag items into the bags (or Ctrl+Space / X, arrows, Enter); open the dialogs.")
def dialogs_and_drag(world: World) -> None:
    root = root_area(world)
    row = world.spawn(UINode(parent=root, layout="row", spacing=20, offset=(0, 40)))
    items = column(world, parent=row, width=200)
    world.spawn(UINode(parent=items), Label("Items", size=18, align="left"))
    for name, kind in ITEMS:
        b = world.spawn(UINode(parent=items, height=34), Button(name), Draggable(name, kind))
        tip(world, b, f"A {kind}: drag it into a bag that takes {kind}s")
    _bag(world, row, "Weapons", ("weapon",))
    _bag(world, row, "Spell book", ("spell",))
    buttons = world.spawn(UINode(parent=root, anchor="bottom", offset=(0, 60), layout="row",
                                 spacing=10))  # fmt: skip
    world.spawn(UINode(parent=buttons, width=130, height=36), Button("Confirm…"))
    world.spawn(UINode(parent=buttons, width=130, height=36), Button("Message…"))
    status = world.spawn(UINode(parent=root, anchor="bottom", offset=(0, 16)), Label(""))
    world.spawn(Behaviour(Status(status)))
    world.spawn(Behaviour(_Bags()))


@dialogs_and_drag.claim
def _items_drop_into_bags_of_their_kind_and_dialogs_answer(app: Any) -> None:
    from kge.ui.driving import click, drag

    world = app.world
    drag(app, "Sword", "Weapons")
    app.step()
    weapons = next(e for e, (t,) in world.query(DropTarget) if t.accepts == ("weapon",))
    sword = next(e for e, (b,) in world.query(Button) if b.text == "Sword")
    assert world.get(sword, UINode).parent == weapons
    drag(app, "Fire", "Weapons")  # a spell does not go into the weapon bag
    app.step()
    fire = next(e for e, (b,) in world.query(Button) if b.text == "Fire")
    assert world.get(fire, UINode).parent != weapons
    click(app, "Confirm…")
    app.step()
    click(app, "Cancel")
    assert world.events(DialogClosed)[0].text == "Cancel"
