"""``RopeJoint``: a maximum distance between two anchors; slack is free.

>>> RopeJoint(None, 2, max_length=3.0).max_length
3.0
"""

from __future__ import annotations

from dataclasses import KW_ONLY, dataclass
from typing import ClassVar

from kge.components.joints.base import TWO_POINT_CHECKS, TwoPointJoint, checks, optional
from kge.components.tracked import Check
from kge.validate import non_negative


@dataclass(slots=True)
class RopeJoint(TwoPointJoint):
    """The anchors of ``body_a`` and ``body_b`` stay within ``max_length``.

    ``max_length`` None = the anchors' distance when built.
    """

    _checks: ClassVar[dict[str, Check]] = checks(
        **TWO_POINT_CHECKS,
        max_length=optional(non_negative),
    )

    _: KW_ONLY
    max_length: float | None = None
