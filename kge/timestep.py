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

from kge.validate import non_negative, positive

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

    def __post_init__(self) -> None:
        positive(self.fixed_dt, "FixedTimestep", "fixed_dt")
        positive(self.max_frame_dt, "FixedTimestep", "max_frame_dt")
        non_negative(self.time_scale, "FixedTimestep", "time_scale")
        if self.max_steps_per_frame < 1:
            raise ValueError("FixedTimestep.max_steps_per_frame must be >= 1")

    def frame_time(self, frame_dt: float) -> float:
        """The game time a frame of ``frame_dt`` real seconds represents (0 when paused)."""
        if self.paused:
            return 0.0
        return min(max(frame_dt, 0.0) * self.time_scale, self.max_frame_dt)

    def advance(self, frame_dt: float) -> int:
        """Add one frame; return the number of fixed steps to run now."""
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
