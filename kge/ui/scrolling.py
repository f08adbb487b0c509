"""Scrolling with the wheel, scrollbars and drags, for scroll views and the widgets that
scroll their own content (lists, trees, text areas, an open dropdown).

The wheel goes to the innermost thing under the pointer that can scroll, then up
through the scroll views around it. Scrollbars (a scroll view's, a list's, a text
area's) drag by their thumb; a press on the track jumps the thumb there. A press on
a scroll view's content (not on a widget) drags it, touch style, when the view
allows it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from kge.components.ui import ScrollList, ScrollView, Slider, SpinBox, TextArea, TreeView
from kge.ui import controls, text_controls
from kge.ui import geometry as geo
from kge.ui.layout import Box
from kge.ui.textview import area_view

if TYPE_CHECKING:
    from kge.ui.interact import Frame

Bar = tuple[int, Box, float, float, float, bool]  #: entity, track, view, content, scroll, vertical


def _count(f: Frame, e: int, w: ScrollList | TreeView) -> int:
    return len(w.items) if isinstance(w, ScrollList) else len(controls.tree_rows(f.state, e, w))


def _widget_bar(f: Frame, e: int, w: Any) -> Bar | None:
    """The scrollbar of a list, tree or text area (None when its content fits)."""
    bar = f.sizer.theme.scrollbar * f.sizer.scale
    if isinstance(w, (ScrollList, TreeView)):
        count = _count(f, e, w)
        view, row_h, top = controls.list_metrics(f, e, w, count)
        if top <= 0:
            return None
        return (e, Box(view.right, view.y, bar, view.h), view.h, count * row_h, w.scroll, True)
    if isinstance(w, TextArea):
        av = area_view(f.sizer, f.state, e, w, f.box(e), f.look(e))
        if not av.bar:
            return None
        v = av.view
        return (e, Box(v.right, v.y, bar, v.h), v.h, v.h + av.max_scroll, w.scroll, True)
    return None


def bars(f: Frame) -> list[Bar]:
    """Every scrollbar shown, topmost last."""
    out: list[Bar] = []
    bar = f.sizer.theme.scrollbar * f.sizer.scale
    for e in f.layout.order:
        if not f.reachable(e):
            continue
        area = f.layout.scroll.get(e)
        if area is not None:
            sv = f.world.try_get(e, ScrollView)
            ty, tx = geo.scroll_tracks(area, bar)
            if sv is not None and ty is not None:
                out.append((e, ty, area.viewport.h, area.content_h, sv.scroll[1], True))
            if sv is not None and tx is not None:
                out.append((e, tx, area.viewport.w, area.content_w, sv.scroll[0], False))
        w = f.layout.widget.get(e)
        if isinstance(w, (ScrollList, TreeView, TextArea)):
            got = _widget_bar(f, e, w)
            if got is not None:
                out.append(got)
    return out


def _set_scroll(f: Frame, e: int, value: float, vertical: bool) -> None:
    w = f.layout.widget.get(e)
    sv = f.world.try_get(e, ScrollView)
    if isinstance(w, (ScrollList, TreeView, TextArea)) and sv is None:
        got = _widget_bar(f, e, w)
        top = max(got[3] - got[2], 0.0) if got is not None else 0.0
        value = min(max(value, 0.0), top)
        if value != w.scroll:
            w.scroll = value
        return
    if sv is None:
        return
    area = f.layout.scroll.get(e)
    if area is None:
        return
    x, y = sv.scroll
    if vertical:
        y = min(max(value, 0.0), area.max_y)
    else:
        x = min(max(value, 0.0), area.max_x)
    if (x, y) != sv.scroll:
        sv.scroll = (x, y)


def press_bar(f: Frame, p: tuple[float, float]) -> bool:
    """A press on a scrollbar: grab its thumb (a press on the track moves it there first)."""
    for e, track, view, content, scroll, vertical in reversed(bars(f)):
        clip = f.layout.clip.get(e)
        if not track.contains(p) or (clip is not None and not clip.contains(p)):
            continue
        thumb = geo.scrollbar(track, view, content, scroll, vertical)
        if not thumb.contains(p):  # the track: centre the thumb on the pointer
            size = thumb.h if vertical else thumb.w
            value = geo.scroll_from_thumb(track, view, content, p[1] if vertical else p[0],
                                          size / 2, vertical)  # fmt: skip
            _set_scroll(f, e, value, vertical)
            thumb = geo.scrollbar(track, view, content, value, vertical)
        grab = (thumb.top - p[1]) if vertical else (p[0] - thumb.x)
        f.state.grab.update(bar=e, track=track, view=view, content=content, vertical=vertical,
                            offset=grab)  # fmt: skip
        f.state.touch(e)
        return True
    return False


def arm_pan(f: Frame, hit: int, p: tuple[float, float]) -> None:
    """A press on a scroll view's content (not a widget) may drag it."""
    e: int | None = hit
    while e is not None:
        sv = f.world.try_get(e, ScrollView)
        if sv is not None and e in f.layout.scroll:
            if sv.drag_scroll:
                f.state.grab.update(pan=e, start=p, scroll=sv.scroll)
            return
        e = f.layout.parent.get(e)


def grab_move(f: Frame, p: tuple[float, float]) -> None:
    g = f.state.grab
    if "bar" in g:
        pointer = p[1] if g["vertical"] else p[0]
        value = geo.scroll_from_thumb(g["track"], g["view"], g["content"], pointer, g["offset"],
                                      g["vertical"])  # fmt: skip
        _set_scroll(f, g["bar"], value, g["vertical"])
    elif "pan" in g:
        e = g["pan"]
        sv = f.world.try_get(e, ScrollView)
        area = f.layout.scroll.get(e)
        if sv is None or area is None:
            return
        sx, sy = g["scroll"]
        dx, dy = p[0] - g["start"][0], p[1] - g["start"][1]
        x = min(max(sx - dx, 0.0), area.max_x) if sv.horizontal else sv.scroll[0]
        y = min(max(sy + dy, 0.0), area.max_y) if sv.vertical else sv.scroll[1]
        if (x, y) != sv.scroll:
            sv.scroll = (x, y)


def wheel(f: Frame, hit: int | None, scroll: tuple[float, float], shift: bool) -> None:
    """The wheel over ``hit``: an open dropdown's list under the pointer, else the
    innermost thing that can scroll takes it."""
    dx, dy = scroll
    if shift and dx == 0:
        dx, dy = -dy, 0.0
    p = f.inp.mouse_screen
    if controls.dropdown_wheel(f, p, dy):
        f.took = True
        return
    e: int | None = hit
    while e is not None:
        if _wheel_one(f, e, dx, dy):
            f.took = True
            return
        e = f.layout.parent.get(e)


def _wheel_one(f: Frame, e: int, dx: float, dy: float) -> bool:
    w = f.layout.widget.get(e)
    if getattr(w, "disabled", False):
        w = None
    if isinstance(w, (Slider, SpinBox)) and f.state.focused == e and dy:
        if isinstance(w, Slider):
            controls.nudge_slider(f, e, w, 1 if dy > 0 else -1)
        else:
            text_controls.spin_step(f, e, w, 1 if dy > 0 else -1)
        return True
    if isinstance(w, (ScrollList, TreeView, TextArea)) and dy:
        got = _widget_bar(f, e, w)
        if got is None:
            return False
        if isinstance(w, TextArea):
            step = area_view(f.sizer, f.state, e, w, f.box(e), f.look(e)).line_h * 3
        else:
            count = _count(f, e, w)
            step = controls.list_metrics(f, e, w, count)[1]
        _set_scroll(f, e, w.scroll - dy * step, True)
        return True
    sv = f.world.try_get(e, ScrollView)
    area = f.layout.scroll.get(e)
    if sv is None or area is None:
        return False
    moved = False
    if dy and sv.vertical and area.max_y > 0:
        _set_scroll(f, e, sv.scroll[1] - dy * sv.wheel_step * f.sizer.scale, True)
        moved = True
    if dx and sv.horizontal and area.max_x > 0:
        _set_scroll(f, e, sv.scroll[0] - dx * sv.wheel_step * f.sizer.scale, False)
        moved = True
    return moved
