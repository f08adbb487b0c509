"""Draw order and coordinate spaces as pyglet groups.

One :class:`SpaceGroup` per (layer, space) sets the window's view matrix for
everything under it: ``WORLD`` uses the camera (vertex data in metres, world text
included), ``VIEW`` draws over the camera's viewport in clip coordinates (the light
map's multiply), ``SCREEN`` the identity (HUD pixels). Under it, one plain
``Group`` per ``order`` value. pyglet sorts sibling groups by their ``order``,
so the batch draws layer by layer, space by space, order by order.
"""

from __future__ import annotations

from typing import Any

import pyglet

from kge.render.projection import IDENTITY, Mat4Tuple

WORLD, VIEW, SCREEN = 0, 1, 2
#: a layer above anything a game uses, for debug draw and the stats overlay
OVERLAY_LAYER = 1_000_000


class ViewState:
    """The matrices the groups apply, refreshed once per frame by the renderer."""

    def __init__(self, window: Any) -> None:
        self.window = window
        self.matrices: dict[int, Mat4Tuple] = {WORLD: IDENTITY, VIEW: IDENTITY, SCREEN: IDENTITY}


class SpaceGroup(pyglet.graphics.Group):
    """Sets the view matrix of one coordinate space for one layer."""

    def __init__(self, layer: int, space: int, state: ViewState) -> None:
        super().__init__(order=layer * 4 + space)
        self.space = space
        self.state = state

    def set_state(self) -> None:
        self.state.window.view = pyglet.math.Mat4(*self.state.matrices[self.space])

    def unset_state(self) -> None:
        self.state.window.view = pyglet.math.Mat4()

    # identity semantics: two layers never merge even if their orders collide
    def __eq__(self, other: object) -> bool:
        return self is other

    def __hash__(self) -> int:
        return id(self)


class Groups:
    """Cache of the group for each (layer, space, order)."""

    def __init__(self, state: ViewState) -> None:
        self.state = state
        self._spaces: dict[tuple[int, int], SpaceGroup] = {}
        self._orders: dict[tuple[int, int, int], pyglet.graphics.Group] = {}

    def get(self, layer: int, space: int, order: int = 0) -> pyglet.graphics.Group:
        key = (layer, space, order)
        g = self._orders.get(key)
        if g is None:
            parent = self._spaces.get((layer, space))
            if parent is None:
                parent = self._spaces[(layer, space)] = SpaceGroup(layer, space, self.state)
            g = self._orders[key] = pyglet.graphics.Group(order=order, parent=parent)
        return g
