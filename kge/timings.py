"""Per-system timings: how long each system of a world takes, measured only when asked.

``world.schedule.enable_timings()`` wraps each system's run (its flush of queued
changes included) in a pair of ``time.perf_counter()`` calls, or of the clock it is
given (``time.thread_time``: the game thread's CPU only); with timings off (the
default) the schedule runs exactly as before and pays nothing. The stats overlay (F3
in a window), ``kge schedule --timings`` and the console's ``timings`` command read
the same numbers.

Numbers per system:

* ``calls``, ``total`` (seconds since enabled or reset), ``last`` (its last run);
* ``frame`` (milliseconds in the last *frame*, so a FIXED system that ran twice in
  that frame counts twice) and ``average`` (an exponential moving average of
  ``frame`` over about the last 30 frames: readable, not flickering);
* ``peak`` (the slowest frame since enabled or reset, ms).

>>> t = SystemTimings()
>>> class Physics: ...
>>> p = Physics()
>>> t.add(p, "FIXED", 0.002); t.add(p, "FIXED", 0.001); t.end_frame()
>>> row = t.rows()[0]
>>> row.name, row.calls, round(row.frame, 3), round(row.peak, 3)
('Physics', 2, 3.0, 3.0)
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

#: weight of the newest frame in ``average`` (about a 30-frame window)
SMOOTHING = 1.0 / 30.0


@dataclass(slots=True)
class TimingRow:
    """One system's numbers (milliseconds, except ``total`` in seconds)."""

    name: str
    stage: str
    calls: int
    total: float  #: seconds since timings were enabled or reset
    last: float  #: ms of its last run
    frame: float  #: ms spent in the last frame
    average: float  #: moving average of ``frame`` (ms)
    peak: float  #: slowest frame (ms)


class _Entry:
    __slots__ = ("average", "calls", "current", "frame", "last", "name", "peak", "stage", "total")

    def __init__(self, name: str, stage: str) -> None:
        self.name = name
        self.stage = stage
        self.calls = 0
        self.total = 0.0
        self.last = 0.0
        self.current = 0.0  # seconds in the frame being run
        self.frame = 0.0  # seconds in the last finished frame
        self.average = -1.0  # seconds; negative until the first frame ends
        self.peak = 0.0


class SystemTimings:
    """The timings of one schedule (see the module docstring)."""

    def __init__(self, clock: Callable[[], float] | None = None) -> None:
        #: what the schedule reads before and after each system (seconds); None:
        #: ``time.perf_counter``
        self.clock = clock
        self._entries: dict[int, _Entry] = {}
        self._keep: dict[int, object] = {}  # ids stay unique while the system is known
        self.frames = 0  #: frames ended since enabled or reset

    def add(self, system: object, stage: str, seconds: float) -> None:
        """Record one run of ``system`` that took ``seconds``."""
        key = id(system)
        e = self._entries.get(key)
        if e is None:
            e = self._entries[key] = _Entry(type(system).__name__, stage)
            self._keep[key] = system
        e.calls += 1
        e.total += seconds
        e.last = seconds
        e.current += seconds

    def end_frame(self) -> None:
        """Close the frame: ``frame``, ``average`` and ``peak`` take its sums."""
        for e in self._entries.values():
            e.frame = e.current
            e.current = 0.0
            e.average = e.frame if e.average < 0 else e.average + SMOOTHING * (
                e.frame - e.average
            )
            if e.frame > e.peak:
                e.peak = e.frame
        self.frames += 1

    def forget(self, system: object) -> None:
        """``system`` left the schedule."""
        self._entries.pop(id(system), None)
        self._keep.pop(id(system), None)

    def reset(self) -> None:
        """Start counting again (keeps the systems, zeroes their numbers)."""
        for key, e in list(self._entries.items()):
            self._entries[key] = _Entry(e.name, e.stage)
        self.frames = 0

    def rows(self, top: int | None = None) -> list[TimingRow]:
        """Every timed system, slowest first (by ``average``), at most ``top`` of them."""
        rows = [
            TimingRow(e.name, e.stage, e.calls, e.total, e.last * 1e3, e.frame * 1e3,
                      max(e.average, 0.0) * 1e3, e.peak * 1e3)
            for e in self._entries.values()
        ]  # fmt: skip
        rows.sort(key=lambda r: (-r.average, -r.total, r.name))
        return rows if top is None else rows[:top]

    def of(self, system: object) -> TimingRow | None:
        """The row of one system (None if it has not run while timed)."""
        e = self._entries.get(id(system))
        if e is None:
            return None
        return TimingRow(e.name, e.stage, e.calls, e.total, e.last * 1e3, e.frame * 1e3,
                         max(e.average, 0.0) * 1e3, e.peak * 1e3)  # fmt: skip

    def frame_ms(self) -> float:
        """Every timed system's ``frame`` summed: what the schedule cost last frame (ms)."""
        return sum(e.frame for e in self._entries.values()) * 1e3

    def describe(self, top: int | None = None) -> str:
        """A text table, slowest first (what ``kge schedule --timings`` prints)."""
        head = ("stage", "system", "avg ms", "last frame ms", "peak ms", "calls")
        lines = [head]
        for r in self.rows(top):
            lines.append((r.stage, r.name, f"{r.average:.3f}", f"{r.frame:.3f}",
                          f"{r.peak:.3f}", str(r.calls)))  # fmt: skip
        widths = [max(len(line[i]) for line in lines) for i in range(len(head))]
        return "\n".join(
            "  ".join(c.ljust(w) for c, w in zip(line, widths, strict=True)).rstrip()
            for line in lines
        )
