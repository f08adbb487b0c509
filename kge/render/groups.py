"""Draw order, coordinate spaces and per-camera layer filtering as pyglet groups.

One :class:`SpaceGroup` per (layer, space) sets the window's view matrix for
everything under it: ``WORLD`` uses the camera (vertex data in metres, world text
included), ``VIEW`` draws over the camera's viewport (the light map's multiply;
the camera matrix too, for glows), ``SCREEN`` the identity (HUD pixels). Under it,
one plain ``Group`` per ``order`` value. pyglet sorts sibling groups by their
``order``, so the batch draws layer by layer, space by space, order by order.

With several cameras the batch is drawn once per camera and once more for the
screen space; :attr:`ViewState.shows` then says which (layer, space) a pass draws,
and a group it does not draw scissors itself to nothing (its vertices are still
transformed, no pixel is touched).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pyglet
from pyglet import gl

from kge.render.projection import IDENTITY, Mat4Tuple

WORLD, VIEW, SCREEN = 0, 1, 2
#: a layer above anything a game uses, for debug draw and the stats overlay
OVERLAY_LAYER = 1_000_000


class ViewState:
    """The matrices and filter the groups apply, refreshed per pass by the renderer."""

    def __init__(self, window: Any) -> None:
        self.window = window
        self.matrices: dict[int, Mat4Tuple] = {WORLD: IDENTITY, VIEW: IDENTITY, SCREEN: IDENTITY}
        #: ``fn(layer, space) -> bool``: what this pass draws (None: everything)
        self.shows: Callable[[int, int], bool] | None = None
        #: the pass's scissor rectangle (framebuffer pixels), restored after a hidden group
        self.scissor: tuple[int, int, int, int] = (0, 0, 0, 0)


class SpaceGroup(pyglet.graphics.Group):
    """Sets the view matrix of one coordinate space for one layer (or hides it)."""

    def __init__(self, layer: int, space: int, state: ViewState) -> None:
        super().__init__(order=layer * 4 + space)
        self.layer = layer
        self.space = space
        self.state = state
        self._hidden = False

    def set_state(self) -> None:
        st = self.state
        st.window.view = pyglet.math.Mat4(*st.matrices[self.space])
        self._hidden = st.shows is not None and not st.shows(self.layer, self.space)
        if self._hidden:
            gl.glScissor(0, 0, 0, 0)

    def unset_state(self) -> None:
        self.state.window.view = pyglet.math.Mat4()
        if self._hidden:
            gl.glScissor(*self.state.scissor)

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
