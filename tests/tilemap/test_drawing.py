"""Tile layers drawn headless (EGL): pixels where the tiles are, flips, opacity, culling."""

from __future__ import annotations

import os

os.environ.setdefault("PYGLET_HEADLESS", "1")

from pathlib import Path
from typing import Any

import numpy as np

from kge import App
from kge.components.camera import Camera
from kge.tilemap import load_map
from kge.tilemap.model import TILED_FLIP_H, TILED_FLIP_V
from kge.tilemap.writer import TileLayerSpec

from .maps import ANIM_A, COLORS, GROUND, MARK, ONE_WAY, write_level

SIZE = (200, 160)
PPM = 20  # window pixels per metre; a tile is 1 m



def render(apps: list[App], setup: Any) -> tuple[App, np.ndarray]:
    from kge.render.setup import frame_pixels

    app = App(setup, headless=True, size=SIZE, background=(0, 0, 0))
    apps.append(app)
    app.render()
    return app, frame_pixels(app)


class Near(tuple):
    """A colour that equals any colour within 10 per channel (PNG decoding rounds)."""

    def __eq__(self, other: object) -> bool:
        return isinstance(other, tuple) and all(
            abs(int(a) - int(b)) <= 10 for a, b in zip(self, other, strict=True)
        )

    def __hash__(self) -> int:
        return hash(tuple(self))


def at(px: np.ndarray, x: float, y: float) -> Near:
    """The pixel at world point (x, y) with the camera centred on (5, 4)."""
    sx = int(SIZE[0] / 2 + (x - 5.0) * PPM)
    sy = int(SIZE[1] / 2 + (y - 4.0) * PPM)
    return Near(int(v) for v in px[sy, sx, :3])


def test_tiles_are_drawn_at_their_cells(tmp_path: Path, apps: list[App]) -> None:
    g = np.zeros((8, 10), np.int64)
    g[7, :] = GROUND  # bottom row: y in [0, 1)
    g[2, 3] = ONE_WAY  # row 2 from the top: y in [5, 6), x in [3, 4)
    path = write_level(tmp_path, g)

    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(5.0, 4.0), pixels_per_meter=PPM))
        load_map(world, path)

    _, px = render(apps, setup)
    assert at(px, 0.5, 0.5) == COLORS[0] and at(px, 9.5, 0.5) == COLORS[0]
    assert at(px, 3.5, 5.5) == COLORS[1]
    assert at(px, 2.5, 5.5) == (0, 0, 0) and at(px, 4.5, 5.5) == (0, 0, 0)
    assert at(px, 0.5, 1.5) == (0, 0, 0)
    # the cell's edges land on the expected pixels (one tile = PPM pixels)
    sy = int(SIZE[1] / 2 + (5.5 - 4.0) * PPM)
    xs = np.nonzero(np.abs(px[sy, :, 1].astype(int) - COLORS[1][1]) <= 10)[0]
    assert (xs.min(), xs.max() + 1) == (int(SIZE[0] / 2 - 2 * PPM), int(SIZE[0] / 2 - 1 * PPM))


def test_flips_and_layer_opacity(tmp_path: Path, apps: list[App]) -> None:
    g = np.zeros((8, 10), np.int64)
    g[2, 2] = MARK  # black quarter at the image's top-left
    g[2, 4] = MARK | TILED_FLIP_H  # ... top-right
    g[2, 6] = MARK | TILED_FLIP_V  # ... bottom-left
    faded = np.zeros((8, 10), np.int64)
    faded[5, 5] = GROUND
    path = write_level(tmp_path, g, extra_layers=[TileLayerSpec("Faded", faded, opacity=0.5)])

    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(5.0, 4.0), pixels_per_meter=PPM))
        load_map(world, path)

    _, px = render(apps, setup)
    black, white = (0, 0, 0), COLORS[7]
    # tile at column 2, row 2: x in [2, 3), y in [5, 6); top-left quarter is near (2.25, 5.75)
    assert at(px, 2.25, 5.75) == black and at(px, 2.75, 5.75) == white
    assert at(px, 4.75, 5.75) == black and at(px, 4.25, 5.75) == white
    assert at(px, 6.25, 5.25) == black and at(px, 6.25, 5.75) == white
    assert at(px, 5.5, 2.5) == tuple(c // 2 for c in COLORS[0])  # half opacity over black


def test_animated_tiles_follow_game_time(tmp_path: Path, apps: list[App]) -> None:
    g = np.zeros((8, 10), np.int64)
    g[2, 5] = ANIM_A  # frames: tile 4 for 0.1 s, tile 5 for 0.1 s

    path = write_level(tmp_path, g)

    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(5.0, 4.0), pixels_per_meter=PPM))
        load_map(world, path)

    from kge.render.setup import frame_pixels

    app, px = render(apps, setup)
    assert at(px, 5.5, 5.5) == COLORS[4]
    app.step(9)  # 0.15 s of game time
    app.render()
    assert at(frame_pixels(app), 5.5, 5.5) == COLORS[5]


def test_only_visible_chunks_are_in_the_batch(tmp_path: Path, apps: list[App]) -> None:
    g = np.full((200, 300), GROUND, np.int64)
    path = write_level(tmp_path, g)

    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(150.0, 100.0), pixels_per_meter=PPM))
        load_map(world, path)

    app, _ = render(apps, setup)
    from kge.render.passes import RenderPasses

    (draw,) = [
        p
        for p in app.world.resource(RenderPasses).before()
        if getattr(p, "__name__", "") == "draw_maps"
    ]
    renderer = draw.state["renderer"]  # type: ignore[attr-defined]
    # a 10 x 8 m view touches at most 2 x 2 chunks of 32 tiles (70 chunks in the map)
    assert 1 <= renderer.chunk_count <= 4
    app.world.resource(Camera).center = (20.0, 180.0)
    app.render()
    assert 1 <= renderer.chunk_count <= 4


def test_tint_offset_parallax_and_image_layers(tmp_path: Path, apps: list[App]) -> None:
    from kge.testbed import png
    from kge.tilemap.writer import ImageLayerSpec

    g = np.zeros((8, 10), np.int64)
    tinted = np.zeros((8, 10), np.int64)
    tinted[2, 2] = MARK  # white tile (its black quarter aside) tinted red: x [2, 3), y [5, 6)
    moved = np.zeros((8, 10), np.int64)
    moved[5, 2] = GROUND  # drawn 16 px (1 m) right and 16 px (1 m) down: x [3, 4), y [1, 2)
    fixed = np.zeros((8, 10), np.int64)
    # parallax 0: drawn moved by the camera's offset from the parallax origin (the map's
    # top-left, (0, 8)): with the camera at (5, 4) this tile at (2.5, 6.5) shows at (7.5, 2.5)
    fixed[1, 2] = ONE_WAY
    png.write(tmp_path / "sun.png", np.full((16, 32, 4), (20, 60, 250, 255), np.uint8))
    path = write_level(
        tmp_path,
        g,
        extra_layers=[
            ImageLayerSpec("Sun", "sun.png", offset=(128, 0)),  # x [8, 10), y [7, 8)
            TileLayerSpec("Tinted", tinted, tint="#ff0000"),
            TileLayerSpec("Moved", moved, offset=(16, 16)),
            TileLayerSpec("Fixed", fixed, parallax=(0.0, 0.0)),
        ],
    )

    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(5.0, 4.0), pixels_per_meter=PPM))
        load_map(world, path)

    app, px = render(apps, setup)
    assert at(px, 2.75, 5.75) == (250, 0, 0)
    assert at(px, 3.5, 1.5) == COLORS[0] and at(px, 2.5, 2.5) == (0, 0, 0)
    assert at(px, 9.5, 7.5) == (20, 60, 250) and at(px, 7.5, 7.5) == (0, 0, 0)
    assert at(px, 7.5, 2.5) == COLORS[1]
    from kge.render.setup import frame_pixels

    # the camera moves 2 m right: the map moves 2 m left on screen, the parallax-0 layer does not
    app.world.resource(Camera).center = (7.0, 4.0)
    app.render()
    px = frame_pixels(app)
    assert at(px, 7.5, 2.5) == COLORS[1]  # same screen spot as before (at() assumes centre 5, 4)
    assert at(px, 1.5, 1.5) == COLORS[0]  # the offset tile, 2 m to the left on screen
