"""Make the screenshots of ``docs/particles-lights.md``.

Run ``python docs/particles_lights_screenshot.py`` (headless is fine: EGL
renders offscreen). It opens the testbed samples and the night example at the
sizes the page shows and writes ``docs/images/particles.png`` (four particle
samples side by side) and ``docs/images/lights.png`` (the lit room, the
flashlight and the night street).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import Any

os.environ.setdefault("PYGLET_HEADLESS", "1")
ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "examples"))

import numpy as np

from kge import App
from kge.components.camera import Camera
from kge.render.setup import frame_pixels
from kge.testbed import get_sample
from kge.testbed.png import write as write_png

IMAGES = Path(__file__).resolve().parent / "images"
TILE = (480, 300)


def _shot(setup: Any, steps: int, mouse: tuple[float, float] | None = None) -> np.ndarray:
    app = App(setup, headless=True, size=TILE, background=(8, 8, 14))
    if mouse is not None:
        app.input.move_mouse(*app.world_to_screen(mouse))
    app.step(steps)
    app.render()
    px = frame_pixels(app)[::-1, :, :3].copy()  # top row first, as images are stored
    app.close()
    return px


def _sample(slug: str, steps: int, mouse: tuple[float, float] | None = None) -> np.ndarray:
    s = get_sample(slug)
    cx, cy, zoom = s.camera

    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(cx, cy), zoom=zoom * TILE[0] / 960))
        s.setup(world)

    return _shot(setup, steps, mouse)


def main() -> None:
    import night

    particles = [_sample("fountain", 200), _sample("explosion", 70),
                 _sample("sparks-on-hits", 75), _sample("smoke-trail", 200)]  # fmt: skip
    grid = np.concatenate([np.concatenate(particles[:2], 1), np.concatenate(particles[2:], 1)], 0)
    lights = [_sample("lit-room", 60), _sample("flashlight", 2, mouse=(5.0, 1.0)),
              _shot(night.night, 150)]  # fmt: skip
    IMAGES.mkdir(exist_ok=True)
    write_png(IMAGES / "particles.png", grid)
    write_png(IMAGES / "lights.png", np.concatenate(lights, 1))
    print(f"wrote {IMAGES / 'particles.png'} and {IMAGES / 'lights.png'}")


if __name__ == "__main__":
    main()
