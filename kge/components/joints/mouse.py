"""``MouseJoint``: drag a point of a body towards a moving ``target`` with a soft spring.

For mouse dragging in editors and testbeds. The grab point is ``grab_point``
(world), by default the ``target`` the component was created with (Box2D's
rule), or ``local_anchor_b`` if given; move ``target`` every step to drag.
``max_force`` caps the pull (Box2D's default is 0, which pulls with no force:
set it, typically to ``1000 * mass``). Like Box2D,
the joint damps the body's spin by x0.98 per step.

``body_a`` is Box2D's dummy ground body and may be None.

>>> MouseJoint(None, 7, target=(5.0, 0.0), max_force=1000.0).frequency_hz
5.0
"""

from __future__ import annotations

from dataclasses import KW_ONLY, dataclass
from typing import ClassVar

from kge.components.joints.base import Joint, Vec2, checks, optional
from kge.components.tracked import Check
from kge.validate import frequency, non_negative, point


@dataclass(slots=True)
class MouseJoint(Joint):
    """Pull ``body_b``'s grab point towards ``target`` (world, m)."""

    _checks: ClassVar[dict[str, Check]] = checks(
        target=point,
        grab_point=optional(point),
        local_anchor_b=optional(point),
        max_force=non_negative,
        frequency_hz=frequency,
        damping_ratio=non_negative,
    )

    body_a: int | None
    body_b: int | None
    _: KW_ONLY
    target: Vec2 = (0.0, 0.0)
    grab_point: Vec2 | None = None
    local_anchor_b: Vec2 | None = None
    max_force: float = 0.0
    frequency_hz: float = 5.0
    damping_ratio: float = 0.7

    def __post_init__(self) -> None:
        if self.grab_point is None:
            # the target at creation, not at build time: the physics system builds
            # the joint at the next step, after a drag may already have moved it
            self.grab_point = self.target
