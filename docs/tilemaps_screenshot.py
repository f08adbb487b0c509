"""Make ``docs/images/tilemap-<orientation>.png``: one generated map per Tiled orientation.

Run ``python docs/tilemaps_screenshot.py`` (headless is fine: it renders offscreen
through EGL, 8 bits per channel). Each map is written by code (terrain tiles in the
orientation's cell shape, a river, and a second layer of taller blocks that Tiled
draws bottom-aligned, so the rows behind are overlapped by those in front), loaded
with ``kge.load_map`` and drawn by kge's tile renderer.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import Any

os.environ.setdefault("PYGLET_HEADLESS", "1")
sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

import numpy as np

from kge import App
from kge.components.camera import Camera
from kge.testbed import png
from kge.tilemap import load_map
from kge.tilemap.writer import TileLayerSpec, TilesetSpec, write_map

#: orientation -> (tile width, tile height, hexsidelength)
TILES = {
    "orthogonal": (32, 32, 0),
    "isometric": (64, 32, 0),
    "staggered": (64, 32, 0),
    "hexagonal": (56, 48, 24),
}
#: grass, dark grass, sand, water, stone
TERRAIN = [(92, 160, 72), (70, 132, 60), (214, 196, 132), (64, 120, 200), (140, 140, 150)]
LIFT = 24  # pixels a block stands above its cell
SIZE = (560, 360)
COLS, ROWS = 12, 12


def cell_mask(orientation: str, w: int, h: int, side: int) -> np.ndarray:
    """The cell's shape inside its w x h box, at pixel centres."""
    y, x = np.mgrid[0:h, 0:w] + 0.5
    if orientation == "orthogonal":
        return np.ones((h, w), bool)
    if orientation in ("isometric", "staggered"):
        return np.abs(x - w / 2) / (w / 2) + np.abs(y - h / 2) / (h / 2) <= 1.0
    b = (h - side) / 2  # pointy-top hexagon (stagger axis y)
    top = np.abs(x - w / 2) / (w / 2) * b
    return (y >= top) & (y <= h - top)


def shade(colour: tuple[int, int, int], k: float) -> tuple[int, int, int]:
    r, g, b = (int(min(255, max(0, c * k))) for c in colour)
    return (r, g, b)


def sheet(orientation: str) -> tuple[np.ndarray, np.ndarray]:
    """(terrain sheet, block sheet): one tile per terrain; blocks LIFT px taller."""
    w, h, side = TILES[orientation]
    m = cell_mask(orientation, w, h, side)
    rng = np.random.default_rng(7)
    ground = np.zeros((h, w * len(TERRAIN), 4), np.uint8)
    for i, c in enumerate(TERRAIN):
        tile = ground[:, i * w : (i + 1) * w]
        noise = rng.uniform(0.9, 1.08, (h, w))
        rows = np.linspace(1.12, 0.86, h)[:, None]  # lit from the top
        for ch in range(3):
            tile[..., ch] = np.clip(c[ch] * noise * rows, 0, 255).astype(np.uint8)
        edge = m & ~np.pad(m, 1)[2:, 1:-1]  # the cell's lower edge: a darker rim
        tile[..., 3] = np.where(m, 255, 0)
        tile[edge, :3] = np.array(shade(c, 0.6), np.uint8)
    blocks = np.zeros((h + LIFT, w * 2, 4), np.uint8)
    for i, c in enumerate([(178, 112, 76), (150, 150, 164)]):  # brick, stone
        tile = blocks[:, i * w : (i + 1) * w]
        for s in range(LIFT, 0, -1):  # the sides, darker towards the bottom
            k = 0.55 + 0.25 * (LIFT - s) / LIFT
            region = tile[s : s + h]
            left = np.mgrid[0:h, 0:w][1] < w / 2
            region[m & left] = (*shade(c, k), 255)
            region[m & ~left] = (*shade(c, k * 0.8), 255)
        tile[0:h][m] = (*shade(c, 1.1), 255)  # the top
    return ground, blocks


def grids() -> tuple[np.ndarray, np.ndarray]:
    r, c = np.mgrid[0:ROWS, 0:COLS]
    ground = np.where((r + c) % 3 == 0, 2, 1)  # grass, a little darker every third
    river = np.abs(c - r // 2 - 3) <= 0
    ground[np.abs(c - r // 2 - 3) == 1] = 3  # sand banks
    ground[river] = 4  # water
    ground[(r >= 8) & (c >= 8)] = 5  # a stone yard
    blocks = np.zeros_like(ground)
    blocks[2, 7:10] = 1  # a brick wall
    blocks[3:6, 9] = 1
    blocks[9, 9] = blocks[8, 10] = 2  # stone pillars
    blocks[6, 1] = 2
    return ground.astype(np.int64), blocks.astype(np.int64)


def write(folder: Path, orientation: str) -> Path:
    w, h, side = TILES[orientation]
    ground_img, block_img = sheet(orientation)
    png.write(folder / f"{orientation}-ground.png", ground_img)
    png.write(folder / f"{orientation}-blocks.png", block_img)
    n = len(TERRAIN)
    terrain = TilesetSpec("terrain", f"{orientation}-ground.png", w, h, columns=n, count=n,
                          image_size=(w * n, h))  # fmt: skip
    blocks = TilesetSpec("blocks", f"{orientation}-blocks.png", w, h + LIFT, columns=2, count=2,
                         image_size=(2 * w, h + LIFT))  # fmt: skip
    ground, tall = grids()
    tall = np.where(tall > 0, tall + n, 0)  # the blocks tileset starts after the terrain
    path = folder / f"{orientation}.tmx"
    write_map(path, w, h, [terrain, blocks],
              [TileLayerSpec("Ground", ground), TileLayerSpec("Blocks", tall)],
              orientation=orientation, hex_side=side)  # fmt: skip
    return path


def shoot(path: Path, out: Path) -> None:
    def setup(world: Any) -> None:
        cam = world.insert_resource(Camera(pixels_per_meter=32))
        m = load_map(world, path)
        x0, y0, x1, y1 = m.bounds
        cam.center = ((x0 + x1) / 2, (y0 + y1) / 2)
        cam.zoom = min(SIZE[0] / ((x1 - x0) * 32), SIZE[1] / ((y1 - y0) * 32)) * 0.92

    app = App(setup, headless=True, size=SIZE, background=(24, 26, 32))
    app.screenshot(str(out))
    app.close()


def main() -> None:
    import tempfile

    images = Path(__file__).resolve().parent / "images"
    with tempfile.TemporaryDirectory() as tmp:
        for orientation in TILES:
            out = images / f"tilemap-{orientation}.png"
            shoot(write(Path(tmp), orientation), out)
            print(f"wrote {out}")


if __name__ == "__main__":
    main()
