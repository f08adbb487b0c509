"""``b2Draw`` / ``b2DrawExtended`` and ``b2World.DrawDebugData``: pybox2d's debug drawing.

A program subclasses ``b2Draw`` (or ``b2DrawExtended``, which converts world
points to screen pixels first), overrides the ``Draw*`` methods with its own
renderer's calls, sets ``world.renderer`` and calls ``world.DrawDebugData()``
once per frame. kge walks the world as Box2D's ``b2World::DrawDebugData`` does:
shapes in Box2D's body-state colours, joints as segments between the bodies and
their anchors, fixture AABBs (fattened by b2_aabbExtension, as the broad phase's
are at rest), and centre-of-mass transforms, each switched by
the renderer's ``flags`` (``drawShapes``, ``drawJoints``, ``drawAABBs``,
``drawPairs``, ``drawCOMs``). Pairs draw the lines between the centres of the
AABBs of each touching contact's fixtures (Box2D's broad-phase pairs are a
superset kge does not keep).
"""

from __future__ import annotations

import builtins
import itertools
import math
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING, Any, ClassVar

from kge.box2d.constants import b2_aabbExtension, b2_kinematicBody, b2_staticBody
from kge.box2d.shapes import b2ChainShape, b2CircleShape, b2EdgeShape, b2PolygonShape
from kge.box2d.transform import b2Transform, make_transform
from kge.box2d.vec import as_xy, b2Vec2
from kge.errors import ComponentTypeError
from kge.validate import finite

if TYPE_CHECKING:
    from kge.box2d.body import b2Body
    from kge.box2d.world import b2World

class b2Color:
    """An RGB colour with components in 0..1 (``bytes`` gives 0..255), with pybox2d's
    element-wise arithmetic (``+``, ``-`` with colours or triples; ``*``, ``/`` by numbers).

    >>> c = b2Color(0.2, 0.4, 0.6)
    >>> c + (1, 1, 1), c * 2, b2Color(1, 0.5, 0).bytes
    (b2Color(1.2,1.4,1.6), b2Color(0.4,0.8,1.2), [255, 127, 0])
    """

    __slots__ = ("b", "g", "r")

    def __init__(self, *args: Any) -> None:
        if not args:
            r = g = b = 0.0
        elif len(args) in (1, 3):  # a colour or any triple; or r, g, b
            r, g, b = _rgb(args[0] if len(args) == 1 else args)
        else:
            raise ComponentTypeError(
                f"b2Color takes no arguments, a colour or r, g, b; got {args!r}")
        self.r, self.g, self.b = r, g, b

    def Set(self, r: float, g: float, b: float) -> None:
        self.r, self.g, self.b = b2Color(r, g, b)

    @property
    def bytes(self) -> builtins.list[int]:
        """The components scaled to 0..255 (truncated, as pybox2d's)."""
        return [int(self.r * 255), int(self.g * 255), int(self.b * 255)]

    @bytes.setter
    def bytes(self, value: Any) -> None:
        r, g, b = _rgb(value)
        self.r, self.g, self.b = r / 255.0, g / 255.0, b / 255.0

    @property
    def list(self) -> builtins.list[float]:
        return [self.r, self.g, self.b]

    @list.setter
    def list(self, value: Any) -> None:
        self.r, self.g, self.b = b2Color(*_rgb(value))

    def copy(self) -> b2Color:
        return b2Color(self.r, self.g, self.b)

    def __len__(self) -> int:
        return 3

    def __iter__(self) -> Iterator[float]:
        return iter((self.r, self.g, self.b))

    def __getitem__(self, i: int) -> float:
        return (self.r, self.g, self.b)[i]

    def __setitem__(self, i: int, value: float) -> None:
        setattr(self, ("r", "g", "b")[i], finite(value, "b2Color", "component"))

    def __eq__(self, other: object) -> bool:
        seq: Any = other
        try:
            r, g, b = seq
        except (TypeError, ValueError):
            return NotImplemented
        return bool(self.r == r and self.g == g and self.b == b)

    __hash__ = None  # type: ignore[assignment]  # mutable, like pybox2d's

    def __add__(self, other: Any) -> b2Color:
        r, g, b = _rgb(other)
        return b2Color(self.r + r, self.g + g, self.b + b)

    __radd__ = __add__

    def __sub__(self, other: Any) -> b2Color:
        r, g, b = _rgb(other)
        return b2Color(self.r - r, self.g - g, self.b - b)

    def __rsub__(self, other: Any) -> b2Color:
        r, g, b = _rgb(other)
        return b2Color(r - self.r, g - self.g, b - self.b)

    def __mul__(self, k: float) -> b2Color:
        k = finite(k, "b2Color", "factor")
        return b2Color(self.r * k, self.g * k, self.b * k)

    __rmul__ = __mul__

    def __truediv__(self, k: float) -> b2Color:
        return self * (1.0 / finite(k, "b2Color", "divisor"))

    def __iadd__(self, other: Any) -> b2Color:
        self.r, self.g, self.b = self + other
        return self

    def __isub__(self, other: Any) -> b2Color:
        self.r, self.g, self.b = self - other
        return self

    def __imul__(self, k: float) -> b2Color:
        self.r, self.g, self.b = self * k
        return self

    def __itruediv__(self, k: float) -> b2Color:
        self.r, self.g, self.b = self / k
        return self

    def __repr__(self) -> str:
        return f"b2Color({self.r:g},{self.g:g},{self.b:g})"


def _rgb(value: Any) -> tuple[float, float, float]:
    """Three finite numbers from a colour or a triple (else a kge error)."""
    if isinstance(value, b2Color):
        return value.r, value.g, value.b
    try:
        r, g, b = value
    except (TypeError, ValueError):
        raise ComponentTypeError(f"a b2Color needs three components, got {value!r}") from None
    return (finite(r, "b2Color", "r"), finite(g, "b2Color", "g"), finite(b, "b2Color", "b"))


#: Box2D's debug colours (b2World::DrawDebugData)
INACTIVE = b2Color(0.5, 0.5, 0.3)
STATIC = b2Color(0.5, 0.9, 0.5)
KINEMATIC = b2Color(0.5, 0.5, 0.9)
ASLEEP = b2Color(0.6, 0.6, 0.6)
AWAKE = b2Color(0.9, 0.7, 0.7)
JOINT = b2Color(0.5, 0.8, 0.8)
AABB = b2Color(0.9, 0.3, 0.9)
PAIR = b2Color(0.3, 0.9, 0.9)


class b2Draw:
    """Base of a debug renderer: override the ``Draw*`` methods (they do nothing here)."""

    e_shapeBit = 0x0001
    e_jointBit = 0x0002
    e_aabbBit = 0x0004
    e_pairBit = 0x0008
    e_centerOfMassBit = 0x0010
    e_convertVertices = 0x1000
    _flag_entries: ClassVar[list[tuple[str, int]]] = [
        ("drawShapes", e_shapeBit), ("drawJoints", e_jointBit), ("drawAABBs", e_aabbBit),
        ("drawPairs", e_pairBit), ("drawCOMs", e_centerOfMassBit),
        ("convertVertices", e_convertVertices),
    ]

    def __init__(self, **kwargs: Any) -> None:
        self._flags = 0
        for name, value in kwargs.items():
            if not hasattr(self, name):
                raise ComponentTypeError(f"{type(self).__name__} has no property {name!r}")
            setattr(self, name, value)

    @property
    def flags(self) -> dict[str, bool]:
        """Which parts are drawn, as pybox2d's dict (assign a dict to change them)."""
        return {name: (self._flags & bit) == bit for name, bit in self._flag_entries}

    @flags.setter
    def flags(self, value: dict[str, bool]) -> None:
        if not isinstance(value, dict):
            raise ComponentTypeError(f"b2Draw.flags takes a dict of booleans, got {value!r}")
        unknown = set(value) - {name for name, _ in self._flag_entries}
        if unknown:
            raise ComponentTypeError(f"b2Draw.flags has no {sorted(unknown)}")
        self._flags = sum(bit for name, bit in self._flag_entries if value.get(name))

    def AppendFlags(self, flags: int) -> None:
        self._flags |= int(flags)

    def ClearFlags(self, flags: int) -> None:
        self._flags &= ~int(flags)

    # the renderer's side: pybox2d calls these with world points (b2Vec2) and a b2Color
    def StartDraw(self) -> None:
        """Called before a ``DrawDebugData`` pass (pybox2d's testbed backends' hook)."""

    def EndDraw(self) -> None:
        """Called after a ``DrawDebugData`` pass."""

    def DrawPolygon(self, vertices: list[Any], color: b2Color) -> None:
        """An outlined polygon."""

    def DrawSolidPolygon(self, vertices: list[Any], color: b2Color) -> None:
        """A filled polygon."""

    def DrawCircle(self, center: Any, radius: float, color: b2Color) -> None:
        """An outlined circle."""

    def DrawSolidCircle(self, center: Any, radius: float, axis: Any, color: b2Color) -> None:
        """A filled circle with a radius line along ``axis`` (its rotation)."""

    def DrawSegment(self, p1: Any, p2: Any, color: b2Color) -> None:
        """A line segment."""

    def DrawTransform(self, xf: b2Transform) -> None:
        """A frame: the position with its two axes."""


class b2DrawExtended(b2Draw):
    """A ``b2Draw`` that hands the renderer screen coordinates.

    With ``convertVertices`` on, points are converted before the ``Draw*`` calls:
    ``x * zoom - offset.x`` (mirrored as ``screenSize.x - x`` with ``flipX``), the
    same for y (``flipY`` for a top-left origin), and radii are scaled by ``zoom``.
    """

    def __init__(self, **kwargs: Any) -> None:
        self.convertVertices = False
        self.center = b2Vec2(0.0, 0.0)
        self.offset = b2Vec2(0.0, 0.0)
        self.zoom = 1.0
        self.screenSize = b2Vec2(0.0, 0.0)
        self.flipX = False
        self.flipY = False
        super().__init__(**kwargs)

    def __setattr__(self, name: str, value: Any) -> None:
        """The view's numbers are checked when set (a bad zoom fails here, not mid-draw)."""
        if name in ("center", "offset", "screenSize"):
            value = b2Vec2(*as_xy(value, "b2DrawExtended", name))
        elif name == "zoom":
            value = finite(value, "b2DrawExtended", "zoom")
        object.__setattr__(self, name, value)

    def to_screen(self, point: Any) -> tuple[float, float]:
        x, y = as_xy(point, "b2DrawExtended", "point")
        sx = x * self.zoom - self.offset.x
        sy = y * self.zoom - self.offset.y
        if self.flipX:
            sx = self.screenSize.x - sx
        if self.flipY:
            sy = self.screenSize.y - sy
        return sx, sy


def draw_debug_data(world: b2World, renderer: b2Draw) -> None:
    """Box2D's b2World::DrawDebugData onto ``renderer`` (see the module notes)."""
    flags = renderer._flags
    convert = isinstance(renderer, b2DrawExtended) and renderer.convertVertices
    pt: Callable[[Any], Any] = (
        (lambda p: b2Vec2(*renderer.to_screen(p)))  # type: ignore[attr-defined]
        if convert else (lambda p: b2Vec2(p)))
    scale = renderer.zoom if convert else 1.0  # type: ignore[attr-defined]
    bodies = world.bodies[::-1]  # Box2D's own list order (newest first), as pybox2d draws
    renderer.StartDraw()
    _draw(world, renderer, flags, bodies, pt, scale)
    renderer.EndDraw()


def _draw(world: b2World, renderer: b2Draw, flags: int, bodies: list[b2Body],
          pt: Callable[[Any], Any], scale: float) -> None:
    if flags & b2Draw.e_shapeBit:
        for body in bodies:
            color = _body_color(body)
            xf = body.transform
            for fixture in body.fixtures[::-1]:
                _draw_shape(renderer, fixture.shape, xf, color, pt, scale)
    if flags & b2Draw.e_jointBit:
        for joint in world.joints[::-1]:
            a, b = joint.bodyA, joint.bodyB
            x1, x2 = pt(a.position), pt(b.position)
            p1, p2 = pt(joint.anchorA), pt(joint.anchorB)
            renderer.DrawSegment(x1, p1, JOINT)
            renderer.DrawSegment(p1, p2, JOINT)
            renderer.DrawSegment(x2, p2, JOINT)
    if flags & b2Draw.e_pairBit:
        for contact in world.contacts:
            ca = contact.fixtureA.GetAABB(0).center
            cb = contact.fixtureB.GetAABB(0).center
            renderer.DrawSegment(pt(ca), pt(cb), PAIR)
    if flags & b2Draw.e_aabbBit:
        for body in bodies:
            if not body.active:
                continue
            for fixture in body.fixtures[::-1]:
                for child in range(fixture.shape.childCount):
                    box = fixture.GetAABB(child)
                    lo, hi, m = box.lowerBound, box.upperBound, b2_aabbExtension
                    corners = [(lo.x - m, lo.y - m), (hi.x + m, lo.y - m), (hi.x + m, hi.y + m),
                               (lo.x - m, hi.y + m)]
                    renderer.DrawPolygon([pt(c) for c in corners], AABB)
    if flags & b2Draw.e_centerOfMassBit:
        for body in bodies:
            c = body.worldCenter
            renderer.DrawTransform(make_transform(c.x, c.y, body.angle))


def _body_color(body: b2Body) -> b2Color:
    if not body.active:
        return INACTIVE
    if body.type == b2_staticBody:
        return STATIC
    if body.type == b2_kinematicBody:
        return KINEMATIC
    if not body.awake:
        return ASLEEP
    return AWAKE


def _draw_shape(renderer: b2Draw, shape: Any, xf: b2Transform, color: b2Color,
                pt: Callable[[Any], Any], scale: float) -> None:
    if isinstance(shape, b2CircleShape):
        center = xf * shape.pos
        axis = b2Vec2(math.cos(xf.angle), math.sin(xf.angle))
        renderer.DrawSolidCircle(pt(center), shape.radius * scale, axis, color)
    elif isinstance(shape, b2PolygonShape):
        renderer.DrawSolidPolygon([pt(xf * v) for v in shape.vertices], color)
    elif isinstance(shape, b2EdgeShape):
        v1, v2 = shape.vertices
        renderer.DrawSegment(pt(xf * v1), pt(xf * v2), color)
    elif isinstance(shape, b2ChainShape):  # and b2LoopShape, closed
        points = [pt(xf * v) for v in shape.vertices]
        if shape.loop and len(points) > 2:
            points.append(points[0])
        for p1, p2 in itertools.pairwise(points):
            renderer.DrawSegment(p1, p2, color)
