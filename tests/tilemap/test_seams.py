"""No seams between tiles and no strip of clear colour at a map's edge (8-bit headless frames).

The sheet puts a red tile among blue ones, and the map is all red: a pixel that
shows blue took a texel of a neighbouring tile in the sheet (a seam), a black one
shows the clear colour between or beside tiles.
"""

from __future__ import annotations

import os

os.environ.setdefault("PYGLET_HEADLESS", "1")

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from kge import App, BodyType, RigidBody, Transform
from kge.components.camera import Camera
from kge.components.drawables import Rect
from kge.testbed import png
from kge.tilemap import load_map
from kge.tilemap.writer import TileLayerSpec, TilesetSpec, write_map

T = 16  # tile pixels; one tile is one metre at PPM 16
SIZE = (160, 120)
RED, BLUE = (220, 30, 30), (30, 30, 220)
COLS, ROWS = 40, 12


def write(folder: Path, offset: tuple[float, float] = (0.0, 0.0)) -> Path:
    """A 40 x 12 map of the red tile, the middle of a 3 x 3 sheet of blue ones."""
    sheet = np.zeros((3 * T, 3 * T, 4), np.uint8)
    sheet[...] = (*BLUE, 255)
    sheet[T : 2 * T, T : 2 * T] = (*RED, 255)
    png.write(folder / "sheet.png", sheet)
    grid = np.full((ROWS, COLS), 5, np.int64)  # local id 4: the red middle
    path = folder / "m.tmx"
    write_map(
        path,
        T,
        T,
        [TilesetSpec("s", "sheet.png", T, T, columns=3, count=9, image_size=(3 * T, 3 * T))],
        [TileLayerSpec("Ground", grid, offset=offset)],
    )
    return path


def frame(apps: list[App], path: Path, camera: Camera, spawn: Any = None) -> App:
    def setup(world: Any) -> None:
        world.insert_resource(camera)
        load_map(world, path)
        if spawn is not None:
            spawn(world)

    app = App(setup, headless=True, size=SIZE, background=(0, 0, 0))
    apps.append(app)
    return app


def pixels(app: App) -> np.ndarray:
    from kge.render.setup import frame_pixels

    return frame_pixels(app)[..., :3].astype(int)


def map_rect(app: App, inset: int = 1) -> tuple[slice, slice]:
    """The window pixels the map covers, ``inset`` pixels in from its edges."""
    cam = app.world.resource(Camera)
    x0, y0 = cam.world_to_screen((0.0, 0.0), SIZE)
    x1, y1 = cam.world_to_screen((float(COLS), float(ROWS)), SIZE)
    xs = slice(max(int(np.ceil(x0)) + inset, 0), min(int(np.floor(x1)) - inset, SIZE[0]))
    ys = slice(max(int(np.ceil(y0)) + inset, 0), min(int(np.floor(y1)) - inset, SIZE[1]))
    return ys, xs


def assert_all_red(px: np.ndarray, what: str) -> None:
    off = np.abs(px - np.array(RED)).max(axis=-1) > 12
    ys, xs = np.nonzero(off)
    assert not len(ys), (
        f"{what}: {len(ys)} pixels are not the tile's colour, e.g. {px[ys[0], xs[0]].tolist()} "
        f"at x={xs[0]}, y={ys[0]} (blue: a neighbour's texel, black: a gap)"
    )


@pytest.mark.parametrize(
    ("center", "zoom", "offset"),
    [
        ((20.013, 6.031), 1.0, (0.0, 0.0)),  # the camera between pixels
        ((20.47, 6.29), 1.0, (0.0, 0.0)),
        ((20.0, 6.0), 0.73, (0.0, 0.0)),  # zoomed out: every tile minified
        ((20.21, 5.93), 0.61, (0.0, 0.0)),
        ((20.0, 6.0), 1.0, (0.5, 0.25)),  # a fractional layer offset (map pixels)
    ],
)
def test_tile_layers_show_no_seams(
    tmp_path: Path, apps: list[App], center: tuple[float, float], zoom: float,
    offset: tuple[float, float],
) -> None:  # fmt: skip
    path = write(tmp_path, offset)
    app = frame(apps, path, Camera(center=center, pixels_per_meter=T, zoom=zoom))
    app.render()
    px = pixels(app)
    ys, xs = map_rect(app, inset=2)
    assert ys.stop - ys.start > 20 and xs.stop - xs.start > 20
    assert_all_red(px[ys, xs], f"camera at {center}, zoom {zoom}, layer offset {offset}")


def test_a_bounded_follow_camera_shows_no_strip_at_the_map_edge(
    tmp_path: Path, apps: list[App]
) -> None:
    """The camera follows a body that starts near the map's left edge and runs right: the
    drawn pose lags the simulated one, and that lag must not carry the view past the
    bounds (for a few frames a strip of clear colour showed at the left edge)."""
    path = write(tmp_path)
    state: dict[str, int] = {}

    def runner(world: Any) -> None:
        state["e"] = world.spawn(
            Transform(4.0, 6.0),  # the view (10 m wide) is clamped at x = 5 until it passes
            RigidBody(type=BodyType.KINEMATIC, velocity=(12.0, 0.0)),
            Rect(0.5, 0.5, color=RED),  # drawn, so the camera follows its drawn pose
        )
        world.resource(Camera).follow = state["e"]

    camera = Camera(pixels_per_meter=T, bounds=(0.0, 0.0, float(COLS), float(ROWS)))
    app = frame(apps, path, camera, runner)
    for _ in range(24):
        app.advance(1.0 / 90.0)  # frames between fixed steps: the drawn pose lags
        app.render()
        px = pixels(app)
        assert_all_red(px, "the whole window (the view stays inside the map)")
    assert app.world.get(state["e"], Transform).x > 7.0  # the body ran and the camera moved
