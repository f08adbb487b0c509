"""The stats overlay says how long the light pass takes and when it dominates the frame."""

from __future__ import annotations

from kge import Collider, Transform
from kge.components.camera import Camera
from kge.components.debug import DebugDraw
from kge.components.lights import Light, Lighting, ShadowCaster
from kge.components.shapes import Box
from kge.render.passtime import PassTimer
from kge.render.stats import light_note
from kge.systems.render import RenderSystem


def test_the_note_says_when_the_light_pass_dominates() -> None:
    assert light_note(2.0, 10.0) == "2.0 ms of 10.0"
    assert light_note(5.0, 10.0) == "5.0 ms of 10.0"  # half: not yet
    assert light_note(5.1, 10.0).endswith("(the light pass dominates the frame)")
    assert "dominates" not in light_note(0.0, 0.0)


def test_the_timer_adds_a_pass_over_cameras_and_smooths_frames(monkeypatch) -> None:
    import kge.render.passtime as passtime

    clock = iter(range(100))
    monkeypatch.setattr(passtime.time, "perf_counter", lambda: next(clock) / 1000.0)
    finishes: list[int] = []
    timer = PassTimer(finish=lambda: finishes.append(1))
    timer.start(True)  # t = 0 ms
    ran: list[str] = []
    timer.run("lighting", ran.append, "left view")  # 1 -> 2: 1 ms
    timer.run("lighting", ran.append, "right view")  # 3 -> 4: 1 ms more
    timer.finish()  # 5: a 5 ms frame
    assert ran == ["left view", "right view"]
    assert (timer.ms("lighting"), timer.frame_ms) == (2.0, 5.0)
    assert len(finishes) == 6  # the GPU finished around each measure
    timer.start(True)
    timer.run("lighting", ran.append, "left view")  # 7 -> 8: 1 ms this frame
    timer.finish()  # 9 - 6 = 3 ms
    assert timer.ms("lighting") == 2.0 + 0.2 * (1.0 - 2.0)  # smoothed
    assert timer.frame_ms == 5.0 + 0.2 * (3.0 - 5.0)
    timer.start(False)  # overlay hidden: nothing timed, no stall, figures dropped
    timer.run("lighting", ran.append, "unseen")
    timer.finish()
    assert (timer.ms("lighting"), timer.frame_ms, len(finishes)) == (0.0, 0.0, 10)
    assert ran[-1] == "unseen"  # the pass still ran


def _street(world) -> None:
    world.insert_resource(Camera(pixels_per_meter=20.0))
    world.insert_resource(Lighting(ambient=(30, 30, 40)))
    world.insert_resource(DebugDraw(enabled=False, stats=True))
    for i in range(6):
        world.spawn(Transform(-4.0 + 1.6 * i, 1.0), Light(radius=6.0, shadows=True))
        world.spawn(Transform(-4.0 + 1.6 * i, -1.0), Collider(Box(0.3, 0.3)), ShadowCaster())


def test_the_overlay_shows_the_light_pass_with_lighting_on(make_app) -> None:
    app = make_app(_street)
    for _ in range(3):
        app.render()
    view = app.world.get_system(RenderSystem).view
    assert view.timer.ms("lighting") > 0.0 and view.timer.frame_ms > view.timer.ms("lighting")
    assert "lights " in view.stats.text and " ms of " in view.stats.text
    app.world.resource(Lighting).enabled = False
    app.render()
    assert "lights " not in view.stats.text  # no lighting, no entry
    app.world.resource(DebugDraw).stats = False
    app.render()
    assert view.timer.frame_ms == 0.0  # hidden overlay: nothing timed
