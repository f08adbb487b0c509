"""Fixtures: ``b2Filter``, ``b2FixtureDef`` and ``b2Fixture`` (a kge Collider entity).

A ``b2Fixture`` is a view of one collider entity attached to its body's entity
(``Collider(body=...)``); reading and writing its properties reads and writes
that component, so friction, sensor and filter changes reach the engine at the
next step exactly as a kge game's would. The fixture keeps its own copy of the
definition's shape (as Box2D clones it), so programs may reuse one definition.

pybox2d's ``b2FixtureDef`` takes the filter fields as shortcuts
(``categoryBits=``, ``maskBits=``, ``groupIndex=``); so does this one.
Box2D's default density is 0 (a massless fixture), unlike kge's Collider.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from kge.box2d.errors import KeywordError, MissingError
from kge.box2d.massdata import b2MassData
from kge.box2d.shapes import b2CircleShape, b2Shape, from_kge
from kge.box2d.vec import as_xy, b2Vec2
from kge.components.collider import Collider
from kge.components.filter import Filter
from kge.errors import ComponentTypeError, ValidationError

if TYPE_CHECKING:
    from kge.box2d.body import b2Body


def set_keywords(obj: Any, kwargs: dict[str, Any]) -> None:
    """Apply constructor keywords as properties, refusing names the class does not have
    (pybox2d raises AttributeError: :class:`~kge.box2d.errors.KeywordError` is one)."""
    cls = type(obj)
    for name, value in kwargs.items():
        if not hasattr(cls, name) and name not in obj.__dict__:
            raise KeywordError(f"{cls.__name__} has no property {name!r}")
        setattr(obj, name, value)


def massless_density(shape: b2Shape, density: float) -> float:
    """The collider density for ``shape``: 0 for a point (a zero-radius circle, which
    Box2D gives no mass; kge's stand-in circle must not get any either)."""
    return 0.0 if isinstance(shape, b2CircleShape) and shape.is_point else density


class b2Filter:
    """Collision filtering data: category, mask and group (Box2D's rules)."""

    def __init__(self, categoryBits: int = 0x0001, maskBits: int = 0xFFFF,
                 groupIndex: int = 0) -> None:
        self.categoryBits = categoryBits
        self.maskBits = maskBits
        self.groupIndex = groupIndex

    def to_kge(self) -> Filter:
        return Filter(self.categoryBits, self.maskBits, self.groupIndex)

    @classmethod
    def from_kge(cls, f: Filter) -> b2Filter:
        return cls(f.category_bits, f.mask_bits, f.group_index)

    def __repr__(self) -> str:
        return (f"b2Filter(categoryBits={self.categoryBits:#x}, maskBits={self.maskBits:#x}, "
                f"groupIndex={self.groupIndex})")


class b2FixtureDef:
    """What ``CreateFixture`` needs: a shape and its material."""

    def __init__(self, **kwargs: Any) -> None:
        self.shape: b2Shape | None = None
        self.density = 0.0
        self.friction = 0.2
        self.restitution = 0.0
        self.isSensor = False
        self.userData: Any = None
        self.filter = b2Filter()
        set_keywords(self, kwargs)

    # pybox2d's shortcuts into the filter
    categoryBits = property(lambda self: self.filter.categoryBits,
                            lambda self, v: setattr(self.filter, "categoryBits", v))
    maskBits = property(lambda self: self.filter.maskBits,
                        lambda self, v: setattr(self.filter, "maskBits", v))
    groupIndex = property(lambda self: self.filter.groupIndex,
                          lambda self, v: setattr(self.filter, "groupIndex", v))
    sensor = property(lambda self: self.isSensor, lambda self, v: setattr(self, "isSensor", v))

    def to_collider(self, body_entity: int) -> tuple[Collider, b2Shape]:
        """The Collider component (checked by kge) and the fixture's own copy of the shape."""
        shape = self.shape
        if not isinstance(shape, b2Shape):
            raise MissingError(f"b2FixtureDef.shape: must specify the shape for the fixture "
                               f"(a b2 shape), got {shape!r}")
        filt = self.filter
        if not isinstance(filt, b2Filter):
            raise ComponentTypeError(f"b2FixtureDef.filter must be a b2Filter, got {filt!r}")
        col = Collider(
            shape.to_kge(), density=massless_density(shape, self.density),
            friction=self.friction,
            restitution=self.restitution, filter=filt.to_kge(), sensor=self.isSensor,
            body=body_entity,
        )
        return col, shape.__copy__()


class b2Fixture:
    """A shape attached to a body, with material and filter (a kge Collider entity)."""

    def __init__(self, body: b2Body, entity: int, col: Collider, shape: b2Shape,
                 user_data: Any, density: float) -> None:
        self._owner = body
        self._entity = entity
        self._col = col
        self._b2shape = shape
        shape._owner = self
        self.userData = user_data
        self._destroyed = False
        #: the density the program gave (the collider's is 0 for a point circle)
        self._density = float(density)

    def _reshape(self, shape: b2Shape) -> None:
        """The fixture's shape was edited in place: the collider takes the new geometry
        (and a circle shrunk to a point loses its mass)."""
        col = self._live()
        col.shape = shape.to_kge()
        col.density = massless_density(shape, self._density)

    @property
    def entity(self) -> int:
        """The kge collider entity behind this fixture."""
        return self._entity

    @property
    def body(self) -> b2Body:
        return self._owner

    @property
    def shape(self) -> b2Shape:
        return self._b2shape

    @property
    def type(self) -> int:
        return self._b2shape.type

    def _live(self) -> Collider:
        if self._destroyed:
            raise ValidationError(f"b2Fixture (collider entity {self._entity}) was destroyed")
        return self._col

    @property
    def density(self) -> float:
        return self._density

    @density.setter
    def density(self, value: float) -> None:
        self._live().density = massless_density(self._b2shape, value)
        self._density = float(value)
    friction = property(lambda self: self._col.friction,
                        lambda self, v: setattr(self._live(), "friction", v))
    restitution = property(lambda self: self._col.restitution,
                           lambda self, v: setattr(self._live(), "restitution", v))
    sensor = property(lambda self: self._col.sensor,
                      lambda self, v: setattr(self._live(), "sensor", v))
    isSensor = sensor

    @property
    def filterData(self) -> b2Filter:
        return b2Filter.from_kge(self._col.filter)

    @filterData.setter
    def filterData(self, value: b2Filter) -> None:
        if not isinstance(value, b2Filter):
            raise ComponentTypeError(f"b2Fixture.filterData must be a b2Filter, got {value!r}")
        self._live().filter = value.to_kge()

    def TestPoint(self, p: Any) -> bool:
        """Is the world point ``p`` inside this fixture's shape?"""
        self._live()
        hits = self._owner._world._physics.query_point(as_xy(p, "b2Fixture.TestPoint", "p"))
        return any(h.collider == self._entity for h in hits)

    @property
    def massData(self) -> Any:
        from kge.physics.mass import shape_mass

        md = shape_mass(self._col.shape, self._col.density)
        return b2MassData(md.mass, b2Vec2(*md.center), md.inertia
                          + md.mass * (md.center[0] ** 2 + md.center[1] ** 2))

    def GetAABB(self, childIndex: int = 0) -> Any:
        return self._b2shape.getAABB(self._owner.transform, childIndex)

    @property
    def aabb(self) -> Any:
        return self.GetAABB(0)

    def __repr__(self) -> str:
        return f"b2Fixture(entity={self._entity}, shape={self._b2shape!r})"


def default_should_collide(fa: b2Fixture, fb: b2Fixture) -> bool:
    """Box2D's b2ContactFilter::ShouldCollide on two fixtures' filters."""
    a, b = fa._col.filter, fb._col.filter
    if a.group_index == b.group_index and a.group_index != 0:
        return a.group_index > 0
    return bool(a.mask_bits & b.category_bits) and bool(a.category_bits & b.mask_bits)


def shape_from_collider(col: Collider) -> b2Shape:
    return from_kge(col.shape)
