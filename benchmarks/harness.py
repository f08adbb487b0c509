"""Side-by-side timing on a noisy 2-core machine.

The rules that make the ratios trustworthy:

* every engine of a (scene, size) pair is built once and then run in
  *interleaved* blocks, so a burst of background load hits all of them alike; the
  order of the engines is shuffled for the builds and for every block (seeded, so a
  run can be repeated), so no engine always runs first after a collection or last
  in a block;
* each frame is timed on its own and the report gives the median and the p95
  over all blocks, never a mean that one hiccup can skew;
* ratios (kge / raw pymunk, kge / pybox2d) are computed from medians measured in
  the same run, on the same machine, never against numbers from elsewhere.

Timings are reported, never asserted: tests only run every scene at its smallest
size to prove the suite still works.
"""

from __future__ import annotations

import gc
import random
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
            progress: Callable[[str], None] = lambda s: None, seed: int = 0) -> list[Result]:
    """Time ``engines`` on ``scene`` at ``size`` in interleaved blocks, in shuffled order."""
    runners: dict[str, Runner] = {}
    samples: dict[str, list[float]] = {}
    listed = [e for e in engines if e in scene.engines]
    rng = random.Random(f"{seed}:{scene.name}:{size}")
    names = rng.sample(listed, len(listed))
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
            for name in rng.sample(names, len(names)):
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
    for name in listed:
        runner = runners[name]
        times = samples[name]
        results.append(Result(scene.name, size, name, statistics.median(times),
                              percentile(times, 0.95), len(times), runner.quality()))
        runner.close()
    return results


def largest_fitting(points: list[tuple[int, float]], budget: float = FRAME_BUDGET_MS) -> float:
    """The size whose frame time reaches ``budget``, interpolated log-log between the two
    measured sizes around it; never extrapolated.

    ``points`` are (size, median ms). Frame time grows roughly as a power of the size,
    so a straight line in log-log space between the two nearest points is a fair
    estimate inside the measured range. Outside it there is no figure: ``inf`` when
    even the largest size fits the budget, ``0.0`` when even the smallest does not
    (the report prints "> N" and "< N").

    >>> round(largest_fitting([(100, 4.0), (1000, 40.0)]))
    417
    >>> largest_fitting([(100, 4.0), (1000, 8.0)]), largest_fitting([(100, 20.0)])
    (inf, 0.0)
    """
    import math

    pts = sorted((n, ms) for n, ms in points if n > 0 and ms > 0)
    if not pts:
        return float("nan")
    if pts[-1][1] <= budget:
        return float("inf")
    if pts[0][1] > budget:
        return 0.0
    (n0, m0), (n1, m1) = next((a, b) for a, b in pairwise(pts) if a[1] <= budget < b[1])
    slope = (math.log(m1) - math.log(m0)) / (math.log(n1) - math.log(n0))
    return math.exp(math.log(n0) + (math.log(budget) - math.log(m0)) / slope)


def fitting_label(value: float, sizes: Iterable[int]) -> str:
    """How the report prints :func:`largest_fitting`: a size, or a bound of the range.

    >>> fitting_label(416.7, [100, 1000]), fitting_label(float("inf"), [100, 1000])
    ('417', '> 1,000')
    """
    ordered = sorted(sizes)
    if value == float("inf"):
        return f"> {ordered[-1]:,}"
    if value == 0.0:
        return f"< {ordered[0]:,}"
    return "-" if value != value else f"{value:,.0f}"
