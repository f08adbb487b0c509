"""µs of kge's own work per new contact: its begin and its end, on rain (5,000 circles).

Every new contact runs kge's ``begin`` handler inside pymunk's step and every
ended one its ``separate`` handler (:mod:`kge.physics.contacts`): the Box2D
rules pymunk lacks, the event records. Both are timed per call in a running
rain scene (the circles landing and piling up: about 200 new contacts a frame),
with a wrapper around each handler; the same wrapper around an empty function,
timed in the same calls, is subtracted. Medians per call, so a preemption of a
busy machine does not count. What is left out: the crossing from C into Python
(one cffi callback per call, the same for any Python handler).

The target row (``kge bench``): a new contact's begin plus its end, <= 3 µs.
"""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable
from typing import Any

from kge.app import App
from kge.physics.resource import Physics
from kge.testbed.registry import get_sample

#: circles, warm-up frames (they land), measured frames; and the quick variant's
FULL = (5000, 60, 30)
QUICK = (1000, 30, 10)


def _timed(fn: Callable[[Any], None], into: list[int], empty: list[int]) -> Callable[[Any], None]:
    clock = time.perf_counter_ns

    def nothing(arb: Any) -> None:
        pass

    def call(arb: Any) -> None:
        t = clock()
        fn(arb)
        into.append(clock() - t)
        t = clock()
        nothing(arb)
        empty.append(clock() - t)

    return call


def measure(quick: bool = False) -> dict[str, float]:
    """Median µs of kge's begin and separate handlers per call, and their sum."""
    count, warm, frames = QUICK if quick else FULL
    app = App(get_sample("rain").setup, headless=True, count=count)
    try:
        for _ in range(warm):
            app.step()
        recorder = app.world.resource(Physics)._sim.recorder
        begins: list[int] = []
        ends: list[int] = []
        empty: list[int] = []
        begin, separate = recorder._begin, recorder._separate
        recorder._begin = _timed(begin, begins, empty)  # type: ignore[method-assign,assignment]
        recorder._separate = _timed(separate, ends, empty)  # type: ignore[method-assign,assignment]
        recorder.bind(recorder.space)
        try:
            for _ in range(frames):
                app.step()
        finally:  # kge's own handlers again (the timed ones would keep the world alive)
            del recorder._begin, recorder._separate
            recorder.bind(recorder.space)
    finally:
        app.close()
    base = statistics.median(empty) if empty else 0.0

    def us(samples: list[int]) -> float:
        return max(0.0, statistics.median(samples) - base) / 1e3 if samples else 0.0

    out = {
        "contact_bodies": float(count),
        "contact_begins_per_frame": len(begins) / frames,
        "contact_ends_per_frame": len(ends) / frames,
        "contact_begin_us": us(begins),
        "contact_end_us": us(ends),
    }
    out["contact_us"] = out["contact_begin_us"] + out["contact_end_us"]
    return out


def line(c: dict[str, float]) -> str:
    return (f"  new contact, rain-{c['contact_bodies']:.0f} "
            f"({c['contact_begins_per_frame']:.0f} a frame)  begin {c['contact_begin_us']:.2f}"
            f" + end {c['contact_end_us']:.2f} = {c['contact_us']:.2f} µs")


if __name__ == "__main__":  # python -m benchmarks.contact_cost
    print(line(measure()))
