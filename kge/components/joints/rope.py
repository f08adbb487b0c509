"""``RopeJoint``: a maximum distance between two anchors; slack is free.

>>> RopeJoint(None, 2, max_length=3.0).max_length
3.0
"""

from __future__ import annotations

from dataclasses import KW_ONLY, dataclass
from typing import ClassVar

from kge.components.joints.base import Joint, Vec2, checks, optional
from kge.components.tracked import Check
from kge.validate import non_negative, vec2


@dataclass(slots=True)
class RopeJoint(Joint):
    """The anchors of ``body_a`` and ``body_b`` stay within ``max_length``.

    ``max_length`` None = the anchors' distance when built.
    """

    _checks: ClassVar[dict[str, Check]] = checks(
        anchor_a=optional(vec2),
        anchor_b=optional(vec2),
        local_anchor_a=vec2,
        local_anchor_b=vec2,
        max_length=optional(non_negative),
    )

    body_a: int | None
    body_b: int | None
    _: KW_ONLY
    anchor_a: Vec2 | None = None
    anchor_b: Vec2 | None = None
    local_anchor_a: Vec2 = (0.0, 0.0)
    local_anchor_b: Vec2 = (0.0, 0.0)
    max_length: float | None = None
