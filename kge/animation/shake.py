"""Shake maths: smooth, bounded, deterministic noise and the trauma curve.

``noise(t, seed)`` is a sum of three sines at unrelated frequencies with
seed-derived phases, normalised so ``|noise| <= 1`` always; it is smooth (a
shake, not white jitter) and the same for the same seed and time, so a replay
or a headless test sees the same shake.

>>> abs(noise(0.37, 1)) <= 1.0, noise(0.37, 1) == noise(0.37, 1)
(True, True)
>>> offset(0.0, 1.0, (0.5, 0.5), 15.0, 0)
(0.0, 0.0)
"""

from __future__ import annotations

import math

_FREQS = (1.0, 2.31, 3.97)
_WEIGHTS = (0.6, 0.3, 0.1)  # sum 1: the noise stays in [-1, 1]


def noise(t: float, seed: int) -> float:
    """Smooth noise in [-1, 1] at time ``t`` (cycles), stream ``seed``."""
    total = 0.0
    for k, (f, w) in enumerate(zip(_FREQS, _WEIGHTS, strict=True)):
        phase = math.sin(seed * 12.9898 + k * 78.233) * 43758.5453
        phase -= math.floor(phase)
        total += w * math.sin(2 * math.pi * (f * t + phase))
    return total


def offset(
    trauma: float, time: float, max_offset: tuple[float, float], frequency: float, seed: int
) -> tuple[float, float]:
    """The shake offset (metres) at game time ``time`` for ``trauma`` (0..1)."""
    k = trauma * trauma
    if k == 0.0:
        return (0.0, 0.0)
    t = time * frequency
    return (max_offset[0] * k * noise(t, seed * 2), max_offset[1] * k * noise(t, seed * 2 + 1))


def decayed(trauma: float, decay: float, dt: float) -> float:
    """Trauma after ``dt`` seconds of linear decay (never below 0)."""
    return max(0.0, trauma - decay * dt)
