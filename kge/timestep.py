"""The fixed-step accumulator: how many physics steps a frame runs, and alpha.

Physics needs a constant dt to be stable and deterministic; frames arrive with
whatever dt the display gives. Each frame adds its (scaled, clamped) time to an
accumulator and runs fixed steps while a whole step fits, at most
``max_steps_per_frame`` of them (a slow frame must not trigger a spiral of ever
longer frames; the backlog beyond the cap is dropped). What is left over, as a
fraction of a step, is ``alpha``: the renderer blends the previous and current
physics poses by it.

>>> ts = FixedTimestep(fixed_dt=0.01)
>>> ts.advance(0.025), round(ts.alpha, 6)
(2, 0.5)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from kge.errors import ValidationError
from kge.validate import boolean, finite, integer, non_negative, positive

_EPS = 1e-9


@dataclass(slots=True)
class FixedTimestep:
    fixed_dt: float = 1.0 / 60.0
    max_steps_per_frame: int = 5
    max_frame_dt: float = 0.25
    time_scale: float = 1.0
    paused: bool = False
    accumulator: float = 0.0
    _single_steps: int = 0

    def __setattr__(self, name: str, value: Any) -> None:
        # every write is checked: a NaN time scale or accumulator would freeze the game
        check = _CHECKS.get(name)
        if check is not None:
            value = check(value, "FixedTimestep", name)
        object.__setattr__(self, name, value)

    def frame_time(self, frame_dt: float) -> float:
        """The game time a frame of ``frame_dt`` real seconds represents (0 when paused)."""
        if self.paused:
            return 0.0
        return min(max(frame_dt, 0.0) * self.time_scale, self.max_frame_dt)

    def advance(self, frame_dt: float) -> int:
        """Add one frame; return the number of fixed steps to run now.

        ``frame_dt`` must be a finite number (NaN would stop the clock for good);
        a negative one (a clock stepping back) counts as 0.
        """
        frame_dt = finite(frame_dt, "App.advance", "frame_dt")
        if self.paused:
            if self._single_steps:
                self._single_steps -= 1
                return 1
            return 0
        self.accumulator += self.frame_time(frame_dt)
        steps = 0
        while self.accumulator + _EPS >= self.fixed_dt and steps < self.max_steps_per_frame:
            self.accumulator -= self.fixed_dt
            steps += 1
        if self.accumulator + _EPS >= self.fixed_dt:  # hit the cap: drop the backlog
            whole = math.floor((self.accumulator + _EPS) / self.fixed_dt)
            self.accumulator -= whole * self.fixed_dt
        self.accumulator = max(self.accumulator, 0.0)
        return steps

    def single_step(self) -> None:
        """While paused, run exactly one fixed step on the next frame."""
        self._single_steps += 1

    @property
    def alpha(self) -> float:
        """Interpolation weight of the current pose, in [0, 1)."""
        return min(max(self.accumulator / self.fixed_dt, 0.0), 1.0)


def _at_least_one(value: Any, owner: str, name: str) -> int:
    v = integer(value, owner, name)
    if v < 1:
        raise ValidationError(f"{owner}.{name} must be >= 1, got {v!r}")
    return v


_CHECKS = {
    "fixed_dt": positive,
    "max_steps_per_frame": _at_least_one,
    "max_frame_dt": positive,
    "time_scale": non_negative,
    "paused": boolean,
    "accumulator": finite,
    "_single_steps": integer,
}
