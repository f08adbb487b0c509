"""The benchmark scenes: testbed samples at benchmark sizes, on three engines.

Every scene here is a registered testbed sample (``kge.testbed``), so what is
timed is exactly what a user can open in the testbed. Sizes follow the issue:
pyramid bases 20 / 40 / 100 (210 / 820 / 5,050 boxes), rain 1,000 / 5,000
circles, 5 chains of 40 links, 30x30 and 100x100 joint grids, a 2,000-box
tumbler, 5,000 sleeping boxes, spawn/despawn churn, an event storm, a dense
pile and a sparse field (the "bodies at 60 Hz" targets), and a frame that
spawns 1,000 bodies. Scenes whose population changes (churn, spawn) repeat the
sample's script on the raw engines with the helpers the sample itself uses.
"""

from __future__ import annotations

import functools
import math
from collections import deque
from collections.abc import Callable
from typing import Any

from benchmarks.engines import (
    Box2DRunner,
    KgeRunner,
    Pose,
    PymunkRunner,
    box2d_available,
    spec_of,
)
from benchmarks.harness import Factory, Scene
from benchmarks.mirror import BodySpec, SceneSpec, to_world
from kge.testbed.registry import get_sample
from kge.testbed.samples.build import named
from kge.testbed.samples.large import burst, burst_position, churn_position

Quality = Callable[[SceneSpec, dict[int, Pose], dict[int, Pose]], dict[str, float]]
RawFactory = Callable[[SceneSpec, bool], Any]


class _Measured:
    """Wraps a runner to compute a quality figure from its poses at close time."""

    def __init__(self, runner: Any, spec: SceneSpec, quality: Quality) -> None:
        self.runner = runner
        self.spec = spec
        self.first = runner.poses()
        self.quality_fn = quality
        self.prepare = getattr(runner, "prepare", None)

    def step(self) -> None:
        self.runner.step()

    def quality(self) -> dict[str, float]:
        return self.quality_fn(self.spec, self.first, self.runner.poses())

    def close(self) -> None:
        self.runner.close()


def _raw_engines() -> dict[str, RawFactory]:
    """Each peer twice: bare, and with what a game on it must add every frame."""
    engines: dict[str, RawFactory] = {
        "pymunk": PymunkRunner,
        "pymunk+read": functools.partial(PymunkRunner, read=True),
    }
    if box2d_available() is None:
        engines["box2d"] = Box2DRunner
        engines["box2d+sync"] = functools.partial(Box2DRunner, sync=True)
    return engines


def _engines(slug: str, param: str, quality: Quality, events: bool = False,
             extra: dict[str, Any] | None = None,
             wrap: Callable[[Any, SceneSpec, int], Any] | None = None) -> dict[str, Factory]:
    """kge, raw pymunk and (when installed) pybox2d factories for one sample.

    ``wrap(runner, spec, size)`` drives a raw runner the way the sample's
    scripts drive the kge world (churn).
    """
    sample = get_sample(slug)
    extra = extra or {}

    def kge_factory(n: int) -> _Measured:
        spec = spec_of(sample, **{param: n}, **extra)
        return _Measured(KgeRunner(sample, **{param: n}, **extra), spec, quality)

    def raw(make: RawFactory) -> Factory:
        def factory(n: int) -> _Measured:
            spec = spec_of(sample, **{param: n}, **extra)
            runner = make(spec, events)
            if wrap is not None:
                runner = wrap(runner, spec, n)
            return _Measured(runner, spec, quality)

        return factory

    engines: dict[str, Factory] = {"kge": kge_factory}
    for name, make in _raw_engines().items():
        engines[name] = raw(make)
    return engines


# -- churn and spawn on the raw engines ----------------------------------------------------


def _template(spec: SceneSpec) -> BodySpec:
    return next(b for b in spec.bodies if b.type == "dynamic")


class RawChurn:
    """The Churn sample's script on a raw engine: every ``period`` steps, replace ``batch``."""

    def __init__(self, runner: Any, spec: SceneSpec, count: int, period: int = 5) -> None:
        self.runner = runner
        self.template = _template(spec)
        self.alive = deque(b.entity for b in spec.bodies if b.type == "dynamic")
        self.batch = max(1, count // 10)
        self.period = period
        self.tick = 0
        self.spawned = 0
        self.next_entity = 1 << 40

    def step(self) -> None:
        self.tick += 1
        if self.tick % self.period == 0:
            for _ in range(min(self.batch, len(self.alive))):
                self.runner.remove_body(self.alive.popleft())
            for _ in range(self.batch):
                self.next_entity += 1
                self.runner.add_body(_respawn(self.template, self.next_entity,
                                              churn_position(self.spawned)))
                self.alive.append(self.next_entity)
                self.spawned += 1
        self.runner.step()

    def poses(self) -> dict[int, Pose]:
        return dict(self.runner.poses())

    def close(self) -> None:
        self.runner.close()


def _respawn(template: BodySpec, entity: int, at: tuple[float, float]) -> BodySpec:
    return BodySpec(entity, template.type, at, 0.0, shapes=list(template.shapes))


class KgeSpawn:
    """Time the frame that spawns ``count`` boxes; ``prepare`` (untimed) removes the last wave."""

    def __init__(self, count: int) -> None:
        self.count = count
        self.inner = KgeRunner(get_sample("spawn-burst"), count=count, period=0)
        self.wave = named(self.inner.app.world, "burst")

    def prepare(self) -> None:
        world = self.inner.app.world
        for e in self.wave:
            world.despawn(e)
        self.inner.step()

    def step(self) -> None:
        self.wave = burst(self.inner.app.world, self.count)
        self.inner.step()

    def poses(self) -> dict[int, Pose]:
        return self.inner.poses()

    def close(self) -> None:
        self.inner.close()


class RawSpawn:
    """The same waves on a raw engine."""

    def __init__(self, runner: Any, spec: SceneSpec, count: int) -> None:
        self.runner = runner
        self.template = _template(spec)
        self.count = count
        self.wave = [b.entity for b in spec.bodies if b.type == "dynamic"]
        self.next_entity = 1 << 40

    def prepare(self) -> None:
        for e in self.wave:
            self.runner.remove_body(e)
        self.runner.step()

    def step(self) -> None:
        self.wave = []
        for i in range(self.count):
            self.next_entity += 1
            self.runner.add_body(_respawn(self.template, self.next_entity, burst_position(i)))
            self.wave.append(self.next_entity)
        self.runner.step()

    def poses(self) -> dict[int, Pose]:
        return dict(self.runner.poses())

    def close(self) -> None:
        self.runner.close()


def _spawn_engines() -> dict[str, Factory]:
    sample = get_sample("spawn-burst")

    def kge_factory(n: int) -> _Measured:
        return _Measured(KgeSpawn(n), spec_of(sample, count=n, period=0), count_quality)

    def raw(make: RawFactory) -> Factory:
        def factory(n: int) -> _Measured:
            spec = spec_of(sample, count=n, period=0)
            return _Measured(RawSpawn(make(spec, False), spec, n), spec, count_quality)

        return factory

    engines: dict[str, Factory] = {"kge": kge_factory}
    for name, make in _raw_engines().items():
        engines[name] = raw(make)
    return engines


# -- quality figures -------------------------------------------------------------------------


def pyramid_quality(spec: SceneSpec, first: dict[int, Pose],
                    last: dict[int, Pose]) -> dict[str, float]:
    """Sideways drift of the top box and boxes tipped over by more than 0.3 rad."""
    top = max(first, key=lambda e: first[e][1])
    drift = abs(last[top][0] - first[top][0])
    fallen = sum(1 for p in last.values() if abs(p[2]) > 0.3)
    return {"top_drift_m": round(drift, 4), "fallen": float(fallen)}


def escaped_quality(spec: SceneSpec, first: dict[int, Pose],
                    last: dict[int, Pose]) -> dict[str, float]:
    """Bodies outside the 40 m box."""
    escaped = sum(1 for p in last.values() if abs(p[0]) > 21.0 or p[1] < -1.0)
    return {"escaped": float(escaped)}


def drum_quality(spec: SceneSpec, first: dict[int, Pose],
                 last: dict[int, Pose]) -> dict[str, float]:
    """Boxes outside the tumbler's drum."""
    escaped = sum(1 for p in last.values() if math.hypot(p[0], p[1] - 10.0) > 15.0)
    return {"escaped": float(escaped)}


def moved_quality(spec: SceneSpec, first: dict[int, Pose],
                  last: dict[int, Pose]) -> dict[str, float]:
    """Largest distance any body moved (sleeping bodies must not)."""
    moved = max((math.dist(first[e][:2], last[e][:2]) for e in first if e in last), default=0.0)
    return {"max_move_m": round(moved, 4)}


def count_quality(spec: SceneSpec, first: dict[int, Pose],
                  last: dict[int, Pose]) -> dict[str, float]:
    return {"bodies": float(len(last))}


def joint_quality(spec: SceneSpec, first: dict[int, Pose],
                  last: dict[int, Pose]) -> dict[str, float]:
    """Largest gap between the two anchors of a revolute joint (m)."""
    statics = {b.entity: (b.position[0], b.position[1], b.angle) for b in spec.bodies}

    def pose(e: int | None) -> Pose:
        if e is None:
            return (0.0, 0.0, 0.0)
        return last.get(e) or statics[e]

    gap = max((math.dist(to_world(pose(j.body_a), j.local_a), to_world(pose(j.body_b), j.local_b))
               for j in spec.joints), default=0.0)
    return {"joint_gap_m": round(gap, 4)}


# -- the table -------------------------------------------------------------------------------


def scenes(quick: bool = False) -> list[Scene]:
    """All scenes; ``quick`` uses the smallest size only with few frames (for tests)."""
    table = [
        Scene("pyramid", (20, 40, 100), _engines("pyramid", "rows", pyramid_quality),
              description="pyramid of boxes, base 20/40/100 (210/820/5,050 boxes)", unit="rows"),
        Scene("rain", (1000, 5000), _engines("rain", "count", escaped_quality),
              description="circles raining into a 40 m box"),
        Scene("chain", (200, 1000), _engines("chains", "count", joint_quality,
                                              extra={"links": 40}),
              description="chains of 40 links on revolute joints, pinned to the ground",
              unit="links"),
        Scene("joint-grid", (30, 100), _engines("joint-grid", "side", joint_quality),
              description="side x side circles, revolute joints to their neighbours",
              unit="side", frames=30),
        Scene("tumbler", (500, 2000), _engines("full-tumbler", "count", drum_quality),
              description="kinematic drum turning, prefilled with small boxes"),
        Scene("many-sleeping", (5000,), _engines("sleeping-boxes", "count", moved_quality),
              description="5,000 boxes at rest on a floor, sleep on"),
        Scene("churn", (100, 1000), _engines("churn", "count", count_quality,
                                              wrap=lambda r, spec, n: RawChurn(r, spec, n)),
              description="a tenth of the boxes despawned and respawned every 5 steps"),
        Scene("event-storm", (15, 30), _engines("event-storm", "rows", pyramid_quality,
                                                events=True),
              description="pyramid struck by a ball, events on every collider", unit="rows"),
        Scene("dense-pile", (2000, 6000), _engines("box-pile", "count", escaped_quality,
                                                   extra={"sleep": False}),
              description="boxes settling in a 40 m box, sleep off (worst case)"),
        Scene("sparse", (5000, 20000), _engines("sparse-field", "count", count_quality),
              description="circles drifting far apart without gravity", frames=30),
        Scene("spawn", (1000,), _spawn_engines(), warmup=2, frames=10,
              description="one frame that spawns the bodies (plus its step)"),
    ]
    table += _gym_scenes()
    if quick:
        for s in table:
            small = min(s.sizes)
            s.sizes = (max(2, small // 2) if s.unit in ("rows", "side") else small // 10,)
            s.warmup, s.frames = 2, 4
    return table


def _gym_scenes() -> list[Scene]:
    """Gymnasium's LunarLander on kge.box2d (as "kge") and on pybox2d, when installed."""
    from benchmarks.gym_box2d import LanderRunner, gymnasium_available

    if gymnasium_available() is not None:
        return []
    engines: dict[str, Factory] = {"kge": lambda n: LanderRunner("kge", n)}
    if box2d_available() is None:
        engines["box2d"] = lambda n: LanderRunner("box2d", n)
    return [Scene("lunar-lander", (50,), engines, warmup=4, frames=30, unit="steps",
                  description="Gymnasium LunarLander-v3, heuristic, 50 env steps per frame "
                              "(kge.box2d as kge)")]


def skipped_engines() -> list[str]:
    reason = box2d_available()
    return [] if reason is None else [f"box2d: {reason}"]
