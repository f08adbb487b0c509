"""``MotorJoint``: drive ``body_b`` to a pose relative to ``body_a`` with bounded force.

``linear_offset`` is where ``body_b``'s origin should be, in ``body_a``'s frame,
and ``angular_offset`` the wanted relative angle. ``correction_factor`` (0..1) is
the fraction of the error removed per step. Animate the offsets for moving
platforms or characters that follow a path but still get pushed around.

>>> MotorJoint(None, 2, correction_factor=1.5)
Traceback (most recent call last):
...
kge.errors.ValidationError: MotorJoint.correction_factor must be in [0.0, 1.0], got 1.5
"""

from __future__ import annotations

from dataclasses import KW_ONLY, dataclass
from typing import Any, ClassVar

from kge.components.joints.base import Joint, Vec2, checks
from kge.components.tracked import Check
from kge.validate import finite, in_range, non_negative, point


def fraction(value: Any, owner: str, name: str) -> float:
    return in_range(value, 0.0, 1.0, owner, name)


@dataclass(slots=True)
class MotorJoint(Joint):
    """Box2D's defaults: max_force 1, max_torque 1, correction_factor 0.3."""

    _checks: ClassVar[dict[str, Check]] = checks(
        linear_offset=point,
        angular_offset=finite,
        max_force=non_negative,
        max_torque=non_negative,
        correction_factor=fraction,
    )

    body_a: int | None
    body_b: int | None
    _: KW_ONLY
    linear_offset: Vec2 = (0.0, 0.0)
    angular_offset: float = 0.0
    max_force: float = 1.0
    max_torque: float = 1.0
    correction_factor: float = 0.3
