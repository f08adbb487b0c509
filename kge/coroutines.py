"""Generator coroutines for behaviours: ``yield Wait(0.5)`` instead of timers.

A coroutine is a generator started with ``script.start_coroutine(gen)``. What it
yields decides when it resumes:

* ``None``: next frame;
* ``Wait(seconds)``: after that much *game* time (scaled by ``time_scale``);
* ``WaitFrames(n)``: after n frames;
* anything with an ``is_done()`` method, such as the handle of a tween
  (``yield tweens.start(e, spec)``): once ``is_done()`` is true, checked each frame.

It runs in the update pass, after ``on_update``, and stops for good when it
returns, when ``handle.stop()`` is called, or when its entity or scene goes away.
"""

from __future__ import annotations

from collections.abc import Generator
from dataclasses import dataclass
from typing import Any

from kge.errors import ValidationError
from kge.validate import non_negative


@dataclass(slots=True, frozen=True)
class Wait:
    """Resume after ``seconds`` of game time."""

    seconds: float

    def __post_init__(self) -> None:
        non_negative(self.seconds, "Wait", "seconds")


@dataclass(slots=True, frozen=True)
class WaitFrames:
    """Resume after ``frames`` update passes."""

    frames: int

    def __post_init__(self) -> None:
        if isinstance(self.frames, bool) or not isinstance(self.frames, int) or self.frames < 0:
            raise ValidationError(f"WaitFrames.frames must be an int >= 0, got {self.frames!r}")


class Coroutine:
    """A running coroutine; ``stop()`` ends it."""

    __slots__ = ("_frames_left", "_time_left", "_until", "done", "entity", "gen")

    def __init__(self, entity: int, gen: Generator[Any, None, Any]) -> None:
        if not isinstance(gen, Generator):
            raise TypeError(
                f"start_coroutine() needs a generator (call the function: start_coroutine(f())), "
                f"got {type(gen).__name__}"
            )
        self.entity = entity
        self.gen = gen
        self._time_left = 0.0
        self._frames_left = 0
        self._until: Any = None
        self.done = False

    def stop(self) -> None:
        if not self.done:
            self.done = True
            self.gen.close()

    def tick(self, dt: float) -> None:
        """Advance by one frame of ``dt`` seconds; resume the generator when due."""
        if self.done:
            return
        if self._until is not None:
            if not self._until.is_done():
                return
            self._until = None
        elif self._frames_left > 0:
            self._frames_left -= 1
            if self._frames_left > 0:
                return
        elif self._time_left > 0.0:
            self._time_left -= dt
            if self._time_left > 1e-12:
                return
        try:
            order = next(self.gen)
        except StopIteration:
            self.done = True
            return
        except BaseException:
            self.done = True
            raise
        if order is None:
            self._frames_left = 1
        elif isinstance(order, Wait):
            self._time_left = order.seconds
            self._frames_left = 0
            if order.seconds == 0.0:
                self._frames_left = 1
        elif isinstance(order, WaitFrames):
            self._frames_left = max(order.frames, 1)
        elif callable(getattr(order, "is_done", None)):
            self._until = order
        else:
            self.stop()
            raise TypeError(
                f"coroutine of entity {self.entity} yielded {order!r}; "
                "yield None, Wait(seconds), WaitFrames(n) or a handle with is_done() (a tween)"
            )
