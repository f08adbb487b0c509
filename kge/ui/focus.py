"""Keyboard and gamepad focus: the Tab order, moving by direction, and scrolling the
focused widget into view.

**Tab order** is the layout order (top to bottom, parents before children), with
nodes that set ``UINode.focus_order`` first, lowest first (HTML's ``tabindex``).
While a modal dialog is shown only its widgets take the focus.

**Arrows and the d-pad** move to the nearest focusable widget in that direction (a
3-column grid: Down goes to the cell below); when there is none, Up and Down go
to the previous and next widget in Tab order, wrapping, as menus do.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from kge.components.ui import ScrollView, UINode
from kge.ui.layout import Box, Layout
from kge.world import World

_DIRS: dict[str, tuple[float, float]] = {
    "up": (0.0, 1.0), "down": (0.0, -1.0), "left": (-1.0, 0.0), "right": (1.0, 0.0),
}  # fmt: skip


def tab_order(layout: Layout, nodes: dict[int, UINode], can_focus: Callable[[int], bool],
              modal: int | None) -> list[int]:  # fmt: skip
    """The focusable nodes in Tab order (see the module docstring)."""
    index = {e: i for i, e in enumerate(layout.order)}
    got = [e for e in layout.order if can_focus(e) and (modal is None
                                                         or layout.dialog.get(e) == modal)]
    ranked = [e for e in got if nodes[e].focus_order is not None]
    ranked.sort(key=lambda e: (nodes[e].focus_order, index[e]))
    return ranked + [e for e in got if nodes[e].focus_order is None]


def step(order: list[int], current: int | None, delta: int) -> int | None:
    """The node ``delta`` places from ``current`` in ``order``, wrapping."""
    if not order:
        return None
    if current not in order:
        return order[0] if delta > 0 else order[-1]
    return order[(order.index(current) + delta) % len(order)]


def nearest(layout: Layout, order: list[int], current: int, direction: str) -> int | None:
    """The focusable node nearest to ``current`` towards ``direction``, or None."""
    dx, dy = _DIRS[direction]
    a = layout.visible_box(current) if current in layout.boxes else None
    if a is None:
        return None
    ax, ay = a.center
    best, best_score = None, float("inf")
    for e in order:
        if e == current:
            continue
        b = layout.boxes[e]
        bx, by = b.center
        along = (bx - ax) * dx + (by - ay) * dy
        if along <= 1e-6:
            continue
        if dx:  # sideways: how far apart the boxes are vertically
            across = max(b.y - a.top, a.y - b.top, 0.0)
            gap = max(b.x - a.right, a.x - b.right, 0.0)
        else:
            across = max(b.x - a.right, a.x - b.right, 0.0)
            gap = max(b.y - a.top, a.y - b.top, 0.0)
        score = gap + along * 0.01 + across * 3.0
        if score < best_score:
            best, best_score = e, score
    return best


def scroll_into_view(world: World, layout: Layout, e: int) -> None:
    """Scroll every scroll view around ``e`` so that its box is in view (innermost first)."""
    box: Box | None = layout.boxes.get(e)
    node: int | None = layout.parent.get(e)
    while box is not None and node is not None:
        area = layout.scroll.get(node)
        sv: Any = world.try_get(node, ScrollView) if area is not None else None
        if area is not None and sv is not None:
            v = area.viewport
            sx, sy = sv.scroll
            ny, nx = sy, sx
            if box.h > v.h or box.top > v.top:
                ny = sy - (box.top - v.top)
            elif box.y < v.y:
                ny = sy + (v.y - box.y)
            if box.w > v.w or box.x < v.x:
                nx = sx - (v.x - box.x)
            elif box.right > v.right:
                nx = sx + (box.right - v.right)
            nx = min(max(nx, 0.0), area.max_x) if sv.horizontal else sx
            ny = min(max(ny, 0.0), area.max_y) if sv.vertical else sy
            if (nx, ny) != (sx, sy):
                sv.scroll = (nx, ny)
                box = box.moved(-(nx - sx), ny - sy)
        node = layout.parent.get(node)
