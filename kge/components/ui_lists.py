"""Widgets that pick among items: dropdowns, lists, radio groups, tabs and trees.

``selected`` is an index (or, for a tree, an item id) and is checked at every
write; when the items shrink under it, it moves to the last one left. Lists of
items are :class:`~kge.components.ui_checks.WatchedList`\\ s: editing them in place
is noticed.

>>> d = Dropdown(["Easy", "Hard"])
>>> d.selected = 5
Traceback (most recent call last):
...
kge.errors.ValidationError: Dropdown.selected 5 is not an index of its 2 options
>>> TreeView([TreeItem(1, "a", parent=2), TreeItem(2, "b", parent=1)])
Traceback (most recent call last):
...
kge.errors.ValidationError: TreeView.items: the parents of item 1 form a cycle (1 -> 2 -> 1)
"""

from __future__ import annotations

from collections.abc import Hashable
from collections.abc import Set as AbstractSet
from dataclasses import dataclass, field
from typing import Any, ClassVar

from kge.components.tracked import Check, Tracked
from kge.components.ui_checks import (
    Widget,
    font_size,
    index_in,
    opt_image,
    scroll_px,
    strings,
    text,
    watched,
)
from kge.errors import ComponentTypeError, ValidationError
from kge.validate import boolean, integer

ItemId = Hashable


def _selected_setattr(self: Any, name: str, value: Any) -> None:
    """Writes of an indexed picker: ``selected`` must index its items (or be -1)."""
    if name == "selected" and hasattr(self, self._items_field):
        items = getattr(self, self._items_field)
        value = index_in(value, len(items), self._owner(), name, self._what, self._none)
    Widget.__setattr__(self, name, value)


def _clamp_selected(self: Any, items_field: str) -> None:
    """After the items changed: keep ``selected`` an index of them."""
    if items_field != self._items_field or not hasattr(self, "selected"):
        return
    count = len(getattr(self, items_field))
    if self.selected >= count:
        Tracked.__setattr__(self, "selected", count - 1 if self._none == -1 or count else 0)


class _Picker(Widget):
    __slots__ = ()
    _items_field: ClassVar[str] = "options"
    _what: ClassVar[str] = "options"
    _none: ClassVar[int | None] = None  # the "no selection" index, if allowed

    __setattr__ = _selected_setattr

    def _list_changed(self, name: str) -> None:
        _clamp_selected(self, name)

    def _check_selected(self) -> None:
        items = getattr(self, self._items_field)
        selected: int = getattr(self, "selected")  # noqa: B009  (declared by the subclass)
        if items or self._none is not None:
            index_in(selected, len(items), self._owner(), "selected", self._what, self._none)


@dataclass(slots=True)
class Dropdown(_Picker):
    """Pick one of ``options``; opens a list below (or above) it. Changed: ``ValueChanged``."""

    _checks: ClassVar[dict[str, Check]] = {
        "options": strings, "open": boolean, "disabled": boolean, "max_rows": integer,
    }  # fmt: skip
    _lists: ClassVar[tuple[str, ...]] = ("options",)

    options: list[str] = field(default_factory=list)
    selected: int = 0
    open: bool = False
    disabled: bool = False
    max_rows: int = 8  #: rows shown when open; more scroll

    def __post_init__(self) -> None:
        if self.max_rows < 1:
            raise ValidationError(f"{self._owner()}.max_rows must be >= 1, got {self.max_rows}")
        self._check_selected()

    @property
    def value(self) -> str | None:
        return self.options[self.selected] if 0 <= self.selected < len(self.options) else None


@dataclass(slots=True)
class ScrollList(_Picker):
    """A scrollable list of text rows: wheel, drag, scrollbar, arrows, PageUp/PageDown.

    Only the rows in view are laid out and drawn, so 10,000 items cost what 20 do.
    Clicking a row selects it (``ValueChanged``); Enter or a double click activates it
    (``ItemActivated``).
    """

    _checks: ClassVar[dict[str, Check]] = {
        "items": strings, "scroll": scroll_px, "row_height": font_size,
    }  # fmt: skip
    _lists: ClassVar[tuple[str, ...]] = ("items",)
    _items_field: ClassVar[str] = "items"
    _what: ClassVar[str] = "items"
    _none: ClassVar[int | None] = -1

    items: list[str] = field(default_factory=list)
    selected: int = -1
    scroll: float = 0.0  #: pixels scrolled from the top (clamped to the list's height)
    row_height: float | None = None  #: None: the theme's

    def __post_init__(self) -> None:
        self._check_selected()


@dataclass(slots=True)
class RadioGroup(_Picker):
    """One choice among ``options``, shown as radio buttons (a column, or a row when
    ``horizontal``). Arrows move the choice; past the first or last, the focus moves
    on. Changed: ``ValueChanged`` with the index."""

    _checks: ClassVar[dict[str, Check]] = {
        "options": strings, "horizontal": boolean, "disabled": boolean,
    }  # fmt: skip
    _lists: ClassVar[tuple[str, ...]] = ("options",)
    _none: ClassVar[int | None] = -1

    options: list[str] = field(default_factory=list)
    selected: int = 0
    horizontal: bool = False
    disabled: bool = False

    def __post_init__(self) -> None:
        if not self.options and self.selected == 0:
            Tracked.__setattr__(self, "selected", -1)
        self._check_selected()

    @property
    def value(self) -> str | None:
        return self.options[self.selected] if 0 <= self.selected < len(self.options) else None


@dataclass(slots=True)
class Tabs(_Picker):
    """A tab bar over pages: the node's children, in order, are the pages of ``labels``;
    only the selected one is laid out and shown. Click a tab, Left/Right on the bar,
    Ctrl+Tab / Ctrl+Shift+Tab, or a gamepad's shoulder buttons switch. Changed:
    ``ValueChanged`` with the index."""

    _checks: ClassVar[dict[str, Check]] = {"labels": strings}
    _lists: ClassVar[tuple[str, ...]] = ("labels",)
    _items_field: ClassVar[str] = "labels"
    _what: ClassVar[str] = "labels"

    labels: list[str] = field(default_factory=list)
    selected: int = 0

    def __post_init__(self) -> None:
        self._check_selected()


@dataclass(slots=True, frozen=True)
class TreeItem:
    """One row of a :class:`TreeView`: an id (int or str, unique in the tree), its text,
    the id of its parent (None: a root), and an optional icon image."""

    id: int | str
    text: str
    parent: int | str | None = None
    icon: Any = None

    def __post_init__(self) -> None:
        for name in ("id", "parent"):
            v = getattr(self, name)
            if (v is None and name == "parent") or (
                isinstance(v, (int, str)) and not isinstance(v, bool)
            ):
                continue
            raise ComponentTypeError(f"TreeItem.{name} must be an int or a str, got {v!r}")
        text(self.text, "TreeItem", "text")
        opt_image(self.icon, "TreeItem", "icon")


def _tree_item(value: Any, owner: str, name: str) -> TreeItem:
    if isinstance(value, TreeItem):
        return value
    if isinstance(value, (tuple, list)) and 2 <= len(value) <= 4:
        return TreeItem(*value)
    raise ComponentTypeError(
        f"{owner}.{name} items must be TreeItem(id, text, parent) or (id, text, parent) "
        f"tuples, got {value!r}"
    )


def check_tree(items: list[TreeItem], owner: str, name: str) -> None:
    """Ids unique, every parent an id of the tree, no parent cycle (the message names it)."""
    parents: dict[Any, Any] = {}
    for item in items:
        if item.id in parents:
            raise ValidationError(f"{owner}.{name}: two items have the id {item.id!r}")
        parents[item.id] = item.parent
    for item in items:
        if item.parent is not None and item.parent not in parents:
            raise ValidationError(
                f"{owner}.{name}: item {item.id!r} names the parent {item.parent!r}, "
                "which is not an item of the tree"
            )
    state: dict[Any, int] = {}  # 1: being walked, 2: reaches a root
    for start in parents:
        path: list[Any] = []
        node: Any = start
        while node is not None and state.get(node) != 2:
            if state.get(node) == 1:
                loop = [*path[path.index(node) :], node]
                raise ValidationError(
                    f"{owner}.{name}: the parents of item {loop[0]!r} form a cycle "
                    f"({' -> '.join(map(repr, loop))})"
                )
            state[node] = 1
            path.append(node)
            node = parents[node]
        for p in path:
            state[p] = 2


def _id_set(value: Any, owner: str, name: str) -> frozenset[Any]:
    if isinstance(value, (str, bytes)) or not hasattr(value, "__iter__"):
        raise ComponentTypeError(f"{owner}.{name} must be a set of item ids, got {value!r}")
    return frozenset(value)


@dataclass(slots=True)
class TreeView(Widget):
    """A tree of rows that fold: ``items`` is a flat list of :class:`TreeItem` naming
    their parents (a scene hierarchy maps onto it directly), ``expanded`` the ids
    shown open, ``selected`` the selected id (or None).

    Up/Down move the selection, Right opens (then goes to the first child), Left
    closes (then goes to the parent), Enter or a double click activates
    (``ItemActivated``); clicking the arrow folds (``ItemToggled``). Only rows in view
    are drawn. With ``draggable=True`` a row can be dragged onto another (``Dropped``
    with a :class:`~kge.ui.events.TreeDrop`), for reparenting in an editor.
    """

    _checks: ClassVar[dict[str, Check]] = {
        "items": watched(_tree_item, check_tree), "expanded": _id_set, "scroll": scroll_px,
        "row_height": font_size, "draggable": boolean, "disabled": boolean,
    }  # fmt: skip
    _lists: ClassVar[tuple[str, ...]] = ("items",)

    items: list[TreeItem] = field(default_factory=list)
    expanded: AbstractSet[Any] = frozenset()  #: held as a frozenset (any set is taken)
    selected: int | str | None = None
    scroll: float = 0.0
    row_height: float | None = None
    draggable: bool = False
    disabled: bool = False

    def __setattr__(self, name: str, value: Any) -> None:
        if (name == "selected" and value is not None and hasattr(self, "items")
                and value not in {item.id for item in self.items}):  # fmt: skip
            raise ValidationError(f"{self._owner()}.selected {value!r} is not an item id")
        Widget.__setattr__(self, name, value)

    def __post_init__(self) -> None:
        if self.selected is not None and self.selected not in {i.id for i in self.items}:
            raise ValidationError(f"{self._owner()}.selected {self.selected!r} is not an item id")

    def _list_changed(self, name: str) -> None:
        if self.selected is not None and self.selected not in {i.id for i in self.items}:
            Tracked.__setattr__(self, "selected", None)


__all__ = ["Dropdown", "RadioGroup", "ScrollList", "Tabs", "TreeItem", "TreeView", "check_tree"]
