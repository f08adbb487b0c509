"""``OneWayPlatform``: a collider that only blocks bodies arriving from one side.

Put it on an entity with a Collider. A body whose first contact with the
platform has its normal pointing along ``up`` (it came from above) lands on it;
one arriving from any other side passes through until the two separate, like
the pybox2d "one-sided platform" sample. The decision is made once per contact
when it begins, so a platform costs nothing per step.

>>> OneWayPlatform().up
(0.0, 1.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

from kge.components.tracked import Check, Tracked
from kge.errors import ValidationError
from kge.validate import Vec2, in_range, vec2


def _direction(value: object, owner: str, field: str) -> Vec2:
    x, y = vec2(value, owner, field)
    n = math.hypot(x, y)
    if n < 1e-9:
        raise ValidationError(f"{owner}.{field} must be a non-zero direction, got {value!r}")
    return (x / n, y / n)


def _cos(value: object, owner: str, field: str) -> float:
    return in_range(value, -1.0, 1.0, owner, field)


@dataclass(slots=True)
class OneWayPlatform(Tracked):
    """``up`` is the solid side's outward direction (world frame, normalised).

    ``min_cos``: a contact is accepted when the normal from the platform to
    the other body has at least this cosine with ``up`` (0.5 = within 60°).
    """

    _checks: ClassVar[dict[str, Check]] = {"up": _direction, "min_cos": _cos}

    up: Vec2 = (0.0, 1.0)
    min_cos: float = 0.5
