"""Where a kge frame's time and a body's memory go, finer than ``--breakdown``.

``python -m benchmarks.where`` (or ``python benchmarks/where.py``) writes
``benchmarks/results/where.json``: for each scene of the kge / raw pymunk targets,
the median ms per frame of every physics piece (timers wrapped around the
pieces *on the instances*, so kge carries no timing code), raw pymunk's step on
the same scene beside it, and per-body figures; then the spawn frame by module
(cProfile), memory per body by module (tracemalloc, in its own interpreter) and
the floors the sync-out design rests on (slot stores per body against a thin
view's column copy and its read cost).

Run it on a quiet machine for absolute figures; under load compare within a row.
"""

from __future__ import annotations

import argparse
import cProfile
import gc
import json
import os
import platform
import pstats
import random
import statistics
import subprocess
import sys
import time
from collections import deque
from pathlib import Path
from typing import Any

os.environ.setdefault("PYGLET_HEADLESS", "1")
if __package__ in (None, ""):  # run as a script: make the repository importable
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

import numpy as np

#: (bench scene name, testbed sample, size parameter, size, extra sample arguments)
SCENES: tuple[tuple[str, str, str, int, dict[str, Any]], ...] = (
    ("sparse", "sparse-field", "count", 20000, {}),
    ("rain", "rain", "count", 5000, {}),
    ("pyramid", "pyramid", "rows", 40, {}),
    ("dense-pile", "box-pile", "count", 6000, {"sleep": False}),
    ("chain", "chains", "count", 200, {"links": 40}),
    ("joint-grid", "joint-grid", "side", 100, {}),
)

#: the pieces timed, as (attribute path from the Simulation, method, name)
PIECES = (
    ("", "sync_in", "sync_in"),
    ("", "sync_out", "sync_out"),
    ("", "step", "frame_physics"),
    ("space", "step", "pymunk_step"),
    ("poses", "read", "sync_out.bulk_read"),
    ("", "_write_velocities", "sync_out.write_velocities"),
    ("_speed_cap", "before_substep", "speed_cap"),
    ("ccd", "before_step", "ccd_screen"),
    ("joints", "before_step", "joints.before_step"),
    ("joints", "after_step", "joints.after_step"),
    ("contact_first", "solve", "contact_first"),
    ("recorder", "deliver_post_solve", "events.post_solve"),
)


def scene_profile(slug: str, param: str, size: int, extra: dict[str, Any],
                  frames: int) -> dict[str, Any]:
    """Median ms per piece of ``frames`` kge frames, raw pymunk's step interleaved."""
    from benchmarks.breakdown import timed
    from benchmarks.engines import KgeRunner, PymunkRunner, spec_of
    from kge.physics import simulation
    from kge.systems.physics import PhysicsSystem
    from kge.testbed.registry import get_sample

    sample = get_sample(slug)
    kge = KgeRunner(sample, **{param: size}, **extra)
    raw = PymunkRunner(spec_of(sample, **{param: size}, **extra))
    system = kge.app.world.get_system(PhysicsSystem)
    assert system is not None, f"{slug} has no physics"
    sim = system.sim
    acc: dict[str, float] = {}
    for path, method, key in PIECES:
        owner = getattr(sim, path) if path else sim
        if owner is not None:
            setattr(owner, method, timed(acc, getattr(owner, method), key))
    write_poses = simulation.write_poses
    simulation.write_poses = timed(acc, write_poses, "sync_out.write_poses")
    rows: list[dict[str, float]] = []
    raw_ms: list[float] = []
    try:
        for _ in range(5):
            kge.step()
            raw.step()
        gc.collect()
        gc.disable()
        for _ in range(frames):
            acc.clear()
            t0 = time.perf_counter()
            kge.step()
            total = time.perf_counter() - t0
            t0 = time.perf_counter()
            raw.step()
            raw_ms.append((time.perf_counter() - t0) * 1000.0)
            row = {k: v * 1000.0 for k, v in acc.items()}
            row["frame"] = total * 1000.0
            rows.append(row)
    finally:
        gc.enable()
        simulation.write_poses = write_poses
    bodies = len(sim.poses.ids)
    kge.close()
    keys = sorted({k for r in rows for k in r})
    med = {k: statistics.median(r.get(k, 0.0) for r in rows) for k in keys}
    parts = ("sync_out.bulk_read", "sync_out.write_poses", "sync_out.write_velocities")
    med["sync_out.rest"] = med.get("sync_out", 0.0) - sum(med.get(k, 0.0) for k in parts)
    inside = ("sync_in", "sync_out", "pymunk_step", "speed_cap", "ccd_screen",
              "joints.before_step", "joints.after_step", "contact_first", "events.post_solve")
    med["frame_physics.rest"] = med.get("frame_physics", 0.0) - sum(med.get(k, 0.0)
                                                                     for k in inside)
    med["frame.outside_physics"] = med["frame"] - med.get("frame_physics", 0.0)
    pymunk_ms = statistics.median(raw_ms)
    return {
        "moving_bodies": bodies,
        "frames": frames,
        "median_ms": {k: round(v, 4) for k, v in sorted(med.items())},
        "raw_pymunk_frame_ms": round(pymunk_ms, 4),
        "kge_over_raw": round(med["frame"] / pymunk_ms, 3),
        "us_per_moving_body": {
            k: round(med.get(k, 0.0) * 1000.0 / max(1, bodies), 4)
            for k in ("sync_out", *parts, "sync_out.rest", "speed_cap")
        },
    }


def spawn_profile(count: int = 1000, waves: int = 6) -> dict[str, Any]:
    """The frame that spawns ``count`` bodies: ms per wave by kge module (cProfile, tottime)."""
    from benchmarks.scenes import KgeSpawn

    spawn = KgeSpawn(count)
    prof = cProfile.Profile()
    total = 0.0
    for _ in range(waves):
        spawn.prepare()
        t0 = time.perf_counter()
        prof.enable()
        spawn.step()
        prof.disable()
        total += time.perf_counter() - t0
    spawn.close()
    by: dict[str, float] = {}
    stats = pstats.Stats(prof).stats  # type: ignore[attr-defined]
    for (path, _line, func), (_cc, _nc, tottime, _ct, _callers) in stats.items():
        by[_module(path, func)] = by.get(_module(path, func), 0.0) + tottime
    ranked = sorted(by.items(), key=lambda kv: -kv[1])[:20]
    return {
        "bodies": count,
        "frame_ms_profiled": round(total * 1000.0 / waves, 3),
        "ms_by_module": {k: round(v * 1000.0 / waves, 3) for k, v in ranked},
    }


def _module(path: str, func: str) -> str:
    if path == "~":
        return f"builtin {func}"
    for root in ("kge/", "pymunk/", "esper/", "numpy/", "benchmarks/"):
        at = path.rfind(root)
        if at >= 0:
            return path[at:]
    return os.path.basename(path)


_MEMORY_SCRIPT = """
import gc, sys, tracemalloc, json
from benchmarks.where import memory_by_module
print(json.dumps(memory_by_module(int(sys.argv[1]))))
"""


def memory_by_module(n: int) -> dict[str, Any]:
    """Python heap per body after building the sparse field of ``n`` bodies, by file."""
    import tracemalloc

    from benchmarks.engines import KgeRunner
    from kge.testbed.registry import get_sample

    sample = get_sample("sparse-field")
    gc.collect()
    tracemalloc.start(1)
    runner = KgeRunner(sample, count=n)
    for _ in range(3):
        runner.step()
    gc.collect()
    snap = tracemalloc.take_snapshot()
    tracemalloc.stop()
    by: dict[str, float] = {}
    for stat in snap.statistics("filename"):
        name = _module(stat.traceback[0].filename, "")
        by[name] = by.get(name, 0.0) + stat.size
    ranked = sorted(by.items(), key=lambda kv: -kv[1])[:15]
    return {
        "bodies": n,
        "python_heap_bytes_per_body": round(sum(by.values()) / n, 1),
        "bytes_per_body_by_file": {k: round(v / n, 1) for k, v in ranked},
    }


def memory_profile(n: int = 10_000) -> dict[str, Any]:
    """:func:`memory_by_module` in a fresh interpreter, beside RSS per body of both engines."""
    from benchmarks.costs import memory_per_body

    out = subprocess.run([sys.executable, "-c", _MEMORY_SCRIPT, str(n)], capture_output=True,
                         text=True, check=True, timeout=600)
    result: dict[str, Any] = json.loads(out.stdout.strip().splitlines()[-1])
    result["rss_bytes_per_body_kge"] = round(memory_per_body("kge", n), 1)
    result["rss_bytes_per_body_pymunk"] = round(memory_per_body("pymunk", n), 1)
    return result


def floors(n: int = 20000, repeats: int = 15) -> dict[str, float]:
    """What writing poses costs per body in each design, and what a read costs.

    * ``slot_stores``: today's sync-out write: three slot stores per body (x, y,
      angle) into Transforms scattered in the heap as a game allocates them;
    * ``column_copy``: a thin-view design's write: three ``tolist`` into Python
      list columns (one C copy per column, no per-object store);
    * ``read_slot`` / ``read_view``: one ``t.x`` read, a slot against a property
      indexing such a column (what every user read would pay in a thin view).
    """
    from kge.components.transform import Transform
    from kge.physics.writeback import set_all, slot_setter

    objs = [Transform(float(i), 0.0, 0.0) for i in range(n)]
    random.Random(1).shuffle(objs)  # game objects are not laid out in slot order
    rows = np.random.default_rng(1).random((n, 6))
    setters = [slot_setter(Transform, f) for f in ("x", "y", "angle")]
    columns: list[list[float]] = [[0.0] * n for _ in range(3)]

    class View:
        __slots__ = ("i",)

        def __init__(self, i: int) -> None:
            self.i = i

        @property
        def x(self) -> float:
            return columns[0][self.i]

    views = [View(i) for i in range(n)]

    def slot_stores() -> None:
        for setter, col in zip(setters, rows[:, :3].T.tolist(), strict=True):
            set_all(setter, objs, col)

    def column_copy() -> None:
        for k, col in enumerate(rows[:, :3].T.tolist()):
            columns[k][:] = col

    def read_slot() -> None:
        deque((t.x for t in objs), maxlen=0)

    def read_view() -> None:
        deque((v.x for v in views), maxlen=0)

    out = {}
    for name, fn in (("slot_stores", slot_stores), ("column_copy", column_copy),
                     ("read_slot", read_slot), ("read_view", read_view)):
        times = []
        for _ in range(repeats):
            t0 = time.perf_counter()
            fn()
            times.append(time.perf_counter() - t0)
        out[f"{name}_ns_per_body"] = round(min(times) * 1e9 / n, 1)
    return out


def frame_floor(frames: int = 300) -> dict[str, float]:
    """Median ms of ``App.step()`` on a world with one dynamic body: the fixed cost of a
    kge frame (every stage and system with nothing to do), which a small scene's
    ratio to raw pymunk cannot go below; raw pymunk's step of that one body beside it."""
    import pymunk

    from kge import App, Circle, Collider, RigidBody, Transform

    def one(world: Any) -> None:
        world.spawn(Transform(0.0, 5.0), RigidBody(), Collider(Circle(0.5)))

    app = App(one, headless=True)
    space = pymunk.Space()
    space.gravity = (0.0, -10.0)
    body = pymunk.Body(1.0, 1.0)
    space.add(body, pymunk.Circle(body, 0.5))
    kge_ms, raw_ms = [], []
    for _ in range(frames):
        t0 = time.perf_counter()
        app.step()
        kge_ms.append((time.perf_counter() - t0) * 1000.0)
        t0 = time.perf_counter()
        for _ in range(4):
            space.step(1.0 / 240.0)
        raw_ms.append((time.perf_counter() - t0) * 1000.0)
    app.close()
    return {"kge_frame_ms": round(statistics.median(kge_ms), 4),
            "raw_pymunk_4_substeps_ms": round(statistics.median(raw_ms), 4)}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n")[0])
    parser.add_argument("--frames", type=int, default=20)
    parser.add_argument("--scene", action="append", help="only these bench scenes")
    parser.add_argument("--out", default=str(Path(__file__).parent / "results" / "where.json"))
    args = parser.parse_args(argv)
    report: dict[str, Any] = {
        "machine": f"{platform.machine()}, {os.cpu_count()} cores, Python "
                   f"{platform.python_version()}",
        "load_average_at_start": os.getloadavg()[0],
        "scenes": {},
    }
    for name, slug, param, size, extra in SCENES:
        if args.scene and name not in args.scene:
            continue
        frames = args.frames if size * (1 if param == "count" else 20) < 30000 else 10
        print(f"  {name}-{size}", file=sys.stderr, flush=True)
        report["scenes"][f"{name}-{size}"] = scene_profile(slug, param, size, extra, frames)
    if not args.scene:
        print("  spawn, memory, floors", file=sys.stderr, flush=True)
        report["spawn"] = spawn_profile()
        report["memory"] = memory_profile()
        report["floors"] = floors()
        report["frame_floor"] = frame_floor()
    report["load_average_at_end"] = os.getloadavg()[0]
    Path(args.out).write_text(json.dumps(report, indent=1) + "\n")
    print(json.dumps(report, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
