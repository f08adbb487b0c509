"""How long named render passes take, for the stats overlay.

Only while the overlay is shown: the GPU works behind the CPU, so each measured pass
is bracketed by ``glFinish`` (the time then includes the rasterising, which is what
costs on software GL), and so is the whole frame. Figures are smoothed over frames
(an exponential average), so the overlay reads steadily.

>>> t = PassTimer()
>>> t.start(False); t.run("lighting", lambda frame: None, None); t.finish()
>>> t.ms("lighting"), t.frame_ms
(0.0, 0.0)
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Any

#: weight of the newest frame in the smoothed figures
SMOOTHING = 0.2


def _finish() -> None:
    from pyglet import gl

    gl.glFinish()


class PassTimer:
    """Smoothed milliseconds of named passes and of the frame (see the module docstring)."""

    def __init__(self, finish: Callable[[], None] = _finish) -> None:
        self.enabled = False
        self.frame_ms = 0.0
        self._finish = finish
        self._ms: dict[str, float] = {}
        self._this: dict[str, float] = {}
        self._t0 = 0.0

    def start(self, enabled: bool) -> None:
        """A frame begins; ``enabled``: the overlay is shown (else nothing is timed)."""
        self.enabled = enabled
        self._this = {}
        if not enabled:
            self._ms.clear()
            self.frame_ms = 0.0
            return
        self._finish()
        self._t0 = time.perf_counter()

    def run(self, name: str, fn: Callable[[Any], None], frame: Any) -> None:
        """Run pass ``fn(frame)``, adding its time to ``name`` (passes run once per camera)."""
        if not self.enabled:
            fn(frame)
            return
        self._finish()
        t0 = time.perf_counter()
        fn(frame)
        self._finish()
        self._this[name] = self._this.get(name, 0.0) + (time.perf_counter() - t0) * 1e3

    def finish(self) -> None:
        """The frame is drawn: fold this frame's times into the smoothed figures."""
        if not self.enabled:
            return
        self._finish()
        self.frame_ms = _smooth(self.frame_ms, (time.perf_counter() - self._t0) * 1e3)
        for name in self._ms.keys() | self._this.keys():
            self._ms[name] = _smooth(self._ms.get(name, 0.0), self._this.get(name, 0.0))

    def ms(self, name: str) -> float:
        """The smoothed time of pass ``name`` per frame (0 when not timed)."""
        return self._ms.get(name, 0.0)


def _smooth(old: float, new: float) -> float:
    return new if old <= 0.0 else old + SMOOTHING * (new - old)
