"""Drag and drop between UI nodes: with the mouse, or with the keyboard and gamepad.

Mouse: press on a :class:`~kge.components.ui.Draggable` node and move past its
``threshold``: ``DragStarted``; the targets (:class:`~kge.components.ui.DropTarget`
nodes taking the kind) light up under the pointer; releasing over one emits
``Dropped`` (its ``on_drop`` hook runs), anywhere else ``DragCancelled``. A drag
never also clicks the widget it started on.

Keyboard and gamepad: Ctrl+Space (X) on a focused draggable picks it up; the arrows
(d-pad) then move among the targets that take it, Enter (A) drops, Escape (B)
cancels.

A :class:`~kge.components.ui.TreeView` with ``draggable=True`` drags its rows: the
payload is a :class:`~kge.ui.events.TreeDrop` naming the row, and dropping on a row
of the same tree says where (before, inside or after it), for reparenting.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from kge.components.ui import Draggable, DropTarget, TreeView
from kge.ui.events import DragCancelled, DragStarted, Dropped, TreeDrop
from kge.ui.focus import nearest
from kge.ui.state import Drag

if TYPE_CHECKING:
    from kge.ui.interact import Frame

TREE_KIND = "tree-row"


def _source(f: Frame, e: int | None) -> tuple[int, Draggable] | None:
    while e is not None:
        d = f.world.try_get(e, Draggable)
        if d is not None:
            return (e, d) if not d.disabled else None
        e = f.layout.parent.get(e)
    return None


def _label(f: Frame, e: int) -> str:
    w = f.layout.widget.get(e)
    for name in ("text", "value"):
        v = getattr(w, name, None)
        if isinstance(v, str):
            return v
    return ""


def arm(f: Frame, hit: int, p: tuple[float, float]) -> None:
    """A press: a drag may begin here once the pointer moves far enough."""
    w = f.layout.widget.get(hit)
    if isinstance(w, TreeView) and w.draggable and not w.disabled:
        from kge.ui.controls import _row_at, tree_rows

        rows = tree_rows(f.state, hit, w)
        i = _row_at(f, hit, w, len(rows), p)
        if i is not None:
            item = rows[i][0]
            f.state.drag = Drag(hit, TreeDrop(item.id), TREE_KIND, p, p, label=item.text)
        return
    got = _source(f, hit)
    if got is not None:
        e, d = got
        f.state.drag = Drag(e, d.payload, d.kind, p, p, label=_label(f, e))


def _takes(f: Frame, e: int, kind: str) -> bool:
    t = f.world.try_get(e, DropTarget)
    if t is not None and t.takes(kind) and f.reachable(e):
        return True
    w = f.layout.widget.get(e)
    return kind == TREE_KIND and isinstance(w, TreeView) and w.draggable


def _target(f: Frame, p: tuple[float, float]) -> int | None:
    d = f.state.drag
    if d is None:
        return None
    return f.layout.hit(p, lambda e: _takes(f, e, d.kind) and (e != d.source or d.kind ==
                                                                 TREE_KIND))  # fmt: skip


def moved(f: Frame, p: tuple[float, float]) -> bool:
    """The pointer moved; True while a mouse drag is under way (it takes the move)."""
    d = f.state.drag
    if d is None or d.keyboard:
        return False
    d.at = p
    if not d.started:
        src = f.world.try_get(d.source, Draggable)
        threshold = (src.threshold if src is not None else 6.0) * f.sizer.scale
        if math.dist(p, d.start) < threshold:
            return False
        d.started = True
        f.emit(DragStarted(d.source, d.payload, d.kind))
        if f.state.pressed is not None:
            f.state.touch(f.state.pressed)
            f.state.pressed = None  # a drag is not a click
        f.state.grab.clear()
    over = _target(f, p)
    if over != d.over:
        f.state.touch(d.over, over)
        d.over = over
    return True


def _tree_payload(f: Frame, target: int, payload: Any, p: tuple[float, float]) -> Any:
    """Where on the tree a row was dropped (None: nowhere it may go)."""
    from kge.ui.controls import _row_at, list_metrics, tree_rows

    w = f.layout.widget.get(target)
    if not isinstance(w, TreeView) or not isinstance(payload, TreeDrop):
        return payload
    rows = tree_rows(f.state, target, w)
    i = _row_at(f, target, w, len(rows), p)
    if i is None:
        return TreeDrop(payload.item, None, "inside")
    item = rows[i][0]
    view, row_h, _ = list_metrics(f, target, w, len(rows))
    top = view.top - i * row_h + w.scroll
    k = (top - p[1]) / row_h
    where = "before" if k < 0.25 else "after" if k > 0.75 else "inside"
    parents = {it.id: it.parent for it in w.items}
    node: Any = item.id
    while node is not None:  # not onto itself or its own descendant
        if node == payload.item:
            return None
        node = parents.get(node)
    return TreeDrop(payload.item, item.id, where)


def _finish(f: Frame, target: int | None, at: tuple[float, float]) -> None:
    d = f.state.drag
    assert d is not None
    f.state.drag = None
    f.state.touch(d.source, d.over)
    payload = d.payload
    if target is not None and d.kind == TREE_KIND:
        payload = _tree_payload(f, target, payload, at)
    if target is None or payload is None:
        f.emit(DragCancelled(d.source, d.payload))
        return
    f.emit(Dropped(d.source, target, payload, d.kind, at))


def release(f: Frame, p: tuple[float, float]) -> bool:
    """The button went up: finish a drag under way (True), or forget an armed one."""
    d = f.state.drag
    if d is None or d.keyboard:
        return False
    if not d.started:
        f.state.drag = None
        return False
    _finish(f, _target(f, p), p)
    return True


def pick_up(f: Frame) -> bool:
    """Ctrl+Space / gamepad X: pick up the focused draggable."""
    got = _source(f, f.state.focused)
    if got is None or f.state.drag is not None:
        return False
    e, d = got
    b = f.layout.boxes[e]
    f.state.drag = Drag(e, d.payload, d.kind, b.center, b.center, True, True, None, _label(f, e))
    f.emit(DragStarted(e, d.payload, d.kind))
    _step_target(f, "down")
    return True


def _step_target(f: Frame, direction: str) -> None:
    d = f.state.drag
    assert d is not None
    targets = [e for e in f.layout.order if _takes(f, e, d.kind) and e != d.source]
    if not targets:
        return
    cur = d.over if d.over is not None else d.source
    order = targets + ([cur] if cur not in targets else [])
    nxt = nearest(f.layout, order, cur, direction) if cur in f.layout.boxes else None
    if nxt is None and d.over is None:
        nxt = targets[0]
    if nxt is not None:
        f.state.touch(d.over, nxt)
        d.over = nxt
        d.at = f.layout.boxes[nxt].center


def action(f: Frame, act: str) -> bool:
    """Arrows, Enter and Escape during a keyboard drag."""
    d = f.state.drag
    if d is None or not d.keyboard:
        return False
    if act in ("up", "down", "left", "right"):
        _step_target(f, act)
    elif act == "activate":
        _finish(f, d.over, d.at)
    elif act == "cancel":
        _finish(f, None, d.at)
    else:
        return False
    return True
