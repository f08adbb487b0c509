"""Headless EGL rendering fixtures.

Every App here uses the same window size, so the pooled offscreen window of
``kge.render.setup`` is created once per test session and reused.
"""

from __future__ import annotations

import os

os.environ.setdefault("PYGLET_HEADLESS", "1")

from collections.abc import Callable, Iterator
from typing import Any

import numpy as np
import pytest

from kge import App

SIZE = (200, 160)
BG = (0, 0, 0)


@pytest.fixture
def make_app() -> Iterator[Callable[..., App]]:
    apps: list[App] = []

    def make(scene: Any, **kwargs: Any) -> App:
        kwargs.setdefault("size", SIZE)
        kwargs.setdefault("background", BG)
        app = App(scene, headless=True, **kwargs)
        apps.append(app)
        return app

    yield make
    for app in apps:
        app.close()


def pixels(app: App) -> np.ndarray:
    """Render and read back: ``pixels[y, x]``, y from the bottom (screen coordinates)."""
    from kge.render.setup import frame_pixels

    app.render()
    return frame_pixels(app)


def mask(px: np.ndarray, rgb: tuple[int, int, int], tol: int = 40) -> np.ndarray:
    """Pixels within ``tol`` of ``rgb`` in every channel."""
    d = np.abs(px[..., :3].astype(int) - np.array(rgb))
    return np.all(d <= tol, axis=-1)


def bbox(m: np.ndarray) -> tuple[int, int, int, int]:
    """(x_min, x_max, y_min, y_max) of a boolean mask (asserts it is not empty)."""
    ys, xs = np.nonzero(m)
    assert len(xs), "nothing of that colour was drawn"
    return int(xs.min()), int(xs.max()), int(ys.min()), int(ys.max())
