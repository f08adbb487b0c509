"""``Collider``: one shape with its material and filter (Box2D's fixture).

One collider per entity. ``body=None`` attaches it to the RigidBody of the same
entity, or, when the entity has none, to an implicit static body placed by the
entity's Transform (ground, walls). ``body=e`` attaches it to entity ``e``'s
body in that body's local frame (compound bodies: several collider entities
on one body).

Material rules are Box2D's: friction mixes as sqrt(a*b), restitution as
max(a, b) with no bounce at approach speeds of 1 m/s or less; density gives the
body its mass (sensors count, edges and chains are massless).

``hit_threshold`` (m/s) turns on :class:`~kge.physics.events.Hit` events for
impacts faster than it. ``contact_hooks=True`` lets the ``Physics`` resource's
``on_pre_solve`` / ``on_post_solve`` callbacks see this collider's contacts;
it is opt-in because a Python call per contact per step is the most expensive
thing a physics scene can do.

>>> from kge.components.shapes import Circle
>>> c = Collider(Circle(0.5), density=2.0)
>>> c.friction
0.2
>>> c.density = -1
Traceback (most recent call last):
...
kge.errors.ValidationError: Collider.density must be >= 0, got -1.0
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, ClassVar, cast

from kge.components.filter import Filter
from kge.components.shapes import SHAPE_TYPES, Shape
from kge.components.tracked import Check, Tracked, fast_init
from kge.errors import ComponentTypeError, ValidationError
from kge.validate import FAST, at_most, boolean, non_negative

#: Densest material accepted, kg/m^2 (osmium sheet 1 m thick is about 2e4): with
#: shapes up to 1e6 m, mass and inertia stay finite.
MAX_DENSITY = 1e12
#: Lightest non-zero density accepted, kg/m^2. Below it a body's inverse mass and
#: inertia reach 1e300 and joint solvers overflow to NaN (Box2D's float32 flushes such
#: densities to 0, i.e. a massless body, which gets 1 kg); 0 stays allowed (massless).
MIN_DENSITY = 1e-6


def _shape(value: Any, owner: str, field: str) -> Shape:
    if not isinstance(value, SHAPE_TYPES):
        names = ", ".join(t.__name__ for t in SHAPE_TYPES)
        hint = ""
        if type(value).__module__ == "kge.components.drawables":
            kind = type(value).__name__
            physics = {"Rect": "Box", "Triangle": "Polygon", "Line": "Edge"}.get(kind, kind)
            hint = (
                f" (that is kge.draw.{kind}, a drawable; a collider takes the physics shape "
                f"kge.{physics}: from kge import {physics})"
            )
        raise ComponentTypeError(f"{owner}.{field} must be one of {names}, got {value!r}{hint}")
    return cast(Shape, value)


def _filter(value: Any, owner: str, field: str) -> Filter:
    if not isinstance(value, Filter):
        raise ComponentTypeError(f"{owner}.{field} must be a Filter, got {value!r}")
    return value


def _entity_ref(value: Any, owner: str, field: str) -> int | None:
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int) or value < 0:
        raise ComponentTypeError(f"{owner}.{field} must be an entity id or None, got {value!r}")
    return value


def _density(value: Any, owner: str, field: str) -> float:
    v = at_most(non_negative(value, owner, field), MAX_DENSITY, owner, field, "kg/m^2")
    if 0.0 < v < MIN_DENSITY:
        raise ValidationError(
            f"{owner}.{field} must be 0 (massless) or >= {MIN_DENSITY:g} kg/m^2, got {v!r}"
        )
    return v


def _optional_speed(value: Any, owner: str, field: str) -> float | None:
    return None if value is None else non_negative(value, owner, field)


_EXACT_SHAPES = frozenset(SHAPE_TYPES)
FAST[_shape] = lambda v: type(v) in _EXACT_SHAPES
FAST[_density] = lambda v: type(v) is float and (v == 0.0 or MIN_DENSITY <= v <= MAX_DENSITY)
FAST[_filter] = lambda v: type(v) is Filter
FAST[_entity_ref] = lambda v: v is None or (type(v) is int and v >= 0)
FAST[_optional_speed] = lambda v: v is None or (type(v) is float and v - v == 0.0 and v >= 0.0)


@fast_init
@dataclass(slots=True)
class Collider(Tracked):
    """A shape plus density, friction, restitution, filter and sensor flag."""

    _world_fields: ClassVar[frozenset[str]] = frozenset({"body"})
    _checks: ClassVar[dict[str, Check]] = {
        "shape": _shape,
        "density": _density,
        "friction": non_negative,
        "restitution": non_negative,
        "filter": _filter,
        "sensor": boolean,
        "body": _entity_ref,
        "hit_threshold": _optional_speed,
        "contact_hooks": boolean,
    }

    shape: Shape
    density: float = 1.0
    friction: float = 0.2
    restitution: float = 0.0
    filter: Filter = field(default_factory=Filter)
    sensor: bool = False
    body: int | None = None
    user_data: Any = None
    hit_threshold: float | None = None
    contact_hooks: bool = False
