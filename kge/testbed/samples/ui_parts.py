"""What the UI samples share: the area clear of the testbed's list and help, a panel
column, a tooltip, and a label reporting the last UI event."""

from __future__ import annotations

from typing import Any

from kge.components import Script
from kge.components.ui import Label, Panel, Tooltip, UINode
from kge.ui.events import (
    ButtonClicked,
    DialogClosed,
    Dropped,
    ItemActivated,
    TextSubmitted,
    ValueChanged,
)
from kge.world import World


class Status(Script):
    """Shows the last UI event in a label (what the samples report)."""

    def __init__(self, label: int) -> None:
        self.label = label

    def on_update(self, dt: float) -> None:
        kinds = (ButtonClicked, ValueChanged, TextSubmitted, ItemActivated, DialogClosed, Dropped)
        for ev in self.world.events(*kinds):  # in the order they happened
            shown = next((getattr(ev, k) for k in ("value", "text", "item", "payload")
                          if hasattr(ev, k)), "")  # fmt: skip
            if isinstance(shown, float):
                shown = round(shown, 2)
            self.world.get(self.label, Label).text = f"{type(ev).__name__}: {shown}"


def root_area(world: World) -> int:
    """The area the samples use: the window less a strip on the left and one at the top,
    where the testbed shows its sample list and help (a 1280 x 720 window keeps 192 px
    and 115 px clear)."""
    return world.spawn(UINode(anchor="bottom_right", width="85%", height="84%"))


def column(world: World, **node: Any) -> int:
    """A panel laying its children out in a stretched column."""
    node.setdefault("layout", "column")
    node.setdefault("padding", 14)
    node.setdefault("spacing", 8)
    node.setdefault("align", "stretch")
    return world.spawn(UINode(**node), Panel())


def tip(world: World, entity: int, text: str) -> int:
    """Give ``entity`` a tooltip."""
    world.add(entity, Tooltip(text))
    return entity
