"""The interactive testbed: every sample in one window, Box2D-testbed style.

It is made of kge parts only. Each sample runs in a :class:`TestbedScene`, which
builds the sample and then adds a :class:`TestbedController` script, a camera,
debug drawing with the stats overlay, and screen-space text for the sample list
and help. The controller reacts to input through ordinary Behaviour hooks, so
the same code runs in a window and in headless tests (driven by ``app.input``).

=====================  ==========================================================
PageUp / PageDown      previous / next sample (or click a name in the list)
Tab                    hide / show the sample list
R                      restart the sample
P / O                  pause / single step
arrows, right-drag     pan the camera; mouse wheel zooms
left-drag              grab a dynamic body (a MouseJoint)
shift + left-drag      aim and launch a bomb
1 2 3 4 5              toggle shapes, joints, AABBs, centres of mass, contacts
F1 / F2                toggle all debug drawing / the stats overlay
Esc                    quit
=====================  ==========================================================

The list shows every category, with the current one opened, so it stays short as
samples are added; each sample is framed in the area the list and help leave free.
"""

from __future__ import annotations

import math
from typing import Any

from kge.app import App
from kge.components import Behaviour, Name, Script, Transform
from kge.components.camera import Camera
from kge.components.collider import Collider
from kge.components.debug import DebugDraw
from kge.components.joints import MouseJoint
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Circle
from kge.components.text import Text
from kge.input import Input, MouseEvent
from kge.keys import Key, Mod, Mouse
from kge.physics.resource import Physics
from kge.scene import Scene
from kge.testbed.framing import sample_camera
from kge.testbed.registry import Sample, all_samples, get_sample
from kge.world import World

LIST_TOP = 36.0  # pixels from the top of the window to the first list line (below the stats)
LINE = 15.0  # pixels per list line
LIST_WIDTH = 190.0  # clickable width of the sample list
HELP_HEIGHT = 110.0  # pixels the help text takes at the top of the window
HELP_KEYS = (
    "PgUp/PgDn samples  Tab list  R restart  P pause  O step  Esc quit",
    "drag: grab  shift-drag: bomb  arrows/right-drag: pan  wheel: zoom",
    "1-5: shapes joints AABBs centres contacts  F1: debug  F2: stats",
)
PAN_SPEED = 0.6  # screen widths per second with the arrow keys
DEBUG_KEYS = {Key._1: "shapes", Key._2: "joints", Key._3: "aabbs", Key._4: "centers_of_mass",
              Key._5: "contacts"}


class TestbedScene(Scene):
    """Runs one sample with the testbed's camera, overlay and controller."""

    __test__ = False  # not a pytest test class, despite the name

    def __init__(self, sample: Sample) -> None:
        self.sample = sample
        self.name = sample.name

    def setup(self, world: World, **kwargs: Any) -> None:
        self.sample.setup(world, **kwargs)
        app = world.resource(App)
        w, h = app.size
        if not world.has_resource(Camera):
            free = (LIST_WIDTH, 0.0, float(w), h - HELP_HEIGHT)
            world.insert_resource(sample_camera(world, self.sample, app.size, free))
        if not world.has_resource(DebugDraw):
            world.insert_resource(DebugDraw(stats=True))
        world.spawn(Behaviour(TestbedController(self.sample)), Name("testbed"))
        _overlay(world, self.sample, app.size)


def list_rows(current: Sample) -> list[tuple[str, Sample]]:
    """The sample list as shown: one line per category, the current one opened.

    Each row is (text, the sample a click opens): a category line opens its first
    sample. Keeping closed categories to one line keeps the list off the scene.
    """
    rows: list[tuple[str, Sample]] = []
    by_category: dict[str, list[Sample]] = {}
    for s in all_samples():
        by_category.setdefault(s.category, []).append(s)
    for category, members in by_category.items():
        if category == current.category:
            rows.append((f"- {category}", members[0]))
            for s in members:
                rows.append((f"{'>' if s.slug == current.slug else ' '}   {s.name}", s))
        else:
            rows.append((f"+ {category} ({len(members)})", members[0]))
    return rows


def _overlay(world: World, current: Sample, size: tuple[int, int]) -> None:
    """Sample list (left), help and keys (right), as screen-space text."""
    w, h = size
    for i, (text, s) in enumerate(list_rows(current)):
        color = (255, 220, 90, 255) if s.slug == current.slug and text.startswith(">") else (
            (200, 200, 210, 255) if text.startswith(" ") else (150, 190, 255, 255))
        world.spawn(Text(text, size=9, color=color, screen_space=True,
                         anchor=(0.0, 1.0), offset=(6.0, h - LIST_TOP - i * LINE), layer=200),
                    Name("sample-list"))
    lines = [current.name, current.help] + [f"{k}: {v}" for k, v in current.keys.items()]
    lines += HELP_KEYS
    for i, line in enumerate(lines):
        world.spawn(Text(line, size=10 if i else 13, color=(235, 235, 235, 255),
                         screen_space=True, anchor=(1.0, 1.0), offset=(w - 8.0, h - 10.0 - i * 17),
                         layer=200, bold=i == 0), Name("help"))


class TestbedController(Script):
    """Keys, picking, bombs and camera control for the running sample."""

    __test__ = False

    def __init__(self, sample: Sample) -> None:
        self.sample = sample
        self.grab: int | None = None  # the MouseJoint entity while dragging
        self.bomb_from: tuple[float, float] | None = None
        self.pan_from: tuple[float, float] | None = None

    # -- helpers -----------------------------------------------------------------------
    @property
    def app(self) -> App:
        return self.world.resource(App)

    def camera(self) -> Camera:
        return self.world.resource(Camera)

    def switch(self, step: int) -> None:
        samples = all_samples()
        i = next(i for i, s in enumerate(samples) if s.slug == self.sample.slug)
        self.app.replace_scene(TestbedScene(samples[(i + step) % len(samples)]))

    # -- keys --------------------------------------------------------------------------
    def on_key_down(self, key: int) -> None:
        app = self.app
        if key == Key.PAGEDOWN:
            self.switch(+1)
        elif key == Key.PAGEUP:
            self.switch(-1)
        elif key == Key.R:
            app.replace_scene(TestbedScene(self.sample))
        elif key == Key.P:
            app.paused = not app.paused
        elif key == Key.O:
            app.paused = True
            app.single_step()
        elif key in DEBUG_KEYS:
            debug = self.world.resource(DebugDraw)
            name = DEBUG_KEYS[key]
            setattr(debug, name, not getattr(debug, name))
        elif key == Key.ESCAPE:
            app.quit()
        elif key == Key.TAB:
            for _, (label, tag) in self.world.query(Text, Name):
                if tag.value == "sample-list":
                    label.visible = not label.visible

    def on_update(self, dt: float) -> None:
        keys = self.world.resource(Input)
        dx = keys.axis((Key.LEFT,), (Key.RIGHT,))
        dy = keys.axis((Key.DOWN,), (Key.UP,))
        if dx or dy:
            cam = self.camera()
            # real seconds: panning works while paused too
            step = PAN_SPEED * self.app.size[0] / cam.scale * (1.0 / 60.0)
            cam.center = (cam.center[0] + dx * step, cam.center[1] + dy * step)
            keys.refresh_world_position()

    # -- mouse -------------------------------------------------------------------------
    def on_mouse_down(self, event: MouseEvent) -> None:
        on_list = event.button == Mouse.LEFT and event.screen[0] < LIST_WIDTH
        if on_list and self._click_list(event.screen):
            return
        if event.button == Mouse.RIGHT:
            self.pan_from = event.screen
        elif event.button == Mouse.LEFT and event.modifiers & Mod.SHIFT:
            self.bomb_from = event.world
        elif event.button == Mouse.LEFT:
            self._pick(event.world)

    def on_mouse_move(self, event: MouseEvent) -> None:
        if self.grab is not None and self.world.exists(self.grab):
            self.world.get(self.grab, MouseJoint).target = event.world
        if self.pan_from is not None:
            cam = self.camera()
            dx = (event.screen[0] - self.pan_from[0]) / cam.scale
            dy = (event.screen[1] - self.pan_from[1]) / cam.scale
            cam.center = (cam.center[0] - dx, cam.center[1] - dy)
            self.pan_from = event.screen

    def on_mouse_up(self, event: MouseEvent) -> None:
        if event.button == Mouse.RIGHT:
            self.pan_from = None
        elif event.button == Mouse.LEFT:
            if self.grab is not None and self.world.exists(self.grab):
                self.world.despawn(self.grab)
            self.grab = None
            if self.bomb_from is not None:
                self.launch_bomb(self.bomb_from, event.world)
                self.bomb_from = None

    def on_mouse_scroll(self, event: MouseEvent) -> None:
        cam = self.camera()
        cam.zoom = min(10.0, max(0.1, cam.zoom * 1.1 ** event.scroll[1]))

    def _click_list(self, screen: tuple[float, float]) -> bool:
        shown = any(
            t.visible for _, (t, n) in self.world.query(Text, Name) if n.value == "sample-list"
        )
        row = int((self.app.size[1] - LIST_TOP - screen[1]) // LINE)
        rows = list_rows(self.sample)
        if shown and 0 <= row < len(rows):
            self.app.replace_scene(TestbedScene(rows[row][1]))
            return True
        return False

    def _pick(self, point: tuple[float, float]) -> None:
        physics = self.world.resource(Physics)
        for hit in physics.query_point(point):
            body = hit.body
            if body is None:
                continue
            rb = self.world.try_get(body, RigidBody)
            if rb is None or rb.type is not BodyType.DYNAMIC:
                continue
            mass = physics.mass_data(body).mass
            self.grab = self.world.spawn(
                MouseJoint(None, body, target=point, grab_point=point, max_force=1000.0 * mass),
                Name("testbed-grab"),
            )
            return

    def launch_bomb(self, start: tuple[float, float], end: tuple[float, float]) -> int:
        """A small heavy ball from ``start``, faster the longer the drag (as Box2D's)."""
        vx, vy = 30.0 * (start[0] - end[0]), 30.0 * (start[1] - end[1])
        speed = math.hypot(vx, vy)
        if speed > 100.0:
            vx, vy = vx * 100.0 / speed, vy * 100.0 / speed
        return self.world.spawn(
            Transform(*start), RigidBody(velocity=(vx, vy), bullet=True),
            Collider(Circle(0.3), density=20.0, restitution=0.0), Name("bomb"),
        )


def run_testbed(start: str | None = None, size: tuple[int, int] = (1280, 720),
                frames: int | None = None, screenshot: str | None = None) -> int:
    """Open the testbed window on ``start`` (a sample name) or the first sample.

    ``frames`` closes it after that many frames (smoke tests on a virtual display);
    ``screenshot`` then saves the last frame.
    """
    from kge.hotreload import HotReloadPlugin

    sample = get_sample(start) if start else all_samples()[0]
    app = App(TestbedScene(sample), title="kge testbed", size=size, headless=False)
    app.add_plugins(HotReloadPlugin())  # edit a prefab or a sample's module: it reloads
    app.run(frames, screenshot)
    app.close()
    return 0
