"""``RigidBody``: makes an entity's :class:`Transform` move under physics.

The fields are Box2D's ``b2BodyDef`` in snake_case. ``velocity``,
``angular_velocity`` and ``awake`` are two-way: the physics system writes them
after every step, and a write from user code is applied before the next step
(a velocity write wakes the body, as ``SetLinearVelocity`` does).

``mass=None`` means "from the colliders' densities"; a number overrides it
(Box2D's ``SetMassData``, keeping the centre and scaling the inertia) until it
is set back to None (``ResetMassData``).

>>> rb = RigidBody(type=BodyType.KINEMATIC, velocity=(1, 0))
>>> rb.velocity
(1.0, 0.0)
>>> rb.linear_damping = -1
Traceback (most recent call last):
...
kge.errors.ValidationError: RigidBody.linear_damping must be >= 0, got -1.0
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum
from typing import Any, ClassVar

from kge.components.tracked import Check, Tracked, fast_init
from kge.errors import ComponentTypeError, ValidationError
from kge.validate import FAST, Vec2, at_most, boolean, finite, non_negative, positive, vec2


class BodyType(Enum):
    """Box2D's body types."""

    STATIC = "static"  #: never moves; infinite mass
    KINEMATIC = "kinematic"  #: moves by its velocity only; pushes dynamic bodies
    DYNAMIC = "dynamic"  #: moved by gravity, forces and contacts


def _body_type(value: Any, owner: str, field: str) -> BodyType:
    if isinstance(value, BodyType):
        return value
    if isinstance(value, str):
        try:
            return BodyType(value.lower())
        except ValueError:
            pass
    raise ComponentTypeError(
        f"{owner}.{field} must be a BodyType (STATIC, KINEMATIC or DYNAMIC), got {value!r}"
    )


#: Heaviest mass override accepted, kg (about the Earth's mass): its inertia stays finite.
MAX_MASS = 1e24
#: Lightest mass override accepted, kg: lighter bodies' inverse masses overflow joint
#: solvers (see ``kge.components.collider.MIN_DENSITY``).
MIN_MASS = 1e-6


def _optional_mass(value: Any, owner: str, field: str) -> float | None:
    if value is None:
        return None
    v = at_most(positive(value, owner, field), MAX_MASS, owner, field, "kg")
    if v < MIN_MASS:
        raise ValidationError(f"{owner}.{field} must be >= {MIN_MASS:g} kg, got {v!r}")
    return v


FAST[_body_type] = lambda v: type(v) is BodyType
FAST[_optional_mass] = lambda v: v is None or (type(v) is float and MIN_MASS <= v <= MAX_MASS)


@fast_init
@dataclass(slots=True)
class RigidBody(Tracked):
    """A simulated body; its colliders are the entity's (and those naming it)."""

    _checks: ClassVar[dict[str, Check]] = {
        "type": _body_type,
        "velocity": vec2,
        "angular_velocity": finite,
        "linear_damping": non_negative,
        "angular_damping": non_negative,
        "gravity_scale": finite,
        "fixed_rotation": boolean,
        "bullet": boolean,
        "allow_sleep": boolean,
        "awake": boolean,
        "enabled": boolean,
        "mass": _optional_mass,
    }
    #: a type write runs the world's RigidBody validators (when a system bound them),
    #: so a character's body refuses to become dynamic at the line that asks
    _world_fields: ClassVar[frozenset[str]] = frozenset({"type"})

    type: BodyType = BodyType.DYNAMIC
    velocity: Vec2 = (0.0, 0.0)
    angular_velocity: float = 0.0
    linear_damping: float = 0.0
    angular_damping: float = 0.0
    gravity_scale: float = 1.0
    fixed_rotation: bool = False
    bullet: bool = False
    allow_sleep: bool = True
    awake: bool = True
    enabled: bool = True
    mass: float | None = None

    @property
    def is_dynamic(self) -> bool:
        return self.type is BodyType.DYNAMIC
