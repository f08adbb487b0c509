"""``CameraShake``: trauma-based screen shake (put it beside a Camera, or insert it as a resource).

``trauma`` (0..1) is how shaken the camera is; hits add to it (:meth:`add`) and
it decays by ``decay`` per second of game time. The offset is
``max_offset * trauma ** 2 * noise(t)`` (kge cameras do not rotate, so the
shake is a translation): squaring makes small hits subtle and big
ones violent, and the smooth deterministic noise (``frequency`` Hz, ``seed``)
makes it a shake, not a jitter. The offset is added to the camera's centre for
drawing and taken away again before the next frame's updates, so following,
tweens and game code never see it.

>>> s = CameraShake(decay=2.0)
>>> s.add(0.7); s.add(0.7); s.trauma
1.0
>>> s.add(-1)
Traceback (most recent call last):
...
kge.errors.ValidationError: CameraShake.add: amount must be >= 0, got -1.0
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from kge.components.tracked import Check, Tracked
from kge.errors import ValidationError
from kge.validate import Vec2, at_most, finite, integer, non_negative, positive, vec2


def _trauma(value: Any, owner: str, field: str) -> float:
    return min(max(finite(value, owner, field), 0.0), 1.0)


#: the largest shake offset (m) and frequency (Hz)
MAX_OFFSET = 1e6
MAX_FREQUENCY = 1e4


def _offset(value: Any, owner: str, field: str) -> Vec2:
    x, y = vec2(value, owner, field)
    out = (non_negative(x, owner, f"{field}[0]"), non_negative(y, owner, f"{field}[1]"))
    if max(out) > MAX_OFFSET:
        raise ValidationError(f"{owner}.{field} must be within {MAX_OFFSET:g} m, got {value!r}")
    return out


def _frequency(value: Any, owner: str, field: str) -> float:
    return at_most(positive(value, owner, field), MAX_FREQUENCY, owner, field, "Hz")


def _seed(value: Any, owner: str, field: str) -> int:
    v = integer(value, owner, field)
    if not 0 <= v < 2**32:
        raise ValidationError(f"{owner}.{field} must be in 0..2**32-1, got {v}")
    return v


@dataclass(slots=True)
class CameraShake(Tracked):
    """Trauma-based camera shake. See the module docstring."""

    _checks: ClassVar[dict[str, Check]] = {
        "trauma": _trauma,
        "decay": non_negative,
        "max_offset": _offset,
        "frequency": _frequency,
        "seed": _seed,
    }

    trauma: float = 0.0
    decay: float = 1.0
    max_offset: Vec2 = (0.5, 0.5)
    frequency: float = 15.0
    seed: int = 0

    def add(self, amount: float) -> None:
        """Add ``amount`` of trauma (the total stays at most 1)."""
        a = finite(amount, "CameraShake.add", "amount")
        if a < 0:
            raise ValidationError(f"CameraShake.add: amount must be >= 0, got {a!r}")
        self.trauma = min(1.0, self.trauma + a)
