"""``WheelJoint`` (the manual's line joint): a wheel on a sprung axle.

``body_b`` (the wheel) slides along ``local_axis_a`` of ``body_a`` (the chassis)
on a spring of ``frequency_hz`` / ``damping_ratio`` (suspension) and turns
freely; an optional motor drives the wheel's spin. Box2D's defaults: 2 Hz, 0.7.

>>> WheelJoint(1, 2, anchor=(0.0, 0.5), local_axis_a=(0.0, 1.0)).frequency_hz
2.0
"""

from __future__ import annotations

from dataclasses import KW_ONLY, dataclass, field
from typing import ClassVar

from kge.components.joints.base import (
    ANCHOR_CHECKS,
    AnchoredJoint,
    Vec2,
    checks,
    unit_vector,
)
from kge.components.tracked import Check
from kge.validate import boolean, finite, frequency, non_negative


@dataclass(slots=True)
class WheelJoint(AnchoredJoint):
    """Axle of ``body_b`` on ``body_a``. Read back: ``translation`` (along the
    axis, m), ``speed`` (wheel spin relative to the chassis, rad/s),
    ``motor_torque`` (N·m, magnitude)."""

    _checks: ClassVar[dict[str, Check]] = checks(
        **ANCHOR_CHECKS,
        local_axis_a=unit_vector,
        enable_motor=boolean,
        motor_speed=finite,
        max_motor_torque=non_negative,
        frequency_hz=frequency,
        damping_ratio=non_negative,
    )

    _: KW_ONLY
    local_axis_a: Vec2 = (1.0, 0.0)
    enable_motor: bool = False
    motor_speed: float = 0.0
    max_motor_torque: float = 0.0
    frequency_hz: float = 2.0
    damping_ratio: float = 0.7
    translation: float = field(default=0.0, init=False)
    speed: float = field(default=0.0, init=False)
    motor_torque: float = field(default=0.0, init=False)
