"""Game-layer soak: churn every game-layer component for many frames, watching memory
and every internal table.

Every frame spawns an actor with its own animation clip (a new ``Clip`` object, as a
game making clips per entity does), a tween, a particle emitter, often a physics body
and collider, sometimes a light or a text; every few frames a UI widget joins a panel,
a burst fires on a live emitter and a tile of the map is set or cleared; now and then
an overlay scene with its own animated sprite, emitter, tween and widgets is pushed
and popped; the App draws headless every ``--render-every`` frames. Every entity dies
a fixed number of frames after its birth (from a behaviour, or from here), so the
population stays near ``--population`` while each creation and destruction path
runs thousands of times.

Every ``--interval`` frames the run records Python heap (tracemalloc) and RSS and
checks the physics invariants of ``tests/reliability/harness.py``. The sizes of every
internal table (dicts, sets, lists and numpy arrays held by the world's resources and
systems: the animation clip table, tween rows, particle states and pools, UI state,
render objects, lighting, tile map, physics) are taken before the churn, at the end
of the warm-up and after the teardown (everything churned despawned, the overlays
popped, a few frames run): each table must be back to its size before the churn. The
run fails (exit status 1) when a table is not, when heap or RSS grow more than
``--max-growth`` (5 %) after the warm-up, or when an invariant breaks. Memory is
judged with ``tools/soak.py``'s code.

Commands (figures in benchmarks/results/reliability.md)::

    PYGLET_HEADLESS=1 .venv/bin/python tools/game_soak.py                  # 100,000 frames
    PYGLET_HEADLESS=1 .venv/bin/python tools/game_soak.py --frames 2000 --interval 250
"""

from __future__ import annotations

import argparse
import gc
import json
import random
import shutil
import sys
import tempfile
import time
import tracemalloc
from collections import deque
from collections.abc import Iterator
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

import kge  # noqa: E402
from kge import (  # noqa: E402
    Animator,
    App,
    Behaviour,
    Box,
    Button,
    Camera,
    Circle,
    Clip,
    Collider,
    Label,
    Light,
    Panel,
    ParticleBurst,
    ParticleEmitter,
    RigidBody,
    Slider,
    Sprite,
    Text,
    TextInput,
    Transform,
    Tweens,
    UINode,
    World,
)
from kge.assets import Assets  # noqa: E402
from kge.tilemap.writer import TileLayerSpec, TilesetSpec, write_map  # noqa: E402
from tests.reliability.harness import AppProbe, check_invariants  # noqa: E402
from tools.soak import Fuse, add_run_options, judge_growth, rss_kb  # noqa: E402

MAP_W, MAP_H = 24, 6


# -- internal tables ---------------------------------------------------------------------
def _size(value: Any) -> int | None:
    if isinstance(value, np.ndarray):
        return int(value.shape[0]) if value.ndim else None
    if isinstance(value, deque) and value.maxlen is not None:
        return None  # bounded by construction (a history of recent frames)
    if isinstance(value, (dict, set, frozenset, list, deque)):
        return len(value)
    return None


def _fields(obj: Any) -> Iterator[tuple[str, Any]]:
    names: list[str] = list(getattr(obj, "__dict__", {}))
    for cls in type(obj).__mro__:
        names.extend(getattr(cls, "__slots__", ()))
    for name in dict.fromkeys(names):
        if name.startswith("__"):
            continue
        try:
            yield name, getattr(obj, name)
        except AttributeError:
            continue


def _owned(obj: Any) -> bool:
    """An object of kge's (its tables are walked), not a component, world or app."""
    module = type(obj).__module__
    return module.startswith("kge.") and not isinstance(obj, (World, App, type))


def _walk(obj: Any, path: str, out: dict[str, int], seen: set[int], depth: int) -> None:
    if id(obj) in seen or depth > 4:
        return
    seen.add(id(obj))
    for name, value in _fields(obj):
        size = _size(value)
        where = f"{path}.{name}"
        if size is not None:
            out[where] = out.get(where, 0) + size
            if isinstance(value, dict):  # per-item states (EmitterState...) hold tables too
                items = [v for v in value.values() if _owned(v)]
                for item in items[:64]:
                    _walk(item, where + "[]", out, seen, depth + 1)
        elif _owned(value):
            _walk(value, where, out, seen, depth + 1)


def internal_tables(world: World) -> dict[str, int]:
    """Size of every table (dict, set, list, deque, numpy array's rows) of ``world``'s
    resources and systems, and of the world's own command queue, by attribute path."""
    out: dict[str, int] = {}
    seen: set[int] = set()
    roots: list[tuple[str, Any]] = [
        (type(r).__name__, r) for r in world._resources.values()
    ] + [(type(s).__name__, s) for s in world.schedule.systems()]
    for name, root in roots:
        if _owned(root):
            _walk(root, name, out, seen, 0)
    out["World.entities"] = len(world)
    out["World._queue"] = len(world._queue)
    out["World._dying"] = len(world._dying)
    return out


#: tables allowed to keep what the run filled them with, judged against their size at
#: the end of the warm-up (at most one doubling of slack: pools grow by doubling)
#: instead of their size before the churn, each with its reason
BOUNDED = {
    # caches keyed by content: the soak's four sheet frames, its fonts and looks
    "Animations.state.table.sources": "frame sources of the sheet (content-keyed)",
    "Animations.state.table._source_ids": "frame sources of the sheet (content-keyed)",
    "FrameSizes.": "image sizes checked once per image",
    "UIState.layout.sizer.": "text measures and widget looks (content-keyed)",
    "Tweens._hooked": "component types whose writes tweens watch",
    "RenderSystem.view.groups._orders": "draw orders seen (one per layer)",
    "UIDrawer.groups": "UI draw groups per (kind, depth) and per live clip",
    "Assets._cache": "loaded assets by name (the soak's three files)",
    # physics pools owned by the physics team: capacity kept for the peak population
    "Physics._sim._speed_cap.": "capacity of the speed-cap scratch arrays",
    "Physics._sim.ccd._obstacles.": "CCD obstacle rows (a pool with a free list)",
    "Physics._sim.shapes.": "shape slots (a pool with a free list; a freed slot holds no shape)",
    "Physics._sim.ccd._index": "CCD index, refreshed at its next query",
    "Physics._sim.ccd._untracked": "CCD rows of the last query",
}


def _bounded(name: str) -> bool:
    return any(name.startswith(prefix) for prefix in BOUNDED)


def table_problems(before: dict[str, int], warm: dict[str, int], last: dict[str, int],
                   peak: dict[str, int], after: dict[str, int]) -> list[str]:
    """Tables larger after the teardown than before the churn. The :data:`BOUNDED` ones
    may keep what they were filled with, but must not have grown past twice their size
    at the end of the warm-up by the last sample, nor past their peak during the churn
    after the teardown."""
    problems = []
    for name, size in sorted(after.items()):
        if _bounded(name) and name.endswith("._free"):
            continue  # a pool's free rows: bounded by its capacity, which is judged
        if not _bounded(name):
            if size > before.get(name, 0):
                problems.append(
                    f"table {name}: {before.get(name, 0)} before the churn, {size} after the "
                    "teardown")
            continue
        cap = 2 * max(warm.get(name, 0), before.get(name, 0))
        if last.get(name, 0) > cap:
            problems.append(f"table {name}: {warm.get(name, 0)} at the end of the warm-up, "
                            f"{last[name]} at the end of the run")
        top = max(peak.get(name, 0), before.get(name, 0))
        if size > top:
            problems.append(f"table {name}: at most {top} during the churn, {size} after "
                            "the teardown")
    return problems


# -- the churn ---------------------------------------------------------------------------
def make_assets() -> Path:
    """A sprite sheet, a tile image and a 24 x 6 tile map in a new temporary folder."""
    from kge.testing import write_png

    root = Path(tempfile.mkdtemp(prefix="kge-game-soak-"))
    sheet = np.zeros((16, 64, 4), np.uint8)
    sheet[..., 0] = np.arange(64, dtype=np.uint8)[None, :] * 4
    sheet[..., 3] = 255
    write_png(sheet, root / "sheet.png")
    write_png(np.full((16, 16, 4), 255, np.uint8), root / "t.png")
    ts = TilesetSpec("t", "t.png", 16, 16, columns=1, count=1, image_size=(16, 16))
    grid = np.zeros((MAP_H, MAP_W), int)
    grid[MAP_H - 1, :] = 1
    write_map(root / "m.tmx", 16, 16, [ts], [TileLayerSpec("Ground", grid)])
    return root


class GameChurn:
    """Spawns and retires actors, widgets, tiles and overlays; see the module docstring."""

    def __init__(self, seed: int, population: int, assets: Path) -> None:
        self.rng = random.Random(seed)
        self.population = population
        self.assets = assets
        self.spawned = 0
        self.overlays = 0
        self.manual: list[tuple[int, int]] = []  # (despawn at frame, entity), sorted
        self.churned: set[int] = set()
        self.panel = 0
        self.tmap: Any = None
        self.overlay_until = 0

    # scenes
    def scene(self, world: World) -> None:
        world.insert_resource(Assets(self.assets, anchor=self.assets))
        world.spawn(Camera(pixels_per_meter=16))
        self.tmap = kge.load_map(world, self.assets / "m.tmx", origin=(-12.0, -3.0),
                                 solid_layers=["Ground"])
        world.spawn(Transform(-12.5, 0.0), Collider(Box(0.5, 8.0)))
        world.spawn(Transform(12.5, 0.0), Collider(Box(0.5, 8.0)))
        world.spawn(Transform(0.0, 2.0), Light(radius=8.0))
        self.panel = world.spawn(UINode(width=200, height=400, layout="column"), Panel())

    def overlay(self, world: World) -> None:
        world.insert_resource(Assets(self.assets, anchor=self.assets))
        world.spawn(Camera(pixels_per_meter=16))
        root = world.spawn(UINode(width=160, height=120, layout="column"), Panel())
        world.spawn(UINode(parent=root), Label("paused"))
        world.spawn(UINode(parent=root), Button("resume"))
        hero = self._actor_parts(world, 0.0, 0.0, body=False)
        e = world.spawn(*hero)
        world.resource(Tweens).to(e, Transform, "x", 2.0, 0.2, repeat=-1, yoyo=True)

    # pieces
    def _clip(self) -> Clip:
        # a new Clip each time, with a duration of its own: the per-entity clip case
        return Clip.grid("sheet.png", (4, 1), duration=0.05 + 0.001 * self.rng.randint(0, 50))

    def _actor_parts(self, world: World, x: float, y: float, body: bool) -> list[Any]:
        rng = self.rng
        parts: list[Any] = [
            Transform(x, y, rng.uniform(-3.0, 3.0)),
            Sprite("sheet.png", size=(0.5, 0.5)),
            Animator({"walk": self._clip(), "idle": self._clip()}),
        ]
        if rng.random() < 0.4:  # live emitters cost the most per frame: 2 in 5 actors
            parts.append(ParticleEmitter(
                rate=rng.choice((0.0, 30.0)), lifetime=(0.1, 0.3), speed=(0.5, 2.0),
                spread=1.0, max_particles=16, seed=rng.randint(0, 1 << 30)))
        if body:
            shape = Circle(rng.uniform(0.1, 0.3)) if rng.random() < 0.5 else Box(0.2, 0.15)
            parts += [RigidBody(velocity=(rng.uniform(-2, 2), 0.0)),
                      Collider(shape, friction=0.5)]
        if rng.random() < 0.25:
            parts.append(Light(radius=rng.uniform(1.0, 3.0), color=(255, 200, 120)))
        if rng.random() < 0.2:
            parts.append(Text(rng.choice(("ouch", "+1", "hit", "zap")), size=0.4))
        return parts

    def _retire(self, world: World, entity: int, frame: int, life: int) -> None:
        self.manual.append((frame + life, entity))
        self.churned.add(entity)

    def tick(self, app: App, frame: int) -> None:
        rng = self.rng
        world = app.world
        if app.scenes and len(app.scenes) > 1:  # an overlay is up
            if frame >= self.overlay_until:
                app.pop_scene()
            self._expire(app.worlds[0], frame)
            return
        life = self.population + rng.randint(-20, 20)
        body = rng.random() < 0.5
        parts = self._actor_parts(world, rng.uniform(-10.0, 10.0), 2.0, body)
        if rng.random() < 0.5:
            parts.append(Behaviour(Fuse(life)))  # dies from a behaviour
            entity = world.spawn(*parts)
            self.churned.add(entity)
        else:
            entity = world.spawn(*parts)  # dies from here
            self._retire(world, entity, frame, life)
        self.spawned += 1
        tweens = world.resource(Tweens)
        if body:
            tweens.to(entity, Sprite, "opacity", 60, 0.3 + 0.01 * rng.randint(0, 30))
        else:
            tweens.to(entity, Transform, "x", rng.uniform(-10.0, 10.0), rng.uniform(0.2, 1.0),
                      ease="sine_in_out")
        if frame % 4 == 0:  # a widget joins the panel
            widget = rng.choice((
                lambda: Button("go"), lambda: Label("score"), lambda: Slider(0.0, 1.0, 0.5),
                lambda: TextInput("name", max_length=16),
            ))()
            w = world.spawn(UINode(parent=self.panel, height=20), widget)
            self._retire(world, w, frame, 4 * self.population // 10)
        if frame % 10 == 0:  # a burst on some live emitter
            live = [e for e, _ in world.query(ParticleEmitter)]
            if live:
                world.emit(ParticleBurst(rng.choice(live), rng.randint(1, 12)))
        if frame % 7 == 0 and self.tmap is not None:  # dig or refill a floor tile
            x = rng.randrange(1, MAP_W - 1)
            if self.tmap.tile_at((x - 12.0 + 0.5, -3.0 + 0.5)):
                self.tmap.clear_tile("Ground", x, MAP_H - 1)
            else:
                self.tmap.set_tile("Ground", x, MAP_H - 1, 1)
        if frame % 500 == 250:  # a pause overlay with its own game layer
            app.push_scene(self.overlay, overlay=True)
            self.overlay_until = frame + 20
            self.overlays += 1
        self._expire(world, frame)

    def _expire(self, world: World, frame: int) -> None:
        self.manual.sort()
        while self.manual and self.manual[0][0] <= frame:
            _, e = self.manual.pop(0)
            if world.exists(e):
                world.despawn(e)

    def teardown(self, app: App) -> None:
        """Pop the overlays, despawn everything churned, refill the floor."""
        while len(app.scenes) > 1:
            app.pop_scene()
            app.step()
        world = app.world
        for e in sorted(self.churned):
            if world.exists(e):
                world.despawn(e)
        self.manual.clear()
        self.churned.clear()
        for x in range(MAP_W):
            if not self.tmap.tile_at((x - 12.0 + 0.5, -3.0 + 0.5)):
                self.tmap.set_tile("Ground", x, MAP_H - 1, 1)


# -- the run -----------------------------------------------------------------------------
@dataclass
class Sample:
    frame: int
    heap_kb: float  #: tracemalloc's traced memory (0 without tracemalloc)
    rss_kb: float
    blocks: int  #: the Python allocator's blocks in use (sys.getallocatedblocks)
    objects: int  #: objects the garbage collector tracks
    entities: int
    clips: int
    tween_rows: int
    particles: int
    bodies: int


@dataclass
class Report:
    frames: int
    seconds: float = 0.0
    samples: list[Sample] = field(default_factory=list)
    spawned: int = 0
    overlays: int = 0
    heap_growth: float = 0.0
    rss_growth: float = 0.0
    before: dict[str, int] = field(default_factory=dict)
    warm: dict[str, int] = field(default_factory=dict)
    last: dict[str, int] = field(default_factory=dict)
    peak: dict[str, int] = field(default_factory=dict)
    after: dict[str, int] = field(default_factory=dict)
    ok: bool = True
    problems: list[str] = field(default_factory=list)


def _render_ok() -> bool:
    try:
        import pyglet.gl  # noqa: F401

        from kge.render.setup import ensure_renderer  # noqa: F401
    except Exception:  # no GL here: the churn runs without drawing
        return False
    return True


def run(
    frames: int,
    interval: int,
    population: int = 100,
    seed: int = 1,
    warmup: float = 0.2,
    max_growth: float = 0.05,
    render_every: int = 20,
    log: Any = None,
    trace: bool = True,
) -> Report:
    assets = make_assets()
    churn = GameChurn(seed, population, assets)
    app = App(churn.scene, headless=True)
    probe = AppProbe(app)
    render = render_every > 0 and _render_ok()
    report = Report(frames=frames)
    warm_frame = max(interval, int(frames * warmup) // interval * interval)
    if trace:
        tracemalloc.start()
    started = time.perf_counter()

    def frame_step(frame: int) -> None:
        probe.step()
        if render and frame % render_every == 0:
            app.render()

    try:
        for frame in range(1, 11):  # the scene settles: the tables' size before the churn
            frame_step(frame)
        if render:
            app.render()
        gc.collect()
        report.before = internal_tables(app.world)
        for frame in range(1, frames + 1):
            churn.tick(app, frame)
            frame_step(frame)
            if frame % interval == 0:
                gc.collect()  # measure what is retained, not garbage awaiting the collector
                base = app.worlds[0]
                if app.world is base:
                    check_invariants(probe)
                tables = internal_tables(base)
                if frame == warm_frame:
                    report.warm = tables
                report.last = tables
                for name, size in tables.items():
                    report.peak[name] = max(report.peak.get(name, 0), size)
                s = Sample(
                    frame=frame,
                    heap_kb=tracemalloc.get_traced_memory()[0] / 1024.0 if trace else 0.0,
                    rss_kb=rss_kb(), blocks=sys.getallocatedblocks(),
                    objects=len(gc.get_objects()), entities=len(base),
                    clips=tables.get("Animations.state.table._ends", 0),
                    tween_rows=tables.get("Tweens.group", 0),
                    particles=sum(v for k, v in tables.items() if k.endswith("pool.data")),
                    bodies=len(probe.sim.space.bodies) if app.world is base else -1,
                )
                report.samples.append(s)
                if log is not None:
                    log.write(json.dumps({**asdict(s), "tables": tables}) + "\n")
                    log.flush()
        churn.teardown(app)
        for frame in range(frames + 1, frames + 121):  # tweens end, particles die
            frame_step(frame)
        if render:
            app.render()
        check_invariants(probe)
        gc.collect()
        report.after = internal_tables(app.world)
        if not report.warm:
            report.warm = dict(report.after)
        report.problems.extend(table_problems(
            report.before, report.warm, report.last, report.peak, report.after))
    except AssertionError as err:
        report.problems.append(f"invariant broken: {err}")
    finally:
        report.seconds = time.perf_counter() - started
        tracemalloc.stop()
        report.spawned = churn.spawned
        report.overlays = churn.overlays
        app.close()
        shutil.rmtree(assets, ignore_errors=True)
    # the heap is tracemalloc's figure, or without it the allocator's block count
    report.heap_growth, report.rss_growth, grew = judge_growth(
        [(s.frame, s.heap_kb if trace else float(s.blocks), s.rss_kb)
         for s in report.samples], warm_frame, max_growth)
    report.problems.extend(grew)
    report.ok = not report.problems
    return report


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--frames", type=int, default=100_000)
    add_run_options(p)
    p.add_argument("--render-every", type=int, default=20, help="0: never draw")
    p.add_argument("--tables", help="write the table sizes (before, warm, after) as JSON here")
    args = p.parse_args(argv)
    log = open(args.log, "w") if args.log else None  # noqa: SIM115
    try:
        rep = run(args.frames, args.interval, args.population, args.seed,
                  max_growth=args.max_growth, render_every=args.render_every, log=log,
                  trace=not args.no_tracemalloc)
    finally:
        if log is not None:
            log.close()
    if args.tables:
        Path(args.tables).write_text(json.dumps(
            {"before": rep.before, "warm": rep.warm, "last": rep.last, "peak": rep.peak,
             "after": rep.after}, indent=1))
    print(f"frames {rep.frames} in {rep.seconds:.0f} s; spawned {rep.spawned} actors, "
          f"{rep.overlays} overlays")
    if rep.samples:
        first, last = rep.samples[0], rep.samples[-1]
        print(f"heap {first.heap_kb:.0f} KiB at frame {first.frame} -> {last.heap_kb:.0f} KiB; "
              f"blocks {first.blocks} -> {last.blocks}; gc objects {first.objects} -> "
              f"{last.objects} (heap growth after warm-up {rep.heap_growth:+.2%})")
        print(f"RSS {first.rss_kb:.0f} KiB -> {last.rss_kb:.0f} KiB "
              f"(growth after warm-up {rep.rss_growth:+.2%})")
    for name in sorted(rep.after):
        b, w, a = rep.before.get(name, 0), rep.warm.get(name, 0), rep.after[name]
        end, top = rep.last.get(name, 0), rep.peak.get(name, 0)
        if b or w or a:
            print(f"  {name}: before {b}, warm-up end {w}, run end {end}, peak {top}, "
                  f"after teardown {a}")
    for problem in rep.problems:
        print("PROBLEM:", problem)
    print("OK" if rep.ok else "FAILED")
    return 0 if rep.ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
