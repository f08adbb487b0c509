"""Animation art drawn in code: sprite sheets and a GIF for the samples, games and tests.

``tools/make_assets.py`` writes these to ``examples/assets/`` (PNG, GIF); the
testbed samples use them in memory, so no file is needed to run a sample. Every
image is a pure function of this module (no randomness, no fonts).

>>> walk_sheet().shape
(32, 256, 4)
>>> len(coin_frames()), coin_delays()
(8, [120, 80, 60, 80, 120, 80, 60, 80])
"""

from __future__ import annotations

import io
import math
from collections.abc import Callable

import numpy as np

Cell = Callable[[int, np.ndarray, np.ndarray], np.ndarray]


def _sheet(frames: int, w: int, h: int, cell: Cell) -> np.ndarray:
    """One row of ``frames`` cells; ``cell(i, x, y)`` gets pixel-centre grids (y down)."""
    y, x = np.mgrid[0:h, 0:w].astype(float) + 0.5
    return np.concatenate([cell(i, x, y) for i in range(frames)], axis=1)


def _rgba(r: np.ndarray, g: np.ndarray, b: np.ndarray, a: np.ndarray) -> np.ndarray:
    out = np.stack([r, g, b, a], axis=-1)
    return np.clip(np.rint(out), 0, 255).astype(np.uint8)


def _segment(x: np.ndarray, y: np.ndarray, p: tuple[float, float], q: tuple[float, float]
             ) -> np.ndarray:
    ex, ey = q[0] - p[0], q[1] - p[1]
    t = np.clip(((x - p[0]) * ex + (y - p[1]) * ey) / (ex * ex + ey * ey), 0.0, 1.0)
    return np.hypot(x - (p[0] + t * ex), y - (p[1] + t * ey))


def _walker(i: int, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Frame ``i`` of 8 of a walker seen from the side: legs and arms swing, the body bobs."""
    phase = 2 * math.pi * i / 8
    bob = abs(math.sin(phase)) * 1.5
    d = np.minimum(np.hypot(x - 16, y - (7 + bob)) - 4.5,
                   np.maximum(abs(x - 16) - 3.0, abs(y - (16 + bob)) - 5.0))
    for side in (0, 1):
        swing = math.sin(phase + side * math.pi) * 5.0
        d = np.minimum(d, _segment(x, y, (16, 21 + bob), (16 + swing, 30)) - 1.3)
        d = np.minimum(d, _segment(x, y, (16, 13 + bob), (16 - swing * 0.8, 20 + bob)) - 1.0)
    a = np.clip(1.0 - d / 1.5, 0.0, 1.0)
    shade = np.clip(-d / 3.0, 0.0, 1.0)
    return _rgba(255 - 40 * shade, 200 - 30 * shade, 90 + 0 * x, 255 * a)


def _blast(i: int, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Frame ``i`` of 8 of an explosion: a fireball that swells, whitens, then thins."""
    t = (i + 0.5) / 8
    r = np.hypot(x - 16, y - 16)
    core = np.clip(1.0 - r / (4 + 11 * math.sqrt(t)), 0.0, 1.0)
    heat = core * (1.0 - t)
    alpha = np.minimum(1.0, core * 2.0) * (1.0 - t * 0.7)
    return _rgba(255 + 0 * x, 80 + 175 * heat, 30 + 200 * heat * heat, 255 * alpha)


def _flame(i: int, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Frame ``i`` of 4 of a thruster flame pointing down."""
    length = (10, 14, 11, 15)[i]
    hot = np.clip(1 - y / (length + 1), 0.0, 1.0)
    a = np.clip(-(abs(x - 8) - 5.0 * hot) / 1.5, 0.0, 1.0) * (y >= 1) * (y <= length)
    return _rgba(255 + 0 * x, 120 + 135 * hot, 40 + 200 * hot * hot, 255 * a)


def walk_sheet() -> np.ndarray:
    """8 frames of 32x32: a walk cycle (RGBA, rows top-down)."""
    return _sheet(8, 32, 32, _walker)


def explosion_sheet() -> np.ndarray:
    """8 frames of 32x32: an explosion."""
    return _sheet(8, 32, 32, _blast)


def thruster_sheet() -> np.ndarray:
    """4 frames of 16x16: a flickering flame."""
    return _sheet(4, 16, 16, _flame)


#: file name -> sheet maker (what make_assets writes)
SHEETS: dict[str, Callable[[], np.ndarray]] = {
    "hero_walk.png": walk_sheet,
    "explosion_sheet.png": explosion_sheet,
    "thruster.png": thruster_sheet,
}


def coin_frames() -> list[np.ndarray]:
    """8 frames of 24x24 of a spinning coin (squashed as it turns edge-on)."""
    y, x = np.mgrid[0:24, 0:24].astype(float) + 0.5
    out = []
    for i in range(8):
        squash = abs(math.cos(math.pi * i / 8)) * 0.85 + 0.15
        d = ((x - 12) / (10 * squash)) ** 2 + ((y - 12) / 10) ** 2
        inside = d <= 1
        shade = 200 + 55 * (1 - d)
        out.append(_rgba(shade, shade * 0.8, 40 + 0 * x, 255.0 * inside) * inside[..., None])
    return out


def coin_delays() -> list[int]:
    """Milliseconds per coin frame: quicker while edge-on."""
    return [120, 80, 60, 80, 120, 80, 60, 80]


def coin_gif() -> bytes:
    """The spinning coin as a looping GIF (Pillow's encoder) with per-frame delays."""
    from PIL import Image

    frames = [Image.fromarray(f, "RGBA") for f in coin_frames()]
    out = io.BytesIO()
    frames[0].save(out, format="GIF", save_all=True, append_images=frames[1:],
                   duration=coin_delays(), loop=0, disposal=2)
    return out.getvalue()


def as_image(arr: np.ndarray) -> object:
    """An in-memory image of a top-down RGBA array (``kge.render.images.PixelImage``)."""
    from kge.render.images import PixelImage

    return PixelImage(arr.shape[1], arr.shape[0], np.ascontiguousarray(arr[::-1]).tobytes())
