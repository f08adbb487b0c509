"""Tile map loading and drawing: a generated cave map of N x N tiles (60 % solid).

What is timed, in one run:

* ``load_s``: ``kge.load_map`` on a TMX file (CSV data) written beforehand:
  parsing (kge.tilemap.source), numpy grids, tracing the solid outlines, spawning
  the static colliders, and the first physics step that puts them into the
  pymunk space; the map's drawing data is its numpy grid, so nothing else is
  built up front (chunk vertex lists are made when they come into view);
* ``colliders`` / ``solid``: static collider entities beside solid tiles;
* ``frame_ms``: a steady ``app.render()`` of a fixed 25 x 20 m view, median,
  on the N x N map and on a 100 x 100 map of the same caves, headless EGL:
  their ratio shows the frame cost does not grow with the map.

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


def write_cave_map(folder: Path, n: int) -> Path:
    img = np.zeros((16, 32, 4), np.uint8)
    img[:, :16] = (90, 70, 50, 255)
    img[:, 16:] = (60, 120, 60, 255)
    png.write(folder / "cave.png", img)
    ts = TilesetSpec(
        "cave",
        "cave.png",
        16,
        16,
        columns=2,
        count=2,
        image_size=(32, 16),
        tiles={0: {"properties": {"solid": True}}},
    )
    grid = np.where(cave_cells(n), 1, 0)
    path = folder / f"caves{n}.tmx"
    write_map(path, 16, 16, [ts], [TileLayerSpec("Rock", grid)])
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
    out = {
        "load_s": load_s,
        "map_s": t1 - t0,
        "step_s": load_s - (t1 - t0),
        "colliders": float(len(m.collider_entities)),
        "solid": float(solid),
        "segments": float(segments),
    }
    world.close()
    return out


def frame_ms(path: Path, frames: int) -> tuple[float, int]:
    """(median ms of a steady frame, tile chunks in the batch) for a fixed view."""
    from kge import App
    from kge.components.camera import Camera
    from kge.tilemap import load_map

    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(50.0, 50.0), pixels_per_meter=32))
        load_map(world, path)

    app = App(setup, headless=True, size=(800, 640))
    try:
        for _ in range(10):  # the first frame builds the visible chunks; then settle
            app.render()
        times = []
        for _ in range(frames):
            t0 = time.perf_counter()
            app.render()
            times.append((time.perf_counter() - t0) * 1000)
        from kge.render.passes import RenderPasses

        (draw,) = [
            p
            for p in app.world.resource(RenderPasses).before()
            if getattr(p, "__name__", "") == "draw_maps"
        ]
        chunks = draw.state["renderer"].chunk_count  # type: ignore[attr-defined]
        return statistics.median(times), chunks
    finally:
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
        kge_runs: list[dict[str, float]] = []
        arcade_runs: list[float] = []
        for _ in range(rounds):  # interleaved: a burst of load hits both
            kge_runs.append(load_once(big))
            arcade = arcade_seconds(big)
            if arcade is not None:
                arcade_runs.append(arcade)
        out = {k: statistics.median(r[k] for r in kge_runs) for k in kge_runs[0]}
        if arcade_runs:
            out["arcade_s"] = statistics.median(arcade_runs)
        try:
            frame_ms(small, frames)  # warm-up: the first App pays for GL start-up
            out["frame_ms"], chunks = frame_ms(big, frames)
            out["frame_ms_100"], chunks_100 = frame_ms(small, frames)
            out["chunks"], out["chunks_100"] = float(chunks), float(chunks_100)
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
    args = parser.parse_args(argv)
    r = measure(args.size, rounds=args.rounds)
    for k, v in r.items():
        print(f"{k:>14} {v:.4g}")
    print(f"{'colliders/solid':>14} {r['colliders'] / r['solid']:.4%}")
    return 0


if __name__ == "__main__":
    sys.exit(main())


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

    ratio = None
    if r.get("frame_ms") and r.get("frame_ms_100"):
        ratio = r["frame_ms"] / r["frame_ms_100"]
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
    ]


def table(r: dict[str, float]) -> str:
    keys = ("size", "solid", "colliders", "segments", "load_s", "map_s", "step_s", "arcade_s",
            "frame_ms", "frame_ms_100", "chunks", "chunks_100", "loadavg")  # fmt: skip
    return "  ".join(f"{k} {r[k]:.4g}" for k in keys if k in r)
