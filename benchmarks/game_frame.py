"""The game frame: game-thread CPU per frame of the ``game-frame`` testbed sample, by system.

The sample (:mod:`kge.testbed.samples.game_frame`: a 200 x 50 Tiled level, 300 bodies
with sprites, 30 animated sprites, ~2,780 particles, 4 lights, a 10-widget HUD) runs
headless on EGL at 960 x 540, one fixed step and one ``app.render()`` per frame, after
a warm-up that lets the bodies settle. Every figure is ``time.thread_time()`` of the
game thread (llvmpipe rasterises on worker threads, which a GPU would do; what is
left here is what the game's own thread pays), median ms per frame:

* the schedule's per-system timings (``enable_timings(time.thread_time)``), with the
  render system split into its passes (``tilemap``, ``animation``, ``particles``
  uploads; ``lighting``; ``ui``), the world batch's draw call (``gl_submit``: the
  sprites, tiles and particles handed to GL) and the rest (``render_other``: pose
  blending, sprite sync, cameras);
* inside physics: ``ccd`` (the continuous-collision screening before each step and
  the speed clamp after it) beside ``pymunk_step`` (pymunk's own ``Space.step``
  calls, the CCD's armed sweeps included: they run inside it);
* ``hud_syncs``: UI widgets re-synced over the timed frames (0: an unchanged HUD
  costs nothing).

Run ``python benchmarks/game_frame.py`` for the table; :func:`measure` is what
``kge bench`` calls (``quick``: a few frames, for the test suite).
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from collections import defaultdict
from collections.abc import Callable
from typing import Any

os.environ.setdefault("PYGLET_HEADLESS", "1")

if __package__ in (None, ""):  # run as a script: make the repository importable
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

SIZE = (960, 540)
#: game-thread CPU per frame, at most (issue 36)
FRAME_GOAL_MS = 5.0
#: the groups of the breakdown, in the order printed: (row, schedule systems and
#: sub-timers summed into it)
GROUPS: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("physics", ("PhysicsSystem", "PhysicsEventDelivery", "CharacterSensorSystem",
                 "CharacterSystem", "ParticleTriggers")),
    ("particles", ("ParticleSystem", "pass:particles")),
    ("animation", ("AnimationSystem", "TileAnimationSystem", "TweenSystem",
                   "pass:animation")),
    ("tilemap", ("pass:tilemap",)),
    ("lights", ("pass:lighting",)),
    ("ui", ("UIInput", "pass:ui")),
    ("gl_submit", ("gl_submit",)),
    ("render_other", ("render_other",)),
    ("recording", ("RenderStepRecorder", "RenderStepClock")),
)  # fmt: skip

Clock = Callable[[], float]


class _Acc:
    """Seconds per named timer in the current frame."""

    def __init__(self) -> None:
        self.now: dict[str, float] = defaultdict(float)

    def wrap(self, name: str, fn: Callable[..., Any], clock: Clock = time.thread_time
             ) -> Callable[..., Any]:  # fmt: skip
        now = self.now

        def timed(*args: Any, **kwargs: Any) -> Any:
            t0 = clock()
            try:
                return fn(*args, **kwargs)
            finally:
                now[name] += clock() - t0

        return timed


def _instrument(app: Any, acc: _Acc) -> None:
    """Sub-timers: each render pass, the world batch's draw, CCD and pymunk's step."""
    from kge.render.passes import RenderPasses
    from kge.systems.physics import PhysicsSystem
    from kge.systems.render import RenderSystem

    world = app.world
    passes = world.resource(RenderPasses)
    for entry in passes._entries:
        entry.fn = acc.wrap(f"pass:{entry.name}", entry.fn)
    render = world.get_system(RenderSystem)
    assert render is not None
    batch = render.view.batch
    batch.draw = acc.wrap("gl_submit", batch.draw)
    physics = world.get_system(PhysicsSystem)
    assert physics is not None
    sim = physics.sim
    if sim.ccd is not None:
        sim.ccd.before_step = acc.wrap("ccd", sim.ccd.before_step)
        sim.ccd.after_step = acc.wrap("ccd", sim.ccd.after_step)
    sim.space.step = acc.wrap("pymunk_step", sim.space.step)


def _app(quick: bool) -> Any:
    from kge import App
    from kge.testbed import get_sample

    sample = get_sample("game-frame")
    app = App(sample.setup, headless=True, size=SIZE)
    for _ in range(30 if quick else 240):  # the bodies settle; emitters are prewarmed
        app.step(1)
    app.render()
    app.step(1)
    app.render()
    return app


def measure(quick: bool = False, frames: int = 90) -> dict[str, Any]:
    """Median game-thread ms per frame: total, each group, ``ccd``, ``pymunk_step``."""
    from pyglet import gl

    from kge.components.particles import ParticleEmitter
    from kge.particles import Particles
    from kge.render.ui import drawer_for

    app = _app(quick)
    frames = 4 if quick else frames
    world = app.world
    timings = world.schedule.enable_timings(time.thread_time)
    acc = _Acc()
    _instrument(app, acc)
    drawer = drawer_for(world)
    syncs = drawer.syncs
    per: dict[str, list[float]] = defaultdict(list)
    for _ in range(frames):
        acc.now.clear()
        before = {r.name: r.total for r in timings.rows()}
        t0 = time.thread_time()
        app.step(1)
        app.render()
        total = time.thread_time() - t0
        gl.glFinish()  # llvmpipe's workers finish this frame before the next one's timing
        # ms per system in this frame (totals are seconds since timings were enabled)
        by = {r.name: (r.total - before.get(r.name, 0.0)) * 1e3 for r in timings.rows()}
        subs = {k: v * 1e3 for k, v in acc.now.items()}
        passes = sum(v for k, v in subs.items() if k.startswith("pass:"))
        names = set(by)
        by.update(subs)
        by["render_other"] = by.get("RenderSystem", 0.0) - passes - subs.get("gl_submit", 0.0)
        for name, members in GROUPS:
            per[name].append(sum(by.get(m, 0.0) for m in members))
        listed = {m for _, members in GROUPS for m in members} | {"RenderSystem"}
        per["other_systems"].append(sum(v for k, v in by.items() if k in names
                                        and k not in listed))  # fmt: skip
        per["total"].append(total * 1e3)
        per["ccd"].append(subs.get("ccd", 0.0))
        per["pymunk_step"].append(subs.get("pymunk_step", 0.0))
    out: dict[str, Any] = {k: round(statistics.median(v), 4) for k, v in per.items()}
    particles = world.resource(Particles)
    out["particles_live"] = sum(particles.state(e).pool.count
                                for e, _ in world.query(ParticleEmitter))  # fmt: skip
    out["hud_syncs"] = drawer.syncs - syncs
    out["frames"] = frames
    app.close()
    return out


def targets(game: dict[str, Any]) -> list[tuple[str, float | None, float, bool, str]]:
    """(what, value, goal, at_most, unit) rows of ``kge bench``'s targets."""
    if not game:
        return []
    ratio = game["ccd"] / game["pymunk_step"] if game.get("pymunk_step") else None
    return [
        ("game frame, game-thread CPU per frame (game-frame sample)", game["total"],
         FRAME_GOAL_MS, True, "ms"),
        ("game frame, UI widgets re-synced per frame (unchanged HUD)",
         game["hud_syncs"] / max(game["frames"], 1), 0.0, True, ""),
        ("game frame, CCD screening / pymunk's step", ratio, 1.0, True, ""),
    ]  # fmt: skip


def lines(game: dict[str, Any]) -> list[str]:
    """The breakdown as markdown."""
    if not game:
        return []
    names = [n for n, _ in GROUPS] + ["other_systems"]
    return [
        "", "Game frame (game-frame sample, 960 x 540, headless EGL), game-thread CPU ms per "
        "frame (median; physics includes ccd and pymunk_step):", "",
        "| total | " + " | ".join(names) + " | ccd | pymunk_step | particles live | HUD syncs |",
        "|" + "---:|" * (len(names) + 5),
        f"| {game['total']:.2f} | " + " | ".join(f"{game[n]:.3f}" for n in names)
        + f" | {game['ccd']:.3f} | {game['pymunk_step']:.3f} | {game['particles_live']} "
        f"| {game['hud_syncs']} |",
    ]  # fmt: skip


def run_section(quick: bool, progress: Callable[[str], None]) -> tuple[dict[str, Any], str | None]:
    """What ``kge bench`` calls: the figures, or why they could not be measured."""
    progress("game frame [game-frame sample]")
    try:
        return measure(quick), None
    except Exception as err:  # no GL (headless EGL missing): report, do not fail the run
        return {}, f"game frame skipped: {type(err).__name__}: {err}"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n")[0])
    parser.add_argument("--frames", type=int, default=90)
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args(argv)
    game = measure(args.quick, args.frames)
    print("\n".join(lines(game)))
    for what, value, goal, at_most, unit in targets(game):
        met = value is not None and (value <= goal if at_most else value >= goal)
        print(f"  {what}: {value if value is None else round(value, 3)} {unit} "
              f"(goal {'<=' if at_most else '>='} {goal:g}) {'met' if met else 'missed'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
