"""Screen-space UI as entities: a :class:`UINode` places a box, a widget fills it.

The model is Bevy UI and Arcade's ``arcade.gui``: every UI element is an entity with
a ``UINode`` (where and how big, in window pixels, origin bottom-left) and at most one
widget component (what it is). Nodes nest through ``parent``; a parent with a
``layout`` places its children in a row, a column or a grid, otherwise each child is
anchored inside it. Everything is pure data: the UI plugin (``kge.systems.ui``)
computes the boxes from the window size whenever something changed (so percent
sizes and anchors survive resizes), turns pointer, keyboard and gamepad input into
widget changes and events, and the render pass draws them.

Sizes are pixels (``120``), percents of the parent's inner box (``"50%"``), or
``"auto"`` (fit the children or the widget's measured text), then kept between
``min_width``/``max_width`` (and heights). In a row or column, ``grow`` shares the
room left over among children by weight, and ``shrink`` takes room back from
them, by weight and size, when they do not fit. Anchors name a point of the
parent: ``"center"``, ``"top_left"``, ``"top"``, ``"top_right"``, ``"left"``,
``"right"``, ``"bottom_left"``, ``"bottom"``, ``"bottom_right"``; the same point of
the node is put there, moved by ``offset`` pixels (y up). A root node with
``follow=entity`` is anchored at that entity's place on screen instead (a health
bar or a name tag over a character), ``follow_offset`` metres from it.

Pixel values are at most 1e7; sizes are checked at the write:

>>> UINode(width=-5)
Traceback (most recent call last):
...
kge.errors.ValidationError: UINode.width must be >= 0 pixels, a percent like '50%' or 'auto', got -5
>>> UINode(min_width=300, max_width=100)
Traceback (most recent call last):
...
kge.errors.ValidationError: UINode: min_width (300.0) must be <= max_width (100.0)
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from kge.components.tracked import Check, Tracked
from kge.components.ui_checks import (
    ANCHORS,
    MAX_PIXELS,
    MAX_RANGE,
    Size,
    anchor,
    at_least_one,
    choice,
    entity_ref,
    offset,
    opt_int,
    opt_px,
    px,
    size,
    weight,
)
from kge.components.ui_containers import (
    Dialog,
    DialogButton,
    Draggable,
    DropTarget,
    ScrollView,
    Tooltip,
)
from kge.components.ui_lists import Dropdown, RadioGroup, ScrollList, Tabs, TreeItem, TreeView
from kge.components.ui_style import Style
from kge.components.ui_text import RichText, TextArea, TextInput
from kge.components.ui_widgets import (
    Button,
    ColorPicker,
    Label,
    Panel,
    ProgressBar,
    Slider,
    SpinBox,
    Toggle,
    UIImage,
)
from kge.errors import ValidationError
from kge.validate import boolean, integer, vec2

LAYOUTS = ("free", "row", "column", "grid")
ALIGNS = ("start", "center", "end", "stretch")
_LIMITS = (("min_width", "max_width"), ("min_height", "max_height"))


@dataclass(slots=True)
class UINode(Tracked):
    """Where a UI element goes and how big it is (see the module docstring)."""

    _checks: ClassVar[dict[str, Check]] = {
        "parent": entity_ref,
        "anchor": anchor,
        "offset": offset,
        "width": size,
        "height": size,
        "layout": choice(LAYOUTS),
        "padding": px,
        "spacing": px,
        "align": choice(ALIGNS),
        "justify": choice(("start", "center", "end")),
        "columns": at_least_one,
        "visible": boolean,
        "order": integer,
        "focusable": boolean,
        "min_width": opt_px,
        "max_width": opt_px,
        "min_height": opt_px,
        "max_height": opt_px,
        "grow": weight,
        "shrink": weight,
        "focus_order": opt_int,
        "follow": entity_ref,
        "follow_offset": vec2,
    }
    _world_fields: ClassVar[frozenset[str]] = frozenset(("parent", "follow"))

    anchor: str = "center"
    offset: tuple[float, float] = (0.0, 0.0)
    width: Size = "auto"
    height: Size = "auto"
    parent: int | None = None
    layout: str = "free"  #: how children are placed: free (anchored), row, column, grid
    padding: float = 0.0  #: pixels between the box and its children
    spacing: float = 0.0  #: pixels between children in a row, column or grid
    align: str = "center"  #: cross-axis placement of children (stretch fills)
    justify: str = "start"  #: main-axis placement of the whole row/column
    columns: int = 2  #: grid columns
    visible: bool = True
    order: int = 0  #: among siblings: lower first (placed first, drawn below)
    focusable: bool = True  #: interactive widgets take keyboard/gamepad focus
    min_width: float | None = None
    max_width: float | None = None
    min_height: float | None = None
    max_height: float | None = None
    grow: float = 0.0  #: share of a row's/column's spare room (by weight)
    shrink: float = 0.0  #: share of a row's/column's overflow given back (by weight x size)
    focus_order: int | None = None  #: Tab order: lower first, before nodes without one
    follow: int | None = None  #: a root node follows this entity on screen
    follow_offset: tuple[float, float] = (0.0, 0.0)  #: metres from the followed entity

    def __post_init__(self) -> None:
        for lo, hi in _LIMITS:
            self._check_limits(lo, hi)

    def _check_limits(self, lo: str, hi: str) -> None:
        a, b = getattr(self, lo), getattr(self, hi)
        if a is not None and b is not None and a > b:
            raise ValidationError(f"{self._owner()}: {lo} ({a}) must be <= {hi} ({b})")

    def __setattr__(self, name: str, value: Any) -> None:
        if name.startswith(("min_", "max_")) and hasattr(self, "follow_offset"):
            old = getattr(self, name)
            Tracked.__setattr__(self, name, value)
            pair = next(p for p in _LIMITS if name in p)
            try:
                self._check_limits(*pair)
            except ValidationError:
                Tracked.__setattr__(self, name, old)
                raise
            return
        Tracked.__setattr__(self, name, value)


#: every widget component, in the order a node's widget is looked for
WIDGETS: tuple[type, ...] = (
    Button, Toggle, Slider, SpinBox, TextInput, TextArea, Dropdown, ScrollList, RadioGroup,
    Tabs, TreeView, ColorPicker, Label, RichText, ProgressBar, UIImage,
)  # fmt: skip

__all__ = [
    "ALIGNS",
    "ANCHORS",
    "LAYOUTS",
    "MAX_PIXELS",
    "MAX_RANGE",
    "WIDGETS",
    "Button",
    "ColorPicker",
    "Dialog",
    "DialogButton",
    "Draggable",
    "DropTarget",
    "Dropdown",
    "Label",
    "Panel",
    "ProgressBar",
    "RadioGroup",
    "RichText",
    "ScrollList",
    "ScrollView",
    "Size",
    "Slider",
    "SpinBox",
    "Style",
    "Tabs",
    "TextArea",
    "TextInput",
    "Toggle",
    "Tooltip",
    "TreeItem",
    "TreeView",
    "UIImage",
    "UINode",
]
