"""Fixtures for the animation tests: generated sheets and GIFs, headless Apps."""

from __future__ import annotations

import os
import sys

os.environ.setdefault("PYGLET_HEADLESS", "1")

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from kge import App
from kge.render.images import PixelImage

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
if str(EXAMPLES) not in sys.path:  # the example games import as modules (test_games.py)
    sys.path.insert(0, str(EXAMPLES))

#: the colours of the generated sheet's frames, left to right
COLOURS = [(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 255)]


def strip(colours: list[tuple[int, int, int]], cell: int = 8) -> PixelImage:
    """A one-row sheet: one solid ``cell`` x ``cell`` frame per colour."""
    arr = np.zeros((cell, cell * len(colours), 4), np.uint8)
    for i, c in enumerate(colours):
        arr[:, i * cell : (i + 1) * cell, :3] = c
    arr[..., 3] = 255
    return PixelImage(arr.shape[1], cell, arr.tobytes())


@pytest.fixture
def sheet() -> PixelImage:
    return strip(COLOURS)


def write_gif(path: Path, colours: list[tuple[int, int, int]], durations_ms: list[int]) -> Path:
    from PIL import Image

    frames = [Image.new("RGB", (8, 8), c) for c in colours]
    frames[0].save(path, save_all=True, append_images=frames[1:], duration=durations_ms, loop=0)
    return path


@pytest.fixture
def make_app() -> Iterator[Any]:
    apps: list[App] = []

    def make(scene: Any, **kwargs: Any) -> App:
        kwargs.setdefault("size", (64, 64))
        kwargs.setdefault("background", (0, 0, 0))
        app = App(scene, headless=True, **kwargs)
        apps.append(app)
        return app

    yield make
    for app in apps:
        app.close()


def centre_colour(app: App) -> tuple[int, int, int]:
    from kge.render.setup import frame_pixels

    app.render()
    px = frame_pixels(app)
    h, w = px.shape[:2]
    r, g, b = (int(v) for v in px[h // 2, w // 2, :3])
    return (r, g, b)
