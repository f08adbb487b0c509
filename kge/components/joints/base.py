"""What every joint component shares: body references, collision, breaking, reactions.

A joint is an entity of its own holding one joint component that names two body
entities, ``body_a`` and ``body_b`` (Box2D's bodyA / bodyB). ``None`` stands for
the world's static ground, so a pendulum needs no ground body. The physics system
turns the component into pymunk constraints (see :mod:`kge.physics.joints`) once
both bodies exist, re-applies it whenever a field is written, and writes the live
state back after every step.

Why fields are checked on assignment: a motor speed of NaN or a limit whose lower
bound passes its upper bound would otherwise surface as a NaN pose many steps
later. Paired bounds (``lower_angle``/``upper_angle``, ...) are checked against
each other; to move both past each other at once use :meth:`Joint.set_limits`.

Read-back fields (``reaction_force``, ``angle``, ``motor_torque``, ...) are
written by physics each step and are not constructor arguments.

>>> from kge.components.joints import RevoluteJoint
>>> j = RevoluteJoint(None, 3, anchor=(0.0, 10.0), lower_angle=-0.5, upper_angle=0.5)
>>> j.upper_angle = -1.0
Traceback (most recent call last):
...
kge.errors.ValidationError: RevoluteJoint.upper_angle must be >= lower_angle (-0.5), got -1.0
>>> j.set_limits(-2.0, -1.0)
>>> (j.lower_angle, j.upper_angle)
(-2.0, -1.0)
"""

from __future__ import annotations

import math
from dataclasses import KW_ONLY, dataclass, field
from typing import Any, ClassVar

from kge.components.tracked import Check, Tracked
from kge.errors import ComponentTypeError, ValidationError, where
from kge.validate import boolean, finite, non_negative, point, vec2

Vec2 = tuple[float, float]


def entity_ref(value: Any, owner: str, name: str) -> int | None:
    """An entity id, or None for the world's static ground."""
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int):
        raise ComponentTypeError(
            f"{owner}.{name} must be an entity id (int) or None, "
            f"got {type(value).__name__} {value!r}"
        )
    if value < 0:
        raise ValidationError(f"{owner}.{name} must be an entity id >= 0, got {value!r}")
    return value


def optional(check: Check) -> Check:
    """Allow None in addition to what ``check`` accepts."""

    def checked(value: Any, owner: str, name: str) -> Any:
        return None if value is None else check(value, owner, name)

    return checked


def unit_vector(value: Any, owner: str, name: str) -> Vec2:
    """A non-zero direction, normalised (Box2D normalises ``localAxisA`` the same way)."""
    x, y = vec2(value, owner, name)
    n = math.hypot(x, y)
    if n < 1e-9:
        raise ValidationError(f"{owner}.{name} must be a non-zero direction, got {value!r}")
    return (x / n, y / n)


def nonzero(value: Any, owner: str, name: str) -> float:
    v = finite(value, owner, name)
    if abs(v) < 1e-9:
        raise ValidationError(f"{owner}.{name} must not be 0, got {v!r}")
    return v


def greater_than_zero(value: Any, owner: str, name: str) -> float:
    v = finite(value, owner, name)
    if v <= 0:
        raise ValidationError(f"{owner}.{name} must be > 0, got {v!r}")
    return v


def any_value(value: Any, owner: str, name: str) -> Any:
    return value


#: checks every joint shares
BASE_CHECKS: dict[str, Check] = {
    "collide_connected": boolean,
    "user_data": any_value,
    "break_force": optional(non_negative),
    "break_torque": optional(non_negative),
}


@dataclass(slots=True, kw_only=True)
class Joint(Tracked):
    """Base of the eleven joint components (not spawned on its own).

    ``collide_connected`` lets the two bodies collide with each other (Box2D's
    collideConnected, False by default). ``break_force`` (N) and ``break_torque``
    (N·m) remove the joint, with a ``JointBroken`` event, after a step whose
    reaction exceeded them. ``reaction_force`` is the force on ``body_b`` at the
    anchor and ``reaction_torque`` the torque on ``body_b``, as Box2D's
    ``GetReactionForce(inv_dt)`` / ``GetReactionTorque(inv_dt)``.
    """

    _checks: ClassVar[dict[str, Check]] = BASE_CHECKS
    _world_fields: ClassVar[frozenset[str]] = frozenset({"body_a", "body_b"})
    #: a joint is an entity: the world refuses a second joint component on one entity
    _one_per_entity: ClassVar[str] = "joint"
    #: (lower field, upper field) pairs that must stay ordered
    _ordered: ClassVar[tuple[tuple[str, str], ...]] = ()

    collide_connected: bool = False
    user_data: Any = None
    break_force: float | None = None
    break_torque: float | None = None
    # live state, written by physics
    reaction_force: Vec2 = field(default=(0.0, 0.0), init=False)
    reaction_torque: float = field(default=0.0, init=False)

    def __setattr__(self, name: str, value: Any) -> None:
        for lo, hi in self._ordered:
            if name in (lo, hi):
                self._check_order(name, value, lo, hi)
                break
        Tracked.__setattr__(self, name, value)

    def _owner(self) -> str:
        binding = object.__getattribute__(self, "_binding") if _has(self, "_binding") else None
        return where(None if binding is None else binding.entity, type(self).__name__)

    def _check_order(self, name: str, value: Any, lo: str, hi: str) -> None:
        other_name = hi if name == lo else lo
        if not _has(self, other_name):
            return  # still inside __init__: the other bound is not set yet
        owner = self._owner()
        v = self._checks[name](value, owner, name)
        other = getattr(self, other_name)
        if v is None or other is None:
            return
        if name == lo and v > other:
            raise ValidationError(f"{owner}.{lo} must be <= {hi} ({other!r}), got {v!r}")
        if name == hi and v < other:
            raise ValidationError(f"{owner}.{hi} must be >= {lo} ({other!r}), got {v!r}")

    def set_limits(self, lower: float, upper: float) -> None:
        """Set both bounds of the first ordered pair at once (Box2D's ``SetLimits``)."""
        if not self._ordered:
            raise ComponentTypeError(f"{type(self).__name__} has no limits")
        lo, hi = self._ordered[0]
        owner = self._owner()
        vlo = self._checks[lo](lower, owner, lo)
        vhi = self._checks[hi](upper, owner, hi)
        if vlo > vhi:
            raise ValidationError(f"{owner}: lower limit {vlo!r} must be <= upper limit {vhi!r}")
        Tracked.__setattr__(self, lo, vlo)
        Tracked.__setattr__(self, hi, vhi)


def _has(obj: object, name: str) -> bool:
    try:
        object.__getattribute__(obj, name)
    except AttributeError:
        return False
    return True


#: the checks of the anchor fields every one-point joint has (see AnchoredJoint)
ANCHOR_CHECKS: dict[str, Check] = {
    "anchor": optional(point),
    "local_anchor_a": point,
    "local_anchor_b": point,
}


#: the checks of the two anchor points of rods and ropes (see TwoPointJoint)
TWO_POINT_CHECKS: dict[str, Check] = {
    "anchor_a": optional(point),
    "anchor_b": optional(point),
    "local_anchor_a": point,
    "local_anchor_b": point,
}


def checks(**extra: Check) -> dict[str, Check]:
    """The base checks plus a joint's own (bodies are checked for every two-body joint)."""
    return {**BASE_CHECKS, "body_a": entity_ref, "body_b": entity_ref, **extra}


@dataclass(slots=True)
class AnchoredJoint(Joint):
    """Base of the joints placed at one point (revolute, prismatic, weld, wheel, friction).

    Give either ``anchor``, a world point resolved from the bodies' poses when the
    joint is built (the manual's ``Initialize(bodyA, bodyB, anchor)``), or the two
    ``local_anchor_a`` / ``local_anchor_b`` in each body's frame.
    """

    body_a: int | None
    body_b: int | None
    _: KW_ONLY
    anchor: Vec2 | None = None
    local_anchor_a: Vec2 = (0.0, 0.0)
    local_anchor_b: Vec2 = (0.0, 0.0)


@dataclass(slots=True)
class TwoPointJoint(Joint):
    """Base of the joints between two points (distance, rope).

    Give ``anchor_a`` / ``anchor_b`` as world points, resolved from the bodies' poses
    when the joint is built, or ``local_anchor_a`` / ``local_anchor_b`` in each
    body's frame.
    """

    body_a: int | None
    body_b: int | None
    _: KW_ONLY
    anchor_a: Vec2 | None = None
    anchor_b: Vec2 | None = None
    local_anchor_a: Vec2 = (0.0, 0.0)
    local_anchor_b: Vec2 = (0.0, 0.0)
