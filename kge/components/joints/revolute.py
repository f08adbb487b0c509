"""``RevoluteJoint``: a shared pivot point (hinges, wheels, pendulums, ragdoll joints).

The joint angle is ``body_b``'s angle minus ``body_a``'s minus ``reference_angle``
(radians, CCW). An optional limit keeps it in ``[lower_angle, upper_angle]`` and an
optional motor drives ``speed`` towards ``motor_speed`` with at most
``max_motor_torque``; every field may be changed every step (a servo is a motor
whose speed is a gain times the angle error).

>>> j = RevoluteJoint(None, 5, anchor=(0.0, 10.0), enable_motor=True,
...                   motor_speed=2.0, max_motor_torque=50.0)
>>> j.max_motor_torque = -1
Traceback (most recent call last):
...
kge.errors.ValidationError: RevoluteJoint.max_motor_torque must be >= 0, got -1.0
"""

from __future__ import annotations

from dataclasses import KW_ONLY, dataclass, field
from typing import ClassVar

from kge.components.joints.base import ANCHOR_CHECKS, AnchoredJoint, checks, optional
from kge.components.tracked import Check
from kge.validate import boolean, finite, non_negative


@dataclass(slots=True)
class RevoluteJoint(AnchoredJoint):
    """Pin ``body_a`` and ``body_b`` together at one point.

    Give the pivot either as ``anchor`` (world point, resolved against the bodies'
    poses when the joint is built) or as ``local_anchor_a`` / ``local_anchor_b``
    (relative to each body's origin). ``reference_angle`` None means "the angle
    between the bodies when the joint is built" (Box2D's ``Initialize``).
    Read back each step: ``angle``, ``speed`` (rad/s), ``motor_torque`` (N·m on
    ``body_b``, CCW positive), ``reaction_force``, ``reaction_torque`` (the
    limit's torque on ``body_b``).
    """

    _checks: ClassVar[dict[str, Check]] = checks(
        **ANCHOR_CHECKS,
        reference_angle=optional(finite),
        enable_limit=boolean,
        lower_angle=finite,
        upper_angle=finite,
        enable_motor=boolean,
        motor_speed=finite,
        max_motor_torque=non_negative,
    )
    _ordered: ClassVar[tuple[tuple[str, str], ...]] = (("lower_angle", "upper_angle"),)

    _: KW_ONLY
    reference_angle: float | None = None
    enable_limit: bool = False
    lower_angle: float = 0.0
    upper_angle: float = 0.0
    enable_motor: bool = False
    motor_speed: float = 0.0
    max_motor_torque: float = 0.0
    angle: float = field(default=0.0, init=False)
    speed: float = field(default=0.0, init=False)
    motor_torque: float = field(default=0.0, init=False)
