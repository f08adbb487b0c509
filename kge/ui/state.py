"""``UIState``: what the UI keeps that is not a component field.

Hover, press and focus (entities), the last layout and when it must be redone, the
clipboard, and per-widget view state that the user does not own: a text field's
horizontal scroll, an IME composition, a colour picker's hue, a spin box being
typed into, a drag in flight, a tooltip waiting to show. It is one resource per
world (the UI plugin inserts it).

Change tracking: the UI plugin binds every UI component to :attr:`UIState.writes`,
so a field write (or an edit of a watched list) notes its entity there. The next
layout pass sees the note and lays out again; without one, the previous layout is
reused and the drawer syncs nothing: an unchanged HUD costs about nothing per frame.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from kge.ui.clipboard import Clipboard
from kge.ui.layout import Layout
from kge.ui.measure import TableMeasure, TextMeasure

DOUBLE_CLICK = 0.4  #: seconds between the clicks of a double click


@dataclass(slots=True)
class SpinEdit:
    """A spin box being typed into: its text, caret and selection anchor."""

    text: str
    caret: int
    anchor: int = -1


@dataclass(slots=True)
class Drag:
    """A drag in flight (mouse, or keyboard/gamepad when ``keyboard``)."""

    source: int
    payload: Any
    kind: str
    start: tuple[float, float]
    at: tuple[float, float]
    started: bool = False  #: past the threshold (mouse) or picked up (keyboard)
    keyboard: bool = False
    over: int | None = None  #: the target under the pointer (or focused), if it takes the kind
    label: str = ""


@dataclass(slots=True)
class Tip:
    """The tooltip: which node asks for one, since when, and where it shows."""

    entity: int | None = None
    since: float = 0.0
    shown: bool = False
    at: tuple[float, float] = (0.0, 0.0)


@dataclass(slots=True)
class UIState:
    """See the module docstring."""

    hovered: int | None = None
    pressed: int | None = None
    focused: int | None = None
    layout: Layout = field(default_factory=Layout)
    took_pointer: bool = False  #: the UI took this frame's mouse presses
    store: Clipboard = field(default_factory=Clipboard)
    measure: TextMeasure = field(default_factory=TableMeasure)
    #: entities whose UI components were written since the last layout
    writes: set[int] = field(default_factory=set)
    #: entities that gained or lost a UI component since the last layout
    structural: set[int] = field(default_factory=set)
    #: entities the drawer must sync again (writes, and looks that changed: hover, focus)
    redraw: set[int] = field(default_factory=set)
    #: per-entity count of changes (caches of derived data compare it)
    versions: dict[int, int] = field(default_factory=dict)
    layout_key: tuple[Any, ...] = ()
    time: float = 0.0  #: seconds of UI time (frames' dt)
    text_scroll: dict[int, float] = field(default_factory=dict)
    composition: tuple[int, str, int] | None = None  #: (field, text, caret) of an IME
    picker: dict[int, list[float]] = field(default_factory=dict)  #: hue, sat, value, part
    spin: dict[int, SpinEdit] = field(default_factory=dict)
    dropdown_first: dict[int, int] = field(default_factory=dict)
    drag: Drag | None = None
    tip: Tip = field(default_factory=Tip)
    #: (entity, item, time) of the last click, for double clicks
    last_click: tuple[int, Any, float] | None = None
    #: pointer-grab state while pressed: the widget part being dragged and where it began
    grab: dict[str, Any] = field(default_factory=dict)
    caches: dict[tuple[Any, ...], Any] = field(default_factory=dict)
    #: nodes to despawn once this frame's UI hooks ran (closed dialogs)
    doomed: list[int] = field(default_factory=list)

    @property
    def clipboard(self) -> str:
        """The clipboard's text (the system's in a window)."""
        return self.store.get()

    @clipboard.setter
    def clipboard(self, text: str) -> None:
        self.store.set(text)

    def touch(self, *entities: int | None) -> None:
        """Their look changed (hover, focus...): draw them again."""
        for e in entities:
            if e is not None:
                self.redraw.add(e)

    def state_of(self, entity: int) -> str:
        """ "disabled", "pressed", "hover", "focused" or "normal" (what the renderer shows)."""
        w = self.layout.widget.get(entity)
        if getattr(w, "disabled", False):
            return "disabled"
        if self.pressed == entity:
            return "pressed"
        if self.hovered == entity:
            return "hover"
        if self.focused == entity:
            return "focused"
        return "normal"

    def double_click(self, entity: int, item: Any) -> bool:
        """Note a click on ``item`` of ``entity``; True when it completes a double click."""
        last = self.last_click
        self.last_click = (entity, item, self.time)
        if (last is not None and last[0] == entity and last[1] == item
                and self.time - last[2] <= DOUBLE_CLICK):  # fmt: skip
            self.last_click = None
            return True
        return False

    def forget(self, entities: set[int]) -> None:
        """Drop the per-entity state of nodes that are gone (despawned, or no longer UI)."""
        for table in (self.versions, self.text_scroll, self.picker, self.spin,
                      self.dropdown_first):
            for e in entities & table.keys():
                del table[e]

    def version(self, entity: int) -> int:
        return self.versions.get(entity, 0)
