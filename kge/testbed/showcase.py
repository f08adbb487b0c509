"""The headless showcase: frame each sample like the testbed does, and tile the
frames into one PNG contact sheet (what ``make demo`` writes without a display)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path

import numpy as np
import numpy.typing as npt

from kge.app import App
from kge.components.camera import Camera
from kge.components.debug import DebugDraw
from kge.components.text import Text
from kge.testbed.framing import sample_camera
from kge.testbed.png import write
from kge.testbed.registry import Sample


def frame_sample(app: App, s: Sample, label: bool = True) -> None:
    """Point a camera at the sample, turn on debug drawing and add its name."""
    world = app.world
    if not world.has_resource(Camera):
        w, h = app.size
        world.insert_resource(sample_camera(world, s, app.size, (0.0, 0.0, w, h - 24.0)))
    if not world.has_resource(DebugDraw):
        world.insert_resource(DebugDraw())
    if label:
        world.spawn(Text(s.name, size=14, screen_space=True, offset=(8, app.size[1] - 8),
                         anchor=(0.0, 1.0), color=(235, 235, 235, 255), layer=100))


def grab(app: App) -> npt.NDArray[np.uint8]:
    """The current frame as (h, w, 4) uint8 with row 0 at the top (image order)."""
    from kge.render.setup import frame_pixels

    app.render()
    return np.ascontiguousarray(frame_pixels(app)[::-1])


def _shrink(img: npt.NDArray[np.uint8], scale: int) -> npt.NDArray[np.uint8]:
    """Downscale by ``scale`` keeping the brightest pixel of each block, so one-pixel
    debug-draw lines survive (plain subsampling drops half of them)."""
    h, w = (img.shape[0] // scale) * scale, (img.shape[1] // scale) * scale
    blocks = img[:h, :w].reshape(h // scale, scale, w // scale, scale, img.shape[2])
    return np.ascontiguousarray(blocks.max(axis=(1, 3)))


def contact_sheet(tiles: Sequence[npt.NDArray[np.uint8]], path: str | Path,
                  columns: int = 6, scale: int = 2, gap: int = 4) -> None:
    """Tile frames (downscaled by ``scale``) into one PNG."""
    if not tiles:
        raise ValueError("contact_sheet() needs at least one frame")
    small = [_shrink(t[:, :, :3], scale) for t in tiles]
    h, w = small[0].shape[:2]
    rows = math.ceil(len(small) / columns)
    sheet = np.full((rows * (h + gap) + gap, columns * (w + gap) + gap, 3), 16, np.uint8)
    for i, tile in enumerate(small):
        r, c = divmod(i, columns)
        y, x = gap + r * (h + gap), gap + c * (w + gap)
        sheet[y : y + tile.shape[0], x : x + tile.shape[1]] = tile
    write(path, sheet)
