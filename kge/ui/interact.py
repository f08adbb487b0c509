"""Turning pointer, keyboard and gamepad input into widget changes and UI events.

:func:`handle_input` runs once per frame (the UI system calls it in the INPUT stage,
before behaviours see the input). It walks the frame's input events in order:

* pointer: hover, press, release on the same widget = click; dragging a slider; the
  wheel scrolls a list; a press anywhere over the UI (widgets and panels that block)
  is *taken*: it is removed from the game's view of the input;
* keyboard: Tab / Shift+Tab move the focus, arrows too once something has focus;
  Enter or Space activates, Left/Right change a slider or dropdown, Escape closes a
  dropdown; a focused text field takes typing, Backspace/Delete, Home/End, the
  arrows (with Shift: selection), Ctrl+A/C/X/V and Enter (submit);
* gamepad: the d-pad moves the focus (and changes sliders), ``a`` activates, ``b``
  closes a dropdown.

Widget state the user does not own (hover, press, focus, the clipboard) is the
:class:`UIState` resource, not component fields.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from kge.components.ui import Button, Dropdown, Panel, ScrollList, Slider, TextInput, Toggle
from kge.input import GamepadEvent, Input, KeyEvent, MouseEvent, TextEvent
from kge.keys import Key, Mod, Mouse
from kge.ui.events import ButtonClicked, FocusChanged, TextSubmitted, ValueChanged
from kge.ui.layout import Box, Layout, compute_layout, text_width
from kge.ui.theme import Theme
from kge.world import World

INTERACTIVE: tuple[type, ...] = (Button, Toggle, Slider, TextInput, Dropdown, ScrollList)


@dataclass(slots=True)
class UIState:
    """Hover, press and focus (entities), the clipboard, and the last layout."""

    hovered: int | None = None
    pressed: int | None = None
    focused: int | None = None
    clipboard: str = ""
    layout: Layout = field(default_factory=Layout)
    took_pointer: bool = False  #: the UI took this frame's mouse presses

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


def dropdown_rows(box: Box, count: int) -> list[Box]:
    """The boxes of an open dropdown's options, stacked under it."""
    return [Box(box.x, box.y - (i + 1) * box.h, box.w, box.h) for i in range(count)]


def list_rows(lst: ScrollList, box: Box, theme: Theme) -> list[tuple[int, Box]]:
    """(index, box) of the visible rows of a scroll list (partly visible ones too)."""
    rh = lst.row_height or theme.row_height
    rows = []
    for i in range(len(lst.items)):
        top = box.top - i * rh + lst.scroll
        if top - rh < box.top and top > box.y:
            rows.append((i, Box(box.x, top - rh, box.w, rh)))
    return rows


def max_scroll(lst: ScrollList, box: Box, theme: Theme) -> float:
    return max(len(lst.items) * (lst.row_height or theme.row_height) - box.h, 0.0)


class _Frame:
    """One frame of UI input handling (see :func:`handle_input`)."""

    def __init__(self, world: World, inp: Input, state: UIState, theme: Theme) -> None:
        self.world, self.inp, self.state, self.theme = world, inp, state, theme
        self.layout = state.layout
        self.events: list[Any] = []
        self.took = False
        self.used_keys: list[int] = []

    # -- helpers -------------------------------------------------------------------------------
    def widget(self, e: int | None) -> Any:
        return None if e is None else self.layout.widget.get(e)

    def interactive(self, e: int) -> bool:
        w = self.layout.widget.get(e)
        return isinstance(w, INTERACTIVE) and not getattr(w, "disabled", False)

    def blocking(self, e: int) -> bool:
        if self.interactive(e):
            return True
        p = self.world.try_get(e, Panel)
        return p is not None and p.blocks

    def focusables(self) -> list[int]:
        nodes = self.layout.order
        return [e for e in nodes if self.interactive(e) and self._node_focusable(e)]

    def _node_focusable(self, e: int) -> bool:
        from kge.components.ui import UINode

        n = self.world.try_get(e, UINode)
        return n is not None and n.focusable

    def focus(self, e: int | None) -> None:
        old = self.state.focused
        if e != old:
            self.state.focused = e
            self.close_dropdowns(keep=e)
            self.events.append(FocusChanged(e, old))

    def move_focus(self, delta: int) -> None:
        order = self.focusables()
        if not order:
            return
        cur = self.state.focused
        i = order.index(cur) + delta if cur in order else (0 if delta > 0 else -1)
        self.focus(order[i % len(order)])

    def close_dropdowns(self, keep: int | None = None) -> None:
        for e, w in self.layout.widget.items():
            if isinstance(w, Dropdown) and w.open and e != keep:
                w.open = False

    def changed(self, e: int, value: Any, old: Any) -> None:
        self.events.append(ValueChanged(e, value, old))

    # -- activation ----------------------------------------------------------------------
    def activate(self, e: int) -> None:
        w = self.widget(e)
        if isinstance(w, Button):
            self.events.append(ButtonClicked(e, w.text))
        elif isinstance(w, Toggle):
            w.value = not w.value
            self.changed(e, w.value, not w.value)
        elif isinstance(w, Dropdown):
            w.open = not w.open
        elif isinstance(w, TextInput):
            self.events.append(TextSubmitted(e, w.text))

    def nudge(self, e: int, direction: int) -> bool:
        """Left/right on a slider or dropdown; True when it used the key."""
        w = self.widget(e)
        if isinstance(w, Slider) and not w.disabled:
            step = w.step or (w.max - w.min) / 20.0
            old = w.value
            w.value = min(max(old + direction * step, w.min), w.max)
            if w.value != old:
                self.changed(e, w.value, old)
            return True
        if isinstance(w, (Dropdown, ScrollList)) and (
            w.options if isinstance(w, Dropdown) else w.items
        ):
            self.select(e, w, w.selected + direction)
            return True
        return False

    def select(self, e: int, w: Dropdown | ScrollList, index: int) -> None:
        count = len(w.options) if isinstance(w, Dropdown) else len(w.items)
        index = min(max(index, 0), count - 1)
        if index != w.selected:
            old, w.selected = w.selected, index
            self.changed(e, index, old)

    # -- pointer -----------------------------------------------------------------------------------
    def pointer(self, ev: MouseEvent) -> None:
        st, lay, p = self.state, self.layout, ev.screen
        if ev.kind == "move":
            st.hovered = lay.hit(p, self.interactive)
            if st.pressed is not None and isinstance(self.widget(st.pressed), Slider):
                self.drag_slider(st.pressed, p)
            return
        if ev.kind == "scroll":
            hit = lay.hit(p, self.blocking)
            if hit is not None:
                self.took = True
                w = self.widget(hit)
                if isinstance(w, ScrollList):
                    box = lay.boxes[hit]
                    top = max_scroll(w, box, self.theme)
                    w.scroll = min(
                        max(w.scroll - ev.scroll[1] * (w.row_height or self.theme.row_height), 0.0),
                        top,
                    )
            return
        if ev.button != Mouse.LEFT:
            if lay.hit(p, self.blocking) is not None:
                self.took = True
            return
        if ev.kind == "down":
            self.press(p)
        elif ev.kind == "up" and st.pressed is not None:
            self.took = True
            pressed, st.pressed = st.pressed, None
            if lay.hit(p, self.interactive) == pressed:
                w = self.widget(pressed)
                if isinstance(w, (Button, Toggle)):
                    self.activate(pressed)

    def press(self, p: tuple[float, float]) -> None:
        st, lay = self.state, self.layout
        for e, w in lay.widget.items():  # an open dropdown's list is on top of everything
            if isinstance(w, Dropdown) and w.open and e in lay.boxes:
                for i, row in enumerate(dropdown_rows(lay.boxes[e], len(w.options))):
                    if row.contains(p):
                        self.took = True
                        self.select(e, w, i)
                        w.open = False
                        return
        hit = lay.hit(p, self.blocking)
        if hit is None:
            self.close_dropdowns()
            if st.focused is not None:
                self.focus(None)
            return
        self.took = True
        if not self.interactive(hit):
            return
        st.pressed = hit
        self.focus(hit)
        w, box = self.widget(hit), lay.boxes[hit]
        if isinstance(w, Slider):
            self.drag_slider(hit, p)
        elif isinstance(w, TextInput):
            pad = self.theme.padding
            i = round((p[0] - box.x - pad) / (self.theme.font_size * 0.56))
            w.caret = min(max(i, 0), len(w.text))
            w.anchor = -1
        elif isinstance(w, Dropdown):
            w.open = not w.open
        elif isinstance(w, ScrollList):
            for i, row in list_rows(w, box, self.theme):
                if row.contains(p):
                    self.select(hit, w, i)

    def drag_slider(self, e: int, p: tuple[float, float]) -> None:
        w, box = self.widget(e), self.layout.boxes[e]
        knob = box.h / 2
        t = (p[0] - box.x - knob) / max(box.w - 2 * knob, 1.0)
        value = w.min + min(max(t, 0.0), 1.0) * (w.max - w.min)
        if w.step:
            value = w.min + round((value - w.min) / w.step) * w.step
            value = min(max(value, w.min), w.max)
        if value != w.value:
            old, w.value = w.value, value
            self.changed(e, w.value, old)

    # -- keys -------------------------------------------------------------------------------------
    def key(self, ev: KeyEvent) -> None:
        if not ev.down:
            return
        st = self.state
        focused = st.focused
        w = self.widget(focused)
        k = ev.key
        editing = isinstance(w, TextInput) and not w.disabled and focused is not None
        if editing and self.edit(focused, w, k, ev.modifiers):  # type: ignore[arg-type]
            self.used_keys.append(k)
            return
        if k == Key.TAB:
            self.move_focus(-1 if ev.modifiers & Mod.SHIFT else 1)
        elif focused is None:
            return
        elif k in (Key.DOWN, Key.UP):
            if (isinstance(w, Dropdown) and w.open) or isinstance(w, ScrollList):
                self.nudge(focused, 1 if k == Key.DOWN else -1)
            else:
                self.move_focus(1 if k == Key.DOWN else -1)
        elif k in (Key.LEFT, Key.RIGHT):
            if not self.nudge(focused, 1 if k == Key.RIGHT else -1):
                return
        elif k in (Key.ENTER, Key.NUM_ENTER, Key.SPACE):
            self.activate(focused)
        elif k == Key.ESCAPE and isinstance(w, Dropdown) and w.open:
            w.open = False
        else:
            return
        self.used_keys.append(k)

    def edit(self, e: int, w: TextInput, k: int, mods: int) -> bool:
        """Editing keys of a focused text field; True when the key was used."""
        shift, ctrl = bool(mods & Mod.SHIFT), bool(mods & (Mod.CTRL | Mod.COMMAND))
        text, caret, sel = w.text, w.caret, w.selection
        if k in (Key.ENTER, Key.NUM_ENTER):
            self.events.append(TextSubmitted(e, text))
        elif k == Key.BACKSPACE:
            if sel:
                self.replace(e, w, "")
            elif caret > 0:
                self.set_text(e, w, text[: caret - 1] + text[caret:], caret - 1)
        elif k == Key.DELETE:
            if sel:
                self.replace(e, w, "")
            elif caret < len(text):
                self.set_text(e, w, text[:caret] + text[caret + 1 :], caret)
        elif k in (Key.LEFT, Key.RIGHT, Key.HOME, Key.END):
            target = {Key.LEFT: caret - 1, Key.RIGHT: caret + 1, Key.HOME: 0, Key.END: len(text)}[k]
            if sel and not shift and k in (Key.LEFT, Key.RIGHT):
                target = sel[0] if k == Key.LEFT else sel[1]
            if shift and w.anchor < 0:
                w.anchor = caret
            elif not shift:
                w.anchor = -1
            w.caret = min(max(target, 0), len(text))
        elif ctrl and k == Key.A:
            w.anchor, w.caret = 0, len(text)
        elif ctrl and k in (Key.C, Key.X):
            if sel:
                self.state.clipboard = text[sel[0] : sel[1]]
                if k == Key.X:
                    self.replace(e, w, "")
        elif ctrl and k == Key.V:
            self.replace(e, w, self.state.clipboard)
        elif k == Key.TAB or k == Key.ESCAPE:
            return False
        else:
            return k < 0xFF00  # printable keys arrive as text too: keep them from the game
        return True

    def replace(self, e: int, w: TextInput, s: str) -> None:
        """Put ``s`` over the selection (or at the caret), cut to the room max_length leaves."""
        s = "".join(ch for ch in s if ch >= " " and ch != "\x7f")
        sel = w.selection or (w.caret, w.caret)
        room = w.max_length - (len(w.text) - (sel[1] - sel[0]))
        s = s[: max(room, 0)]
        self.set_text(e, w, w.text[: sel[0]] + s + w.text[sel[1] :], sel[0] + len(s))

    def set_text(self, e: int, w: TextInput, new: str, caret: int) -> None:
        old = w.text
        w.text = new
        w.caret = caret
        w.anchor = -1
        if new != old:
            self.changed(e, new, old)

    # -- gamepad -----------------------------------------------------------------------------------
    def pad(self, ev: GamepadEvent) -> None:
        if ev.kind != "down":
            return
        st = self.state
        b = ev.button
        if st.focused is None:
            if b in ("dpup", "dpdown", "a"):
                self.move_focus(1)
            return
        w = self.widget(st.focused)
        if b in ("dpup", "dpdown"):
            if isinstance(w, (ScrollList,)) or (isinstance(w, Dropdown) and w.open):
                self.nudge(st.focused, 1 if b == "dpdown" else -1)
            else:
                self.move_focus(1 if b == "dpdown" else -1)
        elif b in ("dpleft", "dpright"):
            self.nudge(st.focused, 1 if b == "dpright" else -1)
        elif b == "a":
            self.activate(st.focused)
        elif b == "b" and isinstance(w, Dropdown):
            w.open = False


def handle_input(
    world: World, inp: Input, size: tuple[int, int], state: UIState, theme: Theme
) -> list[Any]:
    """Handle this frame's input for the UI of ``world``; returns the UI events it made.

    Mouse presses over the UI, keys the UI used and text typed into a focused field are
    removed from ``inp`` afterwards, so the game does not react to them too.
    """
    state.layout = compute_layout(world, size, theme)
    boxes = state.layout.boxes
    for name in ("hovered", "pressed", "focused"):
        e = getattr(state, name)
        if e is not None and (e not in boxes or not world.exists(e)):
            setattr(state, name, None)
    f = _Frame(world, inp, state, theme)
    for ev in list(inp.events):
        if isinstance(ev, MouseEvent):
            f.pointer(ev)
        elif isinstance(ev, KeyEvent):
            f.key(ev)
        elif isinstance(ev, TextEvent):
            w = f.widget(state.focused)
            if isinstance(w, TextInput) and not w.disabled and state.focused is not None:
                f.replace(state.focused, w, ev.text)
        elif isinstance(ev, GamepadEvent):
            f.pad(ev)
    state.took_pointer = f.took
    if f.took:
        inp.consume_mouse()
    if f.used_keys:
        inp.consume_keys(*f.used_keys)
    if isinstance(f.widget(state.focused), TextInput):
        inp.consume_text()
    return f.events


def caret_x(w: TextInput, box: Box, theme: Theme) -> float:
    """Where the caret is drawn (the same estimate the pointer uses)."""
    return box.x + theme.padding + text_width(w.text[: w.caret], theme.font_size)
