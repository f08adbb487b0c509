"""Shader programs outlive the Apps that drew with them (kge.render.program_life).

Apps share one GL object space (headless ones reuse pooled windows). When pyglet
deleted a program an App had drawn with (its per-context cache holds them weakly)
while another window's context was current, Mesa's llvmpipe freed the first
context's compiled copies at its next flush behind its own state cache, and that
context's next draw with the program it had used last ran without a vertex shader:
SIGSEGV in glDrawElements. The crash takes the interpreter down, so it runs in a
child process here.
"""

from __future__ import annotations

import gc
import os
import subprocess
import sys
from pathlib import Path

import pyglet

from kge import App, Transform
from kge.components.drawables import Rect

# A tile layer (a program kge keeps for the process) drawn last in window A; an App
# whose shape program only it holds dropped while window B is current; then A again.
SCRIPT = """
import gc, sys
from pathlib import Path
import numpy as np
from kge import App, Transform
from kge.components.camera import Camera
from kge.components.drawables import Rect
from kge.render.setup import frame_pixels
from kge.testbed import png
from kge.tilemap import load_map
from kge.tilemap.writer import TileLayerSpec, TilesetSpec, write_map

folder = Path(sys.argv[1])
png.write(folder / "t.png", np.full((8, 8, 4), 200, np.uint8))
path = folder / "m.tmx"
write_map(path, 8, 8, [TilesetSpec("t", "t.png", 8, 8, columns=1, count=1, image_size=(8, 8))],
          [TileLayerSpec("L", np.ones((2, 2), np.int64))])

def tiles(world, rect=False):
    world.insert_resource(Camera(center=(1.0, 1.0), pixels_per_meter=16))
    if rect:
        world.spawn(Transform(0.5, 0.5), Rect(0.5, 0.5, color=(255, 0, 0), layer=-5))
    load_map(world, path)

def rect(world):
    world.spawn(Transform(0.0, 0.0), Rect(1.0, 1.0, color=(255, 0, 0)))

first = App(lambda w: tiles(w, rect=True), headless=True, size=(64, 48))
first.render(); frame_pixels(first)
other = App(rect, headless=True, size=(80, 48))
other.render(); frame_pixels(other)
first.close(); del first; gc.collect()
again = App(tiles, headless=True, size=(64, 48))
for _ in range(3):
    again.render(); frame_pixels(again)
    other.render(); frame_pixels(other)
print("frames drawn")
"""


def test_an_app_dropped_while_another_window_is_current_does_not_crash_the_next_frame(
    tmp_path: Path,
) -> None:
    env = {**os.environ, "PYGLET_HEADLESS": "1", "PYGLET_AUDIO": "silent"}
    proc = subprocess.run(
        [sys.executable, "-c", SCRIPT, str(tmp_path)],
        capture_output=True,
        text=True,
        env=env,
        timeout=600,
    )
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert "frames drawn" in proc.stdout


def test_the_shape_program_survives_the_app_that_made_it() -> None:
    def scene(world: object) -> None:
        world.spawn(Transform(0.0, 0.0), Rect(1.0, 1.0, color=(0, 255, 0)))  # type: ignore[attr-defined]

    # a window size no other test uses: its context (and pyglet's cache in it) is new
    app = App(scene, headless=True, size=(52, 36))
    app.render()
    from kge.render.setup import renderer_for

    window = renderer_for(app).window  # type: ignore[union-attr]
    window.switch_to()
    program_id = pyglet.shapes.get_default_shader().id
    app.close()
    del app
    gc.collect()
    window.switch_to()
    assert pyglet.shapes.get_default_shader().id == program_id
