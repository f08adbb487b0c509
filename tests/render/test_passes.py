"""Render passes: a plugin draws into the world's batch (before) or over it (after)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from kge import App, Camera, Plugin, Transform, World, draw
from kge.render.passes import Frame, passes_for
from kge.render.setup import frame_pixels


class MarkerPlugin(Plugin):
    """Draws a green square at world (1, 0) in the batch and a red one over the frame."""

    def __init__(self) -> None:
        self.frames: list[Frame] = []
        self.shapes: list[Any] = []

    def build(self, world: World) -> None:
        passes_for(world).add(self.before, phase="before")
        passes_for(world).add(self.after, phase="after")

    def before(self, frame: Frame) -> None:
        import pyglet

        from kge.render.groups import SCREEN

        self.frames.append(frame)
        x, y = frame.world_to_screen((1.0, 0.0))
        if not self.shapes:  # one vertex list in the world's batch, kept between frames
            self.shapes.append(
                pyglet.shapes.Rectangle(
                    0, 0, 10, 10, color=(0, 255, 0), batch=frame.batch,
                    group=frame.groups.get(0, SCREEN),
                )
            )  # fmt: skip
        self.shapes[0].position = (x - 5, y - 5)

    def after(self, frame: Frame) -> None:
        import pyglet

        pyglet.shapes.Rectangle(0, 0, 6, 6, color=(255, 0, 0)).draw()


def scene(world: World) -> None:
    world.spawn(Camera(center=(0.0, 0.0), pixels_per_meter=40))
    world.spawn(Transform(-1.0, 0.0), draw.Rect(0.5, 0.5, color=(0, 0, 255)))


def test_before_pass_draws_in_the_batch_with_the_camera_and_after_pass_on_top(
    make_app: Callable[..., App],
) -> None:
    plugin = MarkerPlugin()
    app = make_app(scene)
    app.add_plugins(plugin)
    app.render()
    px = frame_pixels(app)
    w, h = app.size
    frame = plugin.frames[-1]
    assert frame.viewport == (w, h) and frame.scale == 40.0
    assert tuple(px[h // 2, w // 2 + 40][:3]) == (0, 255, 0)  # world (1, 0): 40 px right
    assert tuple(px[h // 2, w // 2 - 40][:3]) == (0, 0, 255)  # the batch's own rect
    assert tuple(px[2, 2][:3]) == (255, 0, 0)  # after-pass, window pixels
    app.world.get(1, Camera).center = (1.0, 0.0)
    app.render()
    px = frame_pixels(app)
    assert tuple(px[h // 2, w // 2][:3]) == (0, 255, 0)  # follows the camera
