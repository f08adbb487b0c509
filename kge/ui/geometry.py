"""Where the parts of each widget are: one set of answers for the input handling and
the drawing, so a click always lands on the part drawn under it.

All functions are pure: a widget's box (window pixels), its look and the numbers
they need in, boxes out.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from kge.components.ui import ScrollList, TreeItem, TreeView
from kge.ui.layout import Box, ScrollArea
from kge.ui.measure import Font, TextMeasure, width
from kge.ui.theme import Theme

Row = tuple[TreeItem, int, bool]  #: a visible tree row: item, depth, has children


def slider_track(box: Box) -> tuple[Box, float]:
    """The slider's track and its knob radius."""
    knob = box.h / 2
    th = max(box.h / 4, 3.0)
    track = Box(box.x + knob, box.center[1] - th / 2, max(box.w - 2 * knob, 0.0), th)
    return track, max(knob - 2, 1.0)


def dropdown_list(box: Box, count: int, max_rows: int, window_h: float) -> tuple[Box, int, bool]:
    """The open list's box, how many rows it shows, and whether it opens upwards."""
    rows = max(min(count, max_rows), 1)
    h = rows * box.h
    below = box.y
    above = window_h - box.top
    up = h > below and above > below
    if up:
        rows = max(min(rows, int(above // box.h)), 1)
        return Box(box.x, box.top, box.w, rows * box.h), rows, True
    rows = max(min(rows, int(below // box.h)), 1) if below >= box.h else rows
    return Box(box.x, box.y - rows * box.h, box.w, rows * box.h), rows, False


def dropdown_rows(box: Box, count: int, max_rows: int, window_h: float,
                  first: int) -> list[tuple[int, Box]]:  # fmt: skip
    """(option index, row box) of the open list's visible rows, from option ``first``."""
    lst, rows, _ = dropdown_list(box, count, max_rows, window_h)
    first = min(max(first, 0), max(count - rows, 0))
    out = []
    for k in range(min(rows, count - first)):
        out.append((first + k, Box(lst.x, lst.top - (k + 1) * box.h, lst.w, box.h)))
    return out


def visible_rows(view: Box, count: int, row_h: float, scroll: float) -> range:
    """Indices of the rows of a virtual list in view (partly visible ones too).

    Only these are laid out and drawn: the cost does not depend on ``count``.
    """
    if count <= 0 or row_h <= 0 or view.h <= 0:
        return range(0)
    first = max(int(scroll // row_h), 0)
    last = min(math.ceil((scroll + view.h) / row_h), count)
    return range(min(first, count), last)


def row_box(view: Box, i: int, row_h: float, scroll: float) -> Box:
    return Box(view.x, view.top - (i + 1) * row_h + scroll, view.w, row_h)


def list_view(box: Box, count: int, row_h: float, bar: float) -> tuple[Box, float]:
    """The rows' area of a scroll list or tree (less a scrollbar when it overflows) and the
    largest scroll."""
    total = count * row_h
    inner = box
    if total > inner.h and bar > 0:
        inner = Box(inner.x, inner.y, max(inner.w - bar, 0.0), inner.h)
    return inner, max(total - inner.h, 0.0)


def list_rows(lst: ScrollList, box: Box, theme: Theme, scale: float = 1.0) -> list[tuple[int, Box]]:
    """(index, box) of a scroll list's rows in view, for code that hit-tests them itself
    (an editor's drag between rows). Rows are ``row_height`` (or the theme's) tall."""
    row_h = (lst.row_height or theme.row_height) * scale
    view, _ = list_view(box, len(lst.items), row_h, theme.scrollbar * scale)
    return [(i, row_box(view, i, row_h, lst.scroll).intersect(view))
            for i in visible_rows(view, len(lst.items), row_h, lst.scroll)]  # fmt: skip


def scrollbar(track: Box, view: float, content: float, scroll: float,
              vertical: bool = True) -> Box:  # fmt: skip
    """The thumb of a scrollbar in ``track`` for a ``view`` of ``content`` scrolled by
    ``scroll`` (pixels from the top, or the left)."""
    if content <= view or content <= 0:
        return track
    length = track.h if vertical else track.w
    size = max(length * view / content, min(24.0, length))
    room = length - size
    t = min(max(scroll / max(content - view, 1e-9), 0.0), 1.0)
    if vertical:
        return Box(track.x, track.top - size - room * t, track.w, size)
    return Box(track.x + room * t, track.y, size, track.h)


def scroll_tracks(area: ScrollArea, bar: float) -> tuple[Box | None, Box | None]:
    """The vertical and horizontal scrollbar tracks of a scroll view."""
    v = area.viewport
    ty = Box(v.right, v.y, bar, v.h) if area.bar_y else None
    tx = Box(v.x, v.y - bar, v.w, bar) if area.bar_x else None
    return ty, tx


def scroll_from_thumb(track: Box, view: float, content: float, pointer: float,
                      grab: float, vertical: bool = True) -> float:  # fmt: skip
    """The scroll that puts the thumb's grabbed point at ``pointer`` (y or x): ``grab``
    pixels below the thumb's top (vertical) or right of its left end."""
    thumb = scrollbar(track, view, content, 0.0, vertical)
    length = track.h if vertical else track.w
    size = thumb.h if vertical else thumb.w
    room = max(length - size, 1e-9)
    if vertical:
        t = (track.top - grab - pointer) / room
    else:
        t = (pointer - grab - track.x) / room
    return min(max(t, 0.0), 1.0) * max(content - view, 0.0)


def radio_options(box: Box, count: int, horizontal: bool, widths: Sequence[float],
                  gap: float) -> list[Box]:  # fmt: skip
    """Each option's box (circle and text) in a radio group; a row wider than the box is
    squeezed to fit it (the texts are cut)."""
    if horizontal:
        total = sum(widths[:count]) + gap * max(count - 1, 0)
        k = min(1.0, box.w / total) if total > 0 else 1.0
        out, x = [], box.x
        for i in range(count):
            w = (widths[i] if i < len(widths) else 0.0) * k
            out.append(Box(x, box.y, w, box.h))
            x += w + gap * k
        return out
    h = box.h / max(count, 1)
    return [Box(box.x, box.top - (i + 1) * h, box.w, h) for i in range(count)]


def tab_boxes(bar: Box, labels: Sequence[str], font: Font, pad: float, m: TextMeasure) -> list[Box]:
    """Each tab's box along the bar, as wide as its label (shrunk evenly to fit)."""
    widths = [width(m, t, font) + 2 * pad for t in labels]
    total = sum(widths)
    k = min(1.0, bar.w / total) if total > 0 else 1.0
    out, x = [], bar.x
    for w in widths:
        out.append(Box(x, bar.y, w * k, bar.h))
        x += w * k
    return out


def spin_parts(box: Box) -> tuple[Box, Box, Box]:
    """A spin box's ``-`` button, number field and ``+`` button."""
    b = min(box.h, box.w / 3)
    return (Box(box.x, box.y, b, box.h), Box(box.x + b, box.y, max(box.w - 2 * b, 0.0), box.h),
            Box(box.right - b, box.y, b, box.h))  # fmt: skip


def picker_parts(box: Box, alpha: bool) -> dict[str, Box]:
    """A colour picker's saturation/value square, hue bar, alpha bar and swatch."""
    gap = 6.0
    bar = max(min(box.w * 0.08, 22.0), 8.0)
    swatch_h = max(min(box.h * 0.14, 28.0), 10.0)
    bars = 2 if alpha else 1
    sv_w = max(box.w - bars * (bar + gap), 1.0)
    sv = Box(box.x, box.y + swatch_h + gap, sv_w, max(box.h - swatch_h - gap, 1.0))
    out = {"sv": sv, "hue": Box(sv.right + gap, sv.y, bar, sv.h),
           "swatch": Box(box.x, box.y, box.w, swatch_h)}  # fmt: skip
    if alpha:
        out["alpha"] = Box(sv.right + 2 * gap + bar, sv.y, bar, sv.h)
    return out


def tree_rows(tree: TreeView) -> list[Row]:
    """The rows a tree shows: roots then children (depth first, in list order), the
    children of closed items left out."""
    kids: dict[Any, list[TreeItem]] = {}
    for item in tree.items:
        kids.setdefault(item.parent, []).append(item)
    out: list[Row] = []
    stack: list[tuple[TreeItem, int]] = [(it, 0) for it in reversed(kids.get(None, []))]
    seen: set[Any] = set()
    while stack:
        item, depth = stack.pop()
        if item.id in seen:
            continue  # cannot happen in a checked tree; a guard against any cycle
        seen.add(item.id)
        children = kids.get(item.id, [])
        out.append((item, depth, bool(children)))
        if children and item.id in tree.expanded:
            stack.extend((c, depth + 1) for c in reversed(children))
    return out
