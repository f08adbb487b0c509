"""kge.box2d's testbed framework (pybox2d's Framework contract): picking, bombs, contact
points, pausing, text, the window backend's pixels and the command line."""

from __future__ import annotations

import contextlib
import io
import subprocess
import sys
from typing import Any

import numpy as np
import pytest

from kge.box2d.testbed import examples, settings
from kge.box2d.testbed.__main__ import main
from kge.box2d.testbed.headless import HeadlessBackend
from kge.box2d.testbed.presses import Press, parse_presses


def _run(build: Any, frames: int, presses: list[Press] | None = None,
         backend: Any = None) -> Any:
    """Build a Framework subclass with ``build(fw)`` and run it ``frames`` frames."""
    settings.reset()
    backend = backend or HeadlessBackend(frames, presses)
    with examples.bound("kge") as fw:
        fw.backend = backend
        try:
            test = build(fw)()
            test.run()
        finally:
            fw.backend = None
    return backend


def _box_on_ground(fw: Any) -> type:
    class BoxOnGround(fw.Framework):
        name = "Box"
        description = "one box on the ground"

        def __init__(self) -> None:
            super().__init__()
            self.world.CreateStaticBody(shapes=fw.b2.b2EdgeShape(vertices=[(-20, 0), (20, 0)]))
            self.box = self.world.CreateDynamicBody(position=(0, 5))
            self.box.CreatePolygonFixture(box=(1, 1), density=1)

    return BoxOnGround


def test_mouse_picks_and_drags_a_body_and_shift_drag_launches_a_bomb() -> None:
    class Mouse(HeadlessBackend):
        def run(self, test: Any) -> None:
            self.test = test
            for frame in range(90):
                if frame == 40:
                    test.MouseDown(test.box.position.copy())  # grab the box's centre
                    assert test.mouseJoint is not None and test.mouseJoint.bodyB is test.box
                if 40 <= frame < 70:
                    test.MouseMove((0.0, 3.0))  # drag it up
                if frame == 70:
                    self.held_at = test.box.position.copy()
                    test.MouseUp((0.0, 3.0))
                    assert test.mouseJoint is None and test.world.jointCount == 0
                    test.ShiftMouseDown((-5.0, 2.0))
                    test.MouseMove((-6.0, 2.0))
                if frame == 75:
                    test.MouseUp((-6.0, 2.0))  # dragged 1 m left: launched 30 m/s right
                    self.bomb_speed = test.bomb.linearVelocity.copy()
                test.Frame()
            self.frames_run = 90

    backend = _run(_box_on_ground, 90, backend=Mouse(90))
    assert backend.held_at.y > 2.5  # lifted from 1.0 towards the pointer at 3 m
    assert backend.bomb_speed.x == pytest.approx(30.0) and backend.bomb_speed.y == pytest.approx(0)


def test_contact_points_are_gathered_and_drawn_when_asked() -> None:
    settings.reset()
    backend = HeadlessBackend(80)
    with examples.bound("kge") as fw:
        fw.backend = backend
        fw.fwSettings.drawContactPoints = True  # the settings run() starts from
        try:
            test = _box_on_ground(fw)()
            for _ in range(80):
                test.Frame()
        finally:
            fw.backend = None
    states = {p["state"] for p in test.points}
    assert len(test.points) == 2 and states == {2}  # two persisting points under the box
    assert all(abs(p["position"][1]) < 0.02 and p["normal"] == (0, 1) for p in test.points)
    kinds = backend.record.counts()
    assert kinds["point"] == 2  # drawn as points


def test_pause_single_step_and_text() -> None:
    settings.reset()
    settings.fwSettings.pause = True
    backend = HeadlessBackend(5, [Press(2, "F2")])  # F2: one step while paused
    with examples.bound("kge") as fw:
        fw.backend = backend
        try:
            test = _box_on_ground(fw)()
            settings.fwSettings.pause = True
            test.run()
        finally:
            fw.backend = None
            settings.reset()
    assert test.box.linearVelocity.y == pytest.approx(-10.0 / 60.0)  # exactly one step
    lines = [t[2] for t in test.text]
    assert lines[:3] == ["Box", "one box on the ground", "****PAUSED****"]


def test_destroying_a_body_says_goodbye_to_its_joints() -> None:
    gone: list[Any] = []

    def build(fw: Any) -> type:
        base = _box_on_ground(fw)

        class Jointed(base):  # type: ignore[misc, valid-type]
            def JointDestroyed(self, joint: Any) -> None:
                gone.append(joint)

        return Jointed

    class Destroy(HeadlessBackend):
        def run(self, test: Any) -> None:
            joint = test.world.CreateRevoluteJoint(bodyA=test.groundbody, bodyB=test.box,
                                                   anchor=(0, 5))
            test.Frame()
            test.world.DestroyBody(test.box)
            assert gone == [joint]
            self.test, self.frames_run = test, 1

    _run(build, 1, backend=Destroy(1))
    assert len(gone) == 1


def test_window_backend_draws_the_bodies_and_zoom_key_scales_them() -> None:
    from kge.box2d.testbed.window import WindowBackend
    from kge.render.setup import frame_pixels

    def lit_width(backend: Any) -> int:
        app = backend.app
        app.render()
        px = frame_pixels(app)
        test = backend.test
        # the box's row: screen y of its centre (y up in the pixel array)
        _, sy = test.renderer.to_screen(test.box.position)
        row = px[int(test.screenSize[1] - sy), :, :3].astype(int).sum(axis=1)
        return int(np.count_nonzero(row > 60))

    plain = _run(_box_on_ground, 90, backend=WindowBackend(90, headless=True, keep_open=True))
    zoomed = _run(_box_on_ground, 90, backend=WindowBackend(
        90, [Press(5, "z"), Press(10, "z")], headless=True, keep_open=True))
    try:
        width, zoomed_width = lit_width(plain), lit_width(zoomed)
        assert plain.frames_run == 90
        assert abs(width - 20) <= 3  # a 2 m box at 10 px/m
        assert abs(zoomed_width - 20 * 1.21) <= 3  # z twice: 1.1 x 1.1
    finally:
        plain.app.close()
        zoomed.app.close()


def test_command_line() -> None:
    assert parse_presses("120:b,300:w/60") == [Press(120, "b"), Press(300, "w", 60)]
    with pytest.raises(KeyError):
        parse_presses("1:nokey")
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert main(["breakable", "--headless", "--frames", "12", "--keys", "5:b",
                     "--no-drawStats", "--hz", "30"]) == 0
    text = out.getvalue()
    assert "breakable: 12 frames" in text and "4 bodies" in text  # b broke it
    assert "bodies=" not in text  # --no-drawStats
    listing = subprocess.run([sys.executable, "-m", "kge.box2d.testbed", "--list"],
                             capture_output=True, text=True, check=True)
    assert "one_sided_platform" in listing.stdout.split()
    assert main(["no_such_example", "--headless"]) == 2
