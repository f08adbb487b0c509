"""``PrismaticJoint``: a slider along one axis, with no relative rotation.

``translation`` is the distance of ``body_b``'s anchor from ``body_a``'s along
``local_axis_a`` (normalised on assignment, as Box2D does), which turns with
``body_a``. Limit ``[lower_translation, upper_translation]`` and a linear motor
(``motor_speed`` m/s, ``max_motor_force`` N; ``motor_force`` is read back).

>>> PrismaticJoint(None, 4, local_axis_a=(2.0, 0.0)).local_axis_a
(1.0, 0.0)
>>> PrismaticJoint(None, 4, local_axis_a=(0.0, 0.0))
Traceback (most recent call last):
...
kge.errors.ValidationError: PrismaticJoint.local_axis_a must be a non-zero direction, got (0.0, 0.0)
"""

from __future__ import annotations

from dataclasses import KW_ONLY, dataclass, field
from typing import ClassVar

from kge.components.joints.base import (
    ANCHOR_CHECKS,
    AnchoredJoint,
    Vec2,
    checks,
    optional,
    unit_vector,
)
from kge.components.tracked import Check
from kge.validate import boolean, finite, non_negative


@dataclass(slots=True)
class PrismaticJoint(AnchoredJoint):
    """Let ``body_b`` slide along an axis fixed in ``body_a``.

    ``anchor`` (world) or ``local_anchor_a`` / ``local_anchor_b``; ``local_axis_a``
    is in ``body_a``'s frame (for a world axis on a body built unrotated, the same
    vector). Read back: ``translation`` (m), ``speed`` (m/s), ``motor_force`` (N,
    signed along the axis), ``reaction_force``, ``reaction_torque``.
    """

    _checks: ClassVar[dict[str, Check]] = checks(
        **ANCHOR_CHECKS,
        local_axis_a=unit_vector,
        reference_angle=optional(finite),
        enable_limit=boolean,
        lower_translation=finite,
        upper_translation=finite,
        enable_motor=boolean,
        motor_speed=finite,
        max_motor_force=non_negative,
    )
    _ordered: ClassVar[tuple[tuple[str, str], ...]] = (("lower_translation", "upper_translation"),)

    _: KW_ONLY
    local_axis_a: Vec2 = (1.0, 0.0)
    reference_angle: float | None = None
    enable_limit: bool = False
    lower_translation: float = 0.0
    upper_translation: float = 0.0
    enable_motor: bool = False
    motor_speed: float = 0.0
    max_motor_force: float = 0.0
    translation: float = field(default=0.0, init=False)
    speed: float = field(default=0.0, init=False)
    motor_force: float = field(default=0.0, init=False)
