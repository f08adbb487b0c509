"""Per-body costs beside raw pymunk: sync-out, despawn and memory.

The scene table times whole frames; these figures isolate the per-body parts the
issue sets targets for, each measured side by side with raw pymunk in one run:

* ``sync_out_us``: sync-out's time per *moved* body (the sparse field, where
  every body moves every frame), counted from the rows sync-out actually wrote;
* ``sync_in_ms``: sync-in of a frame with no user writes on the same scene (it
  should not grow with the body count);
* ``despawn_ms``: the frame that despawns a 1,000-body wave (the spawn scene's
  ``prepare``), interleaved with raw pymunk removing the same wave;
* ``churn_ms``: spawning a 7-entity scene (3 bodies, 2 joints, 2 ground colliders)
  into a world of 200 or 2,000 bodies and despawning it (a bullet, a respawned
  lander), beside raw pymunk adding and removing the same objects: a structural
  change costs what it changes, so the two kge figures should be about equal;
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


#: world sizes of the structural-change figure (its bodies; half as many joints)
CHURN_WORLDS = (200, 2000)
#: steps the churn worlds take before they are measured (the crowd lands on its ground)
CHURN_SETTLE = 30


def _churn_world(bodies: int) -> tuple[Any, Any, Any]:
    """(app, physics, anchor): ``bodies`` dynamic 0.8 m boxes in pairs on revolute joints,
    resting on a ground (a contact each): the world a few bodies are spawned into."""
    from kge.app import App
    from kge.components import Box, Collider, RevoluteJoint, RigidBody, Transform
    from kge.physics.resource import Physics

    app = App(lambda world: None, headless=True)
    world = app.world
    anchor = world.spawn(Transform(0.0, -1.0), Collider(Box(2.0 * bodies, 1.0)))
    for k in range(bodies // 2):
        x = 2.0 * k
        a = world.spawn(Transform(x, 0.45), RigidBody(), Collider(Box(0.4, 0.4), density=1.0))
        b = world.spawn(Transform(x + 0.9, 0.45), RigidBody(), Collider(Box(0.4, 0.4)))
        world.spawn(RevoluteJoint(a, b, local_anchor_a=(0.45, 0.0), local_anchor_b=(-0.45, 0.0)))
    app.step(CHURN_SETTLE)
    return app, world.resource(Physics), anchor


def _churn_scene(world: Any, x: float) -> list[int]:
    """A lander-sized scene at ``x`` (far above the crowd): a hull and two legs on motorised,
    limited hinges, and a ground of an edge and a 10-segment chain. 7 entities."""
    from kge.components import Box, Chain, Collider, Edge, RevoluteJoint, RigidBody, Transform

    made = [world.spawn(Transform(x, 100.0), Collider(Edge((0.0, 0.0), (20.0, 0.0)))),
            world.spawn(Transform(x, 100.0),
                        Collider(Chain([(2.0 * i, 1.0 + (i % 3)) for i in range(11)])))]
    hull = world.spawn(Transform(x + 10.0, 110.0), RigidBody(),
                       Collider(Box(0.5, 0.3), density=5.0))
    made.append(hull)
    for side in (-1, 1):
        leg = world.spawn(Transform(x + 10.0 - 0.7 * side, 109.5), RigidBody(),
                          Collider(Box(0.05, 0.15), density=1.0))
        made += [leg, world.spawn(RevoluteJoint(
            hull, leg, local_anchor_b=(0.7 * side, 0.6), enable_limit=True, lower_angle=-0.4,
            upper_angle=0.4, enable_motor=True, motor_speed=0.3, max_motor_torque=40.0))]
    return made


def _raw_scene(space: Any, x: float) -> list[Any]:
    """:func:`_churn_scene` in raw pymunk: the same bodies, shapes and constraints."""
    import pymunk

    static = space.static_body
    objs: list[Any] = [pymunk.Segment(static, (x, 100.0), (x + 20.0, 100.0), 0.01)]
    pts = [(x + 2.0 * i, 101.0 + (i % 3)) for i in range(11)]
    objs += [pymunk.Segment(static, pts[i], pts[i + 1], 0.01) for i in range(10)]
    hull = pymunk.Body(3.0, 1.0)
    hull.position = (x + 10.0, 110.0)
    objs += [hull, pymunk.Poly.create_box(hull, (1.0, 0.6), 0.01)]  # kge's Box: half sizes
    for side in (-1, 1):
        leg = pymunk.Body(0.03, 0.001)
        leg.position = (x + 10.0 - 0.7 * side, 109.5)
        objs += [leg, pymunk.Poly.create_box(leg, (0.1, 0.3), 0.01),
                 pymunk.PivotJoint(hull, leg, (0.0, 0.0), (0.7 * side, 0.6)),
                 pymunk.RotaryLimitJoint(hull, leg, -0.4, 0.4), pymunk.SimpleMotor(hull, leg, 0.3)]
    space.add(*objs)
    return objs


def _raw_world(bodies: int) -> Any:
    import pymunk

    space = pymunk.Space()
    space.gravity = (0.0, -10.0)
    space.add(ground := pymunk.Segment(space.static_body, (0.0, -0.5), (2.0 * bodies, -0.5), 0.5))
    for k in range(bodies // 2):
        pair = []
        for dx in (0.0, 0.9):
            body = pymunk.Body(0.64, 0.07)
            body.position = (2.0 * k + dx, 0.45)
            space.add(body, pymunk.Poly.create_box(body, (0.8, 0.8), 0.01))
            pair.append(body)
        pivot = pymunk.PivotJoint(pair[0], pair[1], (0.45, 0.0), (-0.45, 0.0))
        pivot.collide_bodies = False
        space.add(pivot)
    for _ in range(CHURN_SETTLE):
        space.step(1 / 60)
    del ground
    return space


def churn_costs(repeats: int, worlds: tuple[int, ...] = CHURN_WORLDS) -> dict[str, float]:
    """ms to spawn a 7-entity scene (3 bodies, 2 joints, 2 ground colliders) into a world
    and despawn it again, each applied by a sync-in, in worlds of ``worlds`` bodies; raw
    pymunk adding and removing the same objects beside it, interleaved.

    The figure of a structural change's cost: it should not grow with the world
    (kge at the largest world / kge at the smallest about 1).
    """
    kge_worlds = {n: _churn_world(n) for n in worlds}
    raw_worlds = {n: _raw_world(n) for n in worlds}
    times: dict[str, list[float]] = {f"{e}_{n}": [] for n in worlds for e in ("kge", "raw")}
    gc.collect()
    gc.disable()
    try:
        for r in range(repeats + 1):
            for n in worlds:
                app, physics, anchor = kge_worlds[n]
                world = app.world
                t0 = time.perf_counter()
                made = _churn_scene(world, -1000.0)
                physics.is_awake(made[2])  # sync-in: the scene enters the space
                for e in made:
                    world.despawn(e)
                world.flush()
                physics.is_awake(anchor)  # sync-in: it leaves
                t1 = time.perf_counter()
                space = raw_worlds[n]
                objs = _raw_scene(space, -1000.0)
                space.remove(*objs)
                t2 = time.perf_counter()
                if r:  # the first round warms up
                    times[f"kge_{n}"].append((t1 - t0) * 1000.0)
                    times[f"raw_{n}"].append((t2 - t1) * 1000.0)
            gc.collect()
    finally:
        gc.enable()
        for app, _, _ in kge_worlds.values():
            app.close()
    out = {f"churn_{k}_ms": statistics.median(v) for k, v in times.items()}
    out["churn_small"], out["churn_large"] = float(min(worlds)), float(max(worlds))
    return out


def churn_line(c: dict[str, float]) -> str:
    small, large = int(c["churn_small"]), int(c["churn_large"])
    k_s, k_l = c[f"churn_kge_{small}_ms"], c[f"churn_kge_{large}_ms"]
    r_l = c[f"churn_raw_{large}_ms"]
    return (f"  spawn+despawn 7 entities (3 bodies, 2 joints) in {small:,} / {large:,} bodies"
            f"  kge {k_s:.2f} / {k_l:.2f} ms ({k_l / k_s:.2f}x)  pymunk {r_l:.3f} ms"
            f" (kge / pymunk {k_l / r_l:.0f}x)")


def measure(quick: bool = False) -> dict[str, float]:
    """Every figure of this module (smaller and fewer when ``quick``)."""
    out: dict[str, float] = {"component_build_ms": component_build_ms(100 if quick else 1000)}
    out.update(variant_costs(quick))
    out.update(sync_costs(500 if quick else 20_000, 5 if quick else 40))
    out.update(despawn_costs(100 if quick else 1000, 2 if quick else 9))
    out.update(churn_costs(5 if quick else 40))
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
        *([churn_line(c)] if "churn_small" in c else []),
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
        *[
            f"| spawn + despawn 7 entities (3 bodies, 2 joints) in a world of {n:,.0f} bodies, "
            f"ms | {c[f'churn_kge_{n:.0f}_ms']:.2f} | {c[f'churn_raw_{n:.0f}_ms']:.3f} |"
            for n in ((c["churn_small"], c["churn_large"]) if "churn_small" in c else ())
        ],
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
