"""Game-layer features that cost per frame: the ``features`` rows of ``kge bench``.

* ``timings``: per-system timers. An App with the default plugins and 40 extra
  trivial UPDATE systems runs frames with timings off and on, interleaved; the
  overhead is reported per timed system run (µs), and as a share of the frame.
* ``gizmos``: recording N debug lines in a frame (``Gizmos.line``, µs per line; and
  one bulk ``Gizmos.lines`` call), and the frame's draw with them (headless EGL).
* ``particle_forces``: one step of N particles, plain (gravity and drag) and with
  the forces about the origin (radial, tangential, orbit), side by side.

Other sections (sub-emitters, trails, audio effects) join this module as they land.
Timings are medians of interleaved repetitions, reported, never asserted. Run
``python benchmarks/features.py`` for the table.
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from collections.abc import Callable
from typing import Any

os.environ.setdefault("PYGLET_HEADLESS", "1")

if __package__ in (None, ""):  # run as a script: make the repository importable
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

import numpy as np

Row = dict[str, float]


def _median_ms(fn: Callable[[], Any], repeats: int) -> float:
    samples = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        samples.append((time.perf_counter() - t0) * 1e3)
    return statistics.median(samples)


def measure_timings(extra: int = 40, frames: int = 20, repeats: int = 15) -> Row:
    """ms per frame of an App with ``extra`` trivial systems, timings off and on."""
    from kge import App, Stage, System

    class Nop(System):
        stage = Stage.UPDATE

        def process(self, dt: float) -> None:
            pass

    app = App(lambda world: None, headless=True)
    for _ in range(extra):
        app.world.add_system(Nop())
    schedule = app.world.schedule
    runs = len(schedule.systems()) - len(schedule.systems(Stage.RENDER))
    timings = schedule.enable_timings()  # made once: toggling only swaps it in and out
    app.step(frames)

    def frames_off() -> None:
        schedule.timings = None
        app.step(frames)

    def frames_on() -> None:
        schedule.timings = timings
        app.step(frames)

    off, on = [], []
    for _ in range(repeats):  # interleaved: background load hits both alike
        off.append(_median_ms(frames_off, 1) / frames)
        on.append(_median_ms(frames_on, 1) / frames)
    app.close()
    off_ms, on_ms = statistics.median(off), statistics.median(on)
    return {
        "systems": float(runs),
        "off_ms": off_ms,
        "on_ms": on_ms,
        "overhead_us_per_system": max(on_ms - off_ms, 0.0) * 1e3 / runs,
        "overhead_share": max(on_ms - off_ms, 0.0) / off_ms if off_ms > 0 else 0.0,
    }


def measure_gizmos(n: int = 1000, repeats: int = 15) -> Row:
    """Recording ``n`` lines (one call each, and one bulk call), and drawing them."""
    from kge import App
    from kge.debug import Gizmos

    rng = np.random.default_rng(1)
    pts = rng.uniform(-5, 5, (n, 4))
    rows = [tuple(p) for p in pts.tolist()]
    g = Gizmos()

    def per_call() -> None:
        g.begin_frame(0.0)
        line = g.line
        for x0, y0, x1, y1 in rows:
            line((x0, y0), (x1, y1), (255, 0, 0))

    def bulk() -> None:
        g.begin_frame(0.0)
        g.lines(pts, (255, 0, 0))

    app = App(lambda world: None, headless=True, size=(480, 270))
    gizmos = app.world.resource(Gizmos)
    app.render()

    def render_with() -> None:
        for _ in range(5):
            gizmos.lines(pts, (0, 255, 0))
            app.render()
            _finish()
            gizmos.clear()

    def render_without() -> None:
        for _ in range(5):
            app.render()
            _finish()

    calls, bulks, with_, without = [], [], [], []
    for _ in range(repeats):
        calls.append(_median_ms(per_call, 1))
        bulks.append(_median_ms(bulk, 1))
        with_.append(_median_ms(render_with, 1))
        without.append(_median_ms(render_without, 1))
    app.close()
    return {
        "lines": float(n),
        "record_us_per_line": statistics.median(calls) * 1e3 / n,
        "bulk_ms": statistics.median(bulks),
        "draw_ms": max(statistics.median(with_) - statistics.median(without), 0.0) / 5,
    }


def measure_particle_forces(n: int = 20000, repeats: int = 15) -> Row:
    """ms per step of ``n`` particles, plain and with radial, tangential and orbit."""
    from kge.particles.pool import ParticlePool

    rng = np.random.default_rng(2)

    def pool() -> ParticlePool:
        p = ParticlePool(max_particles=n)
        p.add(rng.uniform(-5, 5, (n, 2)), rng.uniform(-1, 1, (n, 2)), np.full(n, 1e9),
              np.zeros(n), np.zeros(n))  # fmt: skip
        return p

    plain_pool, around_pool = pool(), pool()
    around = (0.0, 0.0, -2.0, 3.0, 1.0)
    plain, with_ = [], []
    for _ in range(repeats):  # interleaved
        plain.append(_median_ms(lambda: plain_pool.step(1 / 60, (0.0, -9.8), 0.5), 1))
        with_.append(_median_ms(lambda: around_pool.step(1 / 60, (0.0, -9.8), 0.5, None, None,
                                                         around), 1))  # fmt: skip
    p, w = statistics.median(plain), statistics.median(with_)
    return {"particles": float(n), "plain_ms": p, "forces_ms": w,
            "ratio": w / p if p > 0 else 0.0,
            "extra_us_per_1000": max(w - p, 0.0) * 1e3 / (n / 1000)}  # fmt: skip


def _finish() -> None:
    from pyglet import gl

    gl.glFinish()


def run_features(quick: bool, progress: Any) -> tuple[dict[str, Row], str | None]:
    """The section ``kge bench`` adds, or the reason it failed."""
    out: dict[str, Row] = {}
    repeats = 3 if quick else 15
    try:
        progress("system timings overhead")
        out["timings"] = measure_timings(frames=5 if quick else 20, repeats=repeats)
        progress("particle forces")
        out["particle_forces"] = measure_particle_forces(5000 if quick else 20000, repeats)
        progress("gizmos")
        out["gizmos"] = measure_gizmos(200 if quick else 1000, repeats)
    except Exception as err:  # no GL (headless EGL missing): report, do not fail the run
        return out, f"features skipped: {type(err).__name__}: {err}"
    return out, None


def feature_lines(features: dict[str, Row]) -> list[str]:
    """Markdown lines of the section (for bench.md)."""
    out: list[str] = []
    t = features.get("timings")
    if t:
        out += [
            "",
            f"Per-system timings, an App of {t['systems']:.0f} systems, median ms per frame "
            "(off: the schedule as shipped; on: a perf_counter pair around each system):",
            "",
            "| timings off | timings on | overhead per system run | share of the frame |",
            "|---:|---:|---:|---:|",
            f"| {t['off_ms']:.3f} | {t['on_ms']:.3f} | {t['overhead_us_per_system']:.2f} µs "
            f"| {100 * t['overhead_share']:.0f} % |",
        ]
    f = features.get("particle_forces")
    if f:
        out += [
            "",
            f"Particle forces about the origin, {f['particles']:,.0f} particles, one step:",
            "",
            "| gravity and drag | plus radial, tangential, orbit | ratio | extra per 1,000 |",
            "|---:|---:|---:|---:|",
            f"| {f['plain_ms']:.3f} ms | {f['forces_ms']:.3f} ms | {f['ratio']:.2f} "
            f"| {f['extra_us_per_1000']:.1f} µs |",
        ]
    g = features.get("gizmos")
    if g:
        out += [
            "",
            f"Gizmos, {g['lines']:,.0f} lines in a frame:",
            "",
            "| record, one call per line | record, one bulk call | draw (headless EGL) |",
            "|---:|---:|---:|",
            f"| {g['record_us_per_line']:.2f} µs per line | {g['bulk_ms']:.3f} ms "
            f"| {g['draw_ms']:.2f} ms |",
        ]
    return out


def feature_targets(features: dict[str, Row]) -> list[tuple[str, float | None, float, str]]:
    """(target, measured, goal, unit) rows, all "at most"."""
    t = features.get("timings", {})
    g = features.get("gizmos", {})
    f = features.get("particle_forces", {})
    return [
        ("per-system timer overhead per timed system run", t.get("overhead_us_per_system"),
         2.0, "µs"),
        ("recording a gizmo line", g.get("record_us_per_line"), 5.0, "µs"),
        ("particle forces about the origin, extra per 1,000 particles",
         f.get("extra_us_per_1000"), 30.0, "µs"),
    ]  # fmt: skip


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args(argv)
    features, why = run_features(args.quick, lambda s: print(s, file=sys.stderr))
    print("\n".join(feature_lines(features)))
    if why:
        print(why, file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
