"""How each kind of widget answers the pointer and the navigation actions.

Called by :class:`kge.ui.interact.Frame` with the widget's entity and component:
``press``/``drag``/``release`` for the pointer (window pixels), ``action`` for
``"up"``, ``"down"``, ``"left"``, ``"right"``, ``"activate"``, ``"page_up"``,
``"page_down"``, ``"home"``, ``"end"`` (True when the widget used it; otherwise the
focus moves). Text editing is in :mod:`kge.ui.text_controls`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from kge.components.ui import (
    Button,
    ColorPicker,
    Dialog,
    Dropdown,
    RadioGroup,
    ScrollList,
    Slider,
    SpinBox,
    Tabs,
    TextArea,
    TextInput,
    Toggle,
    TreeView,
)
from kge.components.ui_widgets import hsv_to_rgb, lerp, rgb_to_hsv
from kge.ui import geometry as geo
from kge.ui import text_controls
from kge.ui.dialogs import close_dialog
from kge.ui.events import ButtonClicked, ItemActivated, ItemToggled, TextSubmitted
from kge.ui.layout import Box
from kge.ui.measure import width
from kge.ui.state import UIState

if TYPE_CHECKING:
    from kge.ui.interact import Frame

INTERACTIVE: tuple[type, ...] = (
    Button, Toggle, Slider, SpinBox, TextInput, TextArea, Dropdown, ScrollList, RadioGroup,
    Tabs, TreeView, ColorPicker,
)  # fmt: skip
PICKER_PARTS = ("hue", "sv_s", "sv_v", "alpha")


def is_interactive(w: Any) -> bool:
    return isinstance(w, INTERACTIVE)


# -- activation ----------------------------------------------------------------------------------
def activate(f: Frame, e: int, w: Any) -> None:
    if isinstance(w, Button):
        f.emit(ButtonClicked(e, w.text))
    elif isinstance(w, Toggle):
        w.value = not w.value
        f.changed(e, w.value, not w.value)
    elif isinstance(w, Dropdown):
        set_open(f, e, w, not w.open)
    elif isinstance(w, TextInput):
        f.emit(TextSubmitted(e, w.text))
    elif isinstance(w, (ScrollList, TreeView)):
        none = -1 if isinstance(w, ScrollList) else None
        if w.selected != none:
            f.emit(ItemActivated(e, w.selected))
    elif isinstance(w, (RadioGroup, Tabs)):
        items = w.options if isinstance(w, RadioGroup) else w.labels
        if items:
            select(f, e, w, (w.selected + 1) % len(items))
    elif isinstance(w, SpinBox):
        text_controls.begin_spin_edit(f, e, w)
    elif isinstance(w, ColorPicker):
        hsv = picker_hsv(f, e, w)
        parts = 4 if w.alpha else 3
        hsv[3] = (int(hsv[3]) + 1) % parts
        f.state.touch(e)


def select(f: Frame, e: int, w: Any, index: int) -> None:
    """Select ``index`` of an indexed picker (clamped to its items)."""
    items = (w.options if isinstance(w, (Dropdown, RadioGroup)) else
             w.items if isinstance(w, ScrollList) else w.labels)  # fmt: skip
    if not items:
        return
    index = min(max(index, 0), len(items) - 1)
    if index != w.selected:
        old, w.selected = w.selected, index
        f.changed(e, index, old)
    if isinstance(w, ScrollList):
        keep_row_visible(f, e, w, index)
    elif isinstance(w, Dropdown) and w.open:
        _dropdown_show(f, e, w, index)


# -- dropdowns -----------------------------------------------------------------------------------
def set_open(f: Frame, e: int, w: Dropdown, is_open: bool) -> None:
    if is_open and not w.options:
        return
    w.open = is_open
    if is_open:
        _dropdown_show(f, e, w, w.selected)


def _dropdown_show(f: Frame, e: int, w: Dropdown, index: int) -> None:
    """Scroll the open list so that option ``index`` is in it."""
    box = f.box(e)
    _, rows, _ = geo.dropdown_list(box, len(w.options), w.max_rows, f.size[1])
    first = f.state.dropdown_first.get(e, 0)
    if index < first:
        first = index
    elif index >= first + rows:
        first = index - rows + 1
    f.state.dropdown_first[e] = min(max(first, 0), max(len(w.options) - rows, 0))
    f.state.touch(e)


def close_dropdowns(f: Frame, keep: int | None = None) -> None:
    for e, w in f.layout.widget.items():
        if isinstance(w, Dropdown) and w.open and e != keep:
            w.open = False


def open_dropdown_rows(f: Frame, e: int, w: Dropdown) -> list[tuple[int, Box]]:
    first = f.state.dropdown_first.get(e, 0)
    return geo.dropdown_rows(f.box(e), len(w.options), w.max_rows, f.size[1], first)


def press_open_dropdown(f: Frame, p: tuple[float, float]) -> bool:
    """A press on an open dropdown's list (drawn over everything) picks the option."""
    for e, w in f.layout.widget.items():
        if not (isinstance(w, Dropdown) and w.open and e in f.layout.boxes):
            continue
        lst, _, _ = geo.dropdown_list(f.box(e), len(w.options), w.max_rows, f.size[1])
        if not lst.contains(p):
            continue
        for i, row in open_dropdown_rows(f, e, w):
            if row.contains(p):
                select(f, e, w, i)
                w.open = False
                f.focus(e)
        return True
    return False


def dropdown_wheel(f: Frame, p: tuple[float, float], dy: float) -> bool:
    for e, w in f.layout.widget.items():
        if isinstance(w, Dropdown) and w.open and e in f.layout.boxes:
            lst, rows, _ = geo.dropdown_list(f.box(e), len(w.options), w.max_rows, f.size[1])
            if lst.contains(p):
                first = f.state.dropdown_first.get(e, 0) - round(dy)
                f.state.dropdown_first[e] = min(max(first, 0), max(len(w.options) - rows, 0))
                f.state.touch(e)
                return True
    return False


# -- lists and trees -----------------------------------------------------------------------------
def list_metrics(f: Frame, e: int, w: ScrollList | TreeView,
                 count: int) -> tuple[Box, float, float]:  # fmt: skip
    """The rows' area, the row height and the largest scroll of a list or tree."""
    lk = f.look(e, "normal")
    row_h = f.sizer.row_height(e, w.row_height, lk.font)
    bar = f.sizer.theme.scrollbar * f.sizer.scale
    view, top = geo.list_view(f.box(e), count, row_h, bar)
    return view, row_h, top


def keep_row_visible(f: Frame, e: int, w: ScrollList | TreeView, index: int) -> None:
    count = len(w.items) if isinstance(w, ScrollList) else len(tree_rows(f.state, e, w))
    view, row_h, top = list_metrics(f, e, w, count)
    s = w.scroll
    if index * row_h < s:
        s = index * row_h
    elif (index + 1) * row_h > s + view.h:
        s = (index + 1) * row_h - view.h
    s = min(max(s, 0.0), top)
    if s != w.scroll:
        w.scroll = s


def tree_rows(state: UIState, e: int, w: TreeView) -> list[geo.Row]:
    """The tree's visible rows, cached until the tree changes."""
    key = ("tree", e)
    version = state.version(e)
    got = state.caches.get(key)
    if got is None or got[0] != version or got[1] is not w:
        got = (version, w, geo.tree_rows(w))
        state.caches[key] = got
    rows: list[geo.Row] = got[2]
    return rows


def _row_at(f: Frame, e: int, w: ScrollList | TreeView, count: int,
            p: tuple[float, float]) -> int | None:  # fmt: skip
    view, row_h, _ = list_metrics(f, e, w, count)
    if not view.contains(p):
        return None
    i = int((view.top - p[1] + w.scroll) // row_h)
    return i if 0 <= i < count else None


def _tree_press(f: Frame, e: int, w: TreeView, p: tuple[float, float]) -> None:
    rows = tree_rows(f.state, e, w)
    i = _row_at(f, e, w, len(rows), p)
    if i is None:
        return
    item, depth, has_kids = rows[i]
    view, row_h, _ = list_metrics(f, e, w, len(rows))
    arrow_x = view.x + depth * row_h * 0.8
    if has_kids and arrow_x <= p[0] < arrow_x + row_h:
        toggle_item(f, e, w, item.id)
        return
    if w.selected != item.id:
        old, w.selected = w.selected, item.id
        f.changed(e, item.id, old)
    if f.state.double_click(e, item.id):
        f.emit(ItemActivated(e, item.id))


def toggle_item(f: Frame, e: int, w: TreeView, item: Any, expand: bool | None = None) -> None:
    now = item in w.expanded
    want = (not now) if expand is None else expand
    if want == now:
        return
    w.expanded = w.expanded | {item} if want else w.expanded - {item}
    f.state.versions[e] = f.state.version(e) + 1
    f.emit(ItemToggled(e, item, want))


def _tree_action(f: Frame, e: int, w: TreeView, act: str) -> bool:
    rows = tree_rows(f.state, e, w)
    if not rows:
        return False
    ids = [r[0].id for r in rows]
    i = ids.index(w.selected) if w.selected in ids else -1
    view, row_h, _ = list_metrics(f, e, w, len(rows))
    page = max(int(view.h // row_h) - 1, 1)
    target = i
    if act in ("up", "down"):
        target = max(i - 1, 0) if act == "up" else min(i + 1, len(rows) - 1)
    elif act in ("page_up", "page_down"):
        target = max(i - page, 0) if act == "page_up" else min(i + page, len(rows) - 1)
    elif act in ("home", "end"):
        target = 0 if act == "home" else len(rows) - 1
    elif act == "right" and i >= 0:
        item, _, kids = rows[i]
        if kids and item.id not in w.expanded:
            toggle_item(f, e, w, item.id, True)
            return True
        target = i + 1 if kids and i + 1 < len(rows) else i
    elif act == "left" and i >= 0:
        item, _, kids = rows[i]
        if kids and item.id in w.expanded:
            toggle_item(f, e, w, item.id, False)
            return True
        if item.parent is not None and item.parent in ids:
            target = ids.index(item.parent)
    else:
        return False
    target = max(target, 0)
    if ids[target] != w.selected:
        old, w.selected = w.selected, ids[target]
        f.changed(e, w.selected, old)
    keep_row_visible(f, e, w, target)
    return True


# -- pointer ---------------------------------------------------------------------------------------
def press(f: Frame, e: int, w: Any, p: tuple[float, float], mods: int) -> None:
    box = f.box(e)
    if isinstance(w, Slider):
        drag_slider(f, e, w, p)
    elif isinstance(w, SpinBox):
        if text_controls.editing_spin(f, e):
            text_controls.press(f, e, w, p, mods)
            return
        minus, _, plus = geo.spin_parts(box)
        if minus.contains(p) or plus.contains(p):
            text_controls.spin_step(f, e, w, -1 if minus.contains(p) else 1)
        else:
            f.state.grab.update(spin=e, x=p[0], start=w.value, moved=False)
    elif isinstance(w, (TextInput, TextArea)):
        text_controls.press(f, e, w, p, mods)
    elif isinstance(w, Dropdown):
        set_open(f, e, w, not w.open)
    elif isinstance(w, ScrollList):
        i = _row_at(f, e, w, len(w.items), p)
        if i is not None:
            select(f, e, w, i)
            if f.state.double_click(e, i):
                f.emit(ItemActivated(e, i))
    elif isinstance(w, TreeView):
        _tree_press(f, e, w, p)
    elif isinstance(w, RadioGroup):
        for i, b in enumerate(radio_boxes(f, e, w)):
            if b.contains(p):
                select(f, e, w, i)
    elif isinstance(w, Tabs):
        bar = f.layout.tab_bar.get(e)
        if bar is not None:
            for i, b in enumerate(tab_boxes(f, e, w, bar)):
                if b.contains(p):
                    select(f, e, w, i)
    elif isinstance(w, ColorPicker):
        parts = geo.picker_parts(box, w.alpha)
        for name in ("sv", "hue", "alpha"):
            if name in parts and parts[name].contains(p):
                f.state.grab.update(picker=e, part=name)
                drag_picker(f, e, w, p)


def drag(f: Frame, e: int, w: Any, p: tuple[float, float]) -> None:
    if isinstance(w, Slider):
        drag_slider(f, e, w, p)
    elif isinstance(w, SpinBox) and f.state.grab.get("spin") == e:
        g = f.state.grab
        dx = p[0] - g["x"]
        if abs(dx) > 2:
            g["moved"] = True
        if g["moved"]:
            speed = w.drag_speed or (w.step or 1.0) / 4.0
            text_controls.set_spin(f, e, w, g["start"] + dx * speed)
    elif isinstance(w, (TextInput, TextArea)) or (
        isinstance(w, SpinBox) and text_controls.editing_spin(f, e)):  # fmt: skip
        text_controls.drag(f, e, w, p)
    elif isinstance(w, ColorPicker) and f.state.grab.get("picker") == e:
        drag_picker(f, e, w, p)


def release(f: Frame, e: int, w: Any, p: tuple[float, float], inside: bool) -> None:
    if isinstance(w, (Button, Toggle)) and inside:
        f.activate(e)
    elif isinstance(w, SpinBox):
        g = f.state.grab
        if g.get("spin") == e and not g.get("moved") and inside:
            text_controls.begin_spin_edit(f, e, w)
    f.state.grab.clear()


def drag_slider(f: Frame, e: int, w: Slider, p: tuple[float, float]) -> None:
    track, _ = geo.slider_track(f.box(e))
    t = min(max((p[0] - track.x) / max(track.w, 1.0), 0.0), 1.0)
    value = lerp(w.min, w.max, t)
    if w.step:
        value = _snap(value, w.min, w.step, w.max)
    if value != w.value:
        old, w.value = w.value, value
        f.changed(e, w.value, old)


def _snap(value: float, lo: float, step: float, hi: float) -> float:
    k = round((value - lo) / step)
    snapped = lo + k * step
    return min(max(snapped, lo), hi)


def nudge_slider(f: Frame, e: int, w: Slider, direction: int, big: bool = False) -> None:
    step = w.step or (w.max / 20.0 - w.min / 20.0)
    if big:
        step *= 5
    old = w.value
    value = old + direction * step
    w.value = min(max(value, w.min), w.max) if value == value else old
    if w.value != old:
        f.changed(e, w.value, old)


def picker_hsv(f: Frame, e: int, w: ColorPicker) -> list[float]:
    """The picker's hue, saturation, value and active part (kept while the colour's own
    hue is undefined: a grey)."""
    hsv = f.state.picker.get(e)
    if hsv is None or hsv_to_rgb(*hsv[:3]) != tuple(w.color[:3]):
        h, s, v = rgb_to_hsv(w.color)
        if hsv is not None and (s == 0 or v == 0):
            h = hsv[0]
        hsv = [h, s, v, hsv[3] if hsv is not None else 0.0]
        f.state.picker[e] = hsv
    return hsv


def set_picker(f: Frame, e: int, w: ColorPicker, h: float, s: float, v: float, a: int) -> None:
    hsv = picker_hsv(f, e, w)
    hsv[0], hsv[1], hsv[2] = h, s, v
    color = (*hsv_to_rgb(h, s, v), a)
    f.state.touch(e)
    if color != w.color:
        old, w.color = w.color, color
        f.changed(e, color, old)


def alpha_of(w: ColorPicker) -> int:
    return w.color[3] if len(w.color) > 3 else 255


def drag_picker(f: Frame, e: int, w: ColorPicker, p: tuple[float, float]) -> None:
    parts = geo.picker_parts(f.box(e), w.alpha)
    part = f.state.grab.get("part")
    h, s, v, _ = picker_hsv(f, e, w)
    a = alpha_of(w)
    if part == "sv":
        b = parts["sv"]
        s = min(max((p[0] - b.x) / max(b.w, 1.0), 0.0), 1.0)
        v = min(max((p[1] - b.y) / max(b.h, 1.0), 0.0), 1.0)
    elif part == "hue":
        b = parts["hue"]
        h = min(max((p[1] - b.y) / max(b.h, 1.0), 0.0), 0.999)
    elif part == "alpha" and "alpha" in parts:
        b = parts["alpha"]
        a = round(min(max((p[1] - b.y) / max(b.h, 1.0), 0.0), 1.0) * 255)
    set_picker(f, e, w, h, s, v, a)


def _picker_action(f: Frame, e: int, w: ColorPicker, act: str) -> bool:
    if act not in ("left", "right"):
        return False
    d = 1 if act == "right" else -1
    h, s, v, part = picker_hsv(f, e, w)
    a = alpha_of(w)
    name = PICKER_PARTS[int(part)]
    if name == "hue":
        h = (h + d / 36.0) % 1.0
    elif name == "sv_s":
        s = min(max(s + d * 0.05, 0.0), 1.0)
    elif name == "sv_v":
        v = min(max(v + d * 0.05, 0.0), 1.0)
    else:
        a = min(max(a + d * 15, 0), 255)
    set_picker(f, e, w, h, s, v, a)
    return True


def radio_boxes(f: Frame, e: int, w: RadioGroup) -> list[Box]:
    box = f.box(e)
    lk = f.look(e, "normal")
    line = f.sizer.line(lk.font)
    widths = [line + 8 * f.sizer.scale + width(f.sizer.measure, o, lk.font) for o in w.options]
    return geo.radio_options(box, len(w.options), w.horizontal, widths, 12 * f.sizer.scale)


def tab_boxes(f: Frame, e: int, w: Tabs, bar: Box) -> list[Box]:
    lk = f.look(e, "normal")
    return geo.tab_boxes(bar, w.labels, lk.font, lk.padding, f.sizer.measure)


def switch_tab(f: Frame, delta: int) -> bool:
    """Ctrl+Tab / a shoulder button: the tabs the focus is in (or on) switch pages."""
    e = f.state.focused
    while e is not None:
        w = f.widget(e)
        if isinstance(w, Tabs) and w.labels:
            select(f, e, w, (w.selected + delta) % len(w.labels))
            return True
        e = f.layout.parent.get(e)
    tabs = [k for k, w in f.layout.widget.items() if isinstance(w, Tabs) and w.labels
            and k in f.layout.boxes and f.reachable(k)]  # fmt: skip
    if len(tabs) == 1:
        w = f.widget(tabs[0])
        select(f, tabs[0], w, (w.selected + delta) % len(w.labels))
        return True
    return False


# -- actions -------------------------------------------------------------------------------------
def action(f: Frame, e: int, w: Any, act: str, mods: int) -> bool:
    if isinstance(w, Slider):
        if act in ("left", "right"):
            nudge_slider(f, e, w, 1 if act == "right" else -1)
            return True
        if act in ("page_up", "page_down"):
            nudge_slider(f, e, w, 1 if act == "page_up" else -1, big=True)
            return True
        if act in ("home", "end"):
            old = w.value
            w.value = w.min if act == "home" else w.max
            if w.value != old:
                f.changed(e, w.value, old)
            return True
        return False
    if isinstance(w, SpinBox):
        if act in ("left", "right"):
            text_controls.spin_step(f, e, w, 1 if act == "right" else -1)
            return True
        return False
    if isinstance(w, Dropdown):
        if w.open and act in ("up", "down", "page_up", "page_down", "home", "end"):
            d = {"up": -1, "down": 1, "page_up": -w.max_rows, "page_down": w.max_rows,
                 "home": -len(w.options), "end": len(w.options)}[act]  # fmt: skip
            select(f, e, w, w.selected + d)
            return True
        if act in ("left", "right") and w.options:
            select(f, e, w, w.selected + (1 if act == "right" else -1))
            return True
        return False
    if isinstance(w, ScrollList):
        if not w.items or act in ("left", "right", "activate"):
            if act == "activate" and w.selected >= 0:
                f.emit(ItemActivated(e, w.selected))
                return True
            return False
        view, row_h, _ = list_metrics(f, e, w, len(w.items))
        page = max(int(view.h // row_h) - 1, 1)
        step = {"up": -1, "down": 1, "page_up": -page, "page_down": page,
                "home": -len(w.items), "end": len(w.items)}.get(act)  # fmt: skip
        if step is None:
            return False
        select(f, e, w, (w.selected if w.selected >= 0 else -1 if step > 0 else 0) + step)
        return True
    if isinstance(w, TreeView):
        if act == "activate":
            if w.selected is not None:
                f.emit(ItemActivated(e, w.selected))
            return True
        return _tree_action(f, e, w, act)
    if isinstance(w, RadioGroup):
        back, fwd = ("left", "right") if w.horizontal else ("up", "down")
        if act in (back, fwd) and w.options:
            target = w.selected + (1 if act == fwd else -1)
            if not 0 <= target < len(w.options):
                return False  # past the ends: the focus moves on
            select(f, e, w, target)
            return True
        return False
    if isinstance(w, Tabs):
        if act in ("left", "right") and w.labels:
            select(f, e, w, (w.selected + (1 if act == "right" else -1)) % len(w.labels))
            return True
        return False
    if isinstance(w, ColorPicker):
        return _picker_action(f, e, w, act)
    return False


def cancel(f: Frame) -> bool:
    """Escape / gamepad B: close an open dropdown, else a modal dialog that allows it."""
    for w in f.layout.widget.values():
        if isinstance(w, Dropdown) and w.open:
            w.open = False
            return True
    if f.modal is not None:
        d = f.world.try_get(f.modal, Dialog)
        if d is not None and d.cancel:
            close_dialog(f, f.modal, -1, "")
            return True
    return False

