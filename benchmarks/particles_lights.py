"""Particles and light shadows per frame: the game-layer rows of ``kge bench``.

* ``particles``: one emitter kept at N live particles (births and deaths every
  frame: rate N/s, lifetime 1 s, gravity, drag, size/colour/alpha curves), timed
  per frame as ``update`` (:class:`~kge.systems.particles.ParticleSystem`: the
  vectorised integration, deaths, births) and ``upload`` (writing centres, sizes,
  angles and colours into the emitter's vertex list), plus a whole headless
  ``app.render()`` for reference (llvmpipe rasterising N quads; a GPU does that
  part in hardware). The goal is update + upload <= 5 ms at 50,000.

* ``shadows``: the CPU side of the shadows of 16 shadowed lights over 300 occluder
  edges (75 boxes), per frame: ``static`` gathers the cached static edges and builds
  their penumbra-wedge vertices (one set, extruded for each light on the GPU; the
  goal: <= 2 ms); ``casters`` does the same with the 75 boxes marked
  ``ShadowCaster``, so their edges are re-gathered at their current pose every
  frame; ``render`` is a whole headless frame with the light map.

* ``arcade``: Arcade 3's particle system on the same workload at 5,000
  particles (its own virtual environment, ``KGE_ARCADE_PYTHON`` names its
  interpreter; :mod:`benchmarks.arcade_particles` runs there), beside kge at
  5,000 measured in the same run: the ratio is Arcade's update + vertex write
  over kge's (goal >= 20x). Without that variable the row says why it is missing.

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

import numpy as np

PARTICLE_SIZES = (10_000, 50_000)


def _finish() -> None:
    from pyglet import gl

    gl.glFinish()


def _particle_app(n: int) -> tuple[Any, int]:
    from kge import App, Transform
    from kge.components.particles import Blend, EmitCircle, ParticleEmitter

    def scene(world: Any) -> None:
        world.spawn(Transform(0.0, -2.0), ParticleEmitter(
            rate=float(n), lifetime=1.0, speed=(2.0, 5.0), spread=1.2,
            acceleration=(0.0, -9.8), drag=0.3, spin=(-2.0, 2.0), shape=EmitCircle(0.5),
            size=(0.05, 0.12, 0.0), color=((255, 240, 120), (255, 80, 0)), opacity=(255, 0),
            blend=Blend.ADDITIVE, max_particles=n + n // 10, prewarm=1.0, seed=1,
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
        _finish()  # llvmpipe draws on worker threads: let it end before the next timing
        samples["render"].append((time.perf_counter() - t0) * 1e3)
    drawer.close()
    app.close()
    out = {k: statistics.median(v) for k, v in samples.items()}
    out["live"] = float(statistics.median(live))
    out["us_per_particle"] = out["total"] * 1e3 / max(out["live"], 1.0)
    return out


SHADOW_LIGHTS, SHADOW_BOXES = 16, 75


def _shadow_app(casters: bool) -> Any:
    from kge import App, Collider, Transform
    from kge.components.camera import Camera
    from kge.components.lights import Light, Lighting, ShadowCaster
    from kge.components.shapes import Box

    rng = np.random.default_rng(3)

    def scene(world: Any) -> None:
        world.insert_resource(Camera(pixels_per_meter=16))
        world.insert_resource(Lighting(ambient=(30, 30, 40)))
        for x, y, a in rng.uniform((-14, -8, 0), (14, 8, 3), (SHADOW_BOXES, 3)):
            extra = (ShadowCaster(),) if casters else ()
            world.spawn(Transform(float(x), float(y), float(a)), Collider(Box(0.4, 0.3)), *extra)
        for x, y in rng.uniform((-14, -8), (14, 8), (SHADOW_LIGHTS, 2)):
            world.spawn(Transform(float(x), float(y)), Light(radius=8.0, shadows=True))

    return App(scene, headless=True, size=(480, 270))


def measure_shadows(repeats: int = 30) -> dict[str, float]:
    """Median ms per frame of the shadow geometry (static and caster occluders), a render."""
    from kge.lighting import Occluders
    from kge.render.lighting import wedge_rows

    out: dict[str, float] = {}
    for name in ("static", "casters"):
        app = _shadow_app(casters=name == "casters")
        app.step(1)
        world = app.world
        occluders = world.resource(Occluders)
        times, vertices = [], 0
        for _ in range(repeats):
            t0 = time.perf_counter()
            edges, closed = occluders.edges(world, True)
            rows = wedge_rows(edges, closed)
            times.append((time.perf_counter() - t0) * 1e3)
            vertices = len(rows)
        out[name] = statistics.median(times)
        out[f"{name}_edges"] = float(len(edges))
        out[f"{name}_quads"] = float(vertices // 6)  # one wedge per edge, for every light
        if name == "static":
            renders = []
            for _ in range(max(3, repeats // 5)):
                t0 = time.perf_counter()
                app.render()
                _finish()
                renders.append((time.perf_counter() - t0) * 1e3)
            out["render"] = statistics.median(renders)
        app.close()
    return out


ARCADE_SIZE = 5_000


def measure_arcade(n: int, repeats: int) -> dict[str, float] | str:
    """Arcade's row (run in its own venv) next to kge's at ``n``, or why it could not run."""
    import json
    import subprocess

    python = os.environ.get("KGE_ARCADE_PYTHON")
    if not python:
        return "KGE_ARCADE_PYTHON is not set (Arcade 3 lives in a venv of its own)"
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "arcade_particles.py")
    env = {**os.environ, "PYGLET_HEADLESS": "1", "ARCADE_HEADLESS": "1"}
    env.pop("PYTHONPATH", None)
    done = subprocess.run([python, script, str(n), str(repeats)], capture_output=True,
                          text=True, env=env, timeout=600, check=False)  # fmt: skip
    if done.returncode != 0:
        return f"arcade run failed: {done.stderr.strip().splitlines()[-1:]}"
    arcade = json.loads(done.stdout)
    kge = measure_particles(n, repeats)
    return {
        "arcade_update": arcade["update"], "arcade_upload": arcade["upload"],
        "arcade_total": arcade["total"], "arcade_live": arcade["live"],
        "kge_total": kge["total"], "kge_live": kge["live"],
        "ratio": arcade["total"] / kge["total"],
    }  # fmt: skip


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
        progress(f"shadows [{SHADOW_LIGHTS} lights, {SHADOW_BOXES * 4} edges]")
        out["shadows"] = {str(SHADOW_LIGHTS): measure_shadows(repeats)}
        arcade_n = 500 if quick else ARCADE_SIZE
        progress(f"arcade 3 particles [{arcade_n}]")
        arcade = measure_arcade(arcade_n, repeats)
        if isinstance(arcade, str):
            return out, f"arcade comparison skipped: {arcade}"
        out["arcade"] = {str(arcade_n): arcade}
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
    for lights, r in game.get("shadows", {}).items():
        out += [
            "",
            f"Shadow geometry, {lights} shadowed lights over {r['static_edges']:.0f} "
            "occluder edges, median ms per frame (gather the edges, build their wedge vertices; "
            "the GPU extrudes them for every light):",
            "",
            "| occluders | ms | wedges |",
            "|---|---:|---:|",
            f"| static colliders (cached) | {r['static']:.3f} | {r['static_quads']:.0f} |",
            f"| ShadowCaster bodies (gathered every frame) | {r['casters']:.3f} "
            f"| {r['casters_quads']:.0f} |",
            "",
            f"Whole headless frame with the light map (llvmpipe): {r['render']:.1f} ms.",
        ]
    return out + arcade_lines(game)


def arcade_lines(game: dict[str, dict[str, Row]]) -> list[str]:
    out = []
    for n, r in game.get("arcade", {}).items():
        out += [
            "",
            f"Arcade 3 particles beside kge, {int(n):,} live, same workload, same run "
            "(update + vertex write, median ms per frame):",
            "",
            "| engine | live | ms | |",
            "|---|---:|---:|---:|",
            f"| Arcade 3 | {r['arcade_live']:,.0f} | {r['arcade_total']:.2f} | |",
            f"| kge | {r['kge_live']:,.0f} | {r['kge_total']:.2f} | {r['ratio']:.0f}x |",
        ]
    return out


def game_targets(game: dict[str, dict[str, Row]]) -> list[tuple[str, float | None, float, str]]:
    """(target, measured, goal, unit) rows, all "at most"."""
    big = game.get("particles", {}).get(str(max(PARTICLE_SIZES)))
    shadows = game.get("shadows", {}).get(str(SHADOW_LIGHTS))
    return [
        ("50,000 live particles, update + upload per frame",
         None if big is None else big["total"], 5.0, "ms"),
        (f"shadow geometry (CPU), {SHADOW_LIGHTS} lights over {SHADOW_BOXES * 4} edges per frame",
         None if shadows is None else shadows["static"], 2.0, "ms"),
    ]  # fmt: skip


def game_ratios(game: dict[str, dict[str, Row]]) -> list[tuple[str, float | None, float, str]]:
    """(target, measured, goal, unit) rows, all "at least"."""
    arcade = game.get("arcade", {}).get(str(ARCADE_SIZE))
    return [
        (
            f"Arcade 3 / kge particles at {ARCADE_SIZE:,} (update + upload)",
            None if arcade is None else arcade["ratio"],
            20.0,
            "x",
        )
    ]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=list(PARTICLE_SIZES))
    parser.add_argument("--repeats", type=int, default=30)
    args = parser.parse_args(argv)
    game: dict[str, dict[str, Row]] = {"particles": {}}
    for n in args.sizes:
        game["particles"][str(n)] = measure_particles(n, args.repeats)
    game["shadows"] = {str(SHADOW_LIGHTS): measure_shadows(args.repeats)}
    arcade = measure_arcade(ARCADE_SIZE, args.repeats)
    if isinstance(arcade, str):
        print(f"arcade comparison skipped: {arcade}")
    else:
        game["arcade"] = {str(ARCADE_SIZE): arcade}
    print("\n".join(game_lines(game)))
    for what, value, goal, unit in game_targets(game):
        shown = "not measured" if value is None else f"{value:.3f} {unit}"
        print(f"{what}: {shown} (goal <= {goal:g} {unit})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
