"""Side-by-side timing on a noisy 2-core machine.

The rules that make the ratios trustworthy:

* every engine of a (scene, size) pair is built once and then run in
  *interleaved* blocks (kge, pymunk, box2d, kge, pymunk, ...), so a burst of
  background load hits all of them alike;
* each frame is timed on its own and the report gives the median and the p95
  over all blocks, never a mean that one hiccup can skew;
* ratios (kge / raw pymunk, kge / pybox2d) are computed from medians measured in
  the same run, on the same machine, never against numbers from elsewhere.

Timings are reported, never asserted: tests only run every scene at its smallest
size to prove the suite still works.
"""

from __future__ import annotations

import gc
import statistics
import time
from collections.abc import Callable, Iterable
from dataclasses import asdict, dataclass, field
from itertools import pairwise
from typing import Protocol

FRAME_BUDGET_MS = 1000.0 / 60.0


class Runner(Protocol):
    """One engine running one scene: advance a frame, report a quality figure.

    A runner may also have a ``prepare()`` method, called untimed before each
    frame (the spawn scene removes the previous wave there).
    """

    def step(self) -> None: ...

    def quality(self) -> dict[str, float]: ...

    def close(self) -> None: ...


Factory = Callable[[int], Runner]


@dataclass(slots=True)
class Scene:
    """A benchmark scene: the same geometry built by each engine at several sizes."""

    name: str
    sizes: tuple[int, ...]
    engines: dict[str, Factory]
    warmup: int = 30
    frames: int = 60
    unit: str = "bodies"
    description: str = ""


@dataclass(slots=True)
class Result:
    scene: str
    size: int
    engine: str
    median_ms: float
    p95_ms: float
    frames: int
    quality: dict[str, float] = field(default_factory=dict)

    def as_dict(self) -> dict[str, object]:
        return asdict(self)


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    if not ordered:
        return float("nan")
    k = (len(ordered) - 1) * q
    lo, hi = int(k), min(int(k) + 1, len(ordered) - 1)
    return ordered[lo] + (ordered[hi] - ordered[lo]) * (k - lo)


def _nothing() -> None:
    pass


def measure(scene: Scene, size: int, engines: Iterable[str], blocks: int = 5,
            progress: Callable[[str], None] = lambda s: None) -> list[Result]:
    """Time ``engines`` on ``scene`` at ``size`` in interleaved blocks."""
    runners: dict[str, Runner] = {}
    samples: dict[str, list[float]] = {}
    names = [e for e in engines if e in scene.engines]
    for name in names:
        progress(f"{scene.name}[{size}] building {name}")
        runner = scene.engines[name](size)
        prepare = getattr(runner, "prepare", None) or _nothing
        for _ in range(scene.warmup):
            prepare()
            runner.step()
        runners[name] = runner
        samples[name] = []
    per_block = max(1, scene.frames // blocks)
    gc_was_enabled = gc.isenabled()
    gc.disable()  # a collection inside one engine's block would be charged to it alone
    try:
        for b in range(blocks):
            for name in names:
                progress(f"{scene.name}[{size}] block {b + 1}/{blocks} {name}")
                runner = runners[name]
                prepare = getattr(runner, "prepare", None) or _nothing
                times = samples[name]
                for _ in range(per_block):
                    prepare()
                    t0 = time.perf_counter()
                    runner.step()
                    times.append((time.perf_counter() - t0) * 1000.0)
            gc.collect()
    finally:
        if gc_was_enabled:
            gc.enable()
    results = []
    for name in names:
        runner = runners[name]
        times = samples[name]
        results.append(Result(scene.name, size, name, statistics.median(times),
                              percentile(times, 0.95), len(times), runner.quality()))
        runner.close()
    return results


def largest_fitting(points: list[tuple[int, float]], budget: float = FRAME_BUDGET_MS) -> float:
    """The size whose frame time reaches ``budget``, interpolated (or extrapolated) log-log.

    ``points`` are (size, median ms). Frame time grows roughly as a power of the
    size, so a straight line in log-log space between the two nearest points is a
    fair estimate; the report marks extrapolated values.
    """
    import math

    pts = sorted((n, ms) for n, ms in points if n > 0 and ms > 0)
    if not pts:
        return float("nan")
    if len(pts) == 1:
        n, ms = pts[0]
        return n * budget / ms  # assume linear scaling
    bracket = next(((a, b) for a, b in pairwise(pts) if a[1] <= budget <= b[1]), None)
    if bracket is None:  # extrapolate from the nearest end
        bracket = (pts[-2], pts[-1]) if pts[-1][1] < budget else (pts[0], pts[1])
    (n0, m0), (n1, m1) = bracket
    if m1 == m0:
        return float(n1)
    slope = (math.log(m1) - math.log(m0)) / (math.log(n1) - math.log(n0))
    if slope <= 0:
        return float("inf") if m1 < budget else float(n0)
    return math.exp(math.log(n0) + (math.log(budget) - math.log(m0)) / slope)
