"""Turning pointer, keyboard and gamepad input into widget changes and UI events.

:func:`handle_input` runs once per frame (the UI system calls it in the INPUT stage,
before behaviours see the input). It walks the frame's input events in order:

* pointer: hover, press, release on the same widget = click (two quick ones on a row:
  a double click); dragging sliders, knobs, scrollbars, text selections and drag and
  drop sources; the wheel scrolls the innermost scrollable thing under it; a press
  anywhere over the UI (widgets and panels that block) is *taken*: removed from the
  game's view of the input; while a modal dialog is shown, everything is;
* keyboard: Tab / Shift+Tab move the focus in Tab order, arrows by direction once
  something has focus; Enter or Space activates, Escape cancels (closes a dropdown
  or a dialog); the focused widget gets first say (a text field takes typing and
  its editing keys, a list its arrows and PageUp/PageDown);
* gamepad: the d-pad is the arrows, ``a`` activates, ``b`` cancels, ``x`` picks up a
  draggable, the shoulder buttons switch tabs;
* IME composition events show in the focused text field until the text is typed.

Each widget kind's behaviour lives in :mod:`kge.ui.controls` and
:mod:`kge.ui.text_controls`; this module routes to them and keeps the frame's
bookkeeping (:class:`Frame`).
"""

from __future__ import annotations

from typing import Any

from kge.components.ui import Dialog, DialogButton, Panel, Tooltip, UINode
from kge.input import CompositionEvent, GamepadEvent, Input, KeyEvent, MouseEvent, TextEvent
from kge.keys import Key, Mod, Mouse
from kge.ui import controls, drag, scrolling, text_controls
from kge.ui.dialogs import close_dialog
from kge.ui.events import FocusChanged, ValueChanged
from kge.ui.focus import nearest, scroll_into_view, step, tab_order
from kge.ui.geometry import list_rows
from kge.ui.layout import Layout
from kge.ui.sizing import Sizer
from kge.ui.state import Tip, UIState

__all__ = ["Frame", "UIState", "handle_input", "list_rows"]  # UIState, list_rows: as before
from kge.ui.style import Look
from kge.world import World

#: keys and gamepad buttons -> the UI's actions
KEY_ACTIONS: dict[int, str] = {
    Key.UP: "up", Key.DOWN: "down", Key.LEFT: "left", Key.RIGHT: "right",
    Key.ENTER: "activate", Key.NUM_ENTER: "activate", Key.SPACE: "activate",
    Key.ESCAPE: "cancel", Key.PAGEUP: "page_up", Key.PAGEDOWN: "page_down",
    Key.HOME: "home", Key.END: "end",
}  # fmt: skip
PAD_ACTIONS: dict[str, str] = {
    "dpup": "up", "dpdown": "down", "dpleft": "left", "dpright": "right", "a": "activate",
    "b": "cancel", "x": "pick", "leftshoulder": "tab_prev", "rightshoulder": "tab_next",
}  # fmt: skip


class Frame:
    """One frame of UI input handling: the world, its layout and what the frame did."""

    def __init__(self, world: World, inp: Input, state: UIState, size: tuple[int, int],
                 dt: float) -> None:  # fmt: skip
        self.world, self.inp, self.state, self.size, self.dt = world, inp, state, size, dt
        self.layout: Layout = state.layout
        sizer = self.layout.sizer
        assert sizer is not None, "handle_input lays the UI out first"
        self.sizer: Sizer = sizer
        self.events: list[Any] = []
        self.took = False
        self.used_keys: list[int] = []
        self.nodes: dict[int, UINode] = self.layout.nodes
        self.modal = self.layout.modal

    # -- lookups ---------------------------------------------------------------------------------
    def widget(self, e: int | None) -> Any:
        return None if e is None else self.layout.widget.get(e)

    def look(self, e: int, state: str | None = None) -> Look:
        w = self.widget(e)
        kind = type(w).__name__ if w is not None else "Panel"
        return self.sizer.look(e, kind, state or self.state.state_of(e))

    def box(self, e: int) -> Any:
        return self.layout.boxes[e]

    def reachable(self, e: int) -> bool:
        """Not behind a modal dialog."""
        return self.modal is None or self.layout.dialog.get(e) == self.modal

    def interactive(self, e: int) -> bool:
        w = self.layout.widget.get(e)
        return (controls.is_interactive(w) and not getattr(w, "disabled", False)
                and self.reachable(e))  # fmt: skip

    def blocking(self, e: int) -> bool:
        if self.interactive(e):
            return True
        p = self.world.try_get(e, Panel)
        return (p is not None and p.blocks) or e in self.layout.scroll or (
            self.world.try_get(e, Dialog) is not None)  # fmt: skip

    def can_focus(self, e: int) -> bool:
        n = self.nodes.get(e)
        return n is not None and n.focusable and self.interactive(e)

    def order(self) -> list[int]:
        return tab_order(self.layout, self.nodes, self.can_focus, self.modal)

    # -- changes ---------------------------------------------------------------------------------
    def emit(self, event: Any) -> None:
        self.events.append(event)

    def changed(self, e: int, value: Any, old: Any) -> None:
        self.events.append(ValueChanged(e, value, old))

    def focus(self, e: int | None) -> None:
        st = self.state
        old = st.focused
        if e == old:
            return
        st.focused = e
        st.touch(old, e)
        controls.close_dropdowns(self, keep=e)
        if old is not None:
            text_controls.blur(self, old)
        self.events.append(FocusChanged(e, old))
        if e is not None:
            scroll_into_view(self.world, self.layout, e)
            if st.tip.shown:
                st.touch(st.tip.entity)
            st.tip = Tip()  # the new focus's tooltip, if it has one, after its delay

    def move_focus(self, delta: int) -> None:
        target = step(self.order(), self.state.focused, delta)
        if target is not None:
            self.focus(target)

    def move_dir(self, direction: str) -> None:
        order = self.order()
        cur = self.state.focused
        if cur is None or cur not in order:
            self.focus(step(order, None, 1))
            return
        target = nearest(self.layout, order, cur, direction)
        if target is None and direction in ("up", "down"):
            target = step(order, cur, 1 if direction == "down" else -1)
        if target is not None:
            self.focus(target)

    def activate(self, e: int) -> None:
        w = self.widget(e)
        dialog = self.world.try_get(e, DialogButton)
        controls.activate(self, e, w)
        if dialog is not None and e in self.layout.dialog:
            close_dialog(self, self.layout.dialog[e], dialog.result, getattr(w, "text", ""))

    # -- pointer ---------------------------------------------------------------------------------
    def pointer(self, ev: MouseEvent) -> None:
        st, lay, p = self.state, self.layout, ev.screen
        if ev.kind == "move":
            hovered = lay.hit(p, self.interactive)
            if hovered != st.hovered:
                st.touch(st.hovered, hovered)
                st.hovered = hovered
            self._tooltip_at(p)
            if drag.moved(self, p):
                return
            if "bar" in st.grab or "pan" in st.grab:
                scrolling.grab_move(self, p)
            elif st.pressed is not None:
                controls.drag(self, st.pressed, self.widget(st.pressed), p)
            return
        if ev.kind == "scroll":
            hit = lay.hit(p, lambda e: True)
            if self.modal is not None or lay.hit(p, self.blocking) is not None:
                self.took = True
            scrolling.wheel(self, hit if hit is not None and self.reachable(hit) else None,
                            ev.scroll, bool(ev.modifiers & Mod.SHIFT))  # fmt: skip
            return
        if ev.button != Mouse.LEFT:
            if self.modal is not None or lay.hit(p, self.blocking) is not None:
                self.took = True
            return
        if ev.kind == "down":
            self.press(p, ev.modifiers)
        elif ev.kind == "up":
            self.release(p)

    def press(self, p: tuple[float, float], mods: int) -> None:
        st, lay = self.state, self.layout
        st.tip.shown = False
        if controls.press_open_dropdown(self, p):
            self.took = True
            return
        hit = lay.hit(p, self.blocking)
        if self.modal is not None:
            self.took = True
            if hit is None or not self.reachable(hit):
                return
        if scrolling.press_bar(self, p):
            self.took = True
            return
        if hit is None:
            controls.close_dropdowns(self)
            if st.focused is not None:
                self.focus(None)
            return
        self.took = True
        drag.arm(self, hit, p)
        if not self.interactive(hit):
            scrolling.arm_pan(self, hit, p)
            return
        st.pressed = hit
        st.touch(hit)
        self.focus(hit)
        controls.press(self, hit, self.widget(hit), p, mods)

    def release(self, p: tuple[float, float]) -> None:
        st = self.state
        if drag.release(self, p):
            self.took = True
            st.pressed = None
            return
        if st.pressed is None:
            if st.grab:  # a scrollbar or a pan let go
                st.grab.clear()
                self.took = True
            return
        self.took = True
        pressed, st.pressed = st.pressed, None
        st.touch(pressed)
        inside = self.layout.hit(p, self.interactive) == pressed
        controls.release(self, pressed, self.widget(pressed), p, inside)

    def _tooltip_at(self, p: tuple[float, float]) -> None:
        st = self.state
        over = self.layout.hit(p, lambda e: self.world.try_get(e, Tooltip) is not None
                               and self.reachable(e))  # fmt: skip
        if over != st.tip.entity or (st.tip.shown and over is None):
            if st.tip.shown:
                st.touch(st.tip.entity)
            st.tip = Tip(over, st.time, False, p)
        elif not st.tip.shown:
            st.tip.at = p

    # -- keys and gamepad ------------------------------------------------------------------------
    def key(self, ev: KeyEvent) -> None:
        if not ev.down:
            return
        st = self.state
        focused = st.focused
        w = self.widget(focused)
        k, mods = ev.key, ev.modifiers
        if focused is not None and text_controls.key(self, focused, w, k, mods):
            self.used_keys.append(k)
            return
        if ev.repeat and k not in (Key.UP, Key.DOWN, Key.LEFT, Key.RIGHT, Key.PAGEUP,
                                   Key.PAGEDOWN):  # fmt: skip
            return
        if k == Key.TAB:
            back = bool(mods & Mod.SHIFT)
            if not (mods & Mod.CTRL and controls.switch_tab(self, -1 if back else 1)):
                if not self.order():
                    return  # nothing to focus: Tab is the game's
                self.move_focus(-1 if back else 1)
        elif k == Key.SPACE and mods & Mod.CTRL:
            if not drag.pick_up(self):
                return
        elif k in KEY_ACTIONS:
            if not self.action(KEY_ACTIONS[k], mods):
                return
        else:
            return
        self.used_keys.append(k)

    def action(self, act: str, mods: int = 0) -> bool:
        """Carry out a navigation action (from a key or a gamepad); True when used."""
        st = self.state
        if drag.action(self, act):
            return True
        if act == "cancel" and controls.cancel(self):
            return True
        focused = st.focused
        if act in ("tab_next", "tab_prev"):
            return controls.switch_tab(self, 1 if act == "tab_next" else -1)
        if act == "pick":
            return drag.pick_up(self)
        if focused is None:
            return False
        w = self.widget(focused)
        if controls.action(self, focused, w, act, mods):
            return True
        if act in ("up", "down", "left", "right"):
            self.move_dir(act)
            return True
        if act == "activate":
            self.activate(focused)
            return True
        return False

    def pad(self, ev: GamepadEvent) -> None:
        if ev.kind != "down":
            return
        st = self.state
        act = PAD_ACTIONS.get(ev.button)
        if act is None:
            return
        if st.focused is None and st.drag is None and act in ("up", "down", "activate"):
            self.move_focus(1)  # the first press focuses the first widget
            return
        self.action(act)


def handle_input(world: World, inp: Input, state: UIState, dt: float = 0.0) -> list[Any]:
    """Handle this frame's input for the UI of ``world`` (laid out already, in
    ``state.layout``); returns the UI events it made.

    Mouse presses over the UI, keys the UI used and text typed into a focused field are
    removed from ``inp`` afterwards, so the game does not react to them too.
    """
    boxes = state.layout.boxes
    for name in ("hovered", "pressed", "focused"):
        e = getattr(state, name)
        if e is not None and (e not in boxes or not world.exists(e)):
            setattr(state, name, None)
    state.time += max(dt, 0.0)
    f = Frame(world, inp, state, state.layout.size, dt)
    if f.modal is not None and state.focused is not None and not f.reachable(state.focused):
        f.focus(None)
    for ev in list(inp.events):
        if isinstance(ev, MouseEvent):
            f.pointer(ev)
        elif isinstance(ev, KeyEvent):
            f.key(ev)
        elif isinstance(ev, TextEvent):
            text_controls.typed(f, ev.text)
        elif isinstance(ev, CompositionEvent):
            text_controls.compose(f, ev.text, ev.caret)
        elif isinstance(ev, GamepadEvent):
            f.pad(ev)
    _tooltip_timer(f)
    state.took_pointer = f.took
    if f.took or f.modal is not None:
        inp.consume_mouse()
    if f.used_keys:
        inp.consume_keys(*f.used_keys)
    if text_controls.takes_text(f.widget(state.focused), state, state.focused):
        inp.consume_text()
    return f.events


def _tooltip_timer(f: Frame) -> None:
    st = f.state
    tip = st.tip
    focused = st.focused
    if (tip.entity is None and focused is not None and focused in f.layout.boxes
            and f.world.try_get(focused, Tooltip) is not None):  # fmt: skip
        b = f.layout.boxes[focused]  # nothing under the pointer asks: the focus's tooltip
        tip = st.tip = Tip(focused, st.time, False, (b.center[0], b.y))
    if tip.entity is None or tip.shown:
        return
    t = f.world.try_get(tip.entity, Tooltip)
    if t is None or tip.entity not in f.layout.boxes:
        st.tip = Tip()
        return
    if st.time - tip.since >= t.delay - 1e-9:  # (sums of frame times are not exact)
        tip.shown = True
        st.touch(tip.entity)

