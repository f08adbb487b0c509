"""``DistanceJoint``: keep two anchor points at a fixed distance (a massless rod).

With ``frequency_hz`` > 0 the rod becomes a spring whose natural frequency and
damping ratio do not depend on the masses (Box2D's soft distance joint): a 1 kg
and a 100 kg bob on a 2 Hz joint both bounce twice a second. ``min_length`` /
``max_length`` (Box2D 2.4) add a range the spring cannot leave.

>>> DistanceJoint(None, 2, anchor_a=(0.0, 10.0), anchor_b=(3.0, 10.0)).length is None
True
>>> DistanceJoint(None, 2, frequency_hz=-1.0)
Traceback (most recent call last):
...
kge.errors.ValidationError: DistanceJoint.frequency_hz must be >= 0, got -1.0
"""

from __future__ import annotations

from dataclasses import KW_ONLY, dataclass
from typing import ClassVar

from kge.components.joints.base import TWO_POINT_CHECKS, TwoPointJoint, checks, optional
from kge.components.tracked import Check
from kge.validate import frequency, non_negative


@dataclass(slots=True)
class DistanceJoint(TwoPointJoint):
    """A rod (or spring) between ``body_a`` and ``body_b``.

    Anchors: world points ``anchor_a`` / ``anchor_b`` (resolved when built), or
    ``local_anchor_a`` / ``local_anchor_b``. ``length`` None = the anchors'
    distance when built (Box2D's ``Initialize``).
    """

    _checks: ClassVar[dict[str, Check]] = checks(
        **TWO_POINT_CHECKS,
        length=optional(non_negative),
        min_length=optional(non_negative),
        max_length=optional(non_negative),
        frequency_hz=frequency,
        damping_ratio=non_negative,
    )
    _ordered: ClassVar[tuple[tuple[str, str], ...]] = (("min_length", "max_length"),)

    _: KW_ONLY
    length: float | None = None
    min_length: float | None = None
    max_length: float | None = None
    frequency_hz: float = 0.0
    damping_ratio: float = 0.0
