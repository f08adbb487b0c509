"""Tile map loading and drawing: a generated cave map of N x N tiles (60 % solid).

What is timed, in one run:

* ``load_s``: ``kge.load_map`` on a TMX file (CSV data) written beforehand:
  parsing (pytiled-parser), numpy grids, tracing the solid outlines, spawning
  the static colliders, and the first physics step that puts them into the
  pymunk space; the map's drawing data is its numpy grid, so nothing else is
  built up front (chunk vertex lists are made when they come into view);
* ``colliders`` / ``solid``: static collider entities beside solid tiles;
* ``frame_ms``: a steady ``app.render()`` of a fixed 25 x 20 m view, median,
  on the N x N map and on a 100 x 100 map of the same caves, headless EGL:
  their ratio shows the frame cost does not grow with the map.

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
    from kge.schedule import Stage
    from kge.systems.physics import PhysicsPlugin
    from kge.tilemap import load_map
    from kge.world import World

    world = World()
    world.add_plugins(PhysicsPlugin())
    t0 = time.perf_counter()
    m = load_map(world, path)
    world.schedule.run(Stage.FIXED, 1 / 60)
    load_s = time.perf_counter() - t0
    solid = int(np.count_nonzero(m.layer("Rock").gids))
    out = {"load_s": load_s, "colliders": float(len(m.collider_entities)), "solid": float(solid)}
    world.close()
    return out


def frame_ms(path: Path, frames: int) -> float:
    from kge import App
    from kge.components.camera import Camera
    from kge.tilemap import load_map

    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(50.0, 50.0), pixels_per_meter=32))
        load_map(world, path)

    app = App(setup, headless=True, size=(800, 640))
    try:
        app.render()  # the first frame builds the visible chunks
        times = []
        for _ in range(frames):
            t0 = time.perf_counter()
            app.render()
            times.append((time.perf_counter() - t0) * 1000)
        return statistics.median(times)
    finally:
        app.close()


def measure(n: int = 1000, frames: int = 30) -> dict[str, float]:
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        big = write_cave_map(folder, n)
        small = write_cave_map(folder, 100)
        out = load_once(big)
        try:
            out["frame_ms"] = frame_ms(big, frames)
            out["frame_ms_100"] = frame_ms(small, frames)
        except Exception as err:  # no GL: the load figures still stand
            out["frame_error"] = float("nan")
            print(f"tilemap frame timing skipped: {type(err).__name__}: {err}", file=sys.stderr)
    out["size"] = float(n)
    return out


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n")[0])
    parser.add_argument("--size", type=int, default=1000)
    args = parser.parse_args(argv)
    r = measure(args.size)
    for k, v in r.items():
        print(f"{k:>14} {v:.4g}")
    print(f"{'colliders/solid':>14} {r['colliders'] / r['solid']:.4%}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
