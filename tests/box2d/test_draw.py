"""kge.box2d's debug drawing (b2Draw, b2DrawExtended, b2World.DrawDebugData).

The expected calls were recorded from pybox2d 2.3.10 drawing the same world with
the same recording renderer.
"""

from __future__ import annotations

from typing import Any

import pytest

import kge.box2d as b2
from kge.errors import ComponentTypeError, KgeError

#: pybox2d 2.3.10's calls for the world below (points rounded to 1 mm)
PYBOX2D = [
    ('SolidCircle', (1.5, 2.0), 0.3, (1.0, 0.0), ('c', 0.9, 0.7, 0.7)),
    ('SolidPolygon', ((-0.404, 1.613), (0.552, 1.909), (0.404, 2.387), (-0.552, 2.091)), ('c', 0.9, 0.7, 0.7)),
    ('Segment', (-5.0, 0.0), (5.0, 0.0), ('c', 0.5, 0.9, 0.5)),
    ('Segment', (0.0, 2.0), (1.0, 2.0), ('c', 0.5, 0.8, 0.8)),
    ('Segment', (1.0, 2.0), (1.0, 2.0), ('c', 0.5, 0.8, 0.8)),
    ('Segment', (1.5, 2.0), (1.0, 2.0), ('c', 0.5, 0.8, 0.8)),
    ('Polygon', ((1.1, 1.6), (1.9, 1.6), (1.9, 2.4), (1.1, 2.4)), ('c', 0.9, 0.3, 0.9)),
    ('Polygon', ((-0.662, 1.503), (0.662, 1.503), (0.662, 2.497), (-0.662, 2.497)), ('c', 0.9, 0.3, 0.9)),
    ('Polygon', ((-5.11, -0.11), (5.11, -0.11), (5.11, 0.11), (-5.11, 0.11)), ('c', 0.9, 0.3, 0.9)),
    ('Transform', ('xf', (1.5, 2.0), 0.0)),
    ('Transform', ('xf', (0.0, 2.0), 0.3)),
    ('Transform', ('xf', (0.0, 0.0), 0.0)),
]


def _r(v: Any) -> Any:
    if isinstance(v, b2.b2Color):
        return ("c", round(v.r, 2), round(v.g, 2), round(v.b, 2))
    if isinstance(v, b2.b2Transform):
        return ("xf", _r(v.position), round(v.angle, 3))
    if isinstance(v, b2.b2Vec2):
        return (round(v.x, 3), round(v.y, 3))
    if isinstance(v, (list, tuple)):
        return tuple(_r(x) for x in v)
    if isinstance(v, float):
        return round(v, 3)
    return v


class Recorder(b2.b2Draw):
    def __init__(self) -> None:
        super().__init__()
        self.calls: list[tuple[Any, ...]] = []

    def DrawPolygon(self, vertices: Any, color: b2.b2Color) -> None:
        self.calls.append(("Polygon", _r(vertices), _r(color)))

    def DrawSolidPolygon(self, vertices: Any, color: b2.b2Color) -> None:
        self.calls.append(("SolidPolygon", _r(vertices), _r(color)))

    def DrawCircle(self, center: Any, radius: float, color: b2.b2Color) -> None:
        self.calls.append(("Circle", _r(center), _r(radius), _r(color)))

    def DrawSolidCircle(self, center: Any, radius: float, axis: Any, color: b2.b2Color) -> None:
        self.calls.append(("SolidCircle", _r(center), _r(radius), _r(axis), _r(color)))

    def DrawSegment(self, p1: Any, p2: Any, color: b2.b2Color) -> None:
        self.calls.append(("Segment", _r(p1), _r(p2), _r(color)))

    def DrawTransform(self, xf: b2.b2Transform) -> None:
        self.calls.append(("Transform", _r(xf)))


def _world() -> b2.b2World:
    world = b2.b2World(gravity=(0, -10))
    world.CreateStaticBody(shapes=b2.b2EdgeShape(vertices=[(-5, 0), (5, 0)]))
    box = world.CreateDynamicBody(position=(0, 2), angle=0.3)
    box.CreatePolygonFixture(box=(0.5, 0.25), density=1)
    ball = world.CreateDynamicBody(position=(1.5, 2.0))
    ball.CreateCircleFixture(radius=0.3, density=1)
    world.CreateRevoluteJoint(bodyA=box, bodyB=ball, anchor=(1.0, 2.0))
    return world


def test_draw_debug_data_calls_the_renderer_as_pybox2d_does() -> None:
    world = _world()
    rec = Recorder()
    rec.flags = dict(drawShapes=True, drawJoints=True, drawAABBs=True, drawCOMs=True)
    assert rec.flags["drawJoints"] and not rec.flags["drawPairs"]
    world.renderer = rec
    world.DrawDebugData()
    assert rec.calls == PYBOX2D


def test_flags_select_what_is_drawn_and_sleepers_turn_grey() -> None:
    world = _world()
    rec = Recorder()
    rec.AppendFlags(b2.b2Draw.e_shapeBit)
    world.renderer = rec
    for body in world.bodies:
        body.awake = False
    world.DrawDebugData()
    kinds = {c[0] for c in rec.calls}
    assert kinds == {"SolidCircle", "SolidPolygon", "Segment"}
    assert ("c", 0.6, 0.6, 0.6) in {c[-1] for c in rec.calls}  # Box2D's sleeping grey
    rec.calls.clear()
    rec.ClearFlags(b2.b2Draw.e_shapeBit)
    world.DrawDebugData()
    assert rec.calls == []


def test_extended_renderer_converts_to_screen_pixels() -> None:
    world = _world()
    seen: list[Any] = []

    class Screen(b2.b2DrawExtended):
        def DrawSolidCircle(self, center: Any, radius: float, axis: Any,
                            color: b2.b2Color) -> None:
            seen.append((_r(center), radius))

    screen = Screen(zoom=20.0, offset=(10, 0), screenSize=(640, 480), flipY=True)
    screen.flags = dict(drawShapes=True, convertVertices=True)  # the flag converts (pybox2d)
    assert screen.convertVertices
    world.renderer = screen
    world.DrawDebugData()
    # (1.5, 2.0) m -> x 1.5*20 - 10 = 20 px, y 480 - 2*20 = 440 px, whole pixels; the
    # radius stays in metres (pybox2d 2.3.10 passes 0.3: its backends scale it themselves)
    assert seen == [((20, 440), pytest.approx(0.3))]
    assert all(type(c) is int for c in seen[0][0])


def test_bad_renderer_and_flags_are_refused() -> None:
    world = _world()
    world.DrawDebugData()  # no renderer: nothing to do
    world.renderer = object()
    with pytest.raises(ComponentTypeError):
        world.DrawDebugData()
    with pytest.raises(ComponentTypeError):
        Recorder().flags = dict(drawEverything=True)
    screen = b2.b2DrawExtended(zoom=2.0)
    with pytest.raises(KgeError):
        screen.zoom = float("nan")
    with pytest.raises(KgeError):
        screen.offset = "far"  # type: ignore[assignment]
    assert screen.zoom == 2.0 and screen.offset == (0, 0)  # unchanged
