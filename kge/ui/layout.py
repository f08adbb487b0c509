"""Layout: the window-pixel box of every visible UI node, from its UINode and the window size.

Computed from scratch each time it is asked (menus and HUDs have tens of nodes, and a
fresh computation is what makes resizes and percent sizes free of stale state). Two
passes over the tree: *measure* resolves sizes (pixels, percents of the parent's
inner box, ``"auto"`` from the children or the widget's text), *place* puts children
in rows, columns, grids, or at their anchors.

>>> from kge.world import World
>>> from kge.components.ui import UINode
>>> w = World()
>>> menu = w.spawn(UINode(anchor="top_right", offset=(-10, -10), width=200, height="50%",
...                       layout="column", padding=5, spacing=4, align="stretch"))
>>> a = w.spawn(UINode(parent=menu, height=30))
>>> b = w.spawn(UINode(parent=menu, height=30))
>>> boxes = compute_layout(w, (800, 600)).boxes
>>> boxes[menu]
Box(x=590.0, y=290.0, w=200.0, h=300.0)
>>> boxes[a], boxes[b]
(Box(x=595.0, y=555.0, w=190.0, h=30.0), Box(x=595.0, y=521.0, w=190.0, h=30.0))
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from kge.components.ui import (
    ANCHORS,
    Button,
    Dropdown,
    Label,
    ProgressBar,
    ScrollList,
    Size,
    Slider,
    TextInput,
    Toggle,
    UIImage,
    UINode,
)
from kge.ui.theme import DEFAULT_THEME, Theme
from kge.world import World

WIDGETS: tuple[type, ...] = (
    Button, Toggle, Slider, TextInput, Dropdown, ScrollList, Label, ProgressBar, UIImage,
)  # fmt: skip


@dataclass(slots=True, frozen=True)
class Box:
    """A rectangle in window pixels, origin bottom-left."""

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


@dataclass(slots=True)
class Layout:
    """The result: boxes by entity, and the visible nodes in draw order (parents first)."""

    boxes: dict[int, Box] = field(default_factory=dict)
    order: list[int] = field(default_factory=list)
    widget: dict[int, Any] = field(default_factory=dict)  #: entity -> its widget component
    depth: dict[int, int] = field(default_factory=dict)  #: entity -> nesting depth (roots 0)

    def hit(self, point: tuple[float, float], accept: Callable[[int], bool]) -> int | None:
        """The topmost node under ``point`` that ``accept`` takes, or None."""
        for e in reversed(self.order):
            if self.boxes[e].contains(point) and accept(e):
                return e
        return None


def text_width(text: str, font_size: float) -> float:
    """An estimate of a text's width without a font (layout must run headless)."""
    return len(text) * font_size * 0.56


def intrinsic(widget: Any, theme: Theme) -> tuple[float, float]:
    """The size an ``"auto"`` node with this widget and no children takes."""
    fs, pad = theme.font_size, theme.padding
    line = fs * 1.5
    if isinstance(widget, Label):
        s = widget.size or fs
        return (text_width(widget.text, s) + 4, s * 1.5)
    if isinstance(widget, Button):
        return (max(text_width(widget.text, fs) + 2 * pad, line + pad), line + pad)
    if isinstance(widget, Toggle):
        return (line + 6 + text_width(widget.text, fs), line)
    if isinstance(widget, (Slider, ProgressBar)):
        return (160.0, line if isinstance(widget, Slider) else 14.0)
    if isinstance(widget, TextInput):
        return (220.0, line + pad)
    if isinstance(widget, Dropdown):
        longest = max((text_width(o, fs) for o in widget.options), default=40.0)
        return (longest + 2 * pad + line, line + pad)
    if isinstance(widget, ScrollList):
        return (220.0, (widget.row_height or theme.row_height) * 5)
    if isinstance(widget, UIImage):
        return (64.0, 64.0)
    return (0.0, 0.0)


def _dim(value: Size, avail: float, auto: Callable[[], float]) -> float:
    if isinstance(value, float | int):
        return float(value)
    if value == "auto":
        return auto()
    return max(avail, 0.0) * float(value[:-1]) / 100.0


class _Solver:
    def __init__(self, world: World, theme: Theme) -> None:
        self.theme = theme
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
        for e in self.nodes:
            for t in WIDGETS:
                c = world.try_get(e, t)
                if c is not None:
                    self.widget[e] = c
                    break
        self.out = Layout(widget=self.widget)
        self._measured: dict[tuple[int, float, float], tuple[float, float]] = {}

    def measure(self, e: int, aw: float, ah: float) -> tuple[float, float]:
        key = (e, aw, ah)
        got = self._measured.get(key)
        if got is None:
            n = self.nodes[e]
            cache: list[tuple[float, float]] = []

            def content() -> tuple[float, float]:
                if not cache:
                    cache.append(self.content(e, aw, ah))
                return cache[0]

            got = (
                _dim(n.width, aw, lambda: content()[0]),
                _dim(n.height, ah, lambda: content()[1]),
            )
            self._measured[key] = got
        return got

    def content(self, e: int, aw: float, ah: float) -> tuple[float, float]:
        n = self.nodes[e]
        iw, ih = intrinsic(self.widget.get(e), self.theme)
        kids = self.kids.get(e, [])
        if not kids:
            return (iw, ih)
        pad, sp = n.padding, n.spacing
        sizes = [self.measure(k, aw - 2 * pad, ah - 2 * pad) for k in kids]
        ws, hs = [s[0] for s in sizes], [s[1] for s in sizes]
        gaps = sp * (len(kids) - 1)
        if n.layout == "row":
            cw, ch = sum(ws) + gaps, max(hs)
        elif n.layout == "column":
            cw, ch = max(ws), sum(hs) + gaps
        elif n.layout == "grid":
            cols = min(n.columns, len(kids))
            rows = [hs[i : i + n.columns] for i in range(0, len(hs), n.columns)]
            cw = max(ws) * cols + sp * (cols - 1)
            ch = sum(max(r) for r in rows) + sp * (len(rows) - 1)
        else:
            cw, ch = max(ws), max(hs)
        return (max(cw + 2 * pad, iw), max(ch + 2 * pad, ih))

    def place(self, e: int | None, box: Box, seen: set[int], depth: int = -1) -> None:
        if e is not None:
            if e in seen:
                return  # a parent cycle: drawn once, never looped
            seen.add(e)
            self.out.boxes[e] = box
            self.out.order.append(e)
            self.out.depth[e] = depth
            n = self.nodes[e]
            inner, layout = box.inset(n.padding), n.layout
        else:
            inner, layout = box, "free"
        kids = self.kids.get(e, [])
        if not kids:
            return
        sizes = [self.measure(k, inner.w, inner.h) for k in kids]
        if layout == "free":
            for k, (w, h) in zip(kids, sizes, strict=True):
                self.place(k, self._anchored(self.nodes[k], inner, w, h), seen, depth + 1)
        elif layout == "grid":
            self._grid(
                self.nodes[e] if e is not None else None, kids, sizes, inner, seen, depth + 1
            )
        else:
            self._line(
                self.nodes[e] if e is not None else None, kids, sizes, inner, seen, depth + 1
            )

    @staticmethod
    def _anchored(n: UINode, inner: Box, w: float, h: float) -> Box:
        ax, ay = ANCHORS[n.anchor]
        return Box(
            inner.x + ax * (inner.w - w) + n.offset[0],
            inner.y + ay * (inner.h - h) + n.offset[1],
            w,
            h,
        )

    def _line(self, parent: UINode | None, kids: list[int], sizes: list[tuple[float, float]],
              inner: Box, seen: set[int], depth: int) -> None:  # fmt: skip
        assert parent is not None
        row = parent.layout == "row"
        sp, align = parent.spacing, parent.align
        main = [s[0] if row else s[1] for s in sizes]
        total = sum(main) + sp * (len(kids) - 1)
        room = (inner.w if row else inner.h) - total
        lead = {"start": 0.0, "center": room / 2, "end": room}[parent.justify]
        cross_room = inner.h if row else inner.w
        pos = lead
        for k, (w, h), m in zip(kids, sizes, main, strict=True):
            node = self.nodes[k]
            cross = h if row else w
            if align == "stretch" and (node.height if row else node.width) == "auto":
                cross = cross_room
            # row: start = top; column: start = left
            frac = {"start": 1.0 if row else 0.0, "center": 0.5, "end": 0.0 if row else 1.0,
                    "stretch": 0.5}[align]  # fmt: skip
            c = (cross_room - cross) * frac
            if row:
                b = Box(inner.x + pos, inner.y + c, m, cross)
            else:
                b = Box(inner.x + c, inner.top - pos - m, cross, m)
            b = Box(b.x + node.offset[0], b.y + node.offset[1], b.w, b.h)
            self.place(k, b, seen, depth)
            pos += m + sp

    def _grid(self, parent: UINode | None, kids: list[int], sizes: list[tuple[float, float]],
              inner: Box, seen: set[int], depth: int) -> None:  # fmt: skip
        assert parent is not None
        cols, sp = parent.columns, parent.spacing
        cell_w = max((inner.w - sp * (cols - 1)) / cols, 0.0)
        top = inner.top
        for r in range(0, len(kids), cols):
            row_h = max(s[1] for s in sizes[r : r + cols])
            for c, k in enumerate(kids[r : r + cols]):
                w, h = sizes[r + c]
                node = self.nodes[k]
                w = cell_w if node.width == "auto" else min(w, cell_w)
                b = Box(inner.x + c * (cell_w + sp), top - row_h + (row_h - h) / 2, w, h)
                self.place(
                    k, Box(b.x + node.offset[0], b.y + node.offset[1], b.w, b.h), seen, depth
                )
            top -= row_h + sp


def compute_layout(world: World, size: tuple[int, int], theme: Theme = DEFAULT_THEME) -> Layout:
    """Boxes of every visible UI node for a window of ``size`` pixels."""
    solver = _Solver(world, theme)
    solver.place(None, Box(0.0, 0.0, float(size[0]), float(size[1])), set(), -1)
    return solver.out
