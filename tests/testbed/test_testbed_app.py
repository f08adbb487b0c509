"""The interactive testbed's controls, driven headless through app.input."""

from kge import App, Key, Mod, Mouse, Name, Transform
from kge.components.camera import Camera
from kge.components.debug import DebugDraw
from kge.components.joints import MouseJoint
from kge.testbed import get_sample
from kge.testbed.app import LINE, LIST_TOP, TestbedScene
from kge.testbed.samples.build import named


def open_testbed(slug: str) -> App:
    return App(TestbedScene(get_sample(slug)), headless=True, size=(960, 540))


def screen_of(app: App, point: tuple[float, float]) -> tuple[float, float]:
    return app.world.resource(Camera).world_to_screen(point, app.size)


def test_page_keys_switch_samples_and_r_restarts() -> None:
    app = open_testbed("hello-world")
    app.input.press(Key.PAGEDOWN)
    app.step()
    first = app.scene.name
    assert first != "Hello World"
    app.input.release(Key.PAGEDOWN)
    app.input.press(Key.PAGEUP)
    app.step()
    assert app.scene.name == "Hello World"
    app.input.release(Key.PAGEUP)
    app.step(30)
    box = named(app.world, "box")[0]
    assert app.world.get(box, Transform).y < 4.0
    app.input.press(Key.R)
    app.step()
    assert app.world.get(named(app.world, "box")[0], Transform).y > 3.9  # fresh world


def test_pause_and_single_step() -> None:
    app = open_testbed("hello-world")
    app.input.press(Key.P)
    app.advance(1 / 60)
    app.input.release(Key.P)
    box = named(app.world, "box")[0]
    y = app.world.get(box, Transform).y
    for _ in range(5):
        app.advance(1 / 60)
    assert app.world.get(box, Transform).y == y  # paused
    app.input.press(Key.O)
    app.advance(1 / 60)
    app.advance(1 / 60)
    assert app.world.get(box, Transform).y < y  # exactly one step ran


def test_left_drag_grabs_a_body_with_a_mouse_joint() -> None:
    app = open_testbed("hello-world")
    app.step(120)  # the box rests at y ~ 1
    box = named(app.world, "box")[0]
    app.input.mouse_down(Mouse.LEFT, at=screen_of(app, (0.0, 1.0)))
    app.step()
    (joint_entity,) = named(app.world, "testbed-grab")
    assert app.world.get(joint_entity, MouseJoint).body_b == box
    app.input.move_mouse(*screen_of(app, (0.0, 4.0)))
    app.step(60)
    assert app.world.get(box, Transform).y > 3.0  # lifted towards the pointer
    app.input.mouse_up(Mouse.LEFT)
    app.step()
    assert named(app.world, "testbed-grab") == []


def test_shift_drag_launches_a_bomb() -> None:
    app = open_testbed("pyramid")
    app.input.mouse_down(Mouse.LEFT, at=screen_of(app, (-5.0, 8.0)), modifiers=Mod.SHIFT)
    app.step()
    app.input.mouse_up(Mouse.LEFT, at=screen_of(app, (-6.0, 8.0)), modifiers=Mod.SHIFT)
    app.step()
    (bomb,) = named(app.world, "bomb")
    app.step(5)
    assert app.world.get(bomb, Transform).x > -5.0  # flies away from the drag direction


def test_camera_zoom_pan_and_debug_toggles() -> None:
    app = open_testbed("pyramid")
    cam = app.world.resource(Camera)
    zoom, center = cam.zoom, cam.center
    app.input.scroll_by(0, 2)
    app.step()
    assert cam.zoom > zoom
    app.input.press(Key.RIGHT)
    app.step(10)
    assert cam.center[0] > center[0]
    debug = app.world.resource(DebugDraw)
    shapes = debug.shapes
    app.input.press(Key._1)
    app.input.press(Key._3)
    app.step()
    assert debug.shapes is not shapes and debug.aabbs


def test_clicking_the_list_switches_sample() -> None:
    app = open_testbed("hello-world")
    list_names = [app.world.get(e, Name) for e in named(app.world, "sample-list")]
    assert len(list_names) >= 25
    app.input.click(Mouse.LEFT, at=(20.0, app.size[1] - LIST_TOP - LINE * 3 - 5.0))
    app.step()
    from kge.testbed import all_samples

    assert app.scene.name == all_samples()[3].name
