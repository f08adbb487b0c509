"""Tile map loading and drawing: a generated cave map of N x N tiles (60 % solid).

What is timed, in one run:

* ``load_s``: ``kge.load_map`` on a TMX file (CSV data) written beforehand:
  parsing (kge.tilemap.source), numpy grids, tracing the solid outlines, spawning
  the static colliders, and the first physics step that puts them into the
  pymunk space; the map's drawing data is its numpy grid, so nothing else is
  built up front (chunk vertex lists are made when they come into view);
* ``colliders`` / ``solid``: static collider entities beside solid tiles;
* ``snapshot_s`` / ``snapshot_mb``: ``world.snapshot()`` of the loaded world (the map
  goes along whole: its grids, collision outlines and collider entities);
* ``frame_ms``: a steady ``app.render()`` of a fixed 25 x 20 m view until GL has
  finished it, median, on the N x N map and on a 100 x 100 map of the same caves,
  headless EGL: their ratio shows the frame cost does not grow with the map;
* ``iso_*``: the same figures for the same caves on an **isometric** map (32 x 16 px
  diamonds; one tile is 1 m wide, so the view shows twice the cells), loaded and
  drawn interleaved with the orthogonal one: their ratios are what the orientation
  costs.

* ``map_s`` / ``step_s``: the two parts of ``load_s``: ``load_map`` itself
  (parse, outline tracing, spawning) and the first step (the physics system
  builds the chains' pymunk segments and the CCD obstacle rows);
* ``arcade_s``: Arcade 3's ``load_tilemap`` on the same file, in its own
  virtual environment (``.venv-arcade``, which ``make bench`` creates, or the
  Python named by ``KGE_ARCADE_PYTHON``; see ``benchmarks/arcade_tilemap.py``);
  it builds one sprite per tile. kge and Arcade run interleaved (kge, Arcade,
  kge, Arcade...) and each figure is the median of its rounds, so a burst of
  load on this shared machine hits both;
* ``loadavg``: the 1-minute load average when the run started.

Run ``python benchmarks/tilemap.py --size 1000`` for the figures.
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

os.environ.setdefault("PYGLET_HEADLESS", "1")

import numpy as np

from kge.testbed import png
from kge.testbed.samples.tilemaps import cave_cells
from kge.tilemap.writer import TileLayerSpec, TilesetSpec, write_map


def write_cave_map(folder: Path, n: int, orientation: str = "orthogonal") -> Path:
    """The n x n caves as a map of 16 x 16 px squares, or of 32 x 16 px diamonds."""
    iso = orientation == "isometric"
    tw, th = (32, 16) if iso else (16, 16)
    img = np.zeros((th, 2 * tw, 4), np.uint8)
    img[:, :tw] = (90, 70, 50, 255)
    img[:, tw:] = (60, 120, 60, 255)
    if iso:  # transparent outside the diamond
        y, x = np.mgrid[0:th, 0:tw] + 0.5
        outside = np.abs(x - tw / 2) / (tw / 2) + np.abs(y - th / 2) / (th / 2) > 1
        img[:, :tw][outside] = 0
        img[:, tw:][outside] = 0
    name = f"cave-{orientation}.png"
    png.write(folder / name, img)
    ts = TilesetSpec(
        "cave",
        name,
        tw,
        th,
        columns=2,
        count=2,
        image_size=(2 * tw, th),
        tiles={0: {"properties": {"solid": True}}},
    )
    grid = np.where(cave_cells(n), 1, 0)
    path = folder / f"caves{n}-{orientation}.tmx"
    write_map(path, tw, th, [ts], [TileLayerSpec("Rock", grid)], orientation=orientation)
    return path


def load_once(path: Path) -> dict[str, float]:
    from kge.components.collider import Collider
    from kge.components.shapes import Chain
    from kge.schedule import Stage
    from kge.systems.physics import PhysicsPlugin
    from kge.tilemap import load_map
    from kge.world import World

    world = World()
    world.add_plugins(PhysicsPlugin())
    t0 = time.perf_counter()
    m = load_map(world, path)
    t1 = time.perf_counter()
    world.schedule.run(Stage.FIXED, 1 / 60)
    load_s = time.perf_counter() - t0
    solid = int(np.count_nonzero(m.layer("Rock").gids))
    shapes = [world.get(e, Collider).shape for e in m.collider_entities]
    segments = sum(len(s.vertices) for s in shapes if isinstance(s, Chain))
    t2 = time.perf_counter()
    saved = world.snapshot()  # the map goes along whole (kge.tilemap.runtime)
    snapshot_s = time.perf_counter() - t2
    out = {
        "load_s": load_s,
        "map_s": t1 - t0,
        "step_s": load_s - (t1 - t0),
        "colliders": float(len(m.collider_entities)),
        "solid": float(solid),
        "segments": float(segments),
        "snapshot_s": snapshot_s,
        "snapshot_mb": len(saved) / 1e6,
    }
    world.close()
    return out


def frames_ms(paths: dict[str, Path], frames: int) -> dict[str, tuple[float, int]]:
    """name -> (median ms of a steady frame, tile chunks in the batch), each map drawn
    in its own App over a fixed view (at (50, 50) m on orthogonal maps, on cell
    (50, 50) on isometric ones). The Apps take turns frame by frame, so a burst of
    load on the machine hits all of them; a frame is timed until GL has finished it."""
    from pyglet import gl

    from kge import App
    from kge.components.camera import Camera
    from kge.render.passes import RenderPasses
    from kge.tilemap import load_map

    def scene(path: Path) -> Any:
        def setup(world: Any) -> None:
            cam = world.insert_resource(Camera(center=(50.0, 50.0), pixels_per_meter=32))
            m = load_map(world, path)
            if m.orientation == "isometric":
                cam.center = m.cell_center(50, 50)

        return setup

    apps = {name: App(scene(path), headless=True, size=(800, 640)) for name, path in paths.items()}
    try:
        for _ in range(10):  # the first frame builds the visible chunks; then settle
            for app in apps.values():
                app.render()
        gl.glFinish()
        times: dict[str, list[float]] = {name: [] for name in apps}
        for _ in range(frames):
            for name, app in apps.items():
                t0 = time.perf_counter()
                app.render()
                gl.glFinish()  # the frame's GL work done (llvmpipe draws it on the CPU)
                times[name].append((time.perf_counter() - t0) * 1000)
        out = {}
        for name, app in apps.items():
            (draw,) = [
                p
                for p in app.world.resource(RenderPasses).before()
                if getattr(p, "__name__", "") == "draw_maps"
            ]
            chunks = draw.state["renderer"].chunk_count  # type: ignore[attr-defined]
            out[name] = (statistics.median(times[name]), chunks)
        return out
    finally:
        for app in apps.values():
            app.close()


ARCADE_PYTHON = Path(__file__).resolve().parents[1] / ".venv-arcade" / "bin" / "python"


def arcade_seconds(path: Path, layer: str = "Rock") -> float | None:
    """Arcade 3's load_tilemap time on ``path``, or None when there is no Arcade Python."""
    import subprocess

    python = os.environ.get("KGE_ARCADE_PYTHON") or str(ARCADE_PYTHON)
    if not Path(python).exists():
        return None
    script = Path(__file__).with_name("arcade_tilemap.py")
    done = subprocess.run(
        [python, str(script), str(path), layer], capture_output=True, text=True, check=True
    )
    return float(done.stdout.split()[0])


def measure(n: int = 1000, frames: int = 60, rounds: int = 2) -> dict[str, float]:
    loadavg = os.getloadavg()[0]
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        big = write_cave_map(folder, n)
        small = write_cave_map(folder, 100)
        iso_big = write_cave_map(folder, n, "isometric")
        iso_small = write_cave_map(folder, 100, "isometric")
        kge_runs: list[dict[str, float]] = []
        iso_runs: list[dict[str, float]] = []
        arcade_runs: list[float] = []
        for _ in range(rounds):  # interleaved: a burst of load hits all of them
            kge_runs.append(load_once(big))
            iso_runs.append(load_once(iso_big))
            arcade = arcade_seconds(big)
            if arcade is not None:
                arcade_runs.append(arcade)
        out = {k: statistics.median(r[k] for r in kge_runs) for k in kge_runs[0]}
        out.update({f"iso_{k}": statistics.median(r[k] for r in iso_runs) for k in iso_runs[0]})
        if arcade_runs:
            out["arcade_s"] = statistics.median(arcade_runs)
        try:
            frames_ms({"warm-up": small}, 5)  # the first App pays for GL start-up
            maps = {"frame_ms": big, "frame_ms_100": small,
                    "iso_frame_ms": iso_big, "iso_frame_ms_100": iso_small}  # fmt: skip
            for key, (ms, chunks) in frames_ms(maps, frames).items():
                out[key] = ms
                out[key.replace("frame_ms", "chunks")] = float(chunks)
        except Exception as err:  # no GL: the load figures still stand
            out["frame_error"] = float("nan")
            print(f"tilemap frame timing skipped: {type(err).__name__}: {err}", file=sys.stderr)
    out["size"] = float(n)
    out["loadavg"] = loadavg
    return out


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n")[0])
    parser.add_argument("--size", type=int, default=1000)
    parser.add_argument("--rounds", type=int, default=2)
    parser.add_argument("--json", help="also write the figures and targets to this file")
    args = parser.parse_args(argv)
    r = measure(args.size, rounds=args.rounds)
    for k, v in r.items():
        print(f"{k:>16} {v:.4g}")
    print(f"{'colliders/solid':>16} {r['colliders'] / r['solid']:.4%}")
    goals = targets(r)
    for t in goals:
        value = "-" if t["value"] is None else f"{t['value']:.3g}"
        print(f"  {t['target']:<66} {value:>8}  goal <= {t['goal']}  {t['met']}")
    if args.json:
        import json

        Path(args.json).write_text(json.dumps({"figures": r, "targets": goals}, indent=2) + "\n")
    return 0


# -- the `kge bench` section (called from benchmarks/run.py) -----------------------------------
def run_section(quick: bool, progress: Any) -> tuple[dict[str, float], str | None]:
    """The figures for ``kge bench`` (200 x 200 with --quick), or why they are missing."""
    n = 200 if quick else 1000
    progress(f"tilemap [{n} x {n} caves]")
    try:
        return measure(n, frames=20 if quick else 60, rounds=1 if quick else 2), None
    except Exception as err:  # report, never fail the whole run
        return {}, f"tilemap skipped: {type(err).__name__}: {err}"


def targets(r: dict[str, float]) -> list[dict[str, Any]]:
    """The issue's tile map targets beside the measured figures."""
    n = int(r.get("size", 0))

    def row(what: str, value: float | None, goal: float, unit: str = "") -> dict[str, Any]:
        met = None if value is None or value != value else value <= goal
        return {
            "target": what,
            "value": value,
            "goal": goal,
            "at_most": True,
            "unit": unit,
            "met": met,
        }

    def ratio_of(a: str, b: str) -> float | None:
        return r[a] / r[b] if r.get(a) and r.get(b) else None

    ratio = ratio_of("frame_ms", "frame_ms_100")
    iso = [
        row(f"tilemap {n}x{n} isometric caves: load + collision + first step",
            r.get("iso_load_s"), 3.0, "s"),
        row(f"tilemap {n}x{n} caves: world.snapshot() (map carried whole) / load",
            ratio_of("snapshot_s", "load_s"), 0.1),
        row(f"tilemap {n}x{n} load: isometric / orthogonal", ratio_of("iso_load_s", "load_s"),
            1.5),
        row(f"tilemap frame, fixed view: isometric {n}x{n} / 100x100",
            ratio_of("iso_frame_ms", "iso_frame_ms_100"), 1.25),
        row(f"tilemap {n}x{n} frame: isometric / orthogonal (2x the cells in view)",
            ratio_of("iso_frame_ms", "frame_ms"), 3.0),
    ]  # fmt: skip
    return [
        row(f"tilemap {n}x{n} caves: load + collision + first step", r.get("load_s"), 3.0, "s"),
        row(
            f"tilemap {n}x{n}: static colliders / solid tiles",
            r["colliders"] / r["solid"] if r.get("solid") else None,
            0.05,
        ),
        row(f"tilemap frame, fixed view: {n}x{n} map / 100x100 map", ratio, 1.25),
        row(
            f"tilemap {n}x{n} load: kge / Arcade 3 load_tilemap",
            r["load_s"] / r["arcade_s"] if r.get("arcade_s") else None,
            1.0,
        ),
        *iso,
    ]


def table(r: dict[str, float]) -> str:
    keys = ("size", "solid", "colliders", "segments", "load_s", "map_s", "step_s", "arcade_s",
            "frame_ms", "frame_ms_100", "chunks", "chunks_100", "iso_colliders", "iso_load_s",
            "iso_map_s", "iso_step_s", "iso_frame_ms", "iso_frame_ms_100", "iso_chunks",
            "snapshot_s", "snapshot_mb", "loadavg")  # fmt: skip
    return "  ".join(f"{k} {r[k]:.4g}" for k in keys if k in r)


if __name__ == "__main__":
    sys.exit(main())
