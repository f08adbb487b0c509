"""The headless backend: a test stepped a fixed number of frames, with scripted key presses.

Nothing is shown: each frame's drawing (what the framework and the example hand
the renderer, in world coordinates) and text are kept in a :class:`Record`, so
tests and benchmarks can look at what a window would have shown. Frames are
stepped as fast as they compute.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from time import perf_counter
from typing import TYPE_CHECKING, Any

from kge.box2d.testbed.presses import Press, press_scripted

if TYPE_CHECKING:
    from kge.box2d.testbed.framework import Framework


@dataclass
class Record:
    """One frame's drawing: ``(kind, ...)`` tuples (polygon, circle, segment, point), in
    screen pixels (``test.renderer.to_world`` gives world points), colours as the
    framework and the example gave them."""

    items: list[tuple[Any, ...]] = field(default_factory=list)

    def start(self) -> None:
        self.items = []

    def end(self) -> None:
        pass

    def polygon(self, points: list[tuple[float, float]], color: Any, filled: bool) -> None:
        self.items.append(("polygon", points, color, filled))

    def circle(self, center: tuple[float, float], radius: float, color: Any,
               filled: bool) -> None:
        self.items.append(("circle", center, radius, color, filled))

    def segment(self, p1: tuple[float, float], p2: tuple[float, float], color: Any) -> None:
        self.items.append(("segment", p1, p2, color))

    def point(self, p: tuple[float, float], size: float, color: Any) -> None:
        self.items.append(("point", p, size, color))

    def counts(self) -> Counter[str]:
        return Counter(item[0] for item in self.items)


class HeadlessBackend:
    """Step a test ``frames`` times, pressing and releasing keys as ``presses`` say.

    After :meth:`run`: :attr:`test` is the test, :attr:`frames_run` how many frames
    ran and :attr:`seconds` how long they took.
    """

    def __init__(self, frames: int, presses: list[Press] | None = None) -> None:
        self.frames = int(frames)
        self.presses = list(presses or [])
        self.test: Framework | None = None
        self.record = Record()
        self.frames_run = 0
        self.seconds = 0.0

    def sink(self, test: Framework) -> Record:
        return self.record

    def run(self, test: Framework) -> None:
        self.test = test
        started = perf_counter()
        for frame in range(self.frames):
            press_scripted(test, self.presses, frame)
            test.Frame()
            self.frames_run = frame + 1
            elapsed = perf_counter() - started
            test.fps = self.frames_run / elapsed if elapsed > 0 else 0.0
        self.seconds = perf_counter() - started
