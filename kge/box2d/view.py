"""``KgeDraw``: a ``b2Draw`` that draws a pybox2d program with kge's renderer.

A pybox2d program keeps its own ``b2World`` (a kge World of its own underneath);
to show it in a kge App (the testbed, a game) its debug drawing is turned into
kge drawables in the App's world: ``world.renderer = KgeDraw(app_world)``, then per
frame ``renderer.StartDraw()``, ``world.DrawDebugData()``, ``renderer.EndDraw()`` (as
pybox2d's testbed frames each frame's drawing).
Each ``Draw*`` call reuses one entity of a pool per primitive kind (a
``Polygon``, ``Circle`` or ``Line`` drawable with an identity ``Transform``: the
points are world points already), and entities a frame did not use are hidden,
so a steady scene spawns nothing after its first frame. Colours are Box2D's debug colours.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from kge.box2d.draw import b2Color, b2Draw
from kge.box2d.transform import b2Transform
from kge.box2d.vec import as_xy
from kge.components.drawables import Circle, Line, Polygon
from kge.components.transform import Transform
from kge.world import World

#: a DrawTransform axis, m
AXIS = 0.4


def _rgba(color: b2Color, alpha: int = 255) -> tuple[int, int, int, int]:
    r, g, b = color.bytes
    return (r, g, b, alpha)


class KgeDraw(b2Draw):
    """Draw a ``b2World``'s debug data as drawables in the kge World ``target``."""

    def __init__(self, target: World, *, layer: int = 0, thickness: float = 0.03,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.target = target
        self.layer = layer
        self.thickness = thickness
        self._pools: dict[type, list[int]] = {Polygon: [], Circle: [], Line: []}
        self._used: dict[type, int] = dict.fromkeys(self._pools, 0)
        if not kwargs:
            self.flags = dict(drawShapes=True, drawJoints=True)

    def StartDraw(self) -> None:
        """A frame starts: every pooled drawable is free again (hidden unless drawn)."""
        self._used = dict.fromkeys(self._pools, 0)

    def EndDraw(self) -> None:
        """A frame ends: hide what it did not draw."""
        for kind, pool in self._pools.items():
            for e in pool[self._used[kind]:]:
                drawable: Any = self.target.get(e, kind)
                drawable.visible = False

    def _take(self, kind: type, make: Any) -> Any:
        pool, i = self._pools[kind], self._used[kind]
        self._used[kind] = i + 1
        if i < len(pool):
            drawable: Any = self.target.get(pool[i], kind)
            drawable.visible = True
            return drawable
        drawable = make()
        pool.append(self.target.spawn(Transform(), drawable))
        return drawable

    def _polygon(self, vertices: Sequence[Any], color: b2Color, filled: bool) -> None:
        pts = tuple(as_xy(v, "KgeDraw", "vertex") for v in vertices)
        if len(pts) < 3:
            return
        fill = _rgba(color, 128 if filled else 255)
        p = self._take(Polygon, lambda: Polygon(pts, color=fill, filled=filled,
                                                thickness=self.thickness, layer=self.layer))
        p.vertices, p.color, p.filled = pts, fill, filled

    def DrawPolygon(self, vertices: Sequence[Any], color: b2Color) -> None:
        self._polygon(vertices, color, False)

    def DrawSolidPolygon(self, vertices: Sequence[Any], color: b2Color) -> None:
        self._polygon(vertices, color, True)

    def _circle(self, center: Any, radius: float, color: b2Color, filled: bool) -> None:
        cx, cy = as_xy(center, "KgeDraw", "center")
        fill = _rgba(color, 128 if filled else 255)
        c = self._take(Circle, lambda: Circle(radius, color=fill, filled=filled,
                                              thickness=self.thickness, layer=self.layer))
        c.radius, c.color, c.filled, c.offset = radius, fill, filled, (cx, cy)

    def DrawCircle(self, center: Any, radius: float, color: b2Color) -> None:
        self._circle(center, radius, color, False)

    def DrawSolidCircle(self, center: Any, radius: float, axis: Any, color: b2Color) -> None:
        self._circle(center, radius, color, True)
        cx, cy = as_xy(center, "KgeDraw", "center")
        ax, ay = as_xy(axis, "KgeDraw", "axis")
        self.DrawSegment((cx, cy), (cx + radius * ax, cy + radius * ay), color)

    def DrawSegment(self, p1: Any, p2: Any, color: b2Color) -> None:
        a, b = as_xy(p1, "KgeDraw", "p1"), as_xy(p2, "KgeDraw", "p2")
        rgba = _rgba(color)
        line = self._take(Line, lambda: Line(a, b, color=rgba, thickness=self.thickness,
                                             layer=self.layer + 1))
        line.start, line.end, line.color = a, b, rgba

    def DrawTransform(self, xf: b2Transform) -> None:
        p = xf.position
        c, s = math.cos(xf.angle), math.sin(xf.angle)
        self.DrawSegment(p, (p.x + AXIS * c, p.y + AXIS * s), b2Color(1.0, 0.0, 0.0))
        self.DrawSegment(p, (p.x - AXIS * s, p.y + AXIS * c), b2Color(0.0, 1.0, 0.0))
