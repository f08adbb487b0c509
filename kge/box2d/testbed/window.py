"""The window backend: pybox2d's testbed in a kge window (keyboard, mouse, text included).

A kge :class:`~kge.app.App` runs the test: one ``Frame()`` per fixed step at
``settings.hz``. The framework's renderer hands over screen pixels (y down, as
pybox2d's backends get them); :class:`PixelSink` draws them as kge drawables in
a world measured in pixels (a camera of 1 px per unit), so the test's own view
(``viewCenter``, ``viewZoom``, z / x, the arrow keys) is what moves the picture.
Text from ``Print`` and ``DrawStringAt`` becomes screen-space ``Text``.

Events: scripted presses (``presses``) are handed to the framework at their frame, as
headless; real keys go to the framework (its own keys, then the test's ``Keyboard`` /
``KeyboardUp``; Esc closes), the left button picks a body with a mouse joint
(with shift: aims a bomb, launched on release), the right button drags the
view, the wheel zooms. With ``headless=True`` the same App renders off screen
(EGL), for pixel tests and screenshots.
"""

from __future__ import annotations

from time import perf_counter
from typing import TYPE_CHECKING, Any

from kge.app import App
from kge.box2d.draw import b2Color
from kge.box2d.testbed.keys import FROM_KGE
from kge.box2d.testbed.presses import Press, press_scripted
from kge.box2d.view import KgeDraw
from kge.components import Behaviour, Script
from kge.components.camera import Camera
from kge.components.text import Text
from kge.input import MouseEvent
from kge.keys import Key, Mod, Mouse
from kge.world import World

if TYPE_CHECKING:
    from kge.box2d.testbed.framework import Framework

#: text size (px) and the line colour when a test gives none
TEXT_SIZE = 11.0


def _color(color: Any) -> b2Color:
    """kge's b2Color from any engine's b2Color or a 0..1 triple."""
    r, g, b = list(color)[:3]
    return b2Color(r, g, b)


class PixelSink:
    """Draws the framework's screen-pixel primitives as pooled kge drawables."""

    def __init__(self, height: float) -> None:
        self.height = float(height)
        self.draw: KgeDraw | None = None

    def attach(self, world: World) -> None:
        self.draw = KgeDraw(world, thickness=1.0)

    def _up(self, p: tuple[float, float]) -> tuple[float, float]:
        return (float(p[0]), self.height - float(p[1]))

    def start(self) -> None:
        if self.draw is not None:
            self.draw.StartDraw()

    def end(self) -> None:
        if self.draw is not None:
            self.draw.EndDraw()

    def polygon(self, points: list[tuple[float, float]], color: Any, filled: bool) -> None:
        if self.draw is not None:
            pts = [self._up(p) for p in points]
            method = self.draw.DrawSolidPolygon if filled else self.draw.DrawPolygon
            method(pts, _color(color))

    def circle(self, center: tuple[float, float], radius: float, color: Any,
               filled: bool) -> None:
        if self.draw is not None and radius > 0.0:
            self.draw._circle(self._up(center), radius, _color(color), filled)

    def segment(self, p1: tuple[float, float], p2: tuple[float, float], color: Any) -> None:
        if self.draw is not None:
            self.draw.DrawSegment(self._up(p1), self._up(p2), _color(color))

    def point(self, p: tuple[float, float], size: float, color: Any) -> None:
        if self.draw is not None:
            self.draw._circle(self._up(p), max(size, 1.0), _color(color), True)


class TestDriver(Script):
    """Runs the test in the App: its frames, the events, the text."""

    __test__ = False

    def __init__(self, test: Framework, presses: list[Press]) -> None:
        self.test = test
        self.presses = presses
        self.frame = 0
        self.labels: list[int] = []
        self.pan_from: tuple[float, float] | None = None

    @property
    def app(self) -> App:
        return self.world.resource(App)

    def on_fixed_update(self, dt: float) -> None:
        press_scripted(self.test, self.presses, self.frame)
        self.test.Frame()
        self.frame += 1

    def on_late_update(self, dt: float) -> None:
        self._show_text()

    # -- keys --------------------------------------------------------------------------
    def on_key_down(self, key: int) -> None:
        if key == Key.ESCAPE:
            self.app.quit()
        elif key in FROM_KGE:
            self.test.KeyDown(FROM_KGE[key])

    def on_key_up(self, key: int) -> None:
        if key in FROM_KGE:
            self.test.KeyUp(FROM_KGE[key])

    # -- mouse -------------------------------------------------------------------------
    def _world_point(self, event: MouseEvent) -> Any:
        x, y = event.screen
        return self.test.ConvertScreenToWorld(x, self.test.screenSize[1] - y)

    def on_mouse_down(self, event: MouseEvent) -> None:
        if event.button == Mouse.RIGHT:
            self.pan_from = event.screen
        elif event.button == Mouse.LEFT:
            p = self._world_point(event)
            if event.modifiers & Mod.SHIFT:
                self.test.ShiftMouseDown(p)
            else:
                self.test.MouseDown(p)

    def on_mouse_up(self, event: MouseEvent) -> None:
        if event.button == Mouse.RIGHT:
            self.pan_from = None
        elif event.button == Mouse.LEFT:
            self.test.MouseUp(self._world_point(event))

    def on_mouse_move(self, event: MouseEvent) -> None:
        self.test.MouseMove(self._world_point(event))
        if self.pan_from is not None:
            zoom = self.test.viewZoom
            cx, cy = self.test.viewCenter
            dx, dy = event.screen[0] - self.pan_from[0], event.screen[1] - self.pan_from[1]
            self.test.viewCenter = (cx - dx / zoom, cy - dy / zoom)
            self.pan_from = event.screen

    def on_mouse_scroll(self, event: MouseEvent) -> None:
        self.test.viewZoom = min(50.0, max(0.02, self.test.viewZoom * 1.1 ** event.scroll[1]))

    # -- text --------------------------------------------------------------------------
    def _show_text(self) -> None:
        height = float(self.test.screenSize[1])
        lines = self.test.text
        while len(self.labels) < len(lines):
            self.labels.append(self.world.spawn(Text(
                "", size=TEXT_SIZE, screen_space=True, anchor=(0.0, 1.0), layer=200)))
        for i, entity in enumerate(self.labels):
            label = self.world.get(entity, Text)
            if i < len(lines):
                x, y, text, color = lines[i]
                label.value, label.offset, label.visible = text, (x, height - y), True
                label.color = _rgba(color)
            else:
                label.visible = False


def _rgba(color: Any) -> tuple[int, int, int, int]:
    """pybox2d's text colours are 0..255 triples or quadruples."""
    values = [int(c) for c in list(color)[:4]]
    return (values[0], values[1], values[2], values[3] if len(values) > 3 else 255)


class WindowBackend:
    """Run a test in a kge App: a window (``headless=False``) or off screen."""

    def __init__(self, frames: int | None = None, presses: list[Press] | None = None,
                 screenshot: str | None = None, headless: bool = False,
                 keep_open: bool = False) -> None:
        self.frames = frames
        self.presses = list(presses or [])
        self.screenshot = screenshot
        self.headless = headless
        #: leave the App open after run (tests read its pixels, then close it)
        self.keep_open = keep_open
        self.app: App | None = None
        self.test: Framework | None = None
        self._sink: PixelSink | None = None
        self.frames_run = 0
        self.seconds = 0.0

    def sink(self, test: Framework) -> PixelSink:
        self._sink = PixelSink(test.screenSize[1])
        return self._sink

    def run(self, test: Framework) -> None:
        self.test = test
        sink = self._sink or self.sink(test)
        width, height = int(test.screenSize[0]), int(test.screenSize[1])
        hz = test.settings.hz if test.settings.hz > 0 else 60.0

        driver = TestDriver(test, self.presses)

        def setup(world: World) -> None:
            world.insert_resource(Camera(center=(width / 2, height / 2), pixels_per_meter=1.0))
            sink.attach(world)
            world.spawn(Behaviour(driver))

        app = self.app = App(setup, headless=self.headless, size=(width, height),
                             title=f"kge.box2d testbed - {test.name}", fixed_dt=1.0 / hz,
                             background=(0, 0, 0))
        started = perf_counter()
        try:
            app.run(self.frames, self.screenshot)
        finally:
            self.frames_run, self.seconds = driver.frame, perf_counter() - started
            if not self.keep_open:
                app.close()
