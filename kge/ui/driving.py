"""Driving a game's UI from tests the way a player does: click a widget by its text or
entity, type, press keys, focus, drag, scroll. Public as :mod:`kge.testing` (``from
kge.testing import click``); the testbed's samples check their claims with it too.

Each helper feeds the App's simulated input (the same path a window's events take),
then steps the App once so the UI handles it and the game sees the result::

    from kge.testing import click, type_text

    click(app, "Settings")                       # a button, toggle, label, tab, option...
    type_text(app, "Ada", into=name_field)       # focus a field, type, one step
    assert app.world.get(name_field, TextInput).text == "Ada"

A target is an entity id, or the text shown on it: a Button's or Toggle's text, a
Label's, one of a Tabs' labels or a RadioGroup's options, an open Dropdown's option,
a visible ScrollList or TreeView row. A text shown by several widgets, or by none, or
a widget hidden or scrolled out of view, raises :class:`UITargetError` naming what
was found.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from kge.components.ui import (
    Button,
    Dropdown,
    Label,
    RadioGroup,
    ScrollList,
    Tabs,
    Toggle,
    TreeView,
    UINode,
)
from kge.errors import KgeError
from kge.keys import Key, Mouse
from kge.ui import geometry as geo
from kge.ui.current import current_layout
from kge.ui.layout import Box, Layout
from kge.ui.state import UIState

if TYPE_CHECKING:
    from kge.app import App

Target = int | str


class UITargetError(KgeError, LookupError):
    """No widget (or more than one) answers to a test's target, or it cannot be reached."""


def _layout(app: App) -> Layout:
    return current_layout(app.world)


def _visible(lay: Layout, box: Box, e: int) -> Box:
    clip = lay.clip.get(e)
    return box if clip is None else box.intersect(clip)


def _text_of(w: Any) -> str | None:
    if isinstance(w, (Button, Toggle, Label)):
        return w.text
    return None


def _candidates(app: App, text: str) -> list[tuple[int, Box, str]]:
    """(entity, box to click, what it is) of everything showing ``text``."""
    from kge.ui.controls import tree_rows

    lay = _layout(app)
    world = app.world
    state = world.resource(UIState)
    found: list[tuple[int, Box, str]] = []
    for e in lay.order:
        w = lay.widget.get(e)
        box = lay.boxes[e]
        if _text_of(w) == text:
            found.append((e, box, type(w).__name__))
        elif isinstance(w, Tabs):
            bar = lay.tab_bar.get(e)
            if bar is not None and lay.sizer is not None:
                lk = lay.sizer.look(e, "Tabs")
                tabs = geo.tab_boxes(bar, w.labels, lk.font, lk.padding, lay.sizer.measure)
                for label, b in zip(w.labels, tabs, strict=True):
                    if label == text:
                        found.append((e, b, f"tab of Tabs {e}"))
        elif isinstance(w, RadioGroup) and text in w.options and lay.sizer is not None:
            boxes = _radio_boxes(lay, e, w)
            found.append((e, boxes[w.options.index(text)], f"option of RadioGroup {e}"))
        elif isinstance(w, Dropdown) and w.open and text in w.options:
            first = state.dropdown_first.get(e, 0)
            for i, row in geo.dropdown_rows(box, len(w.options), w.max_rows, lay.size[1], first):
                if w.options[i] == text:
                    found.append((e, row, f"option of Dropdown {e}"))
        elif isinstance(w, (ScrollList, TreeView)) and lay.sizer is not None:
            lk = lay.sizer.look(e, type(w).__name__)
            texts = list(w.items) if isinstance(w, ScrollList) else [
                r[0].text for r in tree_rows(state, e, w)]  # fmt: skip
            row_h = lay.sizer.row_height(e, w.row_height, lk.font)
            thick = lay.sizer.theme.scrollbar * lay.scale
            view, _ = geo.list_view(box, len(texts), row_h, thick)
            for i in geo.visible_rows(view, len(texts), row_h, w.scroll):
                if texts[i] == text:
                    found.append((e, geo.row_box(view, i, row_h, w.scroll).intersect(view),
                                  f"row of {type(w).__name__} {e}"))  # fmt: skip
    return found


def _radio_boxes(lay: Layout, e: int, w: RadioGroup) -> list[Box]:
    from kge.ui.measure import width

    assert lay.sizer is not None
    lk = lay.sizer.look(e, "RadioGroup")
    line = lay.sizer.line(lk.font)
    s = lay.scale
    widths = [line + 8 * s + width(lay.sizer.measure, o, lk.font) for o in w.options]
    return geo.radio_options(lay.boxes[e], len(w.options), w.horizontal, widths, 12 * s)


def find(app: App, target: Target) -> int:
    """The entity of ``target`` (an entity id is checked to be a laid-out UI node)."""
    return _locate(app, target)[0]


def _locate(app: App, target: Target) -> tuple[int, Box]:
    lay = _layout(app)
    if isinstance(target, int) and not isinstance(target, bool):
        if app.world.try_get(target, UINode) is None:
            raise UITargetError(f"entity {target} is not a UI node")
        if target not in lay.boxes:
            raise UITargetError(f"UI node {target} is not shown (hidden, or its parent is)")
        box = _visible(lay, lay.boxes[target], target)
        if box.w < 1 or box.h < 1:
            raise UITargetError(
                f"UI node {target} is scrolled out of view: scroll to it (kge.testing.scroll) "
                "or focus it first (focusing scrolls it into view)"
            )
        return target, box
    if not isinstance(target, str):
        raise UITargetError(f"a target is an entity id or a text, got {target!r}")
    found = _candidates(app, target)
    if not found:
        shown = sorted({t for e in lay.order if (t := _text_of(lay.widget.get(e)))})
        raise UITargetError(
            f"no widget shows {target!r}; texts shown: {', '.join(map(repr, shown[:20]))}"
        )
    if len(found) > 1:
        what = ", ".join(f"{kind} (entity {e})" for e, _, kind in found)
        raise UITargetError(f"{len(found)} widgets show {target!r}: {what}; pass an entity")
    e, box, _ = found[0]
    box = _visible(lay, box, e)
    if box.w < 1 or box.h < 1:
        raise UITargetError(f"{target!r} is scrolled out of view: scroll to it first")
    return e, box


def box_of(app: App, target: Target) -> Box:
    """Where ``target`` is on screen (window pixels, the part that is visible)."""
    return _locate(app, target)[1]


def click(app: App, target: Target, *, button: int = Mouse.LEFT, modifiers: int = 0) -> int:
    """Click ``target`` at its centre and step once; returns its entity."""
    e, box = _locate(app, target)
    app.input.click(button, at=box.center, modifiers=modifiers)
    app.step()
    return e


def double_click(app: App, target: Target) -> int:
    """Two clicks on ``target`` within the double-click time (ScrollList / TreeView rows
    activate, a text field selects a word)."""
    e, box = _locate(app, target)
    app.input.click(at=box.center)
    app.step()
    app.input.click(at=box.center)
    app.step()
    return e


def focus(app: App, target: Target) -> int:
    """Give ``target`` the keyboard focus (scrolling it into view) and step once."""
    from kge.ui.focus import scroll_into_view

    e = _entity(app, target)
    state = app.world.resource(UIState)
    state.touch(state.focused, e)
    state.focused = e
    scroll_into_view(app.world, _layout(app), e)  # (as kge.focus does)
    app.step()
    return e


def _entity(app: App, target: Target) -> int:
    if isinstance(target, int) and not isinstance(target, bool):
        if app.world.try_get(target, UINode) is None:
            raise UITargetError(f"entity {target} is not a UI node")
        return target
    return _locate(app, target)[0]


def type_text(app: App, text: str, *, into: Target | None = None, submit: bool = False) -> None:
    """Type ``text`` (into the focused field, or focus ``into`` first), then step once;
    ``submit`` presses Enter after it."""
    if into is not None:
        focus(app, into)
    app.input.type_text(text)
    app.step()
    if submit:
        press(app, Key.ENTER)


def press(app: App, key: int, modifiers: int = 0) -> None:
    """Tap ``key`` (with ``modifiers``): down, one step, up, one step."""
    app.input.press(key, modifiers)
    app.step()
    app.input.release(key, modifiers)
    app.step()


def compose(app: App, text: str, caret: int = -1) -> None:
    """An input method's composition text (``""`` ends it), then one step."""
    app.input.compose(text, caret)
    app.step()


def drag(app: App, source: Target, to: Target | tuple[float, float], *, steps: int = 6) -> int:
    """Press on ``source``, move to ``to`` (a target or a window point) in ``steps``
    moves, release there; one App step per move. Returns the source entity."""
    e, box = _locate(app, source)
    end = to if isinstance(to, tuple) else _locate(app, to)[1].center
    start = box.center
    app.input.mouse_down(at=start)
    app.step()
    for k in range(1, steps + 1):
        t = k / steps
        app.input.move_mouse(start[0] + (end[0] - start[0]) * t, start[1] + (end[1] - start[1]) * t)
        app.step()
    app.input.mouse_up(at=end)
    app.step()
    return e


def scroll(app: App, target: Target, dy: float, dx: float = 0.0) -> None:
    """Turn the wheel over ``target`` (``dy`` > 0: up, as a wheel's notches), step once."""
    _, box = _locate(app, target)
    app.input.move_mouse(*box.center)
    app.input.scroll_by(dx, dy)
    app.step()


__all__ = [
    "UITargetError",
    "box_of",
    "click",
    "compose",
    "double_click",
    "drag",
    "find",
    "focus",
    "press",
    "scroll",
    "type_text",
]
