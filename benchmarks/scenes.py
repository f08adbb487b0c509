"""The benchmark scenes: testbed samples at benchmark sizes, on three engines.

Every scene here is a registered testbed sample (``kge.testbed``), so what is
timed is exactly what a user can open in the testbed. Sizes follow the issue:
pyramid bases 20 / 40 / 100 (210 / 820 / 5,050 boxes), rain 1,000 / 5,000
circles, 5,000 sleeping boxes, a 2,000-box tumbler, churn, and an event storm.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from benchmarks.engines import (
    Box2DRunner,
    KgeRunner,
    Pose,
    PymunkRunner,
    box2d_available,
    spec_of,
)
from benchmarks.harness import Factory, Scene
from kge.testbed.registry import get_sample

Quality = Callable[[dict[int, Pose], dict[int, Pose]], dict[str, float]]


class _Measured:
    """Wraps a runner to compute a quality figure from its poses at close time."""

    def __init__(self, runner: Any, quality: Quality) -> None:
        self.runner = runner
        self.first = runner.poses()
        self.quality_fn = quality

    def step(self) -> None:
        self.runner.step()

    def quality(self) -> dict[str, float]:
        return self.quality_fn(self.first, self.runner.poses())

    def close(self) -> None:
        self.runner.close()


def _engines(slug: str, param: str, quality: Quality, events: bool = False,
             extra: dict[str, Any] | None = None) -> dict[str, Factory]:
    sample = get_sample(slug)
    extra = extra or {}

    def kge_factory(n: int) -> _Measured:
        return _Measured(KgeRunner(sample, **{param: n}, **extra), quality)

    def pymunk_factory(n: int) -> _Measured:
        spec = spec_of(sample, **{param: n}, **extra)
        return _Measured(PymunkRunner(spec, events=events), quality)

    engines: dict[str, Factory] = {"kge": kge_factory, "pymunk": pymunk_factory}
    if box2d_available() is None:

        def box2d_factory(n: int) -> _Measured:
            spec = spec_of(sample, **{param: n}, **extra)
            return _Measured(Box2DRunner(spec, events=events), quality)

        engines["box2d"] = box2d_factory
    return engines


def pyramid_quality(first: dict[int, Pose], last: dict[int, Pose]) -> dict[str, float]:
    top = max(first, key=lambda e: first[e][1])
    drift = abs(last[top][0] - first[top][0])
    fallen = sum(1 for e, p in last.items() if abs(p[2]) > 0.3)
    return {"top_drift_m": round(drift, 4), "fallen": float(fallen)}


def escaped_quality(first: dict[int, Pose], last: dict[int, Pose]) -> dict[str, float]:
    escaped = sum(1 for p in last.values() if abs(p[0]) > 21.0 or p[1] < -1.0)
    return {"escaped": float(escaped)}


def moved_quality(first: dict[int, Pose], last: dict[int, Pose]) -> dict[str, float]:
    moved = max((math.dist(first[e][:2], last[e][:2]) for e in first if e in last), default=0.0)
    return {"max_move_m": round(moved, 4)}


def count_quality(first: dict[int, Pose], last: dict[int, Pose]) -> dict[str, float]:
    return {"bodies": float(len(last))}


def scenes(quick: bool = False) -> list[Scene]:
    """All scenes; ``quick`` uses the smallest size only with few frames (for tests)."""
    table = [
        Scene("pyramid", (20, 40, 100), _engines("pyramid", "rows", pyramid_quality),
              description="pyramid of boxes, base 20/40/100 (210/820/5,050 boxes)", unit="rows"),
        Scene("rain", (1000, 5000), _engines("rain", "count", escaped_quality),
              description="circles raining into a 40 m box"),
        Scene("many-sleeping", (5000,), _engines("sleeping-boxes", "count", moved_quality),
              description="5,000 boxes at rest on a floor, sleep on"),
        Scene("event-storm", (15, 30), _engines("event-storm", "rows", pyramid_quality,
                                                events=True),
              description="pyramid struck by a ball, events on every collider", unit="rows"),
    ]
    if quick:
        for s in table:
            s.sizes = (min(s.sizes) if s.unit == "rows" else min(s.sizes) // 10,)
            s.warmup, s.frames = 2, 5
    return table


def skipped_engines() -> list[str]:
    reason = box2d_available()
    return [] if reason is None else [f"box2d: {reason}"]
