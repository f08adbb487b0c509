"""UI events as data: what the widgets did this frame.

The UI system fills :class:`UIEvents` (a per-frame resource: cleared when the next
frame's input is handled, so both fixed-step and update code of the frame see each
event) and calls the matching Behaviour hook on the widget's entity:
``on_click(event)``, ``on_value_changed(event)``, ``on_text_submitted(event)``.
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
    """A Toggle (bool), Slider (float), Dropdown or ScrollList (index) changed."""

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
