"""The UI's layout, kept current: laid out again only when something it depends on changed.

What a layout depends on: the UI components (every write is noted in
:attr:`~kge.ui.state.UIState.writes` by the UI plugin), the window size, the UI and
text scales, the theme and the text measure. Nodes following an entity move with
it every call without a new layout.
"""

from __future__ import annotations

from collections.abc import Callable

from kge.components.transform import Transform
from kge.components.ui import Dialog, ScrollView, Tabs, UINode
from kge.host import Host
from kge.ui.layout import Layout, compute_layout, node_shape
from kge.ui.settings import UISettings
from kge.ui.state import UIState
from kge.ui.theme import DEFAULT_THEME, Theme
from kge.world import World

ToScreen = Callable[[int, tuple[float, float]], tuple[float, float] | None]


def _default_to_screen(world: World) -> ToScreen | None:
    host = world.try_resource(Host)
    convert = getattr(host, "world_to_screen", None)
    if convert is None:
        return None

    def to_screen(entity: int, offset: tuple[float, float]) -> tuple[float, float] | None:
        t = world.try_get(entity, Transform) if world.exists(entity) else None
        if t is None:
            return None
        x, y = convert((t.x + offset[0], t.y + offset[1]))
        return (float(x), float(y))

    return to_screen


def current_layout(world: World, size: tuple[int, int] | None = None,
                   to_screen: ToScreen | None = None) -> Layout:  # fmt: skip
    """The UI's layout for a window of ``size`` (the App's by default), laid out again only
    when something it depends on changed since the last call.

    Nodes following an entity are moved to its current place on screen each call
    (``to_screen(entity, offset)``; by default through the App's camera).
    """
    state = world.resource(UIState)
    if size is None:
        host = world.try_resource(Host)
        size = host.size if host is not None else (960, 540)
    theme = world.try_resource(Theme) or DEFAULT_THEME
    settings = world.try_resource(UISettings) or UISettings()
    scale = settings.factor(size)
    key = (tuple(size), scale, settings.text_scale, id(theme), id(state.measure))
    if to_screen is None:
        to_screen = _default_to_screen(world)
    lay = state.layout
    if (state.writes and not state.structural and key == state.layout_key
            and lay.sizer is not None
            and all(_neutral(world, lay, e) for e in state.writes)):  # fmt: skip
        for e in state.writes:  # values changed, not sizes: the same boxes, drawn again
            state.versions[e] = state.versions.get(e, 0) + 1
        state.redraw |= state.writes
        state.writes.clear()
    if state.writes or key != state.layout_key or lay.sizer is None:
        for e in state.writes:
            state.versions[e] = state.versions.get(e, 0) + 1
        state.forget({e for e in state.structural
                      if not world.exists(e) or not world.has(e, UINode)})
        state.structural.clear()
        state.redraw |= state.writes
        state.writes.clear()
        version = lay.version + 1
        lay = compute_layout(world, size, theme, scale=scale, text_scale=settings.text_scale,
                             measure=state.measure, to_screen=to_screen,
                             sizer=lay.sizer)  # fmt: skip
        lay.version = version
        state.layout = lay
        state.layout_key = key
    elif lay.follow:
        _refollow(world, state, to_screen)
    return state.layout


#: widgets whose writes can move other nodes (a tab's page, wrapped text's height)
_MOVERS: tuple[type, ...] = (Tabs,)


def _neutral(world: World, lay: Layout, e: int) -> bool:
    """Does the write noted for ``e`` leave every box as it was? (Its UINode fields are
    as laid out, and an "auto" node's widget still asks for the same size.)"""
    node = lay.nodes.get(e)
    if node is None or world.try_get(e, UINode) is not node or e not in lay.shape:
        return False
    if node_shape(node) != lay.shape[e]:
        return False
    if world.try_get(e, ScrollView) is not None or world.try_get(e, Dialog) is not None:
        return False
    w = lay.widget.get(e)
    if w is None or isinstance(w, _MOVERS) or getattr(w, "wrap", False):
        return w is None
    if node.width != "auto" and node.height != "auto":
        return True
    natural = lay.natural.get(e)
    sizer = lay.sizer
    assert sizer is not None
    return natural is not None and sizer.intrinsic(e, w, 0.0) == natural


def _refollow(world: World, state: UIState, to_screen: ToScreen | None) -> None:
    """Move the nodes that follow entities to where those are now."""
    lay = state.layout
    nodes = {e: world.try_get(e, UINode) for e in lay.follow}
    for root, (target, old) in list(lay.follow.items()):
        node = nodes[root]
        point = to_screen(target, node.follow_offset) if (to_screen and node) else None
        if point is None or not all(v == v and abs(v) < 1e9 for v in point):
            state.writes.add(root)  # gone: lay out again (it is hidden then)
            state.structural.add(root)
            continue
        dx, dy = point[0] - old[0], point[1] - old[1]
        if dx == 0 and dy == 0:
            continue
        lay.follow[root] = (target, point)
        for e in lay.subtree(root):
            lay.boxes[e] = lay.boxes[e].moved(dx, dy)
            state.redraw.add(e)
        lay.moved()
    if state.writes:
        current_layout(world, lay.size, to_screen)
