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

import functools
import os
import time
from typing import Any

from kge.components.camera import Camera
from kge.components.debug import DebugDraw
from kge.components.drawables import DRAWABLE_TYPES
from kge.components.rigidbody import RigidBody
from kge.components.sprite import Sprite
from kge.components.text import Text
from kge.components.tracked import validate_writes
from kge.components.transform import Transform
from kge.errors import DisplayError, ValidationError, where
from kge.host import Host
from kge.input import Input
from kge.keys import Key
from kge.plugin import Plugin
from kge.schedule import Stage, System, SystemSet
from kge.world import World


class RenderSystem(System):
    """Draws the world's drawables with the active camera (RENDER stage)."""

    stage = Stage.RENDER
    in_set = SystemSet.DRAW

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
    in_set = SystemSet.FIRST
    started = 0.0

    def process(self, dt: float) -> None:
        self.started = time.perf_counter()


class RenderStepRecorder(System):
    """Records poses for interpolation and the step time (last in the FIXED stage)."""

    stage = Stage.FIXED
    in_set = SystemSet.LAST

    def process(self, dt: float) -> None:
        renderer = self.world.get_system(RenderSystem)
        if renderer is None:
            return
        clock = self.world.get_system(RenderStepClock)
        spent = time.perf_counter() - clock.started if clock is not None else 0.0
        renderer.view.after_step(spent)


class CameraFollow(System):
    """Moves every camera with ``follow`` set towards its target (LATE stage)."""

    stage = Stage.LATE
    in_set = SystemSet.CAMERA

    def process(self, dt: float) -> None:
        world = self.world
        cams = [c for _, (c,) in world.query(Camera)]
        res = world.try_resource(Camera)
        if res is not None:
            cams.append(res)
        host = world.try_resource(Host)
        viewport = host.size if host is not None else None
        for cam in cams:
            if cam.follow is None:
                continue
            t = world.try_get(cam.follow, Transform)
            if t is not None:
                velocity = (0.0, 0.0)
                if cam.look_ahead > 0:
                    rb = world.try_get(cam.follow, RigidBody)
                    if rb is not None:
                        velocity = rb.velocity
                cam.track((t.x, t.y), dt, viewport, velocity)


class DebugKeys(System):
    """F1 toggles the physics debug view, F2 the stats overlay (INPUT stage).

    An ordinary system reading the Input resource, so a real window and a headless
    test (``app.input.press(Key.F1)``) take the same path, once.
    """

    stage = Stage.INPUT
    in_set = SystemSet.DEBUG

    def process(self, dt: float) -> None:
        keys = self.world.try_resource(Input)
        if keys is None:
            return
        for key, field in ((Key.F1, "enabled"), (Key.F2, "stats")):
            if keys.pressed(key):
                settings = self.world.try_resource(DebugDraw)
                if settings is None:  # first press: the view appears
                    settings = self.world.insert_resource(DebugDraw(enabled=False))
                setattr(settings, field, not getattr(settings, field))


class PygletFrontend:
    """How an App draws, saves screenshots and opens its window (``app.frontend``).

    The App calls it without knowing pyglet exists; each method imports pyglet's GL
    side (through :mod:`kge.render`) only when it runs.
    """

    def _ensure(self, host: Host, window: Any = None) -> None:
        """Create the App's renderer and add the drawing systems to all its worlds, once."""
        from kge.render.setup import ensure_renderer, renderer_for

        if renderer_for(host) is None:
            ensure_renderer(host, window)
            for factory in (RenderStepClock, RenderStepRecorder, RenderSystem):
                host.add_system_to_all(factory)

    def render(self, host: Host) -> None:
        """Draw the visible worlds bottom first (a frozen one at its last pose), then
        the scene transition, if one plays."""
        from kge.render.setup import renderer_for

        self._ensure(host)
        renderer = renderer_for(host)
        assert renderer is not None
        self._draw_worlds(host, renderer)
        if host.transition is not None:
            from kge.render.transitions import draw_transition

            draw_transition(renderer, host.transition, host.background)

    @staticmethod
    def _draw_worlds(host: Host, renderer: Any) -> None:
        top = host.world
        worlds = host.visible_worlds()
        try:
            for i, world in enumerate(worlds):
                renderer.clear = i == 0
                alpha = getattr(host, "alpha", 1.0) if world is top else 1.0
                world.schedule.run(Stage.RENDER, alpha)
        finally:
            renderer.clear = True

    def capture(self, host: Host) -> Any:
        """Draw the visible worlds and read the frame back as a texture (the old scene of a
        transition); None when this App has not drawn yet (nothing to picture)."""
        from kge.render.setup import renderer_for
        from kge.render.transitions import take_picture

        renderer = renderer_for(host)
        if renderer is None:
            return None
        self._draw_worlds(host, renderer)
        return take_picture(renderer)

    def screenshot(self, host: Host, path: str) -> None:
        from kge.render.setup import save_color_buffer

        self.render(host)
        save_color_buffer(host, path)

    def run_window(self, host: Host, frames: int | None, screenshot: str | None) -> bool:
        try:
            from kge.render.window import run_windowed
        except ImportError:
            return False
        app: Any = host  # the window drives the whole App (its loop and scene stack)
        try:
            run_windowed(app, frames, screenshot, prepare=self._ensure)
        except Exception as err:
            if type(err).__name__ != "NoSuchDisplayException":
                raise
            display = os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")
            raise DisplayError(
                f"cannot open a window: the display {display!r} does not answer; start it, "
                "or unset DISPLAY (or pass headless=True) to run without a window"
            ) from None
        return True


class RenderPlugin(Plugin):
    """Drawing: the App's window (or EGL pbuffer) and the render systems.

    Every world gets :class:`CameraFollow` at once (pure, so mouse picking through a
    following camera works headless). The window and the drawing systems are
    created on the first ``app.render()`` (or ``app.run()`` with a display), so a
    headless App that never draws never loads pyglet's GL.
    """

    def build_app(self, app: Host) -> None:
        app.frontend = PygletFrontend()

    def build(self, world: World) -> None:
        world.add_system(CameraFollow())
        world.add_system(DebugKeys())
        world.validator(Sprite, functools.partial(_check_sprite_image, world))
        validate_writes(world, Sprite)
        world.validator(Text, functools.partial(_check_text, world))
        validate_writes(world, Text)
        world.validator(Camera, functools.partial(_check_camera_follow, world))
        validate_writes(world, Camera)
        for drawn in DRAWABLE_TYPES:  # a bad write names its entity
            validate_writes(world, drawn)


def _check_camera_follow(world: World, entity: int | None, cam: Camera) -> None:
    """A camera following an entity that does not exist (or has no Transform) is refused
    at the call, not left watching nothing."""
    target = cam.follow
    if target is None:
        return
    if not world.exists(target):
        raise ValidationError(
            f"{where(entity, 'Camera', 'follow')}: entity {target} does not exist"
        )
    if world.try_get(target, Transform) is None:
        raise ValidationError(
            f"{where(entity, 'Camera', 'follow')}: entity {target} has no Transform to follow"
        )


def _check_sprite_image(world: World, entity: int | None, sprite: Sprite) -> None:
    """A sprite whose image file is missing or cannot load (truncated, 0 x 0, too large)
    is refused at spawn, not at the first frame.

    The file is looked up (the asset store's search, listing every place tried) and its
    header checked once per file (:mod:`kge.assets.headers`); decoding waits for the
    first draw, so a headless App never decodes an image.
    """
    image = sprite.image
    if isinstance(image, (str, os.PathLike)):
        from kge.assets.store import assets_for

        assets_for(world).checked_image(image, owner=where(entity, "Sprite", "image"))


def _check_text(world: World, entity: int | None, text: Text) -> None:
    """Text is checked at the call, headless: its markup parses, a font file exists (it
    is registered then), and a font family that exists nowhere gives a FontWarning."""
    from kge.text.fonts import FONTS, is_font_file
    from kge.text.markup import parse

    owner = where(entity, "Text")
    if text.markup:
        try:
            parse(text.text)
        except ValidationError as exc:
            raise ValidationError(f"{owner}.text: {exc}") from None
    font = text.font
    if font is None:
        return
    if is_font_file(font):
        from kge.assets.store import assets_for

        assets = assets_for(world)
        found = assets.resolve(font, owner=where(entity, "Text", "font"))
        assets.font(font)
        FONTS.names[font] = found.where
        return
    if not FONTS.known(font):
        FONTS.warn_missing(font, where(entity, "Text", "font"))
