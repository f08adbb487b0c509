"""Game-layer features that cost per frame: the ``features`` rows of ``kge bench``.

* ``timings``: per-system timers. An App with the default plugins and 40 extra
  trivial UPDATE systems runs frames with timings off and on, interleaved; the
  overhead is reported per timed system run (µs), and as a share of the frame.
* ``gizmos``: recording N debug lines in a frame (``Gizmos.line``, µs per line; and
  one bulk ``Gizmos.lines`` call), and the frame's draw with them (headless EGL).
* ``particle_forces``: one step of N particles, plain (gravity and drag) and with
  the forces about the origin (radial, tangential, orbit), side by side.

* ``particle_turbulence``: the curl-noise field on N particles (the velocity update
  of :class:`~kge.systems.particle_turbulence.ParticleTurbulenceSystem`) beside the
  plain step of the same particles.

* ``particle_subemitters``: an emitter kept at N live particles (N births and deaths
  a second) whose every death sprays 4 particles of a sub-emitter, beside the same
  emitter without it: the particle update, the effects pass and the sub-emitter's own
  particles per frame.

* ``particle_trails``: N live particles with 12-point trails: the ring-buffer
  sampling (the effects system) and the strips' vertex write (the trail drawer), per
  frame, beside the particles' own update and quad upload.

Other sections (audio effects) join this module as they land.
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


def measure_particle_turbulence(n: int = 5000, repeats: int = 15) -> Row:
    """ms per frame of the turbulence field on ``n`` particles beside their plain step."""
    from kge.particles.pool import ParticlePool
    from kge.particles.turbulence import curl

    rng = np.random.default_rng(3)
    pool = ParticlePool(max_particles=n)
    pool.add(rng.uniform(-5, 5, (n, 2)), rng.uniform(-1, 1, (n, 2)), np.full(n, 1e9),
             np.zeros(n), np.zeros(n))  # fmt: skip

    def field() -> None:
        acc = curl(pool.pos[:n], 1.5, 0.7, 0.5, 4)
        acc *= np.float32(2.0 / 60)
        pool.data[2:4, :n] += acc.T

    plain, noise = [], []
    for _ in range(repeats):  # interleaved
        plain.append(_median_ms(lambda: pool.step(1 / 60, (0.0, -9.8), 0.5), 1))
        noise.append(_median_ms(field, 1))
    p, t = statistics.median(plain), statistics.median(noise)
    return {"particles": float(n), "plain_ms": p, "turbulence_ms": t,
            "us_per_1000": t * 1e3 / (n / 1000)}  # fmt: skip


def _frame_systems(subs: bool, n: int) -> tuple[Any, list[Any]]:
    """An App with an emitter of ``n`` live particles (and a death sub-emitter), and the
    particle systems of its frame."""
    from kge import App, ParticleSubEmitters, SubEmitEvent, SubEmitter, Transform
    from kge.components.particles import ParticleEmitter
    from kge.systems.particle_effects import ParticleEffectsSystem
    from kge.systems.particles import ParticleSystem

    def scene(world: Any) -> None:
        kids = world.spawn(Transform(), ParticleEmitter(
            emitting=False, speed=(1.0, 2.0), spread=6.28, lifetime=0.25, max_particles=4 * n,
            seed=2))  # fmt: skip
        extra = (ParticleSubEmitters(SubEmitter(kids, SubEmitEvent.DEATH, count=4,
                                                inherit_velocity=0.5)),) if subs else ()
        world.spawn(Transform(), ParticleEmitter(
            rate=float(n), lifetime=(0.8, 1.2), speed=(2.0, 5.0), spread=1.2,
            acceleration=(0.0, -9.8), max_particles=2 * n, prewarm=1.0, seed=1), *extra)

    app = App(scene, headless=True)
    app.step(30)
    world = app.world
    return app, [world.get_system(ParticleSystem), world.get_system(ParticleEffectsSystem)]


def measure_particle_subemitters(n: int = 3000, repeats: int = 15) -> Row:
    """ms per frame of the particle systems for ``n`` live particles with and without a
    death sub-emitter (4 particles per death)."""
    from kge.particles import Particles

    plain_app, plain = _frame_systems(False, n)
    subs_app, subs = _frame_systems(True, n)
    times: dict[str, list[float]] = {"plain": [], "subs": []}
    for _ in range(repeats):  # interleaved
        for name, systems in (("plain", plain), ("subs", subs)):
            t0 = time.perf_counter()
            for system in systems:
                system.process(1 / 60)
            times[name].append((time.perf_counter() - t0) * 1e3)
    particles = subs_app.world.resource(Particles)
    out = {"particles": float(particles.count(2)), "spawned": float(particles.count(1)),
           "plain_ms": statistics.median(times["plain"]),
           "subs_ms": statistics.median(times["subs"])}  # fmt: skip
    out["extra_ms"] = max(out["subs_ms"] - out["plain_ms"], 0.0)
    plain_app.close()
    subs_app.close()
    return out


def measure_particle_trails(n: int = 3000, points: int = 12, repeats: int = 15) -> Row:
    """ms per frame for ``n`` particles with ``points``-point trails: sampling and
    strip upload, beside the particles' own update and quad upload."""
    from kge import App, ParticleTrail, Transform
    from kge.components.particles import ParticleEmitter
    from kge.particles import Particles
    from kge.render.particle_trails import TrailDrawer
    from kge.render.particles import ParticleDrawer
    from kge.systems.particle_effects import ParticleEffectsSystem
    from kge.systems.particles import ParticleSystem
    from kge.systems.render import RenderSystem

    def scene(world: Any) -> None:
        world.spawn(Transform(), ParticleEmitter(
            rate=float(n), lifetime=1.0, speed=(2.0, 5.0), spread=1.2, acceleration=(0.0, -9.8),
            max_particles=n + n // 10, prewarm=1.0, seed=1),
            ParticleTrail(duration=0.4, points=points, width=(0.1, 0.0)))  # fmt: skip

    app = App(scene, headless=True, size=(320, 180))
    app.step(1)
    app.render()
    world = app.world
    update, effects = world.get_system(ParticleSystem), world.get_system(ParticleEffectsSystem)
    view = world.get_system(RenderSystem)
    assert update is not None and effects is not None and view is not None
    quads = ParticleDrawer(world, view.view.batch, view.view.groups)
    strips = TrailDrawer(world, view.view.batch, view.view.groups)
    st = world.resource(Particles).state(1)
    em, trail = world.get(1, ParticleEmitter), world.get(1, ParticleTrail)
    times: dict[str, list[float]] = {"update": [], "upload": [], "record": [], "strips": []}
    for _ in range(repeats):
        marks = [time.perf_counter()]
        update.process(1 / 60)
        marks.append(time.perf_counter())
        quads.upload(1, em, st)
        marks.append(time.perf_counter())
        effects.process(1 / 60)
        marks.append(time.perf_counter())
        strips.upload(1, em, st, trail)
        marks.append(time.perf_counter())
        for key, a, b in zip(times, marks, marks[1:], strict=False):
            times[key].append((b - a) * 1e3)
    out = {k: statistics.median(v) for k, v in times.items()}
    out["particles"] = float(st.pool.count)
    out["points"] = float(points)
    quads.close()
    strips.close()
    app.close()
    return out


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
        progress("particle turbulence")
        out["particle_turbulence"] = measure_particle_turbulence(1000 if quick else 5000, repeats)
        progress("particle sub-emitters")
        out["particle_subemitters"] = measure_particle_subemitters(600 if quick else 3000,
                                                                   repeats)  # fmt: skip
        progress("particle trails")
        out["particle_trails"] = measure_particle_trails(600 if quick else 3000, 12, repeats)
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
    tb = features.get("particle_turbulence")
    if tb:
        out += [
            "",
            f"Particle turbulence (curl noise), {tb['particles']:,.0f} particles, per frame:",
            "",
            "| plain step (gravity, drag) | turbulence field | per 1,000 particles |",
            "|---:|---:|---:|",
            f"| {tb['plain_ms']:.3f} ms | {tb['turbulence_ms']:.3f} ms "
            f"| {tb['us_per_1000']:.1f} µs |",
        ]
    se = features.get("particle_subemitters")
    if se:
        out += [
            "",
            f"Particle sub-emitters, {se['particles']:,.0f} live particles whose every death "
            f"sprays 4 (a pool of {se['spawned']:,.0f}), particle systems per frame:",
            "",
            "| without sub-emitters | with | extra |",
            "|---:|---:|---:|",
            f"| {se['plain_ms']:.3f} ms | {se['subs_ms']:.3f} ms | {se['extra_ms']:.3f} ms |",
        ]
    tr = features.get("particle_trails")
    if tr:
        out += [
            "",
            f"Particle trails, {tr['particles']:,.0f} live particles with {tr['points']:.0f}-point "
            "trails, median ms per frame:",
            "",
            "| particles: update | particles: quad upload | trails: sampling | trails: strip "
            "upload |",
            "|---:|---:|---:|---:|",
            f"| {tr['update']:.3f} | {tr['upload']:.3f} | {tr['record']:.3f} "
            f"| {tr['strips']:.3f} |",
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
