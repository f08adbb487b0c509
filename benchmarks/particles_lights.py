"""Particles and light shadows per frame: the game-layer rows of ``kge bench``.

* ``particles``: one emitter kept at N live particles (births and deaths every
  frame: rate N/s, lifetime 1 s, gravity, drag, size/colour/alpha curves), timed
  per frame as ``update`` (:class:`~kge.systems.particles.ParticleSystem`: the
  vectorised integration, deaths, births) and ``upload`` (writing centres, sizes,
  angles and colours into the emitter's vertex list), plus a whole headless
  ``app.render()`` for reference (llvmpipe rasterising N quads; a GPU does that
  part in hardware). The goal is update + upload <= 5 ms at 50,000.

Timings are medians of interleaved repetitions, reported, never asserted. Run
``python benchmarks/particles_lights.py`` for the table; :func:`measure_particles`
with a small N is what the test suite calls.
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from typing import Any

os.environ.setdefault("PYGLET_HEADLESS", "1")

if __package__ in (None, ""):  # run as a script: make the repository importable
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

PARTICLE_SIZES = (10_000, 50_000)


def _particle_app(n: int) -> tuple[Any, int]:
    from kge import App, Transform
    from kge.components.particles import EmitCircle, ParticleEmitter

    def scene(world: Any) -> None:
        world.spawn(Transform(0.0, -2.0), ParticleEmitter(
            rate=float(n), lifetime=1.0, speed=(2.0, 5.0), spread=1.2,
            acceleration=(0.0, -9.8), drag=0.3, spin=(-2.0, 2.0), shape=EmitCircle(0.5),
            size=(0.05, 0.12, 0.0), color=((255, 240, 120), (255, 80, 0)), alpha=(1.0, 0.0),
            blend="additive", max_particles=n + n // 10, prewarm=1.0, seed=1,
        ))  # fmt: skip

    app = App(scene, headless=True, size=(480, 270))
    app.step(1)
    emitter = next(e for e, _ in app.world.query(ParticleEmitter))
    return app, emitter


def measure_particles(n: int, repeats: int = 30) -> dict[str, float]:
    """Median ms per frame for ``n`` live particles: update, upload, their sum, a render."""
    from kge.components.particles import ParticleEmitter
    from kge.particles import Particles
    from kge.render.particles import ParticleDrawer
    from kge.systems.particles import ParticleSystem
    from kge.systems.render import RenderSystem

    app, emitter = _particle_app(n)
    app.render()
    world = app.world
    system = world.get_system(ParticleSystem)
    view = world.get_system(RenderSystem)
    assert system is not None and view is not None
    drawer = ParticleDrawer(world, view.view.batch, view.view.groups)
    particles = world.resource(Particles)
    state = particles.state(emitter)
    em = world.get(emitter, ParticleEmitter)
    samples: dict[str, list[float]] = {"update": [], "upload": [], "total": [], "render": []}
    live = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        system.process(1.0 / 60.0)
        t1 = time.perf_counter()
        drawer.upload(emitter, em, state)
        t2 = time.perf_counter()
        samples["update"].append((t1 - t0) * 1e3)
        samples["upload"].append((t2 - t1) * 1e3)
        samples["total"].append((t2 - t0) * 1e3)
        live.append(state.pool.count)
        t0 = time.perf_counter()
        app.render()
        samples["render"].append((time.perf_counter() - t0) * 1e3)
    drawer.close()
    app.close()
    out = {k: statistics.median(v) for k, v in samples.items()}
    out["live"] = float(statistics.median(live))
    out["us_per_particle"] = out["total"] * 1e3 / max(out["live"], 1.0)
    return out


Row = dict[str, float]


def run_game(quick: bool, progress: Any) -> tuple[dict[str, dict[str, Row]], str | None]:
    """The section ``kge bench`` adds: {"particles": {n: row}}, or the reason it failed."""
    try:
        sizes = (2_000,) if quick else PARTICLE_SIZES
        repeats = 3 if quick else 30
        out: dict[str, dict[str, Row]] = {"particles": {}}
        for n in sizes:
            progress(f"particles [{n}]")
            out["particles"][str(n)] = measure_particles(n, repeats)
        return out, None
    except Exception as err:  # no GL (headless EGL missing): report, do not fail the run
        return {}, f"particles/lights skipped: {type(err).__name__}: {err}"


def game_lines(game: dict[str, dict[str, Row]]) -> list[str]:
    """Markdown lines of the section (for bench.md)."""
    out = ["", "Particles, median ms per frame (update = integrate, age, births and deaths; "
           "upload = vertex write; render = a whole headless frame, llvmpipe):", "",
           "| live | update | upload | update + upload | µs per particle | render |",
           "|---:|---:|---:|---:|---:|---:|"]  # fmt: skip
    for _, r in sorted(game.get("particles", {}).items(), key=lambda kv: int(kv[0])):
        out.append(f"| {r['live']:,.0f} | {r['update']:.2f} | {r['upload']:.2f} | {r['total']:.2f}"
                   f" | {r['us_per_particle']:.3f} | {r['render']:.1f} |")  # fmt: skip
    return out


def game_targets(game: dict[str, dict[str, Row]]) -> list[tuple[str, float | None, float, str]]:
    """(target, measured, goal, unit) rows, all "at most"."""
    big = game.get("particles", {}).get(str(max(PARTICLE_SIZES)))
    return [
        ("50,000 live particles, update + upload per frame",
         None if big is None else big["total"], 5.0, "ms"),
    ]  # fmt: skip


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=list(PARTICLE_SIZES))
    parser.add_argument("--repeats", type=int, default=30)
    args = parser.parse_args(argv)
    print("particles, median ms per frame")
    cols = ("live", "update", "upload", "total", "us_per_particle", "render")
    print(f"{'n':>8} " + " ".join(f"{c:>16}" for c in cols))
    for n in args.sizes:
        r = measure_particles(n, args.repeats)
        print(f"{n:>8} " + " ".join(f"{r[c]:>16.3f}" for c in cols))
    return 0


if __name__ == "__main__":
    sys.exit(main())
