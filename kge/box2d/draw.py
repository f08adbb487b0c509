"""``b2Draw`` / ``b2DrawExtended`` and ``b2World.DrawDebugData``: pybox2d's debug drawing.

A program subclasses ``b2Draw`` (or ``b2DrawExtended``, which converts world
points to screen pixels first), overrides the ``Draw*`` methods with its own
renderer's calls, sets ``world.renderer`` and calls ``world.DrawDebugData()``
once per frame. kge walks the world as Box2D's ``b2World::DrawDebugData`` does:
shapes in Box2D's body-state colours, joints as segments between the bodies and
their anchors, fixture AABBs (fattened by b2_aabbExtension, as the broad phase's
are at rest), and centre-of-mass transforms, each switched by
the renderer's ``flags`` (``drawShapes``, ``drawJoints``, ``drawAABBs``,
``drawPairs``, ``drawCOMs``). ``drawPairs`` draws nothing, as in Box2D 2.3 (whose
pair loop is commented out).
"""

from __future__ import annotations

import builtins
import itertools
import math
from collections.abc import Callable, Iterator, Sequence
from typing import TYPE_CHECKING, Any, ClassVar

from kge.box2d.constants import (
    b2_aabbExtension,
    b2_kinematicBody,
    b2_staticBody,
    e_distanceJoint,
    e_mouseJoint,
    e_pulleyJoint,
)
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


#: the circle Box2D draws at each chain vertex (m)
CHAIN_VERTEX_RADIUS = 0.05

#: Box2D's debug colours (b2World::DrawDebugData)
INACTIVE = b2Color(0.5, 0.5, 0.3)
STATIC = b2Color(0.5, 0.9, 0.5)
KINEMATIC = b2Color(0.5, 0.5, 0.9)
ASLEEP = b2Color(0.6, 0.6, 0.6)
AWAKE = b2Color(0.9, 0.7, 0.7)
JOINT = b2Color(0.5, 0.8, 0.8)
AABB = b2Color(0.9, 0.3, 0.9)


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

    def DrawPolygon(self, vertices: Sequence[Any], color: b2Color) -> None:
        """An outlined polygon."""

    def DrawSolidPolygon(self, vertices: Sequence[Any], color: b2Color) -> None:
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

    With the ``convertVertices`` flag on (``flags = dict(..., convertVertices=True)``,
    or the ``convertVertices`` attribute), points are converted before the ``Draw*``
    calls, as pybox2d does: ``int(x * zoom - offset.x)`` (mirrored as
    ``screenSize.x - x`` with ``flipX``), the same for y (``flipY`` for a top-left
    origin). Radii and ``DrawTransform``'s transform stay in metres (pybox2d's
    backends scale radii by ``zoom`` themselves).
    """

    def __init__(self, **kwargs: Any) -> None:
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

    @property
    def convertVertices(self) -> bool:
        return bool(self._flags & self.e_convertVertices)

    @convertVertices.setter
    def convertVertices(self, value: bool) -> None:
        if value:
            self.AppendFlags(self.e_convertVertices)
        else:
            self.ClearFlags(self.e_convertVertices)

    def to_screen(self, point: Any) -> tuple[int, int]:
        """Screen pixels of a world point: whole pixels, truncated as pybox2d's."""
        x, y = as_xy(point, "b2DrawExtended", "point")
        sx = int(x * self.zoom - self.offset.x)
        sy = int(y * self.zoom - self.offset.y)
        if self.flipX:
            sx = int(self.screenSize.x) - sx
        if self.flipY:
            sy = int(self.screenSize.y) - sy
        return sx, sy


def draw_debug_data(world: b2World, renderer: b2Draw) -> None:
    """Box2D's b2World::DrawDebugData onto ``renderer`` (see the module notes): points as
    (x, y) tuples, in whole screen pixels when the renderer converts them."""
    flags = renderer._flags
    project = _projector(renderer)

    def pt(p: Any) -> tuple[float, float]:
        x, y = as_xy(p, "DrawDebugData", "point")
        return project(x, y)

    bodies = world.bodies[::-1]  # Box2D's own list order (newest first), as pybox2d draws
    _draw(world, renderer, flags, bodies, project, pt)


def _projector(renderer: b2Draw) -> Callable[[float, float], tuple[Any, Any]]:
    """World (x, y) -> what the renderer's Draw calls get: the same floats, or whole screen
    pixels (``b2DrawExtended.to_screen``'s rule) when it converts vertices."""
    if not (isinstance(renderer, b2DrawExtended)
            and renderer._flags & b2Draw.e_convertVertices):
        return lambda x, y: (x, y)
    z, ox, oy = renderer.zoom, renderer.offset.x, renderer.offset.y
    fx = int(renderer.screenSize.x) if renderer.flipX else None
    fy = int(renderer.screenSize.y) if renderer.flipY else None

    def to_screen(x: float, y: float) -> tuple[int, int]:
        sx, sy = int(x * z - ox), int(y * z - oy)
        return (sx if fx is None else fx - sx, sy if fy is None else fy - sy)

    return to_screen


def _draw(world: b2World, renderer: b2Draw, flags: int, bodies: list[b2Body],
          project: Callable[[float, float], Any], pt: Callable[[Any], Any]) -> None:
    if flags & b2Draw.e_shapeBit:
        for body in bodies:
            color = _body_color(body)
            tf = body._tf
            c, s = math.cos(tf.angle), math.sin(tf.angle)
            x0, y0 = tf.x, tf.y

            def place(v: tuple[float, float], c: float = c, s: float = s, x0: float = x0,
                      y0: float = y0) -> Any:
                return project(c * v[0] - s * v[1] + x0, s * v[0] + c * v[1] + y0)

            for fixture in body.fixtures[::-1]:
                _draw_shape(renderer, fixture.shape, (c, s), color, place)
    if flags & b2Draw.e_jointBit:
        for joint in world.joints[::-1]:
            _draw_joint(renderer, joint, pt)
    # e_pairBit: Box2D 2.3 draws nothing for pairs (its loop body is commented out)
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
                    renderer.DrawPolygon(tuple(pt(c) for c in corners), AABB)
    if flags & b2Draw.e_centerOfMassBit:
        for body in bodies:
            center = body.worldCenter
            renderer.DrawTransform(make_transform(center.x, center.y, body.angle))


def _draw_joint(renderer: b2Draw, joint: Any, pt: Callable[[Any], Any]) -> None:
    """Box2D's b2World::DrawJoint: a distance joint's rod, a pulley's ropes and beam, nothing
    for a mouse joint; otherwise body origin - anchor - anchor - body origin."""
    p1, p2 = pt(joint.anchorA), pt(joint.anchorB)
    if joint.type == e_distanceJoint:
        renderer.DrawSegment(p1, p2, JOINT)
    elif joint.type == e_pulleyJoint:
        s1, s2 = pt(joint.groundAnchorA), pt(joint.groundAnchorB)
        renderer.DrawSegment(s1, p1, JOINT)
        renderer.DrawSegment(s2, p2, JOINT)
        renderer.DrawSegment(s1, s2, JOINT)
    elif joint.type != e_mouseJoint:
        x1, x2 = pt(joint.bodyA.position), pt(joint.bodyB.position)
        renderer.DrawSegment(x1, p1, JOINT)
        renderer.DrawSegment(p1, p2, JOINT)
        renderer.DrawSegment(x2, p2, JOINT)


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


def _draw_shape(renderer: b2Draw, shape: Any, rot: tuple[float, float], color: b2Color,
                place: Callable[[tuple[float, float]], Any]) -> None:
    """One shape; ``place`` takes a body-local point to what the renderer gets."""
    if isinstance(shape, b2CircleShape):
        renderer.DrawSolidCircle(place(shape.pos.tuple), shape.radius, rot, color)
    elif isinstance(shape, b2PolygonShape):
        renderer.DrawSolidPolygon(tuple(place(v) for v in shape._vertices), color)
    elif isinstance(shape, b2EdgeShape):
        renderer.DrawSegment(place(shape.vertex1.tuple), place(shape.vertex2.tuple), color)
    elif isinstance(shape, b2ChainShape):  # a loop's vertices repeat the first at the end
        points = [place(v) for v in shape.vertices]
        for p1, p2 in itertools.pairwise(points):
            renderer.DrawSegment(p1, p2, color)
            renderer.DrawCircle(p1, CHAIN_VERTEX_RADIUS, color)
