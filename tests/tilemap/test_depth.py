"""Isometric depth order: a layer with ``depth_sort`` draws each tile row at its own
depth, so a sprite ordered by ``TileMap.depth_order`` at its feet is hidden by a tall
block in front of it and hides the block when it stands in front (pixels), and the
map's tile objects are ordered the same way at load."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from kge import App, Sprite, Transform
from kge.components.camera import Camera
from kge.components.tilemap import MapObject
from kge.render.images import solid
from kge.render.setup import frame_pixels
from kge.testbed import png
from kge.tilemap import TileMap, load_map
from kge.tilemap.writer import ObjectLayerSpec, TileLayerSpec, TilesetSpec, write_map

SIZE, PPM = (200, 160), 64
BLUE, RED, GREEN = (0, 0, 255), (255, 0, 0), (0, 200, 0)


def write(folder: Path, objects: list[dict[str, Any]]) -> Path:
    """A 6 x 6 isometric map (32 x 16 px diamonds, 1 m x 0.5 m) with one block 32 x 32 px
    (1 m x 1 m, so it rises 0.5 m above its cell) at cell (3, 3), and a green tile."""
    sheet = np.zeros((32, 64, 4), np.uint8)
    sheet[:, :32] = (*BLUE, 255)
    sheet[16:, 32:] = (*GREEN, 255)  # tile 1: a green 32 x 16 box at the bottom
    png.write(folder / "b.png", sheet)
    ts = TilesetSpec("b", "b.png", 32, 32, columns=2, count=2, image_size=(64, 32))
    grid = np.zeros((6, 6), np.int64)
    grid[3, 3] = 1
    layers: list[Any] = [TileLayerSpec("Blocks", grid, properties={"depth_sort": True})]
    layers.append(ObjectLayerSpec("Things", objects))
    path = folder / "iso.tmx"
    write_map(path, 32, 16, [ts], layers, orientation="isometric")
    return path


def test_sprites_and_tile_objects_go_behind_and_in_front_of_a_block_by_their_feet(
    tmp_path: Path,
) -> None:
    # a tile object standing at cell (5, 2)'s centre: Tiled's isometric object
    # coordinates are pixels along the cell axes (a cell is 16 px on each)
    obj = {"id": 1, "name": "crate", "gid": 2, "x": 5.5 * 16, "y": 2.5 * 16,
           "width": 32, "height": 32}  # fmt: skip
    path = write(tmp_path, [obj])
    made: list[TileMap] = []

    def setup(world: Any) -> None:
        m = load_map(world, path)
        made.append(m)
        cx, cy = m.cell_center(3, 3)
        world.insert_resource(Camera(center=(cx, cy + 0.25), pixels_per_meter=PPM))
        for cell in ((2, 2), (4, 4)):  # behind the block, in front of it
            feet = m.cell_center(*cell)
            world.spawn(
                Transform(*feet),
                Sprite(solid(8, 8, RED), size=(0.4, 0.4), anchor=(0.5, 0.0),
                       order=m.depth_order(feet)),
            )  # fmt: skip

    app = App(setup, headless=True, size=SIZE, background=(0, 0, 0))
    try:
        app.render()
        px = frame_pixels(app)
        m = made[0]
        cx, cy = m.cell_center(3, 3)
        cam = (cx, cy + 0.25)

        def at(x: float, y: float) -> tuple[int, ...]:
            sx = int(SIZE[0] / 2 + (x - cam[0]) * PPM)
            sy = int(SIZE[1] / 2 + (y - cam[1]) * PPM)
            return tuple(int(v) for v in px[sy, sx, :3])

        # the block: x cx +- 0.5, y from cy - 0.25 (the cell's bottom corner) up 1 m
        assert at(cx + 0.4, cy + 0.6) == BLUE
        # the sprite behind (feet at cy + 0.5, 0.4 m tall): hidden where the block is
        assert at(cx, cy + 0.6) == BLUE and at(cx, cy + 0.85) == RED
        # the sprite in front (feet at cy - 0.5): drawn over the block's foot
        assert at(cx, cy - 0.15) == RED and at(cx + 0.3, cy - 0.15) == BLUE
        # the tile object at cell (5, 2) got its depth order at load, in front of the block
        (crate,) = m.objects
        assert app.world.get(crate, MapObject).name == "crate"
        assert app.world.get(crate, Sprite).order == m.depth_order(m.cell_center(5, 2))
        assert app.world.get(crate, Sprite).order > m.depth_order(m.cell_center(3, 3))
    finally:
        app.close()
