"""Shapes: polygon, circle, edge and chain (``b2LoopShape``), pybox2d's four shape types.

pybox2d shapes are free-standing geometry that a fixture *copies* when it is
created; programs mutate one shape and reuse it for the next fixture
(BipedalWalker edits ``fd.shape.vertices`` before each terrain piece). So these
classes hold plain data, and :meth:`b2Shape.to_kge` turns them into kge's frozen
shape components at fixture creation.

Polygons go through Box2D's own ``b2PolygonShape::Set``: close points are
welded, the convex hull is taken by gift wrapping from the right-most point,
and fewer than 3 hull points (or more than 16 inputs) are refused. So the
``vertices`` read back are in Box2D's order, which renderers rely on.

>>> b2PolygonShape(box=(1, 0.5)).vertices
[(-1.0, -0.5), (1.0, -0.5), (1.0, 0.5), (-1.0, 0.5)]
>>> b2PolygonShape(vertices=[(0, 0), (1, 1), (1, 0), (0.5, 0.2)]).vertices
[(1.0, 0.0), (1.0, 1.0), (0.0, 0.0)]
"""

from __future__ import annotations

import math
from typing import Any

from kge import collision
from kge.box2d.constants import b2_linearSlop, b2_maxPolygonVertices, b2_polygonRadius
from kge.box2d.errors import MissingError, b2AssertException
from kge.box2d.rays import cast
from kge.box2d.transform import b2AABB, b2Transform
from kge.box2d.vec import as_xy, b2Vec2
from kge.collision.geometry import convex
from kge.components.shapes import Chain, Circle, Edge, Polygon, Shape
from kge.errors import ComponentTypeError, ValidationError

Vec2 = tuple[float, float]

#: the kge radius of a zero-radius b2CircleShape (m): far below Box2D's linear slop, so
#: the point collides as Box2D's does, through the other shape's skin
POINT_RADIUS = 1e-6


def _points(value: Any, owner: str) -> list[Vec2]:
    """The points of a ``vertices`` value; anything but pairs of numbers is a MissingError
    (pybox2d's ValueError)."""
    if isinstance(value, (str, bytes)) or not hasattr(value, "__iter__"):
        raise MissingError(f"{owner}.vertices must be a sequence of points, got {value!r}")
    try:
        return [as_xy(p, owner, f"vertices[{i}]") for i, p in enumerate(value)]
    except ComponentTypeError as e:
        raise MissingError(str(e)) from None


def polygon_hull(points: list[Vec2], owner: str = "b2PolygonShape") -> list[Vec2]:
    """Box2D 2.3's b2PolygonShape::Set: weld, then gift-wrap the convex hull."""
    n = len(points)
    if n > b2_maxPolygonVertices:
        raise ValidationError(
            f"{owner}.vertices must have 3..{b2_maxPolygonVertices} points, got {n}"
        )
    if n < 3:
        raise b2AssertException(
            f"{owner}.vertices must have 3..{b2_maxPolygonVertices} points, got {n}"
        )
    weld = (0.5 * b2_linearSlop) ** 2
    ps: list[Vec2] = []
    for x, y in points:
        if all((x - qx) ** 2 + (y - qy) ** 2 >= weld for qx, qy in ps):
            ps.append((x, y))
    n = len(ps)
    if n < 3:
        raise b2AssertException(f"{owner}: the points are degenerate (fewer than 3 apart)")
    i0 = 0
    x0 = ps[0][0]
    for i in range(1, n):
        x = ps[i][0]
        if x > x0 or (x == x0 and ps[i][1] < ps[i0][1]):
            i0, x0 = i, x
    hull: list[int] = []
    ih = i0
    while True:
        hull.append(ih)
        ie = 0
        hx, hy = ps[ih]
        for j in range(1, n):
            if ie == ih:
                ie = j
                continue
            rx, ry = ps[ie][0] - hx, ps[ie][1] - hy
            vx, vy = ps[j][0] - hx, ps[j][1] - hy
            c = rx * vy - ry * vx
            if c < 0.0 or (c == 0.0 and vx * vx + vy * vy > rx * rx + ry * ry):
                ie = j
        ih = ie
        if ie == i0 or len(hull) > n:
            break
    if len(hull) < 3:
        raise b2AssertException(f"{owner}: the points are collinear (no area)")
    return [ps[i] for i in hull]


class b2Shape:
    """Base of the four shape types."""

    radius: float
    #: the fixture whose live shape this is (None for a free-standing shape)
    _owner: Any = None

    def to_kge(self) -> Shape:
        raise NotImplementedError

    def _commit(self, old: dict[str, Any]) -> None:
        """A property of a fixture's shape changed: rebuild the collider's shape, as
        pybox2d programs expect (``fixture.shape.radius = 2``); a refused value puts
        the old geometry back."""
        owner = self._owner
        if owner is None:
            return
        try:
            owner._reshape(self)
        except Exception:
            self.__dict__.clear()
            self.__dict__.update(old)
            raise

    @property
    def type(self) -> int:
        return _TYPE_IDS[type(self).__name__]

    @property
    def childCount(self) -> int:
        return 1

    # Box2D's shape type numbers
    e_circle, e_edge, e_polygon, e_chain, e_typeCount = 0, 1, 2, 3, 4

    def getAsType(self) -> b2Shape:
        """This shape as its own type (pybox2d's downcast: kge's shapes already are)."""
        return self

    def getAABB(self, transform: b2Transform, childIndex: int = 0) -> b2AABB:
        """The box around child ``childIndex`` placed at ``transform`` (with the skin radius)."""
        pts = [transform * p for p in self._outline(childIndex)]
        r = self.radius
        xs, ys = [p.x for p in pts], [p.y for p in pts]
        return b2AABB((min(xs) - r, min(ys) - r), (max(xs) + r, max(ys) + r))

    def _outline(self, child: int = 0) -> list[Vec2]:
        raise NotImplementedError

    def TestPoint(self, xf: b2Transform, p: Any) -> bool:
        """Is the world point ``p`` inside this shape placed at ``xf``? (edges: never)"""
        return collision.test_point(self.to_kge(), _pose(xf), as_xy(p, "TestPoint", "p"))

    def RayCast(self, output: Any, input: Any, transform: b2Transform,
                childIndex: int = 0) -> bool:
        """Cast ``input``'s ray at child ``childIndex`` placed at ``transform``; on a hit
        fill ``output`` (fraction, normal) and return True."""
        return cast(self.to_kge(), _pose(transform), output, input, childIndex)

    def __copy__(self) -> b2Shape:
        new = type(self).__new__(type(self))
        new.__dict__.update(self.__dict__)
        new.__dict__.pop("_owner", None)
        return new


class b2CircleShape(b2Shape):
    """A circle of ``radius`` centred at ``pos`` (body-local)."""

    def __init__(self, radius: float = 0.0, pos: Any = (0.0, 0.0), **kw: Any) -> None:
        self.radius = radius
        self.pos = pos
        _set_extra(self, kw)

    @property
    def radius(self) -> float:
        return self._radius

    @radius.setter
    def radius(self, value: float) -> None:
        old = dict(self.__dict__)
        self._radius = float(value)
        self._commit(old)

    @property
    def pos(self) -> b2Vec2:
        return self._pos

    @pos.setter
    def pos(self, value: Any) -> None:
        old = dict(self.__dict__)
        self._pos = b2Vec2(*as_xy(value, "b2CircleShape", "pos"))
        self._commit(old)

    p = pos

    @property
    def is_point(self) -> bool:
        """A radius of 0: Box2D's point, which touches polygons and edges by their skin."""
        return self._radius == 0.0

    def to_kge(self) -> Shape:
        """The kge circle; a point (radius 0) becomes a circle of :data:`POINT_RADIUS`
        (kge's circles need a size), whose fixture gets no mass, as Box2D's point has none."""
        if not self._radius >= 0.0:
            raise ValidationError(f"b2CircleShape.radius must be >= 0, got {self._radius!r}")
        return Circle(self._radius or POINT_RADIUS, (self._pos.x, self._pos.y))

    def _outline(self, child: int = 0) -> list[Vec2]:
        return [(self._pos.x, self._pos.y)]

    def __repr__(self) -> str:
        return f"b2CircleShape(radius={self._radius:g}, pos={self._pos!r})"


class b2PolygonShape(b2Shape):
    """A convex polygon (3..16 vertices), given by ``vertices`` or ``box``."""

    def __init__(self, vertices: Any = None, box: Any = None, **kw: Any) -> None:
        self.radius = b2_polygonRadius
        self._vertices: list[Vec2] = []
        if box is not None:
            self.box = box
        if vertices is not None:
            self.vertices = vertices
        _set_extra(self, kw)

    @property
    def vertices(self) -> list[Vec2]:
        return list(self._vertices)

    @vertices.setter
    def vertices(self, value: Any) -> None:
        old = dict(self.__dict__)
        self._vertices = polygon_hull(_points(value, "b2PolygonShape"))
        self._commit(old)

    @property
    def vertexCount(self) -> int:
        return len(self._vertices)

    def __len__(self) -> int:
        return len(self._vertices)

    @property
    def normals(self) -> list[Vec2]:
        vs, out = self._vertices, []
        for i, (x0, y0) in enumerate(vs):
            x1, y1 = vs[(i + 1) % len(vs)]
            ex, ey = x1 - x0, y1 - y0
            n = math.hypot(ex, ey)
            out.append((ey / n, -ex / n))
        return out

    @property
    def centroid(self) -> b2Vec2:
        from kge.physics.mass import polygon_mass  # the engine's own formula

        cx, cy = polygon_mass(self._vertices, 1.0).center
        return b2Vec2(cx, cy)

    @property
    def box(self) -> None:
        raise AttributeError("b2PolygonShape.box is write-only (read vertices)")

    @box.setter
    def box(self, value: Any) -> None:
        if isinstance(value, (str, bytes)) or not hasattr(value, "__len__"):
            raise ComponentTypeError(
                f"b2PolygonShape.box must be (hx, hy[, center, angle]), got {value!r}")
        self.SetAsBox(*value)

    def SetAsBox(self, hx: float, hy: float, center: Any = None, angle: float = 0.0) -> None:
        """A box of half extents ``hx``, ``hy``, optionally centred and rotated."""
        hx, hy = as_xy((hx, hy), "b2PolygonShape", "box")
        if hx <= 0.0 or hy <= 0.0:
            raise ValidationError(f"b2PolygonShape box half extents must be > 0, got {(hx, hy)!r}")
        cx, cy = (0.0, 0.0) if center is None else as_xy(center, "b2PolygonShape", "center")
        old = dict(self.__dict__)
        c, s = math.cos(angle), math.sin(angle)
        corners = ((-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy))
        if center is None and angle == 0.0:
            self._vertices = list(corners)
        else:
            self._vertices = [(c * x - s * y + cx, s * x + c * y + cy) for x, y in corners]
        self._commit(old)

    def to_kge(self) -> Shape:
        if len(self._vertices) < 3:
            raise ValidationError("b2PolygonShape has no vertices (give vertices= or box=)")
        return Polygon(self._vertices)

    def _outline(self, child: int = 0) -> list[Vec2]:
        return self._vertices

    @property
    def valid(self) -> bool:
        try:
            Polygon(self._vertices)
        except ValidationError:
            return False
        return True

    def __repr__(self) -> str:
        return f"b2PolygonShape(vertices={self._vertices!r})"


class b2EdgeShape(b2Shape):
    """A line segment from ``vertex1`` to ``vertex2``, with optional ghost vertices.

    pybox2d's ``vertices`` takes 2 to 4 points: ``[v1, v2]``, ``[v0, v1, v2]``,
    ``[v0, v1, v2, v3]`` or ``[None, v1, v2, v3]``. The ghosts ``vertex0`` (before
    ``vertex1``) and ``vertex3`` (after ``vertex2``) are the neighbouring edges'
    far ends: Box2D uses them to slide shapes across the join without catching
    on it, and so does kge (its chains do the same).

    >>> e = b2EdgeShape(vertices=[None, (0, 0), (1, 0), (2, 1)])
    >>> e.vertices, e.hasVertex0, e.hasVertex3, e.vertex3
    ([(0.0, 0.0), (1.0, 0.0)], False, True, b2Vec2(2,1))
    """

    def __init__(self, vertices: Any = None, vertex1: Any = None, vertex2: Any = None,
                 **kw: Any) -> None:
        self.radius = b2_polygonRadius
        self.vertex0 = b2Vec2(0.0, 0.0)
        self.vertex1 = b2Vec2(0.0, 0.0)
        self.vertex2 = b2Vec2(0.0, 0.0)
        self.vertex3 = b2Vec2(0.0, 0.0)
        self.hasVertex0 = self.hasVertex3 = False
        if vertices is not None:
            self.vertices = vertices
        if vertex1 is not None:
            self.vertex1 = b2Vec2(*as_xy(vertex1, "b2EdgeShape", "vertex1"))
        if vertex2 is not None:
            self.vertex2 = b2Vec2(*as_xy(vertex2, "b2EdgeShape", "vertex2"))
        _set_extra(self, kw)

    @property
    def vertices(self) -> list[Vec2]:
        return [self.vertex1.tuple, self.vertex2.tuple]

    @vertices.setter
    def vertices(self, value: Any) -> None:
        if isinstance(value, (str, bytes)) or not hasattr(value, "__len__"):
            raise MissingError(f"b2EdgeShape.vertices must be 2 to 4 points, got {value!r}")
        given = list(value)
        if not 2 <= len(given) <= 4:
            raise ValidationError(f"b2EdgeShape.vertices must be 2 to 4 points, got {len(given)}")
        if len(given) == 2:
            given = [None, *given, None]
        elif len(given) == 3:
            given = [*given, None]
        v0, v1, v2, v3 = given
        if v1 is None or v2 is None:
            raise MissingError(f"b2EdgeShape.vertices: the edge's own two points are needed, "
                               f"got {value!r}")
        ghosts = [None if g is None else _points([g], "b2EdgeShape")[0] for g in (v0, v3)]
        ends = _points([v1, v2], "b2EdgeShape")
        old = dict(self.__dict__)
        self.vertex1, self.vertex2 = b2Vec2(*ends[0]), b2Vec2(*ends[1])
        self.hasVertex0, self.hasVertex3 = ghosts[0] is not None, ghosts[1] is not None
        self.vertex0 = b2Vec2(*(ghosts[0] or (0.0, 0.0)))
        self.vertex3 = b2Vec2(*(ghosts[1] or (0.0, 0.0)))
        self._commit(old)

    def Set(self, v1: Any, v2: Any) -> None:
        self.vertices = [v1, v2]

    @property
    def vertexCount(self) -> int:
        return 2 + self.hasVertex0 + self.hasVertex3

    @property
    def all_vertices(self) -> list[Vec2]:
        """``vertex0`` to ``vertex3``, the ghosts included ((0, 0) where there is none)."""
        return [self.vertex0.tuple, self.vertex1.tuple, self.vertex2.tuple, self.vertex3.tuple]

    def to_kge(self) -> Shape:
        return Edge(self.vertex1.tuple, self.vertex2.tuple,
                    vertex0=self.vertex0.tuple if self.hasVertex0 else None,
                    vertex3=self.vertex3.tuple if self.hasVertex3 else None)

    def _outline(self, child: int = 0) -> list[Vec2]:
        return self.vertices

    def __repr__(self) -> str:
        return f"b2EdgeShape(vertices={self.vertices!r})"


class b2ChainShape(b2Shape):
    """Connected edges through the points given, as pybox2d 2.3.10 builds them:
    ``vertices=`` and ``vertices_loop=`` make a closed loop (its ``vertices`` read
    back with the first point repeated at the end, as Box2D stores a loop), and
    ``vertices_chain=`` an open chain. Either way the edges join smoothly (each one
    knows its neighbours: Box2D's ghost vertices).

    >>> b2ChainShape(vertices=[(0, 0), (1, 0), (1, 1)]).childCount
    3
    >>> b2ChainShape(vertices_chain=[(0, 0), (1, 0), (1, 1)]).childCount
    2
    """

    def __init__(self, vertices: Any = None, vertices_chain: Any = None,
                 vertices_loop: Any = None, **kw: Any) -> None:
        self.radius = b2_polygonRadius
        self.loop = True
        self._vertices: list[Vec2] = []
        if vertices is not None:
            self.vertices = vertices
        if vertices_loop is not None:
            self.vertices_loop = vertices_loop
        if vertices_chain is not None:
            self.vertices_chain = vertices_chain
        _set_extra(self, kw)

    def _set(self, value: Any, loop: bool) -> None:
        pts = _points(value, type(self).__name__)
        need = 3 if loop else 2
        if len(pts) < need:  # pybox2d: a ValueError for a chain, Box2D's assertion for a loop
            error = b2AssertException if loop else ValidationError
            raise error(
                f"{type(self).__name__}.vertices needs at least {need} points, got {len(pts)}"
            )
        old = dict(self.__dict__)
        self._vertices, self.loop = pts, loop
        self._commit(old)

    @property
    def vertices(self) -> list[Vec2]:
        """The points; a loop's first point comes again at the end (Box2D's storage)."""
        return self._vertices + (self._vertices[:1] if self.loop else [])

    @vertices.setter
    def vertices(self, value: Any) -> None:
        self._set(value, True)

    @property
    def vertices_loop(self) -> list[Vec2]:
        return self.vertices

    @vertices_loop.setter
    def vertices_loop(self, value: Any) -> None:
        self._set(value, True)

    @property
    def vertices_chain(self) -> list[Vec2]:
        return self.vertices

    @vertices_chain.setter
    def vertices_chain(self, value: Any) -> None:
        self._set(value, False)

    @property
    def vertexCount(self) -> int:
        return len(self.vertices)

    @property
    def childCount(self) -> int:
        n = len(self._vertices)
        return n if self.loop else n - 1

    @property
    def edges(self) -> list[b2EdgeShape]:
        """Each child edge with its ghost vertices (its neighbours in the chain)."""
        return [self.getChildEdge(i) for i in range(self.childCount)]

    def getChildEdge(self, index: int) -> b2EdgeShape:
        """Child edge ``index``, with its neighbours as ghost vertices (Box2D's GetChildEdge)."""
        if not 0 <= index < self.childCount:
            raise IndexError(f"{type(self).__name__} child {index} out of range "
                             f"(0..{self.childCount - 1})")
        piece = convex(self.to_kge(), index)
        (v1, v2), v0, v3 = piece.vertices, piece.vertex0, piece.vertex3
        return b2EdgeShape(vertices=[v0, v1, v2, v3])

    def to_kge(self) -> Shape:
        return Chain(self._vertices, loop=self.loop)

    def _outline(self, child: int = 0) -> list[Vec2]:
        return self.getChildEdge(child).vertices

    def __repr__(self) -> str:
        return f"{type(self).__name__}(vertices={self._vertices!r})"


class b2LoopShape(b2ChainShape):
    """pybox2d's loop shape: a :class:`b2ChainShape` (``vertices=`` makes a loop)."""


def _pose(xf: Any) -> tuple[float, float, float]:
    if not isinstance(xf, b2Transform):
        raise ComponentTypeError(f"a b2Transform is needed, got {xf!r}")
    return (xf.position.x, xf.position.y, xf.angle)


def _set_extra(shape: b2Shape, kw: dict[str, Any]) -> None:
    for name, value in kw.items():
        if not hasattr(type(shape), name) and name != "radius":
            raise ComponentTypeError(f"{type(shape).__name__} has no property {name!r}")
        setattr(shape, name, value)


_TYPE_IDS = {"b2CircleShape": 0, "b2EdgeShape": 1, "b2PolygonShape": 2,
             "b2ChainShape": 3, "b2LoopShape": 3}


def from_kge(shape: Shape) -> b2Shape:
    """The pybox2d view of a kge shape (for fixtures made from kge shapes)."""
    if isinstance(shape, Circle):
        return b2CircleShape(radius=shape.radius, pos=shape.center)
    if isinstance(shape, Edge):
        return b2EdgeShape(vertices=[shape.v1, shape.v2])
    if isinstance(shape, Chain):
        key = "vertices_loop" if shape.loop else "vertices_chain"
        return b2ChainShape(**{key: list(shape.vertices)})
    if isinstance(shape, Polygon):
        return b2PolygonShape(vertices=list(shape.vertices))
    return b2PolygonShape(vertices=list(shape.vertices()))  # Box
