"""Rendering systems: draw the world, record poses after each step, follow with the camera.

* :class:`RenderSystem` (RENDER stage) mirrors Sprite, Text and shape
  components into one pyglet batch and draws it at the blended pose
  (see :mod:`kge.render`). Its pyglet side is imported when it is attached,
  so importing this module stays headless.
* :class:`RenderStepClock` / :class:`RenderStepRecorder` (FIXED stage, first
  and last) time each fixed step and record poses for interpolation.
* :class:`CameraFollow` (LATE stage) moves cameras that follow an entity. It
  is pure and needs no window, so mouse picking through a following camera
  works headless too.

``App.render()`` adds all of them on first use (``kge.render.setup``).
"""

from __future__ import annotations

import time
from typing import Any

from kge.components.camera import Camera
from kge.components.transform import Transform
from kge.schedule import Stage, System


class RenderSystem(System):
    """Draws the world's drawables with the active camera (RENDER stage)."""

    stage = Stage.RENDER
    order = 0

    def attach(self, world: Any) -> None:
        super().attach(world)
        from kge.render.frame import WorldView

        self.view = WorldView(world)

    def process(self, dt: float) -> None:
        """``dt`` is the interpolation alpha (the App runs RENDER with it)."""
        self.view.draw(dt)

    def detach(self) -> None:
        self.view.close()


class RenderStepClock(System):
    """Starts the fixed-step timer (first in the FIXED stage)."""

    stage = Stage.FIXED
    order = -1_000_000
    started = 0.0

    def process(self, dt: float) -> None:
        self.started = time.perf_counter()


class RenderStepRecorder(System):
    """Records poses for interpolation and the step time (last in the FIXED stage)."""

    stage = Stage.FIXED
    order = 1_000_000

    def process(self, dt: float) -> None:
        renderer = self.world.get_system(RenderSystem)
        if renderer is None:
            return
        clock = self.world.get_system(RenderStepClock)
        spent = time.perf_counter() - clock.started if clock is not None else 0.0
        renderer.view.after_step(spent)


def active_camera(world: Any) -> Camera | None:
    """Lowest entity id with a Camera, else the Camera resource, else None."""
    cams = world.query(Camera)
    if cams:
        cam: Camera = min(cams, key=lambda item: item[0])[1][0]
        return cam
    found: Camera | None = world.try_resource(Camera)
    return found


class CameraFollow(System):
    """Moves every camera with ``follow`` set towards its target (LATE stage)."""

    stage = Stage.LATE
    order = 200

    def process(self, dt: float) -> None:
        world = self.world
        cams = [c for _, (c,) in world.query(Camera)]
        res = world.try_resource(Camera)
        if res is not None:
            cams.append(res)
        viewport = None
        try:
            from kge.app import App

            app = world.try_resource(App)
            if app is not None:
                viewport = app.size
        except ImportError:  # pragma: no cover
            pass
        for cam in cams:
            if cam.follow is None:
                continue
            t = world.try_get(cam.follow, Transform)
            if t is not None:
                cam.track((t.x, t.y), dt, viewport)
