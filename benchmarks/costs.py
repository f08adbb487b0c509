"""Per-body costs beside raw pymunk: sync-out, despawn and memory.

The scene table times whole frames; these figures isolate the per-body parts the
issue sets targets for, each measured side by side with raw pymunk in one run:

* ``sync_out_us``: sync-out's time per *moved* body (the sparse field, where
  every body moves every frame), counted from the rows sync-out actually wrote;
* ``sync_in_ms``: sync-in of a frame with no user writes on the same scene (it
  should not grow with the body count);
* ``despawn_ms``: the frame that despawns a 1,000-body wave (the spawn scene's
  ``prepare``), interleaved with raw pymunk removing the same wave;
* ``bytes_per_body``: RSS growth per body while building the sparse field of
  10,000 bodies, each engine in a fresh interpreter (memory a process has freed
  is not given back, so one process cannot measure both).
"""

from __future__ import annotations

import gc
import statistics
import subprocess
import sys
import time
from collections import deque
from typing import Any

from benchmarks.breakdown import PhaseTimer
from benchmarks.engines import PymunkRunner, spec_of
from kge.physics import simulation
from kge.systems.physics import PhysicsSystem
from kge.testbed.registry import get_sample

#: bodies of the sparse field for the memory figure
MEMORY_BODIES = 10_000


def sync_costs(size: int, frames: int) -> dict[str, float]:
    """Sync-out µs per moved body and sync-in ms per frame, on the sparse field."""
    from benchmarks.scenes import scenes

    sparse = next(s for s in scenes() if s.name == "sparse")
    measured: Any = sparse.engines["kge"](size)
    app = measured.runner.app
    app.step(10)
    timer = PhaseTimer(app)
    moved = [0]
    inner = simulation.write_poses

    def counted(targets: Any, slots: Any, new: Any) -> None:
        moved[0] += len(new)
        inner(targets, slots, new)

    simulation.write_poses = counted  # type: ignore[assignment]  # the module's name, which sync-out calls
    per_body = []
    try:
        for _ in range(frames):
            moved[0] = 0
            timer.frame()
            if moved[0]:
                per_body.append(timer.frames[-1]["sync-out"] * 1000.0 / moved[0])
    finally:
        simulation.write_poses = inner
        measured.close()
    return {
        "sync_out_us": statistics.median(per_body) if per_body else float("nan"),
        "sync_out_floor_us": slot_write_floor(size),
        "sync_in_ms": timer.medians()["sync-in"],
        "bodies": float(size),
    }


#: component fields sync-out writes per moved body (Transform x, y, angle;
#: RigidBody velocity, angular_velocity)
FIELDS_PER_BODY = 5


def slot_write_floor(n: int, repeats: int = 9) -> float:
    """µs per body of ``FIELDS_PER_BODY`` bare slot stores, the cheapest way Python
    can write a field of ``n`` slotted objects (each column mapped through the
    slot's C setter, as sync-out does): the floor of any per-object sync-out."""

    class Slotted:
        __slots__ = ("v",)

    objs = [Slotted() for _ in range(n)]
    values = [float(i) for i in range(n)]
    setter = Slotted.v.__set__  # type: ignore[attr-defined]
    best = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        deque(map(setter, objs, values), maxlen=0)
        best.append(time.perf_counter() - t0)
    return statistics.median(best) * 1e6 / n * FIELDS_PER_BODY


def despawn_costs(count: int, repeats: int) -> dict[str, float]:
    """Median ms of the frame that despawns ``count`` bodies, kge and raw pymunk."""
    from benchmarks.scenes import scenes

    spawn = next(s for s in scenes() if s.name == "spawn")
    runners: dict[str, Any] = {e: spawn.engines[e](count) for e in ("kge", "pymunk")}
    times: dict[str, list[float]] = {e: [] for e in runners}
    gc.collect()
    gc.disable()
    try:
        for _ in range(repeats):
            for e, r in runners.items():
                r.step()  # a new wave (untimed here: the scene table times it)
                t0 = time.perf_counter()
                r.prepare()  # despawn the wave and step
                times[e].append((time.perf_counter() - t0) * 1000.0)
            gc.collect()
    finally:
        gc.enable()
        for r in runners.values():
            r.close()
    out = {f"despawn_{e}_ms": statistics.median(v) for e, v in times.items()}
    out["despawn_count"] = float(count)
    return out


_MEMORY_SCRIPT = """
import gc, sys
from benchmarks.scenes import scenes
from benchmarks.engines import spec_of, PymunkRunner
from kge.testbed.registry import get_sample

def rss():
    with open('/proc/self/statm') as f:
        return int(f.read().split()[1]) * 4096

engine, n = sys.argv[1], int(sys.argv[2])
sample = get_sample('sparse-field')
spec = spec_of(sample, count=n) if engine == 'pymunk' else None
small = scenes()[0].engines  # imports every engine module before the baseline
gc.collect()
before = rss()
if engine == 'kge':
    from benchmarks.engines import KgeRunner
    r = KgeRunner(sample, count=n)
else:
    r = PymunkRunner(spec)
for _ in range(3):
    r.step()
gc.collect()
print((rss() - before) / n)
"""


def memory_per_body(engine: str, bodies: int = MEMORY_BODIES) -> float:
    """RSS growth per body building the sparse field in a fresh interpreter."""
    out = subprocess.run(
        [sys.executable, "-c", _MEMORY_SCRIPT, engine, str(bodies)],
        capture_output=True, text=True, check=True, timeout=600,
    )
    return float(out.stdout.strip().splitlines()[-1])


#: kge variants of one scene, each a change made before the first step
VARIANTS: dict[str, dict[str, Any]] = {
    "default": {},
    "no-ccd": {"ccd": False},
    "spatial-hash": {"spatial_hash": 1.0},
    "threads-2": {"threads": 2},
}


def _variant(scene: Any, size: int, change: dict[str, Any]) -> Any:
    from kge.physics.settings import PhysicsSettings

    measured = scene.engines["kge"](size)
    app = measured.runner.app
    settings = dict(change)
    if not settings.pop("ccd", True):
        app.world.get_system(PhysicsSystem).sim.ccd = None  # continuous collision absent
    for name, value in settings.items():
        setattr(app.world.resource(PhysicsSettings), name, value)
    return measured


#: testbed samples of the variant scenes (their size parameter is ``count``)
_SLUGS: dict[str, tuple[str, dict[str, Any]]] = {
    "rain": ("rain", {}), "dense-pile": ("box-pile", {"sleep": False}),
}


def variant_costs(quick: bool = False, blocks: int = 7) -> dict[str, float]:
    """Frame ms of rain and the dense pile in kge's variants (:data:`VARIANTS`), interleaved.

    Continuous collision's cost when nothing moves fast is ``default`` against
    ``no-ccd``; the broad phase and the threaded solver against ``default`` are what
    ``PhysicsSettings.spatial_hash`` and ``threads`` win or lose.
    """
    from benchmarks.scenes import scenes

    table = {s.name: s for s in scenes()}
    out: dict[str, float] = {}
    frames = 3 if quick else 6
    for name, size in (("rain", 1000 if quick else 5000), ("dense-pile", 2000 if quick else 6000)):
        scene = table[name]
        runners = {v: _variant(scene, size, change) for v, change in VARIANTS.items()}
        slug, extra = _SLUGS[name]
        spec = spec_of(get_sample(slug), count=size, **extra)
        runners["pymunk"] = PymunkRunner(spec)  # the floor of the step alone
        runners["pymunk-events"] = PymunkRunner(spec, events=True)  # + no-op begin/separate
        times: dict[str, list[float]] = {v: [] for v in runners}
        try:
            for r in runners.values():
                for _ in range(scene.warmup):
                    r.step()
            for _ in range(2 if quick else blocks):
                for v, r in runners.items():
                    t0 = time.perf_counter()
                    for _ in range(frames):
                        r.step()
                    times[v].append((time.perf_counter() - t0) * 1000.0 / frames)
        finally:
            for r in runners.values():
                r.close()
        for v, ts in times.items():
            out[f"variant_{name}_{v}_ms"] = statistics.median(ts)
        out[f"variant_{name}_size"] = float(size)
    return out


def variant_lines(c: dict[str, float]) -> list[str]:
    """One line per scene: each variant's frame ms and its ratio to the default."""
    lines = []
    for name in ("rain", "dense-pile"):
        base = c.get(f"variant_{name}_default_ms")
        if not base:
            continue
        cells = "  ".join(
            f"{v} {c[f'variant_{name}_{v}_ms']:.2f} ms ({c[f'variant_{name}_{v}_ms'] / base:.2f}x)"
            for v in VARIANTS
        )
        lines.append(f"  {name}-{c[f'variant_{name}_size']:.0f}: {cells}")
        raw, raw_events = c[f"variant_{name}_pymunk_ms"], c[f"variant_{name}_pymunk-events_ms"]
        lines.append(
            f"    raw pymunk {raw:.2f} ms, with no-op begin/separate callbacks {raw_events:.2f} ms:"
            f" kge / raw {base / raw:.2f}, kge / raw with callbacks {base / raw_events:.2f}"
        )
    return lines


def component_build_ms(count: int = 1000, repeats: int = 9) -> float:
    """ms to construct the components of ``count`` spawn-burst boxes, spawning nothing.

    Transform, RigidBody, Collider (a Box, its material and Filter) and Name, each
    checked as it is built: with raw pymunk's own spawn time beside it, the floor of
    any spawn that starts from validated components, before the ECS or physics.
    """
    from kge.components import Collider, Filter, Name, RigidBody, Transform
    from kge.components.shapes import Box

    times = []
    gc.collect()
    gc.disable()
    try:
        for _ in range(repeats):
            t0 = time.perf_counter()
            for i in range(count):
                (Transform(1.5 * i, 2.0, 0.0), RigidBody(),
                 Collider(Box(0.5, 0.5), density=1.0, friction=0.6, restitution=0.0,
                          filter=Filter()), Name("burst"))
            times.append((time.perf_counter() - t0) * 1000.0)
    finally:
        gc.enable()
    return statistics.median(times)


def measure(quick: bool = False) -> dict[str, float]:
    """Every figure of this module (smaller and fewer when ``quick``)."""
    out: dict[str, float] = {"component_build_ms": component_build_ms(100 if quick else 1000)}
    out.update(variant_costs(quick))
    out.update(sync_costs(500 if quick else 20_000, 5 if quick else 40))
    out.update(despawn_costs(100 if quick else 1000, 2 if quick else 9))
    n = 1000 if quick else MEMORY_BODIES
    out["bytes_per_body_kge"] = memory_per_body("kge", n)
    out["bytes_per_body_pymunk"] = memory_per_body("pymunk", n)
    return out


def table(costs: dict[str, float]) -> str:
    c = costs
    return "\n".join([
        f"  sync-out per moved body ({c['bodies']:.0f} moving)  {c['sync_out_us']:.3f} µs",
        f"  floor: {FIELDS_PER_BODY} bare slot stores per body"
        f"      {c['sync_out_floor_us']:.3f} µs",
        f"  sync-in, frame with no writes              {c['sync_in_ms']:.3f} ms",
        f"  despawn frame, {c['despawn_count']:,.0f} bodies"
        f"            kge {c['despawn_kge_ms']:.1f} ms"
        f"  pymunk {c['despawn_pymunk_ms']:.1f} ms",
        f"  building the components of the spawn wave  {c['component_build_ms']:.1f} ms",
        f"  memory per body (RSS)                      kge {c['bytes_per_body_kge']:.0f} B"
        f"  pymunk {c['bytes_per_body_pymunk']:.0f} B",
        "  kge variants, frame ms (x default; threads-2 is not deterministic):",
        *variant_lines(c),
    ])


def markdown(costs: dict[str, float]) -> list[str]:
    """The figures as a markdown table (lines), for the report."""
    c = costs
    return [
        "", "Per-body costs (`benchmarks/costs.py`):", "",
        "| figure | kge | raw pymunk |", "|---|---:|---:|",
        f"| sync-out per moved body ({c['bodies']:,.0f} moving), µs "
        f"| {c['sync_out_us']:.3f} | - |",
        f"| floor: {FIELDS_PER_BODY} bare slot stores per body, µs "
        f"| {c['sync_out_floor_us']:.3f} | - |",
        f"| sync-in of a frame with no writes ({c['bodies']:,.0f} bodies), ms "
        f"| {c['sync_in_ms']:.3f} | - |",
        f"| despawn frame, {c['despawn_count']:,.0f} bodies, ms "
        f"| {c['despawn_kge_ms']:.1f} | {c['despawn_pymunk_ms']:.1f} |",
        f"| components of the spawn wave, built and checked, ms "
        f"| {c['component_build_ms']:.1f} | - |",
        f"| memory per body (RSS growth, sparse field), bytes "
        f"| {c['bytes_per_body_kge']:,.0f} | {c['bytes_per_body_pymunk']:,.0f} |",
        "", "kge variants, frame ms (ratio to the default; `threads-2` is not deterministic):",
        "", "| scene | " + " | ".join(VARIANTS) + " |", "|---|" + "---:|" * len(VARIANTS),
        *[
            f"| {name}-{c[f'variant_{name}_size']:.0f} | " + " | ".join(
                f"{c[f'variant_{name}_{v}_ms']:.2f} "
                f"({c[f'variant_{name}_{v}_ms'] / c[f'variant_{name}_default_ms']:.2f}x)"
                for v in VARIANTS) + " |"
            for name in ("rain", "dense-pile") if f"variant_{name}_default_ms" in c
        ],
        "", "Raw pymunk beside them (same run): the step alone, and with no-op begin/separate "
        "callbacks, the floor of delivering Box2D's contact events through pymunk:", "",
        "| scene | raw pymunk ms | with callbacks ms | kge / raw | kge / raw with callbacks |",
        "|---|---:|---:|---:|---:|",
        *[
            f"| {name}-{c[f'variant_{name}_size']:.0f} | {c[f'variant_{name}_pymunk_ms']:.2f} "
            f"| {c[f'variant_{name}_pymunk-events_ms']:.2f} "
            f"| {c[f'variant_{name}_default_ms'] / c[f'variant_{name}_pymunk_ms']:.2f} "
            f"| {c[f'variant_{name}_default_ms'] / c[f'variant_{name}_pymunk-events_ms']:.2f} |"
            for name in ("rain", "dense-pile") if f"variant_{name}_default_ms" in c
        ],
    ]
