"""``FrictionJoint``: top-down friction that slows relative motion with bounded force.

Use it between a body and the ground in a top-down game (gravity 0): the body
slows down and stops as if sliding on a floor, with at most ``max_force`` (N) and
``max_torque`` (N·m).

>>> FrictionJoint(None, 3, max_force=10.0, max_torque=0.5).max_torque
0.5
"""

from __future__ import annotations

from dataclasses import KW_ONLY, dataclass
from typing import ClassVar

from kge.components.joints.base import ANCHOR_CHECKS, AnchoredJoint, checks
from kge.components.tracked import Check
from kge.validate import non_negative


@dataclass(slots=True)
class FrictionJoint(AnchoredJoint):
    """Friction of ``body_b`` against ``body_a`` at ``anchor`` (or the local anchors)."""

    _checks: ClassVar[dict[str, Check]] = checks(
        **ANCHOR_CHECKS,
        max_force=non_negative,
        max_torque=non_negative,
    )

    _: KW_ONLY
    max_force: float = 0.0
    max_torque: float = 0.0
