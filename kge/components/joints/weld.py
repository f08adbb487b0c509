"""``WeldJoint``: glue two bodies together, rigidly or with a soft angular spring.

``frequency_hz`` 0 is rigid; above 0 the relative angle springs around
``reference_angle`` (a flexible beam, a wobbly sign).

>>> WeldJoint(1, 2, anchor=(1.0, 0.0), frequency_hz=5.0, damping_ratio=0.7).frequency_hz
5.0
"""

from __future__ import annotations

from dataclasses import KW_ONLY, dataclass
from typing import ClassVar

from kge.components.joints.base import ANCHOR_CHECKS, AnchoredJoint, checks, optional
from kge.components.tracked import Check
from kge.validate import finite, frequency, non_negative


@dataclass(slots=True)
class WeldJoint(AnchoredJoint):
    """Weld ``body_b`` to ``body_a`` at ``anchor`` (or the local anchors)."""

    _checks: ClassVar[dict[str, Check]] = checks(
        **ANCHOR_CHECKS,
        reference_angle=optional(finite),
        frequency_hz=frequency,
        damping_ratio=non_negative,
    )

    _: KW_ONLY
    reference_angle: float | None = None
    frequency_hz: float = 0.0
    damping_ratio: float = 0.0
