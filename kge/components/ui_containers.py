"""Components that change how other UI nodes behave: scrolling, dialogs, tooltips,
drag and drop.

* :class:`ScrollView` on a node scrolls its children (any widgets) inside its box;
* :class:`Dialog` makes a node a window of its own, drawn on top; a modal one keeps
  the input and the focus to itself while it is shown;
* :class:`Tooltip` on any node shows a hint after the pointer rests on it (or the
  focus does);
* :class:`Draggable` / :class:`DropTarget` make nodes sources and targets of drag
  and drop (mouse, or the keyboard and gamepad: pick up, move the focus, drop).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from kge.components.tracked import Check, Tracked
from kge.components.ui_checks import offset, px, text
from kge.errors import ComponentTypeError, ValidationError
from kge.validate import boolean, finite, integer


@dataclass(slots=True)
class ScrollView(Tracked):
    """Scrolls the node's children inside its box (the node's ``layout`` places them).

    ``scroll`` is (x, y) pixels: y from the top down, x from the left; offsets past
    the end are clamped when laid out. The wheel scrolls (Shift+wheel sideways), the
    scrollbars drag, ``drag_scroll`` lets a press on the content drag it (touch
    style), and a focused child is always scrolled into view.
    """

    _checks: ClassVar[dict[str, Check]] = {
        "scroll": offset, "horizontal": boolean, "vertical": boolean, "scrollbar": boolean,
        "drag_scroll": boolean, "wheel_step": px,
    }  # fmt: skip

    scroll: tuple[float, float] = (0.0, 0.0)
    vertical: bool = True
    horizontal: bool = False
    scrollbar: bool = True  #: draw scrollbars (they take room only when the content overflows)
    drag_scroll: bool = True
    wheel_step: float = 48.0  #: pixels per wheel notch


@dataclass(slots=True)
class Dialog(Tracked):
    """A window: a titled panel drawn above the rest of the UI. While a ``modal`` one is
    shown, clicks outside it are taken (not passed below), the focus stays inside, and
    the window behind is dimmed. Escape (gamepad B) closes it with result -1; a button
    carrying :class:`DialogButton` closes it with that button's result. Either way
    ``DialogClosed`` is emitted and the dialog's entity is despawned (``keep=True``:
    hidden instead)."""

    _checks: ClassVar[dict[str, Check]] = {
        "title": text, "modal": boolean, "keep": boolean, "cancel": boolean,
    }  # fmt: skip

    title: str = ""
    modal: bool = True
    keep: bool = False
    cancel: bool = True  #: Escape / gamepad B close it with result -1


@dataclass(slots=True)
class DialogButton(Tracked):
    """Marks a Button inside a Dialog: clicking it closes the dialog with ``result``."""

    _checks: ClassVar[dict[str, Check]] = {"result": integer}

    result: int = 0


@dataclass(slots=True)
class Tooltip(Tracked):
    """A hint shown near a node after the pointer rests on it ``delay`` seconds (or the
    keyboard/gamepad focus does)."""

    _checks: ClassVar[dict[str, Check]] = {"text": text, "delay": finite}

    text: str = ""
    delay: float = 0.6

    def __post_init__(self) -> None:
        if not 0.0 <= self.delay <= 60.0:
            raise ValidationError(
                f"{self._owner()}.delay must be in 0..60 seconds, got {self.delay}"
            )


def _kind(value: Any, owner: str, name: str) -> str:
    v = text(value, owner, name)
    if not v:
        raise ValidationError(f"{owner}.{name} must not be empty")
    return v


def _kinds(value: Any, owner: str, name: str) -> tuple[str, ...]:
    if isinstance(value, str) or not hasattr(value, "__iter__"):
        raise ComponentTypeError(f"{owner}.{name} must be a tuple of kinds (str), got {value!r}")
    return tuple(_kind(v, owner, name) for v in value)


@dataclass(slots=True)
class Draggable(Tracked):
    """The node can be dragged: ``payload`` travels with it (any data: an item id, a
    file path), ``kind`` says what it is for targets to choose. A drag starts after the
    pointer moves ``threshold`` pixels with the button down, or with Ctrl+Space (a
    gamepad's X) on the focused node; the focus then moves among targets and Enter
    (A) drops, Escape (B) cancels."""

    _checks: ClassVar[dict[str, Check]] = {
        "kind": _kind, "threshold": px, "disabled": boolean,
    }  # fmt: skip

    payload: Any = None
    kind: str = "item"
    threshold: float = 6.0
    disabled: bool = False


@dataclass(slots=True)
class DropTarget(Tracked):
    """The node takes drops of the kinds in ``accepts`` (empty: any kind). A drop emits
    ``Dropped``; the node is highlighted while an acceptable drag is over it."""

    _checks: ClassVar[dict[str, Check]] = {"accepts": _kinds, "disabled": boolean}

    accepts: tuple[str, ...] = ()
    disabled: bool = False

    def takes(self, kind: str) -> bool:
        return not self.disabled and (not self.accepts or kind in self.accepts)


__all__ = ["Dialog", "DialogButton", "Draggable", "DropTarget", "ScrollView", "Tooltip"]
