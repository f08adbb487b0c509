"""Drawing the widgets with rows and text: dropdowns, lists, trees, radio groups, tabs,
text fields, text areas, a spin box's number, and scrollbars.

Lists and trees draw only the rows in view, each in a fixed slot (the slot's label is
given the row's text as the list scrolls), so a 10,000-row list keeps about twenty
labels. Text fields clip their text to their inside.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from kge.components.ui import (
    Dropdown,
    RadioGroup,
    ScrollList,
    ScrollView,
    SpinBox,
    Tabs,
    TextArea,
    TextInput,
    TreeView,
)
from kge.render.ui_glyphs import chevron
from kge.ui import geometry as geo
from kge.ui.controls import tree_rows
from kge.ui.drag import TREE_KIND
from kge.ui.layout import Box
from kge.ui.measure import Font, elide, visible, width
from kge.ui.style import Look
from kge.ui.textview import area_view, field_view, shown_text

if TYPE_CHECKING:
    from kge.render.ui import Canvas, UIDrawer

Color = tuple[int, ...]  #: RGBA (themes and components always hold four channels)
CLEAR: Color = (0, 0, 0, 0)
TOP = 1_000_000


def _theme(d: UIDrawer) -> Any:
    assert d.sizer is not None
    return d.sizer.theme


def _bar(d: UIDrawer, c: Canvas, part: str, track: Box, view: float, content: float,
         scroll: float, vertical: bool = True, z: int | None = None) -> None:  # fmt: skip
    """A scrollbar: its track and thumb."""
    lk = d.look(c.e, "ScrollBar", "normal")
    grabbed = d.state.grab.get("bar") == c.e
    thumb = geo.scrollbar(track, view, content, scroll, vertical)
    r = min(track.w, track.h) / 2
    c.rect((part, "track"), track.inset(1), lk.background, 6, r, z=z)
    color = _theme(d).button_pressed if grabbed else _theme(d).text_muted
    c.rect((part, "thumb"), thumb.inset(2), color, 7, r, z=z)


def scrollbars(d: UIDrawer, c: Canvas) -> None:
    """A scroll view's scrollbars."""
    area = d.layout.scroll[c.e]
    sv = d.world.try_get(c.e, ScrollView)
    if sv is None:
        return
    bar = _theme(d).scrollbar * d.layout.scale
    ty, tx = geo.scroll_tracks(area, bar)
    if ty is not None:
        _bar(d, c, "vbar", ty, area.viewport.h, area.content_h, sv.scroll[1], True)
    if tx is not None:
        _bar(d, c, "hbar", tx, area.viewport.w, area.content_w, sv.scroll[0], False)


# -- dropdown --------------------------------------------------------------------------------------
def _dropdown(d: UIDrawer, c: Canvas, w: Dropdown, lk: Look) -> None:
    b = c.box
    c.rect("fill", b, lk.background, 2, lk.radius, lk.border_width, lk.border)
    arrow = min(b.h * 0.4, 16 * d.layout.scale)
    text = Box(b.x + lk.padding, b.y, max(b.w - 2 * lk.padding - arrow - 4, 0.0), b.h)
    c.line_of_text("value", w.value or "", text, lk.font, lk.text, "left")
    chevron(c, "arrow", b.right - lk.padding - arrow / 2, b.center[1], arrow,
            _theme(d).text_muted, "up" if w.open else "down")  # fmt: skip
    if not w.open or not w.options:
        return
    th = _theme(d)
    lst, rows, _ = geo.dropdown_list(b, len(w.options), w.max_rows, d.layout.size[1])
    c.rect("list", lst, (*th.panel[:3], 255), 0, min(lk.radius, 6.0), 1.0, th.panel_border,
           z=TOP)  # fmt: skip
    first = d.state.dropdown_first.get(c.e, 0)
    shown = geo.dropdown_rows(b, len(w.options), w.max_rows, d.layout.size[1], first)
    for k, (i, row) in enumerate(shown):
        if i == w.selected:
            c.rect(("sel", k), row.inset(2), th.button_pressed, 0, 4, z=TOP + 1)
        c.line_of_text(("opt", k), w.options[i], Box(row.x + lk.padding, row.y,
                       max(row.w - 2 * lk.padding, 0.0), row.h), lk.font, th.text, "left",
                       z=TOP + 2)  # fmt: skip
    if len(w.options) > rows:
        bar = th.scrollbar * d.layout.scale
        track = Box(lst.right - bar - 2, lst.y + 2, bar, lst.h - 4)
        _bar(d, c, "optbar", track, rows, len(w.options), first, True, z=TOP + 3)


# -- lists and trees -------------------------------------------------------------------------------
def _rows_area(d: UIDrawer, c: Canvas, w: ScrollList | TreeView, lk: Look,
               count: int) -> tuple[Box, float]:  # fmt: skip
    assert d.sizer is not None
    c.rect("bg", c.box, lk.background, 2, lk.radius, lk.border_width, lk.border)
    row_h = d.sizer.row_height(c.e, w.row_height, lk.font)
    bar = _theme(d).scrollbar * d.layout.scale
    view, top = geo.list_view(c.box, count, row_h, bar)
    if top > 0:
        track = Box(view.right, view.y, bar, view.h)
        _bar(d, c, "bar", track, view.h, count * row_h, min(w.scroll, top), True)
    c.clip_to(view.inset(1) if lk.border_width else view)
    return view, row_h


def _list(d: UIDrawer, c: Canvas, w: ScrollList, lk: Look) -> None:
    view, row_h = _rows_area(d, c, w, lk, len(w.items))
    pad = lk.padding
    th = _theme(d)
    scroll = w.scroll
    # parts are keyed by row, not by place: scrolling moves the labels in view and makes
    # only the rows scrolled in (a label re-laid for new text costs more than a move)
    for i in geo.visible_rows(view, len(w.items), row_h, scroll):
        row = geo.row_box(view, i, row_h, scroll)
        if i == w.selected:
            c.rect("sel", row, th.selection, 3, own=True)
        text = Box(row.x + pad, row.y, max(row.w - 2 * pad, 0.0), row.h)
        c.line_of_text(("row", i), w.items[i], text, lk.font, lk.text, "left", own=True)


def _tree(d: UIDrawer, c: Canvas, w: TreeView, lk: Look) -> None:
    rows = tree_rows(d.state, c.e, w)
    view, row_h = _rows_area(d, c, w, lk, len(rows))
    th = _theme(d)
    indent = row_h * 0.8
    for i in geo.visible_rows(view, len(rows), row_h, w.scroll):
        slot = i  # keyed by row: scrolling moves the parts in view (see _list)
        item, depth, kids = rows[i]
        row = geo.row_box(view, i, row_h, w.scroll)
        if item.id == w.selected:
            c.rect("sel", row, th.selection, 3, own=True)
        x = row.x + depth * indent
        if kids:
            way = "down" if item.id in w.expanded else "right"
            chevron(c, ("arrow", slot), x + row_h / 2, row.center[1], row_h * 0.35,
                    th.text_muted, way, own=True)  # fmt: skip
        x += row_h
        if item.icon is not None:
            side = row_h * 0.7
            c.image(("icon", slot), item.icon, Box(x, row.center[1] - side / 2, side, side), 4,
                    own=True)  # fmt: skip
            x += side + 4 * d.layout.scale
        c.line_of_text(("row", slot), item.text, Box(x, row.y, max(row.right - x, 0.0), row.h),
                       lk.font, lk.text, "left", own=True)  # fmt: skip
    drag = d.state.drag
    if drag is not None and drag.kind == TREE_KIND and drag.over == c.e and drag.started:
        _tree_drop_mark(d, c, w, rows, view, row_h, drag.at)


def _tree_drop_mark(d: UIDrawer, c: Canvas, w: TreeView, rows: list[Any], view: Box,
                    row_h: float, at: tuple[float, float]) -> None:  # fmt: skip
    if not view.contains(at):
        return
    i = int((view.top - at[1] + w.scroll) // row_h)
    if not 0 <= i < len(rows):
        return
    row = geo.row_box(view, i, row_h, w.scroll)
    k = (row.top - at[1]) / row_h
    accent = _theme(d).accent
    if k < 0.25 or k > 0.75:
        y = row.top if k < 0.25 else row.y
        c.line("dropline", (row.x + 4, y), (row.right - 4, y), 2.0, accent, 6, own=True)
    else:
        c.rect("dropbox", row.inset(1), CLEAR, 6, 4, 2, accent, own=True)


# -- radio groups and tabs -------------------------------------------------------------------------
def _radio(d: UIDrawer, c: Canvas, w: RadioGroup, lk: Look) -> None:
    m = d.measure
    line = m.line_height(lk.font)
    gap = 8 * d.layout.scale
    widths = [line + gap + width(m, o, lk.font) for o in w.options]
    boxes = geo.radio_options(c.box, len(w.options), w.horizontal, widths, 12 * d.layout.scale)
    for i, (opt, b) in enumerate(zip(w.options, boxes, strict=True)):
        side = min(b.h, line) * 0.8
        circle = Box(b.x + (line - side) / 2, b.center[1] - side / 2, side, side)
        c.rect(("ring", i), circle, lk.background, 2, side / 2, max(lk.border_width, 1.5),
               lk.accent if i == w.selected else lk.border)  # fmt: skip
        if i == w.selected:
            c.rect(("dot", i), circle.inset(side * 0.27), lk.accent, 3, side)
        text = Box(b.x + line + gap, b.y, max(b.right - b.x - line - gap, 0.0), b.h)
        c.line_of_text(("text", i), opt, text, lk.font, lk.text, "left")


def _tabs(d: UIDrawer, c: Canvas, w: Tabs, lk: Look) -> None:
    bar = d.layout.tab_bar.get(c.e)
    if bar is None:
        assert d.sizer is not None
        h = d.sizer.tab_bar(c.e, w)
        bar = Box(c.box.x, c.box.top - h, c.box.w, h)
    th = _theme(d)
    area = Box(c.box.x, c.box.y, c.box.w, max(bar.y - c.box.y, 0.0))
    c.rect("page", area, th.panel, 0, lk.radius * 0.5)
    boxes = geo.tab_boxes(bar, w.labels, lk.font, lk.padding, d.measure)
    for i, (label, b) in enumerate(zip(w.labels, boxes, strict=True)):
        state = "selected" if i == w.selected else "normal"
        tl = d.look(c.e, "Tabs", state)
        c.rect(("tab", i), Box(b.x + 1, b.y, max(b.w - 2, 0.0), b.h), tl.background, 2,
               tl.radius * 0.6)  # fmt: skip
        c.line_of_text(("label", i), label, b.inset(tl.padding / 2), tl.font, tl.text)
    c.rect("rule", Box(bar.x, bar.y - 1, bar.w, 2), lk.accent, 3)


# -- text ------------------------------------------------------------------------------------------
def _selection_rect(c: Canvas, part: Any, x0: float, x1: float, top: float, h: float,
                    color: Color) -> None:  # fmt: skip
    if x1 > x0:
        c.rect(part, Box(x0, top - h, x1 - x0, h), color, 3, own=True)


def _text_input(d: UIDrawer, c: Canvas, w: TextInput, lk: Look) -> None:
    b = c.box
    focused = d.state.focused == c.e
    th = _theme(d)
    edge = th.focus if focused else lk.border
    c.rect("field", b, lk.background, 2, lk.radius, max(lk.border_width, 1.0), edge)
    _field_text(d, c, w, lk, b, w.text, w.caret, w.anchor, w.placeholder, focused and not
                w.disabled)  # fmt: skip


def spin_text(d: UIDrawer, c: Canvas, w: SpinBox, lk: Look, field: Box) -> None:
    edit = d.state.spin.get(c.e)
    if edit is None:
        text = w.text() + w.suffix
        c.line_of_text("value", text, field.inset(2), lk.font, lk.text, "center", own=False)
        return
    _field_text(d, c, w, lk, field, edit.text, edit.caret, edit.anchor, "", True)


def _field_text(d: UIDrawer, c: Canvas, w: Any, lk: Look, box: Box, text: str, caret: int,
                anchor: int, placeholder: str, editing: bool) -> None:  # fmt: skip
    assert d.sizer is not None
    fv = field_view(d.sizer, d.state, c.e, text, caret, box, lk, shown_text(w, text))
    c.clip_to(fv.area)
    m = d.measure
    lh, asc = m.line_height(lk.font), m.ascent(lk.font)
    top = box.center[1] + lh / 2
    th = _theme(d)
    sel = (min(anchor, caret), max(anchor, caret)) if 0 <= anchor != caret else None
    if editing and sel is not None:
        _selection_rect(c, "sel", fv.x_of(sel[0]), fv.x_of(sel[1]), top, lh, th.selection)
    if fv.shown:
        c.label("text", visible(fv.shown), fv.area.x - fv.scroll, top - asc, lk.font, lk.text,
                 4, own=True)  # fmt: skip
    elif placeholder:
        c.label("text", elide(m, visible(placeholder), lk.font, fv.area.w), fv.area.x,
                top - asc, lk.font, th.text_muted, 4, own=True)  # fmt: skip
    comp = d.state.composition
    if comp is not None and comp[0] == c.e:
        x0, x1 = fv.x_of(caret), fv.x_of(caret + len(comp[1]))
        c.rect("ime", Box(x0, top - lh + 2, max(x1 - x0, 1.0), 2), lk.text, 5, own=True)
        caret = caret + comp[2]
    if editing and int(d.state.time * 2.0) % 2 == 0:
        cx = fv.x_of(caret)
        c.rect("caret", Box(cx, top - lh, max(2 * d.layout.scale, 1.0), lh), lk.text, 5, own=True)


def _text_area(d: UIDrawer, c: Canvas, w: TextArea, lk: Look) -> None:
    assert d.sizer is not None
    b = c.box
    focused = d.state.focused == c.e
    th = _theme(d)
    c.rect("field", b, lk.background, 2, lk.radius, max(lk.border_width, 1.0),
           th.focus if focused else lk.border)  # fmt: skip
    av = area_view(d.sizer, d.state, c.e, w, b, lk)
    scroll = min(w.scroll, av.max_scroll)
    if av.bar:
        bar = th.scrollbar * d.layout.scale
        _bar(d, c, "bar", Box(av.view.right, av.view.y, bar, av.view.h), av.view.h,
             av.view.h + av.max_scroll, scroll)  # fmt: skip
    c.clip_to(av.view)
    m = d.measure
    font: Font = av.font
    asc = m.ascent(font)
    first = max(int(scroll // av.line_h), 0)
    count = int(av.view.h // av.line_h) + 2
    sel = w.selection if focused else None
    if not w.text and w.placeholder:
        c.label(("line", 0), visible(w.placeholder), av.view.x, av.view.top - asc, font,
                th.text_muted, 4, own=True)  # fmt: skip
    for i in range(first, min(first + count, len(av.lines))):
        slot = i  # keyed by line: scrolling moves the labels in view
        a, z = av.lines[i]
        top = av.line_top(i, scroll)
        if sel is not None and sel[0] <= z and sel[1] >= a:
            s0, s1 = max(sel[0], a), min(sel[1], z)
            x0 = av.view.x + width(m, w.text[a:s0], font)
            x1 = av.view.x + width(m, w.text[a:s1], font) + (4 if sel[1] > z else 0)
            _selection_rect(c, ("sel", slot), x0, x1, top, av.line_h, th.selection)
        c.label(("line", slot), visible(w.text[a:z]), av.view.x, top - asc, font, lk.text, 4,
                own=True)  # fmt: skip
    if focused and not w.disabled and int(d.state.time * 2.0) % 2 == 0:
        line = av.line_of(w.caret)
        a, _ = av.lines[line]
        cx = av.view.x + width(m, w.text[a : w.caret], font)
        top = av.line_top(line, scroll)
        c.rect("caret", Box(cx, top - av.line_h, max(2 * d.layout.scale, 1.0), av.line_h),
               lk.text, 5, own=True)  # fmt: skip


PAINTERS: dict[type, Any] = {
    Dropdown: _dropdown, ScrollList: _list, TreeView: _tree, RadioGroup: _radio, Tabs: _tabs,
    TextInput: _text_input, TextArea: _text_area,
}  # fmt: skip
