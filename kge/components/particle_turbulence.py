"""``ParticleTurbulence``: a swirling noise field over an emitter's particles (pure data).

On an entity with a :class:`~kge.components.particles.ParticleEmitter`, it adds a
seeded curl-noise acceleration (:mod:`kge.particles.turbulence`) to every live
particle each frame: smoke that billows, embers that wander, magic that flows.

* ``strength``: the peak acceleration, m/s^2 (0 turns it off);
* ``frequency``: noise cells per metre (small: wide, slow swirls; large: jitter);
* ``speed``: how fast the field itself changes, cells per second (0: a fixed field
  the particles flow through);
* ``seed``: another seed, another field; the same seed gives the same particles
  in every run and every process.

The field lives in the emitter's space: world metres, or the entity's frame for a
``ParticleSpace.LOCAL`` emitter. Its clock is the emitter's game time (pause, time
scale and snapshots apply).

>>> ParticleTurbulence(strength=4.0, frequency=0.5).speed
1.0
>>> ParticleTurbulence(frequency=0.0)
Traceback (most recent call last):
...
kge.errors.ValidationError: ParticleTurbulence.frequency must be > 0, got 0.0
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from kge.components.particles import LIMIT
from kge.components.tracked import Check, Tracked
from kge.errors import ValidationError
from kge.validate import at_most, boolean, finite, integer, non_negative, positive

#: the finest noise a field may have, cells per metre (a cell of 1 mm)
MAX_FREQUENCY = 1000.0


def _strength(value: Any, owner: str, field: str) -> float:
    v = finite(value, owner, field)
    if abs(v) > LIMIT:
        raise ValidationError(f"{owner}.{field} must be within +-{LIMIT:g} m/s^2, got {v!r}")
    return v


def _frequency(value: Any, owner: str, field: str) -> float:
    return at_most(positive(value, owner, field), MAX_FREQUENCY, owner, field, "cells per metre")


def _speed(value: Any, owner: str, field: str) -> float:
    return at_most(non_negative(value, owner, field), LIMIT, owner, field, "cells per second")


def _seed(value: Any, owner: str, field: str) -> int:
    n = integer(value, owner, field)
    if not 0 <= n < 2**32:
        raise ValidationError(f"{owner}.{field} must be in 0..2**32 - 1, got {n}")
    return n


@dataclass(slots=True)
class ParticleTurbulence(Tracked):
    """Curl-noise turbulence on the emitter of this entity. See the module docstring."""

    _checks: ClassVar[dict[str, Check]] = {
        "strength": _strength,
        "frequency": _frequency,
        "speed": _speed,
        "seed": _seed,
        "enabled": boolean,
    }

    strength: float = 2.0
    frequency: float = 1.0
    speed: float = 1.0
    seed: int = 0
    enabled: bool = True
