"""``ParticleTrail``: trails behind particles, or one ribbon through them (pure data).

On an entity with a :class:`~kge.components.particles.ParticleEmitter`:

* ``mode=TrailMode.PARTICLE`` (default): each particle draws a strip through where
  it was over the last ``duration`` seconds (``points`` samples): comet tails, sword
  swooshes, tracer smoke;
* ``mode=TrailMode.RIBBON``: one strip joins all live particles from the newest to
  the oldest: a magic stream, a jet of water, a whip.

``width`` (metres), ``color`` (RGB 0-255) and ``opacity`` (0-255) are curves over the
trail's length from its head (the particle, or the newest particle) to its tail, one
value or evenly spaced keys, as the emitter's over-life curves. The trail's colour is
multiplied by the particle's current colour and opacity, so trails fade with their
particles.

>>> ParticleTrail(duration=0.5, width=(0.2, 0.0)).points
12
>>> ParticleTrail(points=1)
Traceback (most recent call last):
...
kge.errors.ValidationError: ParticleTrail.points must be in 2..64, got 1
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from enum import StrEnum
from typing import Any, ClassVar

from kge.components.particles import _colors, _opacities, _sizes
from kge.components.tracked import Check, Tracked
from kge.errors import ValidationError
from kge.validate import at_most, choice, integer, positive

#: the most samples a particle's trail keeps
MAX_POINTS = 64


class TrailMode(StrEnum):
    """What a :class:`ParticleTrail` draws."""

    PARTICLE = "particle"  #: a trail behind every particle
    RIBBON = "ribbon"  #: one strip through all live particles, newest to oldest


def _points(value: Any, owner: str, field: str) -> int:
    n = integer(value, owner, field)
    if not 2 <= n <= MAX_POINTS:
        raise ValidationError(f"{owner}.{field} must be in 2..{MAX_POINTS}, got {n}")
    return n


def _duration(value: Any, owner: str, field: str) -> float:
    return at_most(positive(value, owner, field), 60.0, owner, field, "s")


@dataclass(slots=True)
class ParticleTrail(Tracked):
    """Trails or a ribbon drawn from the emitter's particles. See the module docstring."""

    _checks: ClassVar[dict[str, Check]] = {
        "mode": choice(TrailMode),
        "duration": _duration,
        "points": _points,
        "width": _sizes,
        "color": _colors,
        "opacity": _opacities,
    }

    mode: TrailMode = TrailMode.PARTICLE
    duration: float = 0.3  #: seconds of path each particle's trail covers
    points: int = 12  #: samples along it (more: smoother curves, more vertices)
    width: Sequence[float] | float = (0.1, 0.0)  #: metres, head to tail
    color: Sequence[Any] = ((255, 255, 255),)
    opacity: Sequence[float] | float = (255.0, 0.0)
