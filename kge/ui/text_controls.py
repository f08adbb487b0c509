"""Typing into text fields: the one-line :class:`TextInput`, the multi-line
:class:`TextArea` and a :class:`SpinBox` being typed into.

Keys: Backspace/Delete (with Ctrl: a word), Left/Right (Ctrl: by word), Home/End
(Ctrl in a text area: the text's ends), Up/Down/PageUp/PageDown in a text area,
Shift with any of them selects, Ctrl+A selects all, Ctrl+C/X/V copy, cut and paste
through the clipboard, Enter submits (a text area breaks the line; Ctrl+Enter
submits), Escape leaves a spin box unchanged. A click places the caret on the
character under the pointer (measured), Shift+click extends the selection, a double
click selects a word, dragging selects. An IME's composition shows at the caret
until its text is typed.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from kge.components.ui import SpinBox, TextArea, TextInput
from kge.keys import Key, Mod
from kge.ui import editing
from kge.ui.events import TextSubmitted
from kge.ui.state import SpinEdit, UIState
from kge.ui.textview import AreaView, FieldView, area_view, field_view, shown_text

if TYPE_CHECKING:
    from kge.ui.interact import Frame

Editable = TextInput | TextArea | SpinEdit


def editing_spin(f: Frame, e: int) -> bool:
    return e in f.state.spin


def takes_text(w: Any, state: UIState, e: int | None) -> bool:
    """Does the focused widget take typed text (so the game must not see it)?"""
    if e is None:
        return False
    if isinstance(w, TextInput):
        return not w.disabled
    if isinstance(w, TextArea):
        return not (w.disabled or w.read_only)
    return isinstance(w, SpinBox) and e in state.spin


def _buffer(f: Frame, e: int, w: Any) -> Editable | None:
    if isinstance(w, (TextInput, TextArea)) and not w.disabled:
        return w
    if isinstance(w, SpinBox):
        return f.state.spin.get(e)
    return None


def _limit(b: Editable) -> int:
    return b.max_length if isinstance(b, (TextInput, TextArea)) else 64


def _set(f: Frame, e: int, b: Editable, text: str, caret: int, anchor: int = -1) -> None:
    old = b.text
    if text != old:
        b.text = text
    b.caret = caret
    b.anchor = anchor
    f.state.touch(e)
    if text != old and not isinstance(b, SpinEdit):
        f.changed(e, text, old)


def _field(f: Frame, e: int, w: Any, b: Editable) -> FieldView:
    lk = f.look(e)
    box = f.box(e)
    if isinstance(w, SpinBox):
        from kge.ui.geometry import spin_parts

        box = spin_parts(box)[1]
    return field_view(f.sizer, f.state, e, b.text, b.caret, box, lk, shown_text(w, b.text))


def _area(f: Frame, e: int, w: TextArea) -> AreaView:
    return area_view(f.sizer, f.state, e, w, f.box(e), f.look(e))


# -- typing -----------------------------------------------------------------------------------
def typed(f: Frame, text: str) -> None:
    """Text typed (a TextEvent). Line breaks are left out: Enter is handled as a key (a
    window also sends it as the text "\\r")."""
    insert_text(f, text.replace("\r", "").replace("\n", ""))


def insert_text(f: Frame, text: str) -> None:
    """Put ``text`` (typed or pasted) into the focused text widget."""
    e = f.state.focused
    if e is None:
        return
    w = f.widget(e)
    b = _buffer(f, e, w)
    if b is None or (isinstance(w, TextArea) and w.read_only):
        return
    f.state.composition = None
    multiline = isinstance(w, TextArea)
    s = editing.clean(text, multiline, w.tab_size if isinstance(w, TextArea) else 4)
    if isinstance(w, SpinBox):
        s = "".join(ch for ch in s if ch in "0123456789.-+eE")
    if not s:
        return  # nothing left to type (control characters, letters in a number)
    new, caret = editing.insert(b.text, b.caret, b.anchor, s, _limit(b))
    _set(f, e, b, new, caret)
    _follow(f, e, w, b)


def compose(f: Frame, text: str, caret: int) -> None:
    e = f.state.focused
    if e is None or _buffer(f, e, f.widget(e)) is None:
        return
    f.state.composition = (e, text, caret) if text else None
    f.state.touch(e)


def blur(f: Frame, e: int) -> None:
    """The focus left ``e``: a spin box being typed into keeps its value; an IME's
    composition is dropped."""
    if f.state.composition is not None and f.state.composition[0] == e:
        f.state.composition = None
    if e in f.state.spin:
        w = f.widget(e)
        if isinstance(w, SpinBox):
            commit_spin(f, e, w)


# -- keys ---------------------------------------------------------------------------------------
def key(f: Frame, e: int, w: Any, k: int, mods: int) -> bool:
    """Editing keys of a focused text widget; True when the key was used."""
    b = _buffer(f, e, w)
    if b is None:
        return False
    shift = bool(mods & Mod.SHIFT)
    ctrl = bool(mods & (Mod.CTRL | Mod.COMMAND))
    area = w if isinstance(w, TextArea) else None
    read_only = area is not None and area.read_only
    text, caret = b.text, b.caret
    if k in (Key.ENTER, Key.NUM_ENTER):
        if isinstance(w, SpinBox):
            commit_spin(f, e, w)
        elif area is not None and not ctrl:
            if read_only:
                return True
            new, c = editing.insert(text, caret, b.anchor, "\n", _limit(b))
            _set(f, e, b, new, c)
        else:
            f.emit(TextSubmitted(e, text))
        _follow(f, e, w, b)
        return True
    if k == Key.ESCAPE:
        if isinstance(w, SpinBox):
            f.state.spin.pop(e, None)
            f.state.touch(e)
            return True
        return False
    if k in (Key.BACKSPACE, Key.DELETE):
        if not read_only:
            new, c = editing.delete(text, caret, b.anchor, k == Key.DELETE, ctrl)
            _set(f, e, b, new, c)
            _follow(f, e, w, b)
        return True
    if k in (Key.LEFT, Key.RIGHT, Key.HOME, Key.END, Key.UP, Key.DOWN, Key.PAGEUP,
             Key.PAGEDOWN):  # fmt: skip
        target = _target(f, e, w, b, k, ctrl)
        if target is None:
            return False
        sel = editing.selection(caret, b.anchor)
        if sel and not shift and k in (Key.LEFT, Key.RIGHT):
            target = sel[0] if k == Key.LEFT else sel[1]
        b.caret, b.anchor = editing.move(caret, b.anchor, target, shift, len(text))
        f.state.touch(e)
        _follow(f, e, w, b)
        return True
    if ctrl and k == Key.A:
        b.anchor, b.caret = 0, len(text)
        f.state.touch(e)
        return True
    if ctrl and k in (Key.C, Key.X):
        sel = editing.selection(caret, b.anchor)
        if sel and not (isinstance(w, TextInput) and w.password):
            f.state.clipboard = text[sel[0] : sel[1]]
            if k == Key.X and not read_only:
                _set(f, e, b, text[: sel[0]] + text[sel[1] :], sel[0])
        return True
    if ctrl and k == Key.V:
        if not read_only:
            insert_text(f, f.state.clipboard)
        return True
    if k == Key.TAB:
        if area is not None and area.tab_size > 0 and not ctrl and not read_only:
            new, c = editing.insert(text, caret, b.anchor, " " * area.tab_size, _limit(b))
            _set(f, e, b, new, c)
            _follow(f, e, w, b)
            return True
        return False
    return k < 0xFF00 and not ctrl  # printable keys arrive as text too: keep them from the game


def _target(f: Frame, e: int, w: Any, b: Editable, k: int, ctrl: bool) -> int | None:
    text, caret = b.text, b.caret
    if k == Key.LEFT:
        return editing.word_left(text, caret) if ctrl else caret - 1
    if k == Key.RIGHT:
        return editing.word_right(text, caret) if ctrl else caret + 1
    if not isinstance(w, TextArea):
        if k in (Key.HOME, Key.END):
            return 0 if k == Key.HOME else len(text)
        return None  # Up/Down in a one-line field: the focus moves
    view = _area(f, e, w)
    line = view.line_of(caret)
    a, z = view.lines[line]
    if k in (Key.HOME, Key.END):
        if ctrl:
            return 0 if k == Key.HOME else len(text)
        return a if k == Key.HOME else z
    rows = {Key.UP: -1, Key.DOWN: 1}.get(k)
    if rows is None:
        page = max(int(view.view.h // view.line_h) - 1, 1)
        rows = -page if k == Key.PAGEUP else page
    target_line = min(max(line + rows, 0), len(view.lines) - 1)
    if target_line == line:
        return 0 if rows < 0 else len(text)
    x = _x_in_line(f, view, text, a, caret)
    ta, tz = view.lines[target_line]
    return ta + _index_in_line(f, view, text[ta:tz], x)


def _x_in_line(f: Frame, view: AreaView, text: str, start: int, i: int) -> float:
    from kge.ui.measure import width

    return width(f.sizer.measure, text[start:i], view.font)


def _index_in_line(f: Frame, view: AreaView, line: str, x: float) -> int:
    from kge.ui.measure import index_at

    return index_at(f.sizer.measure, line, view.font, x)


def _follow(f: Frame, e: int, w: Any, b: Editable) -> None:
    """Keep the caret in view: a field scrolls sideways (on its next view), a text area
    moves its ``scroll``."""
    if isinstance(w, TextArea):
        view = _area(f, e, w)
        line = view.line_of(b.caret)
        top = line * view.line_h
        s = w.scroll
        if top < s:
            s = top
        elif top + view.line_h > s + view.view.h:
            s = top + view.line_h - view.view.h
        s = min(max(s, 0.0), view.max_scroll)
        if s != w.scroll:
            w.scroll = s
    elif isinstance(w, (TextInput, SpinBox)):
        _field(f, e, w, b)


# -- pointer --------------------------------------------------------------------------------------
def index_at(f: Frame, e: int, w: Any, b: Editable, p: tuple[float, float]) -> int:
    """The caret position under the pointer."""
    if isinstance(w, TextArea):
        view = _area(f, e, w)
        line = int((view.view.top - p[1] + w.scroll) // view.line_h)
        line = min(max(line, 0), len(view.lines) - 1)
        a, z = view.lines[line]
        return a + _index_in_line(f, view, b.text[a:z], p[0] - view.view.x)
    fv = _field(f, e, w, b)
    return min(fv.index_at(p[0]), len(b.text))


def press(f: Frame, e: int, w: Any, p: tuple[float, float], mods: int) -> None:
    b = _buffer(f, e, w)
    if b is None:
        return
    i = index_at(f, e, w, b, p)
    if f.state.double_click(e, ("text", i)):
        a, z = editing.word_at(b.text, i)
        b.anchor, b.caret = a, z
    elif mods & Mod.SHIFT:
        b.caret, b.anchor = editing.move(b.caret, b.anchor, i, True, len(b.text))
    else:
        b.caret, b.anchor = i, -1
        f.state.grab.update(select=e, origin=i)
    f.state.touch(e)


def drag(f: Frame, e: int, w: Any, p: tuple[float, float]) -> None:
    g = f.state.grab
    b = _buffer(f, e, w)
    if b is None or g.get("select") != e:
        return
    i = index_at(f, e, w, b, p)
    b.caret, b.anchor = i, g["origin"] if i != g["origin"] else -1
    f.state.touch(e)
    _follow(f, e, w, b)


# -- spin boxes ------------------------------------------------------------------------------------
def begin_spin_edit(f: Frame, e: int, w: SpinBox) -> None:
    if w.disabled:
        return
    text = w.text()
    f.state.spin[e] = SpinEdit(text, len(text), 0)
    f.state.touch(e)


def commit_spin(f: Frame, e: int, w: SpinBox) -> None:
    """Keep the typed value (refused text leaves the value as it was)."""
    edit = f.state.spin.pop(e, None)
    f.state.touch(e)
    if edit is None:
        return
    try:
        value = float(edit.text)
    except ValueError:
        return
    set_spin(f, e, w, value)


def set_spin(f: Frame, e: int, w: SpinBox, value: float) -> None:
    if value != value or value in (float("inf"), float("-inf")):
        return
    if w.rounded:
        value = float(round(value))
    elif w.step:
        value = math.floor(value / w.step + 0.5) * w.step  # to the nearest step, halves up
        value = round(value, 10)
    value = min(max(value, w.min), w.max)
    if value != w.value:
        old, w.value = w.value, value
        f.changed(e, w.value, old)


def spin_step(f: Frame, e: int, w: SpinBox, direction: int) -> None:
    set_spin(f, e, w, w.value + direction * (w.step or 1.0))
