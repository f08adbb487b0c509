"""Soak test: spawn/despawn churn for many steps, watching memory, events and pymunk.

A bin of static walls receives a steady rain of bodies (circles, boxes and
polygons, some hinged in pairs, some sensors); every body is despawned a fixed
number of steps after it was spawned, some from behaviours, some from contact
hooks, so the population stays around ``--population`` while every code path
of creation and destruction runs thousands of times. Every ``--interval``
steps the run records Python heap (tracemalloc) and RSS, and checks the
invariants of ``tests/reliability/harness.py`` (pymunk objects == ECS, begin /
end events balanced, no NaN). It fails (exit status 1) when memory grows more
than ``--max-growth`` (5 %) between the end of the warm-up and the end of the
run, or when an invariant breaks.

With ``--render`` the scene also carries sprites and shape drawables and is
drawn headless every ``--render-every`` steps, and the render system's pyglet
objects (sprites, meshes) are counted against the entities that should have
them.

Commands (see benchmarks/results/reliability.md for the figures)::

    .venv/bin/python tools/soak.py                     # 100,000 steps (about 10 min)
    .venv/bin/python tools/soak.py --steps 3000 --interval 500   # the CI run
    PYGLET_HEADLESS=1 .venv/bin/python tools/soak.py --steps 20000 --render
"""

from __future__ import annotations

import argparse
import gc
import json
import os
import random
import sys
import time
import tracemalloc
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from kge import (  # noqa: E402
    App,
    Behaviour,
    BodyType,
    Box,
    Circle,
    Collider,
    Polygon,
    RevoluteJoint,
    RigidBody,
    Script,
    Transform,
    World,
)
from kge.physics.events import ContactBegin  # noqa: E402
from tests.reliability.harness import (  # noqa: E402
    AppProbe,
    check_invariants,
    check_no_leftovers,
)


@dataclass
class Sample:
    step: int
    heap_kb: float
    rss_kb: float
    entities: int
    bodies: int
    shapes: int
    constraints: int
    begins: int
    ends: int


@dataclass
class Report:
    steps: int
    seconds: float
    samples: list[Sample] = field(default_factory=list)
    spawned: int = 0
    despawned: int = 0
    heap_growth: float = 0.0
    rss_growth: float = 0.0
    render_objects: dict[str, int] = field(default_factory=dict)
    ok: bool = True
    problems: list[str] = field(default_factory=list)


def rss_kb() -> float:
    """Resident set size in KiB (Linux /proc; 0 elsewhere)."""
    try:
        with open("/proc/self/statm") as f:
            pages = int(f.read().split()[1])
    except OSError:
        return 0.0
    return pages * os.sysconf("SC_PAGE_SIZE") / 1024.0


def judge_growth(
    samples: list[tuple[int, float, float]], warm_step: int, max_growth: float
) -> tuple[float, float, list[str]]:
    """Heap and RSS growth from the end of the warm-up to the last sample, and problems.

    ``samples`` are (step, heap KiB, RSS KiB). The heap is judged on its upper
    envelope (the peak of the late half against the peak of the early half of the
    samples after ``warm_step``), so one busy moment does not decide it.
    """
    warm = [s for s in samples if s[0] >= warm_step]
    if len(warm) < 2:
        return 0.0, 0.0, []
    (_, heap0, rss0), (_, heap1, rss1) = warm[0], warm[-1]
    heap_growth = heap1 / heap0 - 1.0 if heap0 else 0.0
    rss_growth = rss1 / rss0 - 1.0 if rss0 else 0.0
    problems = []
    peak_late = max(s[1] for s in warm[len(warm) // 2:])
    peak_early = max(s[1] for s in warm[: max(1, len(warm) // 2)])
    envelope = peak_late / peak_early - 1.0 if peak_early else 0.0
    if envelope > max_growth:
        problems.append(f"Python heap grew {envelope:.1%} after warm-up")
    if rss_growth > max_growth:
        problems.append(f"RSS grew {rss_growth:.1%} after warm-up")
    return heap_growth, rss_growth, problems


class Fuse(Script):
    """Despawns its entity after ``life`` fixed steps (from a behaviour)."""

    def __init__(self, life: int) -> None:
        self.life = life

    def on_fixed_update(self, dt: float) -> None:
        self.life -= 1
        if self.life <= 0 and self.world.exists(self.entity):
            self.world.despawn(self.entity)


class Fragile(Fuse):
    """Also despawns itself on its third contact (from a contact hook)."""

    def __init__(self, life: int) -> None:
        super().__init__(life)
        self.hits = 0

    def on_contact_begin(self, event: ContactBegin) -> None:
        self.hits += 1
        if self.hits >= 3 and self.world.exists(self.entity):
            self.world.despawn(self.entity)


class Churn:
    """Spawns bodies into the bin; tracks the ones despawned from test code."""

    def __init__(self, seed: int, population: int, render: bool) -> None:
        self.rng = random.Random(seed)
        self.population = population
        self.render = render
        self.life = population  # steps; one spawn per step keeps ~population alive
        self.spawned = 0
        self.manual: list[tuple[int, int]] = []  # (despawn at step, entity)

    def scene(self, world: World) -> None:
        world.spawn(Transform(0.0, -1.0), Collider(Box(12.0, 1.0)))
        world.spawn(Transform(-12.0, 10.0), Collider(Box(0.5, 11.0)))
        world.spawn(Transform(12.0, 10.0), Collider(Box(0.5, 11.0)))

    def _extras(self) -> list[Any]:
        if not self.render:
            return []
        from kge import draw, solid

        if self.rng.random() < 0.5:
            from kge import Sprite

            return [Sprite(solid(4, 4, (200, 80, 80)), size=(0.4, 0.4))]
        return [draw.Rect(0.4, 0.4, color=(80, 200, 80, 255))]

    def body(self, world: World, x: float, y: float, life: int) -> int:
        r = self.rng.random()
        shape: Any
        if r < 0.4:
            shape = Circle(self.rng.uniform(0.1, 0.4))
        elif r < 0.8:
            shape = Box(self.rng.uniform(0.1, 0.4), self.rng.uniform(0.1, 0.4))
        else:
            shape = Polygon([(0.0, 0.0), (0.5, 0.0), (0.1, 0.4)])
        kind = BodyType.DYNAMIC if self.rng.random() < 0.95 else BodyType.KINEMATIC
        script = Fragile(life) if self.rng.random() < 0.3 else Fuse(life)
        sensor = self.rng.random() < 0.05
        self.spawned += 1
        return world.spawn(
            Transform(x, y, self.rng.uniform(-3.0, 3.0)),
            RigidBody(type=kind, velocity=(self.rng.uniform(-2, 2), 0.0)),
            Collider(shape, sensor=sensor, friction=0.5),
            Behaviour(script),
            *self._extras(),
        )

    def tick(self, world: World, step: int) -> None:
        x = self.rng.uniform(-10.0, 10.0)
        life = self.life + self.rng.randint(-20, 20)
        if self.rng.random() < 0.1:  # a hinged pair, despawned from here (test code)
            a = self.body(world, x, 6.0, 10 * life)
            b = self.body(world, x + 0.8, 6.0, 10 * life)
            j = world.spawn(RevoluteJoint(a, b, anchor=(x + 0.4, 6.0)))
            self.manual.append((step + life, a))
            self.manual.append((step + life, j))
        else:
            self.body(world, x, 6.0, life)
        while self.manual and self.manual[0][0] <= step:
            _, e = self.manual.pop(0)
            if world.exists(e):
                world.despawn(e)


def render_counts(app: App) -> dict[str, int]:
    """pyglet objects of the render system beside the entities that should own them."""
    from kge import Sprite, draw
    from kge.systems.render import RenderSystem

    system = app.world.get_system(RenderSystem)
    if system is None:
        return {}
    view = system.view
    world = app.world
    return {
        "sprites": len(view.sprites),
        "sprite_entities": len(world.query(Sprite)),
        "meshes": len(view.meshes),
        "mesh_entities": len(world.query(draw.Rect)),
    }


def run(
    steps: int,
    interval: int,
    population: int = 100,
    seed: int = 1,
    warmup: float = 0.2,
    max_growth: float = 0.05,
    render: bool = False,
    render_every: int = 10,
    log: Any = None,
    trace: bool = True,
) -> Report:
    churn = Churn(seed, population, render)
    app = App(churn.scene, headless=True)
    probe = AppProbe(app)
    if trace:
        tracemalloc.start()
    started = time.perf_counter()
    report = Report(steps=steps, seconds=0.0)
    warm_step = max(interval, int(steps * warmup) // interval * interval)
    try:
        for step in range(1, steps + 1):
            churn.tick(app.world, step)
            probe.step()
            if render and step % render_every == 0:
                app.render()
            if step % interval == 0:
                # measure what is retained, not cyclic garbage awaiting the collector:
                # despawned scripts and their worlds form cycles, and between
                # collections they make the heap saw-tooth by +-40 %
                gc.collect()
                check_invariants(probe)
                sim = probe.sim
                if render:
                    report.render_objects = render_counts(app)
                    rc = report.render_objects
                    if rc and (rc["sprites"] != rc["sprite_entities"]
                               or rc["meshes"] != rc["mesh_entities"]):
                        report.problems.append(f"step {step}: pyglet objects {rc}")
                s = Sample(
                    step=step,
                    heap_kb=tracemalloc.get_traced_memory()[0] / 1024.0 if trace else 0.0,
                    rss_kb=rss_kb(),
                    entities=len(app.world),
                    bodies=len(sim.space.bodies),
                    shapes=len(sim.space.shapes),
                    constraints=len(sim.space.constraints),
                    begins=probe.balance.begins,
                    ends=probe.balance.ends,
                )
                report.samples.append(s)
                if log is not None:
                    log.write(json.dumps(asdict(s)) + "\n")
                    log.flush()
        # the end: despawn every body and joint; nothing may stay behind anywhere
        for e, _ in app.world.query(RigidBody):
            app.world.despawn(e)
        probe.step(2)
        check_invariants(probe)
        check_no_leftovers(probe)
        sim = probe.sim
        walls = sum(1 for r in sim.bodies.values() if r.implicit)  # the bin's 3 static bodies
        left = (len(sim.space.bodies) - walls, len(sim.space.constraints),
                len(sim.joints.components))
        if left != (0, 0, 0):
            report.problems.append(f"after despawning everything: {left} bodies/joints left")
        if probe.balance.begins != probe.balance.ends:
            report.problems.append(
                f"unbalanced events: {probe.balance.begins} begins, {probe.balance.ends} ends"
            )
        if render:
            app.render()
            rc = render_counts(app)
            if rc and (rc["sprites"] or rc["meshes"]):
                report.problems.append(f"pyglet objects left after despawning all: {rc}")
    except AssertionError as err:
        report.problems.append(f"invariant broken: {err}")
    finally:
        report.seconds = time.perf_counter() - started
        tracemalloc.stop()
        report.spawned = churn.spawned
        app.close()
    report.heap_growth, report.rss_growth, grew = judge_growth(
        [(s.step, s.heap_kb, s.rss_kb) for s in report.samples], warm_step, max_growth)
    report.problems.extend(grew)
    report.ok = not report.problems
    return report


def add_run_options(p: argparse.ArgumentParser) -> None:
    """The options every soak shares: sampling, churn size, seed, limits, the log."""
    p.add_argument("--interval", type=int, default=2_000)
    p.add_argument("--population", type=int, default=100)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--max-growth", type=float, default=0.05)
    p.add_argument("--log", help="write one JSON line per sample to this file")
    p.add_argument("--no-tracemalloc", action="store_true",
                   help="no tracemalloc (it slows the run about 2x)")


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--steps", type=int, default=100_000)
    add_run_options(p)
    p.add_argument("--render", action="store_true",
                   help="also draw headless and count pyglet objects")
    p.add_argument("--render-every", type=int, default=10)
    args = p.parse_args(argv)
    log = open(args.log, "w") if args.log else None  # noqa: SIM115
    try:
        rep = run(args.steps, args.interval, args.population, args.seed,
                  max_growth=args.max_growth, render=args.render,
                  render_every=args.render_every, log=log, trace=not args.no_tracemalloc)
    finally:
        if log is not None:
            log.close()
    first, last = rep.samples[0], rep.samples[-1]
    print(f"steps {rep.steps} in {rep.seconds:.0f} s; spawned {rep.spawned} bodies")
    print(f"heap {first.heap_kb:.0f} KiB at step {first.step} -> {last.heap_kb:.0f} KiB "
          f"(growth after warm-up {rep.heap_growth:+.2%})")
    print(f"RSS {first.rss_kb:.0f} KiB -> {last.rss_kb:.0f} KiB "
          f"(growth after warm-up {rep.rss_growth:+.2%})")
    print(f"events: {last.begins} begins, {last.ends} ends; live entities {last.entities}, "
          f"space: {last.bodies} bodies, {last.shapes} shapes, {last.constraints} constraints")
    if rep.render_objects:
        print(f"render objects: {rep.render_objects}")
    for problem in rep.problems:
        print("PROBLEM:", problem)
    print("OK" if rep.ok else "FAILED")
    return 0 if rep.ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
