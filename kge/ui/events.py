"""UI events as data: what the widgets did this frame.

The UI system fills :class:`UIEvents` (a per-frame resource: cleared when the next
frame's input is handled, so both fixed-step and update code of the frame see each
event) and calls the matching Behaviour hook on the widget's entity (see
:data:`HOOKS`): ``on_click(event)``, ``on_value_changed(event)``,
``on_text_submitted(event)``, ``on_item_activated(event)``, ``on_item_toggled(event)``,
``on_dialog_closed(event)``, ``on_drag_started(event)``; ``on_drop(event)`` runs on the
drop *target*.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, TypeVar

E = TypeVar("E")


@dataclass(slots=True, frozen=True)
class ButtonClicked:
    entity: int
    text: str = ""


@dataclass(slots=True, frozen=True)
class ValueChanged:
    """A Toggle (bool), Slider or SpinBox (float), Dropdown, ScrollList, RadioGroup or
    Tabs (index), TreeView (item id), ColorPicker (RGBA), TextInput or TextArea (text)
    changed."""

    entity: int
    value: Any
    old: Any = None


@dataclass(slots=True, frozen=True)
class TextSubmitted:
    entity: int
    text: str


@dataclass(slots=True, frozen=True)
class FocusChanged:
    entity: int | None
    old: int | None


@dataclass(slots=True, frozen=True)
class ItemActivated:
    """Enter or a double click on a ScrollList row (its index) or a TreeView row (its id)."""

    entity: int
    item: Any


@dataclass(slots=True, frozen=True)
class ItemToggled:
    """A TreeView row was opened or closed."""

    entity: int
    item: Any
    expanded: bool


@dataclass(slots=True, frozen=True)
class DialogClosed:
    """A Dialog closed: ``result`` is its DialogButton's (-1: cancelled), ``text`` the
    button's text ("" when cancelled)."""

    entity: int
    result: int
    text: str = ""


@dataclass(slots=True, frozen=True)
class DragStarted:
    source: int
    payload: Any
    kind: str


@dataclass(slots=True, frozen=True)
class TreeDrop:
    """The payload of a TreeView row drag: ``item`` dropped ``where`` ("before",
    "inside", "after") ``target`` (an item id of the tree it was dropped on)."""

    item: Any
    target: Any = None
    where: str = "inside"


@dataclass(slots=True, frozen=True)
class Dropped:
    """A drag ended over a target that takes its kind. ``at`` is the pointer, window px."""

    source: int
    target: int
    payload: Any
    kind: str
    at: tuple[float, float] = (0.0, 0.0)


@dataclass(slots=True, frozen=True)
class DragCancelled:
    source: int
    payload: Any


#: event type -> the Behaviour hook it calls, and which field names the entity
HOOKS: dict[type, tuple[str, str]] = {
    ButtonClicked: ("on_click", "entity"),
    ValueChanged: ("on_value_changed", "entity"),
    TextSubmitted: ("on_text_submitted", "entity"),
    ItemActivated: ("on_item_activated", "entity"),
    ItemToggled: ("on_item_toggled", "entity"),
    DialogClosed: ("on_dialog_closed", "entity"),
    DragStarted: ("on_drag_started", "source"),
    Dropped: ("on_drop", "target"),
    DragCancelled: ("on_drag_cancelled", "source"),
}


@dataclass(slots=True)
class UIEvents:
    """This frame's UI events, in the order they happened."""

    items: list[Any] = field(default_factory=list)

    def of(self, kind: type[E]) -> list[E]:
        """The events of one type (``ui.of(ButtonClicked)``)."""
        return [e for e in self.items if isinstance(e, kind)]

    def clicked(self, entity: int) -> bool:
        """Was the button ``entity`` clicked this frame?"""
        return any(isinstance(e, ButtonClicked) and e.entity == entity for e in self.items)

    def clear(self) -> None:
        self.items.clear()
