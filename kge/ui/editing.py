"""Text editing shared by the one-line field, the multi-line editor and a spin box being
typed into: insert, delete, move the caret (by character, word or to an end), select.

A buffer is anything with ``text``, ``caret`` and ``anchor`` (a TextInput, a TextArea,
a :class:`~kge.ui.state.SpinEdit`); the functions return the new text and caret and
never write, so the caller decides what a change emits.

>>> clean("a\\tb\\r\\nc\\x00", multiline=False)
'a    b c'
>>> insert("hello", 5, -1, " world", 8)
('hello wo', 8)
>>> word_left("one two  three", 14), word_right("one two", 0)
(9, 3)
"""

from __future__ import annotations

from kge.ui.measure import is_control


def clean(text: str, multiline: bool, tab: int = 4) -> str:
    """Typed or pasted text made fit for a field: line ends normalised (to spaces in
    a one-line field), tabs to spaces, other control characters dropped."""
    text = text.replace("\r\n", "\n").replace("\r", "\n").replace("\t", " " * max(tab, 1))
    if not multiline:
        text = text.replace("\n", " ")
    return "".join(ch for ch in text if ch == "\n" or not is_control(ch))


def selection(caret: int, anchor: int) -> tuple[int, int] | None:
    if anchor < 0 or anchor == caret:
        return None
    return (min(anchor, caret), max(anchor, caret))


def insert(text: str, caret: int, anchor: int, s: str, max_length: int) -> tuple[str, int]:
    """Put ``s`` over the selection (or at the caret), cut to the room ``max_length`` leaves."""
    sel = selection(caret, anchor) or (caret, caret)
    room = max_length - (len(text) - (sel[1] - sel[0]))
    s = s[: max(room, 0)]
    return text[: sel[0]] + s + text[sel[1] :], sel[0] + len(s)


def delete(text: str, caret: int, anchor: int, forward: bool, word: bool) -> tuple[str, int]:
    """Backspace (``forward`` False) or Delete: the selection, else a character or word."""
    sel = selection(caret, anchor)
    if sel is not None:
        return text[: sel[0]] + text[sel[1] :], sel[0]
    if forward:
        end = word_right(text, caret) if word else min(caret + 1, len(text))
        return text[:caret] + text[end:], caret
    start = word_left(text, caret) if word else max(caret - 1, 0)
    return text[:start] + text[caret:], start


def word_left(text: str, i: int) -> int:
    """The start of the word before position ``i``."""
    while i > 0 and not text[i - 1].isalnum():
        i -= 1
    while i > 0 and text[i - 1].isalnum():
        i -= 1
    return i


def word_right(text: str, i: int) -> int:
    """The end of the word after position ``i``."""
    n = len(text)
    while i < n and not text[i].isalnum():
        i += 1
    while i < n and text[i].isalnum():
        i += 1
    return i


def move(caret: int, anchor: int, target: int, shift: bool, length: int) -> tuple[int, int]:
    """The caret moved to ``target`` (kept in the text); with ``shift`` the selection
    grows from where it began, without it the selection ends."""
    target = min(max(target, 0), length)
    if shift:
        return target, (caret if anchor < 0 else anchor)
    return target, -1


def word_at(text: str, i: int) -> tuple[int, int]:
    """The word (or run of other characters) around position ``i`` (a double click)."""
    if not text:
        return (0, 0)
    i = min(max(i, 0), len(text) - 1)
    kind = text[i].isalnum()
    a = i
    while a > 0 and text[a - 1].isalnum() == kind and text[a - 1] != "\n":
        a -= 1
    b = i
    while b < len(text) and text[b].isalnum() == kind and text[b] != "\n":
        b += 1
    return (a, b)
