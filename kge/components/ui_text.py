"""Text widgets: a one-line field, a multi-line editor and rich (marked-up) text.

``caret`` and ``anchor`` are character indices; the selection lies between them
(``anchor`` -1: none; ``caret`` -1: at the end). Writing either outside the text is
refused:

>>> field = TextInput("hello")
>>> field.caret = -1; field.caret
5
>>> field.caret = 99
Traceback (most recent call last):
...
kge.errors.ValidationError: TextInput.caret must be a character index 0..5 (or -1), got 99
>>> TextInput("toolong", max_length=3)
Traceback (most recent call last):
...
kge.errors.ValidationError: TextInput.text has 7 characters, more than max_length 3
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from kge.components.color import Color
from kge.components.tracked import Check, Tracked
from kge.components.ui_checks import choice, font_size, opt_color, px, scroll_px, text
from kge.components.ui_markup import Run, parse
from kge.errors import ValidationError
from kge.validate import boolean, integer


def _editable_setattr(self: Any, name: str, value: Any) -> None:
    """Writes of a text widget: ``text`` within ``max_length``; caret/anchor in the text."""
    if name == "text":
        value = text(value, self._owner(), name)
        limit = getattr(self, "max_length", None)
        if limit is not None and len(value) > limit:
            raise ValidationError(
                f"{self._owner()}.text has {len(value)} characters, more than max_length {limit}"
            )
    elif name in ("caret", "anchor") and hasattr(self, "anchor"):  # not inside __init__
        value = integer(value, self._owner(), name)
        if not -1 <= value <= len(self.text):
            raise ValidationError(
                f"{self._owner()}.{name} must be a character index 0..{len(self.text)} "
                f"(or -1), got {value}"
            )
        if name == "caret" and value < 0:  # -1: at the end, as in the constructor
            value = len(self.text)
    elif name in ("caret", "anchor"):
        value = integer(value, self._owner(), name)
    elif name == "max_length":
        value = integer(value, self._owner(), name)
        held = len(self.text) if hasattr(self, "caret") else 0  # not inside __init__
        if value < held or value < 0:
            raise ValidationError(
                f"{self._owner()}.max_length must be >= 0 and hold the text's {held} "
                f"characters, got {value}"
            )
    Tracked.__setattr__(self, name, value)
    if name == "text" and hasattr(self, "caret"):
        Tracked.__setattr__(self, "caret", min(max(self.caret, 0), len(value)))
        Tracked.__setattr__(self, "anchor", -1)


def _editable_init(self: Any) -> None:
    if self.max_length < 0:
        raise ValidationError(
            f"{self._owner()}.max_length must be >= 0 and hold the text's {len(self.text)} "
            f"characters, got {self.max_length}"
        )
    if len(self.text) > self.max_length:
        raise ValidationError(
            f"{self._owner()}.text has {len(self.text)} characters, more than max_length "
            f"{self.max_length}"
        )
    Tracked.__setattr__(self, "caret", len(self.text) if self.caret < 0 else min(self.caret,
                                                                                 len(self.text)))
    Tracked.__setattr__(self, "anchor", min(max(self.anchor, -1), len(self.text)))


def _selection(self: Any) -> tuple[int, int] | None:
    if self.anchor < 0 or self.anchor == self.caret:
        return None
    return (min(self.anchor, self.caret), max(self.anchor, self.caret))


@dataclass(slots=True)
class TextInput(Tracked):
    """A one-line text field: caret, selection, typing, the clipboard, ``max_length``.

    Setting ``text`` longer than ``max_length`` is refused; typing beyond it is dropped.
    Enter emits ``TextSubmitted`` (and ``on_text_submitted``). ``password=True`` shows
    dots. Text wider than the field scrolls to keep the caret in view.
    """

    _checks: ClassVar[dict[str, Check]] = {
        "placeholder": text, "disabled": boolean, "password": boolean,
    }  # fmt: skip

    text: str = ""
    placeholder: str = ""
    max_length: int = 256
    caret: int = -1  #: -1: at the end
    anchor: int = -1  #: the other end of the selection (-1: no selection)
    disabled: bool = False
    password: bool = False

    def __post_init__(self) -> None:
        _editable_init(self)

    __setattr__ = _editable_setattr
    selection = property(_selection, doc="(start, end) of the selected characters, or None.")


@dataclass(slots=True)
class TextArea(Tracked):
    """A multi-line text editor: Enter breaks the line, arrows move by character and line,
    Home/End to the line's ends, PageUp/PageDown, the wheel and a scrollbar scroll,
    Shift selects, Ctrl+A/C/X/V. Ctrl+Enter emits ``TextSubmitted``.

    ``wrap=True`` breaks long lines at the box's width. ``tab_size`` > 0 makes Tab
    insert that many spaces (0: Tab moves the focus on, as in a form). ``read_only``
    keeps the caret and selection (copy works) but refuses edits (a log view).
    """

    _checks: ClassVar[dict[str, Check]] = {
        "placeholder": text, "disabled": boolean, "wrap": boolean, "read_only": boolean,
        "tab_size": integer, "scroll": scroll_px,
    }  # fmt: skip

    text: str = ""
    placeholder: str = ""
    max_length: int = 100_000
    caret: int = -1
    anchor: int = -1
    wrap: bool = True
    read_only: bool = False
    tab_size: int = 0
    scroll: float = 0.0  #: pixels scrolled from the top (clamped to the text's height)
    disabled: bool = False

    def __post_init__(self) -> None:
        if not 0 <= self.tab_size <= 16:
            raise ValidationError(f"{self._owner()}.tab_size must be in 0..16, got {self.tab_size}")
        _editable_init(self)

    __setattr__ = _editable_setattr
    selection = property(_selection, doc="(start, end) of the selected characters, or None.")


def _markup(value: Any, owner: str, name: str) -> str:
    parse(text(value, owner, name), owner)  # refuse a bad tag at the write
    return str(value)


@dataclass(slots=True)
class RichText(Tracked):
    """Text with bold, italic, colour and size runs from BBCode-style markup (see
    :mod:`kge.components.ui_markup`), wrapped at the box's width when ``wrap``."""

    _checks: ClassVar[dict[str, Check]] = {
        "markup": _markup, "size": font_size, "color": opt_color,
        "align": choice(("left", "center", "right")), "wrap": boolean, "line_spacing": px,
    }  # fmt: skip

    markup: str = ""
    size: float | None = None
    color: Color | None = None
    align: str = "left"
    wrap: bool = True
    line_spacing: float = 0.0  #: extra pixels between lines

    @property
    def runs(self) -> list[Run]:
        return parse(self.markup, self._owner())


__all__ = ["RichText", "Run", "TextArea", "TextInput"]
