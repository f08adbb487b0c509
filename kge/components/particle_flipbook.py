"""``ParticleFlipbook``: animated particle textures from a sprite sheet (pure data).

On an entity with a :class:`~kge.components.particles.ParticleEmitter` whose
``texture`` is a sprite sheet of ``columns`` x ``rows`` equal frames (read left to
right, top to bottom; ``frames`` of them, all by default), each particle shows one
frame at a time:

* ``fps=None`` (default): the animation plays once over each particle's life (an
  explosion puff that always ends on its last frame), ``cycles`` times;
* ``fps`` a number: frames per second of the particle's age, looping (``loop=False``
  holds the last frame);
* ``random_start=True``: each particle starts at its own random frame (seeded by the
  emitter's seed: the same in every run), so a swarm does not flap in step.

>>> ParticleFlipbook(4, 2).count
8
>>> ParticleFlipbook(4, 2, frames=9)
Traceback (most recent call last):
...
kge.errors.ValidationError: ParticleFlipbook.frames must be in 1..8 (columns x rows), got 9
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from kge.components.tracked import Check, Tracked
from kge.errors import ValidationError
from kge.validate import at_most, boolean, integer, positive

#: the most columns or rows a sheet may have
MAX_CELLS = 256


def _cells(value: Any, owner: str, field: str) -> int:
    n = integer(value, owner, field)
    if not 1 <= n <= MAX_CELLS:
        raise ValidationError(f"{owner}.{field} must be in 1..{MAX_CELLS}, got {n}")
    return n


def _frames(value: Any, owner: str, field: str) -> int | None:
    return None if value is None else _cells_count(value, owner, field)


def _cells_count(value: Any, owner: str, field: str) -> int:
    n = integer(value, owner, field)
    if n < 1:
        raise ValidationError(f"{owner}.{field} must be >= 1, got {n}")
    return n


def _fps(value: Any, owner: str, field: str) -> float | None:
    return None if value is None else at_most(positive(value, owner, field), 1e4, owner, field,
                                                 "frames per second")  # fmt: skip


def _cycles(value: Any, owner: str, field: str) -> float:
    return at_most(positive(value, owner, field), 1e4, owner, field, "cycles")


@dataclass(slots=True)
class ParticleFlipbook(Tracked):
    """Animated particle frames from the emitter's sprite sheet. See the module docstring."""

    _checks: ClassVar[dict[str, Check]] = {
        "columns": _cells,
        "rows": _cells,
        "frames": _frames,
        "fps": _fps,
        "cycles": _cycles,
        "loop": boolean,
        "random_start": boolean,
    }

    columns: int = 1
    rows: int = 1
    frames: int | None = None  #: None: every cell of the sheet
    fps: float | None = None
    cycles: float = 1.0
    loop: bool = True
    random_start: bool = False

    def __post_init__(self) -> None:
        self._fit(self.frames)

    @property
    def count(self) -> int:
        """The frames the animation plays."""
        return self.columns * self.rows if self.frames is None else self.frames

    def _fit(self, frames: int | None, columns: int | None = None, rows: int | None = None
             ) -> None:  # fmt: skip
        total = (columns or self.columns) * (rows or self.rows)
        if frames is not None and frames > total:
            raise ValidationError(
                f"{self._owner()}.frames must be in 1..{total} (columns x rows), got {frames}"
            )

    def __setattr__(self, name: str, value: Any) -> None:
        if hasattr(self, "frames"):  # built: a write keeps the frames within the sheet
            if name == "frames":
                self._fit(_frames(value, self._owner(), name))
            elif name == "columns":
                self._fit(self.frames, columns=_cells(value, self._owner(), name))
            elif name == "rows":
                self._fit(self.frames, rows=_cells(value, self._owner(), name))
        Tracked.__setattr__(self, name, value)
