"""Layout: the window-pixel box of every visible UI node, from its UINode and the window size.

Two passes over the tree: *measure* resolves sizes (pixels, percents of the parent's
inner box, ``"auto"`` from the children or the widget's measured text, then
``min``/``max``), *place* puts children in rows, columns, grids or at their anchors,
sharing a row's spare room by ``grow`` and its overflow by ``shrink``. Scroll views
place their children in a content box moved by the scroll offset and clip them;
tabs lay out only the selected page; dialogs are drawn (and hit) above the rest.
Design pixels are multiplied by the UI scale (:mod:`kge.ui.settings`).

Every box is finite: pixel inputs are at most 1e7 (checked at the write) and sizes
are clamped to 1e7, so no nesting can overflow.

>>> from kge.world import World
>>> from kge.components.ui import UINode
>>> w = World()
>>> menu = w.spawn(UINode(anchor="top_right", offset=(-10, -10), width=200, height="50%",
...                       layout="column", padding=5, spacing=4, align="stretch"))
>>> a = w.spawn(UINode(parent=menu, height=30))
>>> b = w.spawn(UINode(parent=menu, height=30, grow=1))
>>> boxes = compute_layout(w, (800, 600)).boxes
>>> boxes[menu]
Box(x=590.0, y=290.0, w=200.0, h=300.0)
>>> boxes[a], boxes[b]       # b grows into the room a leaves
(Box(x=595.0, y=555.0, w=190.0, h=30.0), Box(x=595.0, y=295.0, w=190.0, h=256.0))
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, NamedTuple

from kge.components.ui import (
    ANCHORS,
    MAX_PIXELS,
    WIDGETS,
    Dialog,
    ScrollView,
    Size,
    Style,
    Tabs,
    UINode,
)
from kge.ui.measure import TableMeasure, TextMeasure
from kge.ui.sizing import Sizer
from kge.ui.theme import DEFAULT_THEME, Theme
from kge.world import World

#: the deepest nesting of UI nodes (the parent check refuses deeper ones)
MAX_DEPTH = 100
#: a dialog's nodes are drawn this many depth levels above the base UI
DIALOG_LAYER = 4096
_CELL = 64.0  #: pixels per cell of the hit-test grid


class Box(NamedTuple):
    """A rectangle in window pixels, origin bottom-left (a named tuple: layouts make
    thousands)."""

    x: float
    y: float
    w: float
    h: float

    @property
    def right(self) -> float:
        return self.x + self.w

    @property
    def top(self) -> float:
        return self.y + self.h

    @property
    def center(self) -> tuple[float, float]:
        return (self.x + self.w / 2, self.y + self.h / 2)

    def contains(self, p: tuple[float, float]) -> bool:
        return self.x <= p[0] < self.x + self.w and self.y <= p[1] < self.y + self.h

    def inset(self, d: float) -> Box:
        return Box(self.x + d, self.y + d, max(self.w - 2 * d, 0.0), max(self.h - 2 * d, 0.0))

    def moved(self, dx: float, dy: float) -> Box:
        return Box(self.x + dx, self.y + dy, self.w, self.h)

    def intersect(self, other: Box | None) -> Box:
        if other is None:
            return self
        x0, y0 = max(self.x, other.x), max(self.y, other.y)
        x1, y1 = min(self.right, other.right), min(self.top, other.top)
        return Box(x0, y0, max(x1 - x0, 0.0), max(y1 - y0, 0.0))


#: a child's box and clip, as a parent's layout hands it to ``place``
Placed = tuple[int, "Box", "Box | None"]


@dataclass(slots=True)
class ScrollArea:
    """What a scroll view's layout found: its viewport, content size and scroll range."""

    viewport: Box
    content_w: float
    content_h: float
    max_x: float
    max_y: float
    bar_y: bool  #: a vertical scrollbar is shown
    bar_x: bool


@dataclass(slots=True)
class Layout:
    """The result: boxes by entity, the visible nodes in draw order (parents first,
    dialogs last) and what the input handling and drawing need to know of them."""

    boxes: dict[int, Box] = field(default_factory=dict)
    order: list[int] = field(default_factory=list)
    widget: dict[int, Any] = field(default_factory=dict)  #: entity -> its widget component
    depth: dict[int, int] = field(default_factory=dict)  #: draw level (roots 0; dialogs high)
    clip: dict[int, Box] = field(default_factory=dict)  #: visible part, for clipped nodes
    scroll: dict[int, ScrollArea] = field(default_factory=dict)
    tab_bar: dict[int, Box] = field(default_factory=dict)
    parent: dict[int, int | None] = field(default_factory=dict)
    dialog: dict[int, int] = field(default_factory=dict)  #: entity -> its dialog (if inside one)
    follow: dict[int, tuple[int, tuple[float, float]]] = field(default_factory=dict)
    nodes: dict[int, UINode] = field(default_factory=dict)  #: every UI node, shown or not
    #: what each node's size was computed from: its UINode's fields and, for an "auto"
    #: size, its widget's natural size (a write that changes neither needs no new layout)
    shape: dict[int, tuple[Any, ...]] = field(default_factory=dict)
    natural: dict[int, tuple[float, float]] = field(default_factory=dict)
    modal: int | None = None  #: the modal dialog drawn on top, if one is shown
    sizer: Sizer | None = None
    size: tuple[int, int] = (0, 0)
    scale: float = 1.0
    version: int = 0  #: bumped by every full layout
    _cells: dict[tuple[int, int], list[int]] | None = field(default=None, repr=False)

    def hit(self, point: tuple[float, float], accept: Callable[[int], bool]) -> int | None:
        """The topmost node under ``point`` that ``accept`` takes, or None.

        Looked up in a grid of 64-pixel cells (built on the first hit after a layout),
        so a pointer move over 1,000 widgets tests the few under it.
        """
        cells = self._cells
        if cells is None:
            cells = self._cells = self._index()
        for e in cells.get((int(point[0] // _CELL), int(point[1] // _CELL)), ()):
            if self.visible_box(e).contains(point) and accept(e):
                return e
        return None

    def _index(self) -> dict[tuple[int, int], list[int]]:
        cells: dict[tuple[int, int], list[int]] = {}
        for e in reversed(self.order):  # topmost first
            b = self.visible_box(e)
            if b.w <= 0 or b.h <= 0:
                continue
            x0, x1 = int(b.x // _CELL), int((b.x + b.w) // _CELL)
            y0, y1 = int(b.y // _CELL), int((b.y + b.h) // _CELL)
            if (x1 - x0 + 1) * (y1 - y0 + 1) > 4096:  # larger than the window: clip to it
                x0, y0 = max(x0, -1), max(y0, -1)
                x1 = min(x1, int(self.size[0] // _CELL) + 1)
                y1 = min(y1, int(self.size[1] // _CELL) + 1)
            for cx in range(x0, x1 + 1):
                for cy in range(y0, y1 + 1):
                    cells.setdefault((cx, cy), []).append(e)
        return cells

    def moved(self) -> None:
        """Boxes were moved in place (nodes following an entity): hit anew."""
        self._cells = None

    def visible_box(self, e: int) -> Box:
        """The node's box cut by the scroll views around it."""
        b = self.boxes[e]
        c = self.clip.get(e)
        return b if c is None else b.intersect(c)

    def subtree(self, root: int) -> list[int]:
        """``root`` and the laid-out nodes under it."""
        out = [root]
        kids: dict[int, list[int]] = {}
        for e in self.order:
            p = self.parent.get(e)
            if p is not None:
                kids.setdefault(p, []).append(e)
        i = 0
        while i < len(out):
            out.extend(kids.get(out[i], ()))
            i += 1
        return out


def _finite(v: float) -> float:
    if 0.0 <= v <= MAX_PIXELS:
        return v
    return MAX_PIXELS if v > MAX_PIXELS else 0.0  # NaN and negatives: 0


def _clamp(v: float, lo: float | None, hi: float | None, s: float) -> float:
    if hi is not None:
        v = min(v, hi * s)
    if lo is not None:
        v = max(v, lo * s)
    return _finite(v)


class _Solver:
    def __init__(self, world: World, sizer: Sizer, s: float,
                 to_screen: Callable[[int, tuple[float, float]], tuple[float, float] | None] | None,
                 ) -> None:  # fmt: skip
        self.sizer, self.s, self.to_screen = sizer, s, to_screen
        self.nodes: dict[int, UINode] = {e: n for e, (n,) in world.query(UINode)}
        self.kids: dict[int | None, list[int]] = {}
        for e, n in sorted(self.nodes.items(), key=lambda kv: (kv[1].order, kv[0])):
            if not n.visible:
                continue
            p = n.parent
            if p is not None and p not in self.nodes:
                continue  # its parent is gone: it is not shown
            self.kids.setdefault(p, []).append(e)
        self.widget: dict[int, Any] = {}
        for t in reversed(WIDGETS):  # the first kind in WIDGETS wins
            found: Any = world.query(t)
            for e, (c,) in found:
                if e in self.nodes:
                    self.widget[e] = c
        self.scrolls: dict[int, ScrollView] = {
            e: c for e, (c,) in world.query(ScrollView) if e in self.nodes
        }
        self.dialogs: dict[int, Dialog] = {
            e: d for e, (d,) in world.query(Dialog) if e in self.nodes
        }
        self.out = Layout(widget=self.widget, sizer=sizer, scale=s, nodes=self.nodes)
        self._measured: dict[tuple[int, float, float], tuple[float, float]] = {}
        self._dialog_stack: list[int] = []

    # -- measure -------------------------------------------------------------------------------
    def measure(self, e: int, aw: float, ah: float) -> tuple[float, float]:
        key = (e, aw, ah)
        got = self._measured.get(key)
        if got is None:
            n, s = self.nodes[e], self.s
            w = self._dim(n.width, aw, None)
            if w is None:
                w = self.content(e, aw, ah)[0]
            w = _clamp(w, n.min_width, n.max_width, s)
            h = self._dim(n.height, ah, None)
            if h is None:
                h = self.content(e, w if n.width != "auto" else aw, ah)[1]
            got = (w, _clamp(h, n.min_height, n.max_height, s))
            self._measured[key] = got
        return got

    def _dim(self, value: Size, avail: float, auto: float | None) -> float | None:
        if isinstance(value, float | int):
            return float(value) * self.s
        if value == "auto":
            return auto
        return max(avail, 0.0) * float(value[:-1]) / 100.0

    def content(self, e: int, aw: float, ah: float) -> tuple[float, float]:
        n = self.nodes[e]
        widget = self.widget.get(e)
        pad = n.padding * self.s
        iw, ih = (0.0, 0.0) if widget is None else self.sizer.intrinsic(e, widget, aw - 2 * pad)
        self.out.natural[e] = (iw, ih)
        kids = self.kids.get(e, [])
        if isinstance(widget, Tabs):
            bar = self.sizer.tab_bar(e, widget)
            page = kids[widget.selected] if 0 <= widget.selected < len(kids) else None
            if page is None:
                return (iw + 2 * pad, bar + 2 * pad)
            pw, ph = self.measure(page, aw - 2 * pad, ah - 2 * pad - bar)
            return (max(pw, iw) + 2 * pad, ph + bar + 2 * pad)
        title = self._title(e)
        if not kids:
            return (iw, ih + title)
        cw, ch = self._kids_extent(n, kids, aw - 2 * pad, ah - 2 * pad - title)
        sv = self.scrolls.get(e)
        if sv is not None:  # a scroll view never outgrows the room it has where it scrolls
            bar = self.sizer.theme.scrollbar * self.s if sv.scrollbar else 0.0
            if sv.vertical:
                ch = min(ch, max(ah - 2 * pad - title, 0.0))
                cw += bar if sv.scrollbar else 0.0
            if sv.horizontal:
                cw = min(cw, max(aw - 2 * pad, 0.0))
        return (max(cw + 2 * pad, iw), max(ch + 2 * pad + title, ih))

    def _title(self, e: int) -> float:
        d = self.dialogs.get(e)
        return self.sizer.title_bar(e, d.title) if d is not None else 0.0

    def _kids_extent(self, n: UINode, kids: list[int], aw: float, ah: float) -> tuple[float, float]:
        sp = n.spacing * self.s
        ws: list[float] = []
        hs: list[float] = []
        for k in kids:  # a loop, not a comprehension: one stack frame less per level
            kw, kh = self.measure(k, aw, ah)
            ws.append(kw)
            hs.append(kh)
        gaps = sp * (len(kids) - 1)
        if n.layout == "row":
            return (sum(ws) + gaps, max(hs))
        if n.layout == "column":
            return (max(ws), sum(hs) + gaps)
        if n.layout == "grid":
            cols = min(n.columns, len(kids))
            rows = [hs[i : i + n.columns] for i in range(0, len(hs), n.columns)]
            tall = sum(max(r) for r in rows) + sp * (len(rows) - 1)
            return (max(ws) * cols + sp * (cols - 1), tall)
        return (max(ws), max(hs))

    # -- place ---------------------------------------------------------------------------------
    # Children's boxes are computed by the helpers below and placed by ``place`` itself,
    # one stack frame per nesting level (a 256-deep nest stays far from Python's limit).
    def place(self, e: int, box: Box, depth: int, clip: Box | None, parent: int | None) -> None:
        out = self.out
        if e in out.boxes:
            return  # a parent cycle written behind the validators' back: drawn once
        box = Box(box.x, box.y, _finite(box.w), _finite(box.h))
        dialog = e in self.dialogs
        if dialog:
            self._dialog_stack.append(e)
            depth = DIALOG_LAYER * len(self._dialog_stack)
        out.boxes[e] = box
        out.shape[e] = node_shape(self.nodes[e])
        out.order.append(e)
        out.depth[e] = depth
        out.parent[e] = parent
        if clip is not None:
            out.clip[e] = clip
        if self._dialog_stack:
            out.dialog[e] = self._dialog_stack[-1]
        try:
            for k, b, c in self._children(e, box, clip):
                self.place(k, b, depth + 1, c, e)
        finally:
            if dialog:
                self._dialog_stack.pop()

    def _children(self, e: int, box: Box, clip: Box | None) -> list[Placed]:
        n = self.nodes[e]
        kids = self.kids.get(e, [])
        if not kids:
            return []
        inner = box.inset(n.padding * self.s)
        title = self._title(e)
        if title:
            inner = Box(inner.x, inner.y, inner.w, max(inner.h - title, 0.0))
        widget = self.widget.get(e)
        if isinstance(widget, Tabs):
            bar = self.sizer.tab_bar(e, widget)
            self.out.tab_bar[e] = Box(inner.x, inner.top - bar, inner.w, bar)
            if not 0 <= widget.selected < len(kids):
                return []
            page = kids[widget.selected]
            area = Box(inner.x, inner.y, inner.w, max(inner.h - bar, 0.0))
            pn = self.nodes[page]
            w, h = self.measure(page, area.w, area.h)
            w = area.w if pn.width == "auto" else w
            h = area.h if pn.height == "auto" else h
            return [(page, self._anchored(pn, area, w, h), clip)]
        sv = self.scrolls.get(e)
        if sv is not None:
            return self._scroll(e, n, sv, kids, inner, clip)
        return self._arrange(n, kids, inner, clip)

    def _arrange(self, n: UINode, kids: list[int], inner: Box, clip: Box | None) -> list[Placed]:
        sizes = []
        for k in kids:
            sizes.append(self.measure(k, inner.w, inner.h))
        if n.layout == "grid":
            return self._grid(n, kids, sizes, inner, clip)
        if n.layout in ("row", "column"):
            return self._line(n, kids, sizes, inner, clip)
        return [(k, self._anchored(self.nodes[k], inner, w, h), clip)
                for k, (w, h) in zip(kids, sizes, strict=True)]  # fmt: skip

    def _scroll(self, e: int, n: UINode, sv: ScrollView, kids: list[int], inner: Box,
                clip: Box | None) -> list[Placed]:  # fmt: skip
        bar = self.sizer.theme.scrollbar * self.s if sv.scrollbar else 0.0
        cw, ch = self._kids_extent(n, kids, inner.w, inner.h)
        bar_y = sv.vertical and ch > inner.h + 0.5
        bar_x = sv.horizontal and cw > inner.w - (bar if bar_y else 0.0) + 0.5
        bar_y = bar_y or (sv.vertical and bar_x and ch > inner.h - bar + 0.5)
        view = Box(inner.x, inner.y + (bar if bar_x else 0.0),
                   max(inner.w - (bar if bar_y else 0.0), 0.0),
                   max(inner.h - (bar if bar_x else 0.0), 0.0))  # fmt: skip
        if bar_y or bar_x:  # less room: measure again (wrapped text grows taller)
            cw, ch = self._kids_extent(n, kids, view.w, view.h)
        content_w = max(view.w, cw) if sv.horizontal else view.w
        content_h = max(view.h, ch) if sv.vertical else view.h
        max_x, max_y = _finite(content_w - view.w), _finite(content_h - view.h)
        sx = min(max(sv.scroll[0], 0.0), max_x)
        sy = min(max(sv.scroll[1], 0.0), max_y)
        if (sx, sy) != sv.scroll:  # past the end: clamped (documented), not marked changed
            object.__setattr__(sv, "scroll", (sx, sy))
        shown = sv.scrollbar  # (without bars, bar_x / bar_y took no room: bar is 0)
        self.out.scroll[e] = ScrollArea(view, content_w, content_h, max_x, max_y,
                                        bar_y and shown, bar_x and shown)  # fmt: skip
        content = Box(view.x - sx, view.top + sy - content_h, content_w, content_h)
        return self._arrange(n, kids, content, view.intersect(clip))

    def _anchored(self, n: UINode, inner: Box, w: float, h: float) -> Box:
        ax, ay = ANCHORS[n.anchor]
        return Box(
            inner.x + ax * (inner.w - w) + n.offset[0] * self.s,
            inner.y + ay * (inner.h - h) + n.offset[1] * self.s,
            w,
            h,
        )

    def _flex(self, kids: list[int], main: list[float], room: float, row: bool) -> list[float]:
        """Share spare room by ``grow`` or overflow by ``shrink``, within min/max."""
        s = self.s
        nodes = [self.nodes[k] for k in kids]
        free = room - sum(main)
        sizes = list(main)
        active = set(range(len(kids)))
        for _ in range(len(kids)):  # each pass freezes the children that hit a limit
            if abs(free) < 1e-9 or not active:
                break
            if free > 0:
                weights = {i: nodes[i].grow for i in active}
            else:
                weights = {i: self._shrink(kids[i], nodes[i], row) * max(sizes[i], 0.0)
                           for i in active}  # fmt: skip
            total = sum(weights.values())
            if total <= 0:
                break
            spent = 0.0
            frozen = set()
            for i, wgt in weights.items():
                if wgt <= 0:
                    frozen.add(i)
                    continue
                nd = nodes[i]
                lo, hi = (nd.min_width, nd.max_width) if row else (nd.min_height, nd.max_height)
                want = sizes[i] + free * wgt / total
                got = _clamp(want, lo, hi, s)
                if got != want:
                    frozen.add(i)
                spent += got - sizes[i]
                sizes[i] = got
            free -= spent
            active -= frozen
            if not frozen:
                break
        return sizes

    def _shrink(self, e: int, n: UINode, row: bool) -> float:
        """A node's shrink weight: its own, or 1 for an auto-sized scroll view (it scrolls
        what does not fit instead of overflowing its parent)."""
        sv = self.scrolls.get(e)
        if n.shrink == 0 and sv is not None and (sv.horizontal if row else sv.vertical):
            return 1.0 if (n.width if row else n.height) == "auto" else 0.0
        return n.shrink

    def _line(self, parent: UINode, kids: list[int], sizes: list[tuple[float, float]],
              inner: Box, clip: Box | None) -> list[Placed]:  # fmt: skip
        row = parent.layout == "row"
        sp, align = parent.spacing * self.s, parent.align
        main = [z[0] if row else z[1] for z in sizes]
        room = (inner.w if row else inner.h) - sp * (len(kids) - 1)
        main = self._flex(kids, main, room, row)
        total = sum(main) + sp * (len(kids) - 1)
        left = (inner.w if row else inner.h) - total
        pos = {"start": 0.0, "center": left / 2, "end": left}[parent.justify]
        cross_room = inner.h if row else inner.w
        frac = {"start": 1.0 if row else 0.0, "center": 0.5, "end": 0.0 if row else 1.0,
                "stretch": 0.5}[align]  # fmt: skip
        out: list[Placed] = []
        for k, (w, h), m in zip(kids, sizes, main, strict=True):
            node = self.nodes[k]
            cross = h if row else w
            if align == "stretch" and (node.height if row else node.width) == "auto":
                lo, hi = (node.min_height, node.max_height) if row else (
                    node.min_width, node.max_width)  # fmt: skip
                cross = _clamp(cross_room, lo, hi, self.s)
            c = (cross_room - cross) * frac
            if row:
                b = Box(inner.x + pos, inner.y + c, m, cross)
            else:
                b = Box(inner.x + c, inner.top - pos - m, cross, m)
            out.append((k, b.moved(node.offset[0] * self.s, node.offset[1] * self.s), clip))
            pos += m + sp
        return out

    def _grid(self, parent: UINode, kids: list[int], sizes: list[tuple[float, float]],
              inner: Box, clip: Box | None) -> list[Placed]:  # fmt: skip
        cols, sp = parent.columns, parent.spacing * self.s
        cell_w = max((inner.w - sp * (cols - 1)) / cols, 0.0)
        top = inner.top
        out: list[Placed] = []
        for r in range(0, len(kids), cols):
            row_h = max(z[1] for z in sizes[r : r + cols])
            for c, k in enumerate(kids[r : r + cols]):
                w, h = sizes[r + c]
                node = self.nodes[k]
                w = cell_w if node.width == "auto" else min(w, cell_w)
                b = Box(inner.x + c * (cell_w + sp), top - row_h + (row_h - h) / 2, w, h)
                out.append((k, b.moved(node.offset[0] * self.s, node.offset[1] * self.s), clip))
            top -= row_h + sp
        return out

    # -- roots ---------------------------------------------------------------------------------
    def roots(self, window: Box) -> None:
        for e in self.kids.get(None, []):
            n = self.nodes[e]
            w, h = self.measure(e, window.w, window.h)
            if n.follow is None:
                self.place(e, self._anchored(n, window, w, h), 0, None, None)
                continue
            point = self.to_screen(n.follow, n.follow_offset) if self.to_screen else None
            if point is None:
                continue  # the followed entity is gone (or has no place): not shown
            ax, ay = ANCHORS[n.anchor]
            x = point[0] - ax * w + n.offset[0] * self.s
            y = point[1] - ay * h + n.offset[1] * self.s
            if not (math.isfinite(x) and math.isfinite(y)):
                continue
            self.out.follow[e] = (n.follow, point)
            self.place(e, Box(x, y, w, h), 0, None, None)
            continue
        # dialogs last: drawn over, and hit before, everything else (stable otherwise)
        order = self.out.order
        order.sort(key=lambda k: self.out.depth[k] // DIALOG_LAYER)
        modal = [e for e in order if e in self.dialogs and self.dialogs[e].modal]
        self.out.modal = modal[-1] if modal else None


def node_shape(n: UINode) -> tuple[Any, ...]:
    """The UINode fields a layout reads."""
    return (n.anchor, n.offset, n.width, n.height, n.parent, n.layout, n.padding, n.spacing,
            n.align, n.justify, n.columns, n.visible, n.order, n.min_width, n.max_width,
            n.min_height, n.max_height, n.grow, n.shrink, n.follow, n.follow_offset)  # fmt: skip


def collect_styles(world: World) -> dict[int, Style]:
    return {e: s for e, (s,) in world.query(Style)}


def compute_layout(
    world: World,
    size: tuple[int, int],
    theme: Theme = DEFAULT_THEME,
    *,
    scale: float = 1.0,
    text_scale: float = 1.0,
    measure: TextMeasure | None = None,
    to_screen: Callable[[int, tuple[float, float]], tuple[float, float] | None] | None = None,
    sizer: Sizer | None = None,
) -> Layout:
    """Boxes of every visible UI node for a window of ``size`` pixels.

    ``to_screen(entity, offset)`` places nodes that follow an entity (None: they are
    not shown). A ``sizer`` from an earlier layout with the same theme, scales and
    measure is reused (its measured widths are kept).
    """
    styles = collect_styles(world)
    if sizer is None or not sizer.same(theme, scale, text_scale, measure):
        sizer = Sizer(theme, scale, text_scale, measure or TableMeasure(), styles)
    else:
        sizer.restyle(styles)
    solver = _Solver(world, sizer, scale, to_screen)
    solver.out.size = (int(size[0]), int(size[1]))
    solver.roots(Box(0.0, 0.0, float(size[0]), float(size[1])))
    return solver.out

