"""Testing your own game headless: step until something happens, drive input and the UI
(``click(app, "Play")``, ``type_text``, ``focus``, ``drag``: :mod:`kge.ui.driving`),
compare screenshots with golden images.

These helpers work in any test runner; with pytest, kge's plugin (registered when kge
is installed) adds the fixtures ``kge_app``, ``kge_world`` and ``kge_golden`` and the
``--kge-update-goldens`` option (see :mod:`kge.testing.plugin` and docs/testing.md).

>>> from kge import App, Transform, World
>>> def falling(world: World) -> None:
...     world.spawn(Transform(0, 10))
>>> app = App(falling, headless=True)
>>> step_until(app, lambda: True)      # already true: no step taken
0
>>> step_until(app, lambda: app.world.get(1, Transform).y < 0, timeout=0.1)
Traceback (most recent call last):
...
kge.testing.StepTimeout: the condition was still false after 0.1 game seconds (6 steps)
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from kge.errors import KgeError

if TYPE_CHECKING:
    from kge.app import App


class StepTimeout(KgeError, AssertionError):
    """:func:`step_until` ran out of game time before its condition held."""


class GoldenMismatch(KgeError, AssertionError):
    """A screenshot differs from its golden image by more than the tolerance."""


def step_until(app: App, condition: Callable[[], object], timeout: float = 5.0) -> int:
    """Step ``app`` one fixed step at a time until ``condition()`` is true.

    ``timeout`` is in **game** seconds (``app.fixed_dt`` per step), so the result does
    not depend on how fast the machine is. Returns the number of steps taken; raises
    :class:`StepTimeout` when the condition is still false after ``timeout``.
    """
    if not timeout >= 0 or not math.isfinite(timeout):
        raise ValueError(
            f"step_until: timeout must be a finite number of seconds >= 0, got {timeout!r}"
        )
    limit = round(timeout / app.fixed_dt)
    for steps in range(limit + 1):
        if condition():
            return steps
        if steps < limit:
            app.step(1)
    raise StepTimeout(
        f"the condition was still false after {timeout:g} game seconds ({limit} steps)"
    )


def tap(app: App, key: int, frames: int = 1) -> None:
    """Press ``key``, run ``frames`` steps with it held, release it and run one more.

    Both edges are seen by the game, as with a real key tapped for that long.
    """
    app.input.press(key)
    app.step(frames)
    app.input.release(key)
    app.step(1)


def screenshot_pixels(app: App) -> np.ndarray:
    """Render ``app`` and return its frame as an (h, w, 4) array, row 0 at the **top**
    (the orientation of a PNG file)."""
    from kge.render.setup import frame_pixels

    app.render()
    return np.ascontiguousarray(frame_pixels(app)[::-1])


def read_png(path: str | os.PathLike[str]) -> np.ndarray:
    """A PNG as an (h, w, 4) uint8 array, row 0 at the top (pyglet's decoder: no PIL)."""
    import pyglet

    image = pyglet.image.load(os.fspath(path)).get_image_data()
    raw = image.get_data("RGBA", image.width * 4)
    return np.frombuffer(raw, np.uint8).reshape(image.height, image.width, 4)[::-1].copy()


def write_png(pixels: np.ndarray, path: str | os.PathLike[str]) -> None:
    """Write an (h, w, 4) uint8 array (row 0 at the top) as a PNG."""
    import pyglet

    h, w = pixels.shape[:2]
    data = np.ascontiguousarray(pixels[::-1]).tobytes()
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    pyglet.image.ImageData(w, h, "RGBA", data).save(os.fspath(path))


def compare_with_golden(
    app: App,
    golden: str | os.PathLike[str],
    *,
    tolerance: int = 8,
    max_differing: float = 0.001,
    update: bool = False,
) -> None:
    """Render ``app`` and compare the frame with the PNG at ``golden``.

    A pixel differs when any channel is off by more than ``tolerance`` (0..255); the
    comparison fails when more than ``max_differing`` of the pixels differ (the share,
    0..1), writing ``<name>.actual.png`` beside the golden to look at. ``update=True``
    (or a missing golden) writes the golden instead; a missing one still fails once,
    so that a new golden is looked at before it is trusted.
    """
    path = Path(golden)
    actual = screenshot_pixels(app)
    if update or not path.exists():
        write_png(actual, path)
        if not update:
            raise GoldenMismatch(
                f"no golden image at {path}: wrote it from this run; look at it, then re-run"
            )
        return
    expected = read_png(path)
    if expected.shape != actual.shape:
        write_png(actual, path.with_suffix(".actual.png"))
        raise GoldenMismatch(
            f"{path.name}: the frame is {actual.shape[1]}x{actual.shape[0]} pixels, the golden "
            f"{expected.shape[1]}x{expected.shape[0]}"
        )
    delta = np.abs(actual.astype(np.int16) - expected.astype(np.int16)).max(axis=-1)
    share = float(np.count_nonzero(delta > tolerance)) / delta.size
    if share > max_differing:
        out = path.with_suffix(".actual.png")
        write_png(actual, out)
        raise GoldenMismatch(
            f"{path.name}: {share:.2%} of the pixels differ by more than {tolerance} "
            f"(allowed {max_differing:.2%}; largest difference {int(delta.max())}); "
            f"this run's frame is in {out.name} (pytest --kge-update-goldens accepts it)"
        )


from kge.ui.driving import (  # noqa: E402  (after the helpers above, which it does not need)
    UITargetError,
    box_of,
    click,
    compose,
    double_click,
    drag,
    find,
    focus,
    press,
    scroll,
    type_text,
)

__all__ = [
    "GoldenMismatch",
    "StepTimeout",
    "UITargetError",
    "box_of",
    "click",
    "compare_with_golden",
    "compose",
    "double_click",
    "drag",
    "find",
    "focus",
    "press",
    "read_png",
    "screenshot_pixels",
    "scroll",
    "step_until",
    "tap",
    "type_text",
    "write_png",
]
