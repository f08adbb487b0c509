"""kge's data about each pymunk shape, in kge's own table (nothing is hung on the shape).

Every shape the physics system builds gets a *slot*: a small integer, given when
the shape is registered and given back when it is dropped (slots are reused). The
table holds, per slot, in flat typed columns (:class:`array.array` and a
:class:`bytearray`: a contact callback reads a few of them per new contact, and one
read costs about a list index, a third of a numpy scalar read):

``collider``     the collider entity
``body``         the body entity, ``-1`` for the implicit static body (events say None)
``child``        Box2D's child index: the segment of a chain, 0 for other shapes
``rank``         Box2D's fixture order for choosing contact side A (edge, polygon, circle)
``order``        ``(rank, collider)`` as one integer: the lower slot of a pair is side A
``friction``     the collider's friction as the user gave it (pymunk holds its root)
``restitution``  the collider's restitution
``hit``          the collider's hit threshold in m/s, NaN for none
``flags``        what the ``begin`` handler must look at for this shape (:data:`SENSOR`...)

and, as Python objects, the kge :class:`~kge.components.filter.Filter`, the one-way
platform ``((up_x, up_y), min_cos)`` or None, and the shape itself. Chipmunk names
a shape by its ``cpShape`` pointer in callbacks; :meth:`ShapeTable.slot_of_handle`
maps that pointer to the slot with one dict look-up.

One table belongs to each simulated space (:meth:`ShapeTable.of`), so queries
and continuous collision, which are handed a space, find it.

>>> import pymunk
>>> from kge.components.filter import Filter
>>> space = pymunk.Space()
>>> box = pymunk.Poly.create_box(space.static_body, (1.0, 1.0))
>>> table = ShapeTable.of(space)
>>> i = table.add(box, collider=7, body=None, rank=RANK_POLYGON)
>>> table.collider[i], table.body_entity(i), table.slot(box) == i
(7, None, True)
>>> table.filters[i] == Filter()
True
>>> table.drop([box]); table.slot(box) is None
True
"""

from __future__ import annotations

import math
import weakref
from array import array
from collections.abc import Iterable, Sequence
from typing import Any

import pymunk

from kge.components.collider import Collider
from kge.components.filter import Filter
from kge.components.shapes import Chain, Circle, Edge
from kge.physics.cp import shape_handle

#: Box2D picks side A of a contact by shape type: edge/chain, then polygon, then circle.
RANK_EDGE, RANK_POLYGON, RANK_CIRCLE = 0, 1, 2

#: flags: the shape is a sensor
SENSOR = 1
#: flags: a positive filter group (Box2D's exact rule runs in ``begin``)
GROUPED = 2
#: flags: a one-way platform
ONE_WAY = 4
#: flags: restitution above zero (set on the arbiter of a fast enough impact)
BOUNCY = 8
#: flags: a hit threshold (Hit events)
HIT = 16
#: flags: the collider's contacts run the user's pre/post-solve hooks
HOOKED_FLAG = 32
#: flags whose pairs need more than the plain contact path
SPECIAL = GROUPED | ONE_WAY | BOUNCY | HIT | HOOKED_FLAG
#: flags a material write leaves alone
_KEPT = ONE_WAY | HOOKED_FLAG

_DEFAULT_FILTER = Filter()
_NO_BODY = -1
_RANK_SHIFT = 48  # entity ids stay far below 2**48
_tables: weakref.WeakKeyDictionary[pymunk.Space, ShapeTable] = weakref.WeakKeyDictionary()

_COLUMNS = ("collider", "body", "child", "rank", "order", "friction", "restitution", "hit")

OneWay = tuple[tuple[float, float], float]


def rank_of(collider: Collider) -> int:
    """Box2D's fixture order of the collider's shape (0 edge or chain, 1 polygon, 2 circle)."""
    geom = collider.shape
    if isinstance(geom, (Edge, Chain)):
        return RANK_EDGE
    return RANK_CIRCLE if isinstance(geom, Circle) else RANK_POLYGON


class ShapeTable:
    """Per-shape kge data by slot; see the module docstring."""

    def __init__(self) -> None:
        self.collider = array("q")
        self.body = array("q")
        self.child = array("q")
        self.rank = array("b")
        self.order = array("q")
        self.friction = array("d")
        self.restitution = array("d")
        self.hit = array("d")
        self.flags = bytearray()
        self.filters: list[Filter] = []
        self.oneway: list[OneWay | None] = []
        self.shapes: list[pymunk.Shape | None] = []
        #: Chipmunk's ``cpShape *`` -> slot (cffi pointers hash and compare by address)
        self.index: dict[Any, int] = {}
        self._free: list[int] = []

    @classmethod
    def of(cls, space: pymunk.Space) -> ShapeTable:
        """The table of ``space`` (made on first use; it lives as long as the space)."""
        table = _tables.get(space)
        if table is None:
            table = _tables[space] = cls()
        return table

    def adopt(self, space: pymunk.Space) -> None:
        """Make this the table of ``space`` (a simulation that replaced its space)."""
        _tables[space] = self

    # -- registering ---------------------------------------------------------------------
    def add(
        self,
        shape: pymunk.Shape,
        collider: int,
        body: int | None,
        *,
        child: int = 0,
        rank: int = RANK_POLYGON,
        friction: float = 0.0,
        restitution: float = 0.0,
        hit: float | None = None,
        filter: Filter = _DEFAULT_FILTER,
        sensor: bool = False,
    ) -> int:
        """Give ``shape`` a slot holding this data (its own slot again when it has one,
        as a reshaped segment); returns the slot."""
        (i,) = self._register([shape])
        self._write([i], collider, body, rank, friction, restitution, hit, filter, sensor)
        self.child[i] = child
        return i

    def add_collider(
        self, shapes: Sequence[pymunk.Shape], collider: Collider, collider_entity: int,
        body_entity: int | None,
    ) -> None:
        """Register the shapes built for ``collider``: a chain's segments are its
        children 0, 1, ... in order (in bulk: a tile map has 100,000s of them)."""
        slots = self._register(shapes)
        self._write(
            slots, collider_entity, body_entity, rank_of(collider), collider.friction,
            collider.restitution, collider.hit_threshold, collider.filter, collider.sensor,
        )
        child = self.child
        for k, i in enumerate(slots):
            child[i] = k

    def _register(self, shapes: Sequence[pymunk.Shape]) -> list[int]:
        """The slots of ``shapes``: their own, else free ones, else new ones."""
        index, free, table_shapes = self.index, self._free, self.shapes
        slots = []
        for shape in shapes:
            handle = shape_handle(shape)
            i = index.get(handle)
            if i is None:
                if free:
                    i = free.pop()
                    table_shapes[i] = shape
                else:
                    i = len(table_shapes)
                    table_shapes.append(shape)
                    self.flags.append(0)
                    self.filters.append(_DEFAULT_FILTER)
                    self.oneway.append(None)
                    for name in _COLUMNS:
                        getattr(self, name).append(0)
                index[handle] = i
            slots.append(i)
        return slots

    def _write(
        self, slots: list[int], collider: int, body: int | None, rank: int, friction: float,
        restitution: float, hit: float | None, flt: Filter, sensor: bool,
    ) -> None:
        body_col = _NO_BODY if body is None else body
        order = (rank << _RANK_SHIFT) | collider
        for i in slots:
            self.collider[i] = collider
            self.body[i] = body_col
            self.rank[i] = rank
            self.order[i] = order
            self.oneway[i] = None
            self.flags[i] = 0
        self._material(slots, friction, restitution, hit, flt, sensor)

    def set_material(self, shape: pymunk.Shape, collider: Collider) -> None:
        """The collider's friction, restitution, hit threshold, filter and sensor flag."""
        self._material(
            [self.index[shape_handle(shape)]], collider.friction, collider.restitution,
            collider.hit_threshold, collider.filter, collider.sensor,
        )

    def _material(
        self, slots: list[int], friction: float, restitution: float, hit: float | None,
        flt: Filter, sensor: bool,
    ) -> None:
        hit_col = math.nan if hit is None else hit
        for i in slots:
            self.friction[i] = friction
            self.restitution[i] = restitution
            self.hit[i] = hit_col
        flags = 0
        if sensor:
            flags |= SENSOR
        if flt.group_index > 0:
            flags |= GROUPED
        if restitution > 0.0:
            flags |= BOUNCY
        if hit is not None:
            flags |= HIT
        table_flags, filters = self.flags, self.filters
        for i in slots:
            table_flags[i] = (table_flags[i] & _KEPT) | flags
            filters[i] = flt

    def set_oneway(self, shape: pymunk.Shape, spec: OneWay | None) -> None:
        """Make the shape a one-way platform ``((up_x, up_y), min_cos)``, or not (None)."""
        i = self.index[shape_handle(shape)]
        self.oneway[i] = spec
        self.flags[i] = (self.flags[i] & ~ONE_WAY) | (0 if spec is None else ONE_WAY)

    def set_hooked(self, shape: pymunk.Shape, hooked: bool) -> None:
        """Whether the shape's contacts run the user's pre/post-solve hooks."""
        i = self.index[shape_handle(shape)]
        self.flags[i] = (self.flags[i] & ~HOOKED_FLAG) | (HOOKED_FLAG if hooked else 0)

    def drop(self, shapes: Iterable[pymunk.Shape]) -> None:
        """Give the slots of ``shapes`` back (shapes that are out of every space for good)."""
        index, free = self.index, self._free
        for s in shapes:
            i = index.pop(shape_handle(s), None)
            if i is not None:
                self.shapes[i] = None
                self.filters[i] = _DEFAULT_FILTER
                self.oneway[i] = None
                self.flags[i] = 0
                free.append(i)

    # -- reading ---------------------------------------------------------------------------
    def slot(self, shape: pymunk.Shape) -> int | None:
        """The slot of ``shape``, or None for a shape kge did not build."""
        return self.index.get(shape_handle(shape))

    def slot_of_handle(self, handle: Any) -> int:
        """The slot of the shape whose Chipmunk pointer is ``handle`` (KeyError: none)."""
        return self.index[handle]

    def collider_of(self, shape: pymunk.Shape) -> int | None:
        """The collider entity of ``shape``, or None for a shape kge did not build."""
        i = self.index.get(shape_handle(shape))
        return None if i is None else self.collider[i]

    def filter_of(self, shape: pymunk.Shape) -> Filter:
        """The kge filter of ``shape`` (the default filter for a shape kge did not build)."""
        i = self.index.get(shape_handle(shape))
        return _DEFAULT_FILTER if i is None else self.filters[i]

    def oneway_of(self, shape: pymunk.Shape) -> OneWay | None:
        """The one-way platform ``((up_x, up_y), min_cos)`` of ``shape``, or None."""
        i = self.index.get(shape_handle(shape))
        return None if i is None else self.oneway[i]

    def body_entity(self, i: int) -> int | None:
        """The body entity of slot ``i`` as events name it (None: the implicit static body)."""
        b = self.body[i]
        return None if b == _NO_BODY else b

    def __len__(self) -> int:
        return len(self.index)
