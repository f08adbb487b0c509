"""Make the pictures of ``docs/rendering.md``: ``rendering.png`` (sprites, shapes, text
and the physics debug view) and, from the testbed's rendering samples, ``text.png``,
``materials.png`` and ``cameras.png``.

Run ``python docs/rendering_screenshot.py`` (headless is fine: it renders
offscreen through EGL, 8 bits per channel). Everything on screen is built from
components; no image file is needed, the art is generated in code.
"""

from __future__ import annotations

import math
import os
import sys
from pathlib import Path

os.environ.setdefault("PYGLET_HEADLESS", "1")
sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

import numpy as np

from kge import App, Transform, World
from kge.components.camera import Camera
from kge.components.collider import Collider
from kge.components.debug import DebugDraw
from kge.components.drawables import Circle, Line, Polygon, Rect
from kge.components.joints import RevoluteJoint
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box
from kge.components.shapes import Circle as CircleShape
from kge.components.sprite import Sprite
from kge.components.text import Text
from kge.render.images import checker, from_array

IMAGES = Path(__file__).resolve().parent / "images"
OUT = IMAGES / "rendering.png"
#: the pictures of the rendering samples: (file, samples side by side)
FEATURES = {
    "text.png": ("text-layout", "rich-text"),
    "materials.png": ("shader-materials", "blend-modes", "post-effects"),
    "cameras.png": ("split-screen", "minimap-and-monitor", "camera-rotation"),
}


def crate_art() -> object:
    """A 16 px wooden crate: brown planks with a darker frame and a cross brace."""
    a = np.zeros((16, 16, 3), np.uint8)
    a[:] = (176, 120, 64)
    a[::4] = (150, 100, 52)
    a[[0, -1]] = a[:, [0, -1]] = (92, 60, 30)
    for i in range(16):
        a[i, i] = a[i, 15 - i] = (110, 72, 36)
    return from_array(a)


def scene(world: World) -> None:
    world.insert_resource(Camera(center=(0.0, 3.2), pixels_per_meter=48))
    world.insert_resource(DebugDraw(enabled=True, stats=True, contact_seconds=0.3))
    crate = crate_art()
    # ground: a flat-coloured Rect drawn under the debug outline of its collider
    world.spawn(
        Transform(0.0, -0.25), Rect(13.0, 0.5, color=(70, 82, 98)), Collider(Box(6.5, 0.25))
    )
    # a pyramid of crate sprites with box colliders
    for row in range(5):
        for col in range(5 - row):
            x = (col - (4 - row) / 2) * 1.02 - 2.0
            world.spawn(
                Transform(x, 0.5 + row * 1.0),
                Sprite(crate, size=(1.0, 1.0)),
                RigidBody(),
                Collider(Box(0.5, 0.5), friction=0.6),
            )
    # a pendulum: revolute joint to the ground (None), ball drawn as a shape
    ball = world.spawn(
        Transform(4.6, 4.0),
        Circle(0.45, color=(235, 90, 80)),
        RigidBody(),
        Collider(CircleShape(0.45)),
    )
    world.spawn(RevoluteJoint(None, ball, anchor=(3.0, 5.2)))
    # decoration: a star polygon, a translucent checker sprite, a line, world text
    star = [
        (math.cos(a) * r, math.sin(a) * r)
        for i in range(10)
        for a, r in [(math.pi / 2 + i * math.pi / 5, 0.6 if i % 2 == 0 else 0.25)]
    ]
    world.spawn(Transform(-5.2, 5.6, 0.2), Polygon(tuple(star), color=(250, 210, 70)))
    world.spawn(
        Transform(5.2, 1.2, 0.4),
        Sprite(checker(8, 8, 2, (60, 160, 230), (230, 240, 250)), size=(1.2, 1.2), opacity=200),
    )
    world.spawn(
        Transform(), Line((-6.5, 6.3), (6.5, 6.3), color=(120, 130, 150, 160), thickness=0.04)
    )
    world.spawn(Transform(-1.2, 5.9), Text("kge on pyglet 2.1", size=20, bold=True))
    world.spawn(
        Text(
            "headless EGL screenshot",
            size=12,
            screen_space=True,
            offset=(632, 324),
            anchor=(1, 1),
            color=(200, 200, 210, 255),
        )
    )


def main(path: Path = OUT) -> Path:
    app = App(scene, headless=True, size=(640, 360))
    app.render()
    app.step(40)  # let the pyramid settle a little and the pendulum swing
    app.timestep.accumulator = 0.5 * app.fixed_dt
    app.screenshot(path)
    app.close()
    return path


def sample_frame(slug: str, steps: int = 150) -> np.ndarray:
    """A testbed sample at 960 x 540, framed as the testbed frames it, shrunk to 640 x 360."""
    from PIL import Image

    from kge.testbed import get_sample
    from kge.testbed.showcase import frame_sample, grab

    s = get_sample(slug)
    app = App(s.setup, headless=True, size=(960, 540))
    frame_sample(app, s)
    app.step(steps)
    pixels = grab(app)
    app.close()
    return np.asarray(Image.fromarray(pixels).resize((640, 360), Image.Resampling.LANCZOS))


def features(folder: Path = IMAGES) -> list[Path]:
    """The samples' pictures: each file has its samples side by side, two to a row."""
    from kge.testbed.png import write

    written = []
    for name, slugs in FEATURES.items():
        # the dissolve shader half way through, the others after 2.5 s of game time
        tiles = [sample_frame(slug, 66 if slug == "shader-materials" else 150) for slug in slugs]
        while len(tiles) % 2:
            blank = np.zeros_like(tiles[0])
            blank[...] = (24, 26, 33, 255)
            tiles.append(blank)
        rows = [np.concatenate(tiles[i : i + 2], axis=1) for i in range(0, len(tiles), 2)]
        write(folder / name, np.concatenate(rows, axis=0))
        written.append(folder / name)
    return written


if __name__ == "__main__":
    for out in (main(), *features()):
        print(f"wrote {out} ({out.stat().st_size} bytes)")
