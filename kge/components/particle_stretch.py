"""``ParticleStretch``: particles drawn stretched along their velocity (pure data).

On an entity with a :class:`~kge.components.particles.ParticleEmitter`, each particle's
quad turns to face its direction of travel and grows along it: rain streaks, sparks,
speed lines, tracer fire. Its length is ``size x length_scale + speed x speed_scale``
metres (at most ``max_length`` when given); its width stays ``size``. The emitter's
``spin`` no longer turns such particles (their velocity does).

>>> ParticleStretch(speed_scale=0.05).length_scale
1.0
>>> ParticleStretch(max_length=0.0)
Traceback (most recent call last):
...
kge.errors.ValidationError: ParticleStretch.max_length must be > 0, got 0.0
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from kge.components.particles import LIMIT
from kge.components.tracked import Check, Tracked
from kge.validate import at_most, non_negative, positive


def _scale(value: Any, owner: str, field: str) -> float:
    return at_most(non_negative(value, owner, field), LIMIT, owner, field)


def _max_length(value: Any, owner: str, field: str) -> float | None:
    return None if value is None else at_most(positive(value, owner, field), LIMIT, owner, field,
                                                 "m")  # fmt: skip


@dataclass(slots=True)
class ParticleStretch(Tracked):
    """Velocity-stretched particles. See the module docstring."""

    _checks: ClassVar[dict[str, Check]] = {
        "speed_scale": _scale,
        "length_scale": _scale,
        "max_length": _max_length,
    }

    speed_scale: float = 0.05  #: seconds: metres of length per m/s of speed
    length_scale: float = 1.0  #: the length at rest, in sizes
    max_length: float | None = None  #: metres
