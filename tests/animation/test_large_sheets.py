"""Sheets larger than the animation atlas: their frames are packed one by one, so a
4096-pixel-wide strip animates; a single frame larger than the atlas is refused naming
its size when its animator is made."""

from __future__ import annotations

import numpy as np
import pytest

from kge import Animator, App, Clip, Sprite, Transform, World
from kge.errors import KgeError
from kge.render.animation import ATLAS_SIZE
from kge.render.images import from_array
from kge.render.setup import frame_pixels


def strip(frames: int, w: int, h: int) -> np.ndarray:
    """``frames`` frames of w x h side by side, frame i filled with red 7 * i + 10."""
    img = np.zeros((h, frames * w, 4), np.uint8)
    img[..., 3] = 255
    for i in range(frames):
        img[:, i * w : (i + 1) * w, 0] = 7 * i + 10
    return img


def test_a_strip_wider_than_the_atlas_animates_frame_by_frame() -> None:
    sheet = from_array(strip(32, 128, 256))  # 4096 x 256: twice the atlas' width
    assert sheet.width > ATLAS_SIZE
    clip = Clip.grid(sheet, (32, 1), duration=0.1)

    def setup(world: World) -> None:
        world.spawn(Transform(0, 0), Sprite(sheet), Animator({"run": clip}, "run"))

    app = App(setup, headless=True, size=(64, 64), background=(0, 0, 0))
    try:
        seen = []
        for _ in range(4):
            app.render()
            seen.append(int(frame_pixels(app)[32, 32, 0]))
            app.step(6)  # 0.1 s: the next frame
        assert seen == [10, 17, 24, 31]
        for _ in range(27):  # on to the strip's last frame, past the atlas' width
            app.step(6)
        app.render()
        assert int(frame_pixels(app)[32, 32, 0]) == 7 * 31 + 10
    finally:
        app.close()


def test_a_frame_larger_than_the_atlas_is_refused_naming_its_size() -> None:
    big = from_array(strip(1, ATLAS_SIZE + 100, 16))
    clip = Clip.grid(big, (1, 1), duration=0.1)

    def setup(world: World) -> None:
        world.spawn(Transform(0, 0), Sprite(big), Animator({"a": clip}, "a"))

    wide = rf"{ATLAS_SIZE + 100}x16 frame is larger than the animation atlas"
    made: list[App] = []
    try:
        with pytest.raises(KgeError, match=wide):  # at the spawn, before any frame
            made.append(App(setup, headless=True, size=(64, 64)))
    finally:
        for app in made:
            app.close()
