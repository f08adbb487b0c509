"""pymunk objects' private fields, read through named functions.

Every pymunk object owns its Chipmunk struct as a cffi pointer in a private field
(``Body._body``, ``Shape._shape``, ``Space._space``, ``Constraint._constraint``,
``Arbiter._arbiter``); the C functions of :data:`kge.physics.cp.lib` take those
pointers. A shape holds its body and space as weak references (``_body``,
``_space``), a body its shapes in an insertion-ordered dict (``_shapes``; the public
``Body.shapes`` is an unordered set copy) and its constraints in a weak dict
(``_constraints``). This module is the only place kge names those fields.

The ``*_handle`` readers are :func:`operator.attrgetter` objects: C-level callables,
so the per-step loops pay one call and no Python frame.

>>> import pymunk
>>> space = pymunk.Space()
>>> body = pymunk.Body(1.0, 1.0)
>>> box = pymunk.Poly.create_box(body, (1.0, 1.0))
>>> space.add(body, box)
>>> shape_body(box) is body, shape_space(box) is space, list(body_shapes(body)) == [box]
(True, True, True)
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Iterable
from operator import attrgetter
from typing import Any

import pymunk

#: the Chipmunk ``cpBody *`` of a :class:`pymunk.Body`
body_handle: Callable[[pymunk.Body], Any] = attrgetter("_body")
#: the Chipmunk ``cpShape *`` of a :class:`pymunk.Shape`
shape_handle: Callable[[pymunk.Shape], Any] = attrgetter("_shape")
#: the Chipmunk ``cpSpace *`` of a :class:`pymunk.Space`
space_handle: Callable[[pymunk.Space], Any] = attrgetter("_space")
#: the Chipmunk ``cpConstraint *`` of a :class:`pymunk.Constraint`
constraint_handle: Callable[[pymunk.Constraint], Any] = attrgetter("_constraint")
#: the Chipmunk ``cpArbiter *`` of a :class:`pymunk.Arbiter` (valid inside its callback)
arbiter_handle: Callable[[pymunk.Arbiter], Any] = attrgetter("_arbiter")


def shape_body(shape: pymunk.Shape) -> pymunk.Body | None:
    """``shape.body`` without the property: the body, or None once it is gone."""
    body: pymunk.Body | None = shape._body()
    return body


def shape_space(shape: pymunk.Shape) -> pymunk.Space | None:
    """``shape.space`` without the property: the space the shape is in, or None."""
    space: pymunk.Space | None = shape._space()
    return space


def body_shapes(body: pymunk.Body) -> Iterable[pymunk.Shape]:
    """The shapes on ``body`` in the order they were attached (``body.shapes`` is a set).

    A live view: attaching or removing shapes while iterating it is an error.
    """
    shapes: dict[pymunk.Shape, None] = body._shapes
    return shapes.keys()


def body_constraints(body: pymunk.Body) -> Collection[pymunk.Constraint]:
    """The constraints on ``body``, without the set copy ``body.constraints`` makes."""
    constraints: Collection[pymunk.Constraint] = body._constraints
    return constraints


def shape_hashid(shape: pymunk.Shape) -> int:
    """The id the space gave ``shape`` when it was added (Chipmunk's hash id).

    Ids only grow, so "every shape's id is below N" means "none was added since".
    """
    return int(shape._hashid)
