"""Where an entity is: position in metres and angle in radians, counter-clockwise.

The physics system writes it for dynamic and kinematic bodies after every step.
Assigning it from user code is a teleport: the body jumps there at the next step
(velocity kept, as Box2D's SetTransform). Rendering reads it, blended with the
previous step's pose for smooth motion.

>>> t = Transform(1.0, 2.0)
>>> t.position
(1.0, 2.0)
>>> t.x = float("nan")
Traceback (most recent call last):
...
kge.errors.ValidationError: Transform.x must be finite, got nan
>>> t.position = (1.0, 2.0, 3.0)
Traceback (most recent call last):
...
kge.errors.ValidationError: Transform.position must be an (x, y) pair, got (1.0, 2.0, 3.0)
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from kge.components.tracked import Check, Tracked, fast_init
from kge.validate import coordinate, finite, point


@fast_init
@dataclass(slots=True)
class Transform(Tracked):
    """Pose of an entity: ``x``, ``y`` (m) and ``angle`` (rad, CCW)."""

    _checks: ClassVar[dict[str, Check]] = {"x": coordinate, "y": coordinate, "angle": finite}

    x: float = 0.0
    y: float = 0.0
    angle: float = 0.0

    @property
    def position(self) -> tuple[float, float]:
        return (self.x, self.y)

    @position.setter
    def position(self, value: tuple[float, float]) -> None:
        # both checked before either is written: a bad pair leaves the pose as it was
        x, y = point(value, "Transform", "position")
        self.x, self.y = x, y
