"""The canvas of a high-DPI window: screen coordinates stay window pixels while drawing
(text, the light map, viewports) happens at the framebuffer's real pixel size."""

from __future__ import annotations

from dataclasses import dataclass

import pytest

from kge import Resolution, ScaleMode, World
from kge.render.canvas import canvas_of


@dataclass
class _Window:
    """A window of ``width`` x ``height`` screen units over a larger framebuffer."""

    width: int
    height: int
    framebuffer: tuple[int, int]

    def get_framebuffer_size(self) -> tuple[int, int]:
        return self.framebuffer


def test_a_high_dpi_window_draws_at_its_framebuffer_size() -> None:
    world = World()
    canvas = canvas_of(world, _Window(640, 360, (1280, 720)))  # a 2x display
    assert canvas.size == (640, 360)  # cameras, UI and the mouse: window units
    assert canvas.rect == (0, 0, 1280, 720) and canvas.pixel_scale == 2.0
    assert canvas.sub_rect((0.5, 0.0, 0.5, 1.0)) == (640, 0, 640, 720)  # split screen


@pytest.mark.parametrize(("mode", "rect", "scale"), [
    (ScaleMode.LETTERBOX, (64, 0, 1152, 720), (3.6, 3.6)),  # bars left and right
    (ScaleMode.STRETCH, (0, 0, 1280, 720), (4.0, 3.6)),
])  # fmt: skip
def test_a_design_resolution_on_a_high_dpi_window(mode, rect, scale) -> None:
    world = World()
    world.insert_resource(Resolution(320, 200, mode=mode))
    canvas = canvas_of(world, _Window(640, 360, (1280, 720)))  # a 2x display
    assert canvas.size == (320, 200)  # design pixels
    assert canvas.rect == rect  # framebuffer pixels, not window units
    assert canvas.scale == pytest.approx(scale) and canvas.pixel_scale == pytest.approx(3.6)
