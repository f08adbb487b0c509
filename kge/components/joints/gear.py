"""``GearJoint``: couple two revolute/prismatic joints by their joint coordinates.

``coordinate_a + ratio * coordinate_b`` stays constant, where a revolute joint's
coordinate is its angle and a prismatic joint's its translation (Box2D's sign:
with ``ratio`` 2, joint B turns at -1/2 of joint A's speed). All four pairings
work, also when the joints' base bodies move (gears on a car's chassis).

Unlike the other joints, a gear names two *joint* entities, ``joint_a`` and
``joint_b``. Its bodies are those joints' ``body_b`` (Box2D requires bodyA =
joint1.bodyB and bodyB = joint2.bodyB); ``body_a`` / ``body_b`` are filled in
by physics when the gear is built and need not be given. Destroying one of the
two joints destroys the gear first, so it never points at a missing joint.

>>> GearJoint(3, 4, ratio=2.0).body_a is None
True
>>> GearJoint(3, 3)
Traceback (most recent call last):
...
kge.errors.ValidationError: GearJoint.joint_b must differ from joint_a (3)
"""

from __future__ import annotations

from dataclasses import KW_ONLY, dataclass
from typing import Any, ClassVar

from kge.components.joints.base import Joint, checks, entity_ref, nonzero
from kge.components.tracked import Check
from kge.errors import ValidationError


def joint_ref(value: Any, owner: str, name: str) -> int:
    ref = entity_ref(value, owner, name)
    if ref is None:
        raise ValidationError(f"{owner}.{name} must name a RevoluteJoint or PrismaticJoint entity")
    return ref


@dataclass(slots=True)
class GearJoint(Joint):
    """Gear ``joint_a`` to ``joint_b`` with ``ratio`` (non-zero, Box2D's sign)."""

    _checks: ClassVar[dict[str, Check]] = checks(
        joint_a=joint_ref, joint_b=joint_ref, ratio=nonzero
    )
    _world_fields: ClassVar[frozenset[str]] = frozenset({"joint_a", "joint_b"})

    joint_a: int
    joint_b: int
    _: KW_ONLY
    ratio: float = 1.0
    body_a: int | None = None
    body_b: int | None = None

    def __post_init__(self) -> None:
        if self.joint_a == self.joint_b:
            raise ValidationError(
                f"{self._owner()}.joint_b must differ from joint_a ({self.joint_a})"
            )
