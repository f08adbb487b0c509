"""``PulleyJoint``: two bodies hung from two fixed ground points by one rope.

The rope keeps ``length_a + ratio * length_b`` constant, so with ``ratio`` 2 side
A moves twice as far as side B (block and tackle). ``max_length_a`` /
``max_length_b`` optionally stop either side (Box2D 2.1's maxLengthA/B).
Box2D's pulley lets the two bodies collide by default, so ``collide_connected``
defaults to True here.

>>> PulleyJoint(1, 2, ground_anchor_a=(-2, 10), ground_anchor_b=(2, 10), ratio=0)
Traceback (most recent call last):
...
kge.errors.ValidationError: PulleyJoint.ratio must be > 0, got 0.0
"""

from __future__ import annotations

from dataclasses import KW_ONLY, dataclass, field
from typing import ClassVar

from kge.components.joints.base import Joint, Vec2, checks, greater_than_zero, optional
from kge.components.tracked import Check
from kge.validate import non_negative, point


@dataclass(slots=True)
class PulleyJoint(Joint):
    """Rope from ``ground_anchor_a`` to ``body_a`` and from ``ground_anchor_b`` to ``body_b``.

    Anchors on the bodies: world ``anchor_a`` / ``anchor_b`` or local ones.
    Read back: ``length_a``, ``length_b`` (m).
    """

    _checks: ClassVar[dict[str, Check]] = checks(
        ground_anchor_a=point,
        ground_anchor_b=point,
        anchor_a=optional(point),
        anchor_b=optional(point),
        local_anchor_a=point,
        local_anchor_b=point,
        ratio=greater_than_zero,
        max_length_a=optional(non_negative),
        max_length_b=optional(non_negative),
    )

    body_a: int | None
    body_b: int | None
    _: KW_ONLY
    ground_anchor_a: Vec2 = (-1.0, 1.0)
    ground_anchor_b: Vec2 = (1.0, 1.0)
    anchor_a: Vec2 | None = None
    anchor_b: Vec2 | None = None
    local_anchor_a: Vec2 = (0.0, 0.0)
    local_anchor_b: Vec2 = (0.0, 0.0)
    ratio: float = 1.0
    max_length_a: float | None = None
    max_length_b: float | None = None
    collide_connected: bool = True
    length_a: float = field(default=0.0, init=False)
    length_b: float = field(default=0.0, init=False)
