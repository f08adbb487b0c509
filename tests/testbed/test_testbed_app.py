"""The interactive testbed's controls, driven headless through app.input."""

from kge import App, Key, Mod, Mouse, Text, Transform
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


def row_at(app: App, row: int) -> tuple[float, float]:
    return (20.0, app.size[1] - LIST_TOP - LINE * row - 5.0)


def test_the_list_opens_only_the_current_category() -> None:
    from kge.testbed import all_samples

    app = open_testbed("hello-world")
    texts = [app.world.get(e, Text).text for e in named(app.world, "sample-list")]
    categories = sorted({s.category for s in all_samples()})
    basics = [s.name for s in all_samples() if s.category == "Basics"]
    assert len(texts) == len(categories) + len(basics)  # one line per closed category
    b = texts.index("- Basics")  # categories are listed by name
    assert texts[b + 1].startswith(">") and "Hello World" in texts[b + 1]
    assert any(t.startswith("+ Joints (") for t in texts)
    # the list ends well above the bottom of a 540-pixel window
    assert LIST_TOP + LINE * len(texts) < app.size[1] - 100


def test_clicking_the_list_switches_sample_and_category() -> None:
    app = open_testbed("hello-world")
    texts = [app.world.get(e, Text).text for e in named(app.world, "sample-list")]
    basics = texts.index("- Basics")  # then "> Hello World", "  Tumbler"
    app.input.click(Mouse.LEFT, at=row_at(app, basics + 2))
    app.step()
    assert app.scene.name == "Tumbler"
    texts = [app.world.get(e, Text).text for e in named(app.world, "sample-list")]
    joints = next(i for i, t in enumerate(texts) if t.startswith("+ Joints"))
    app.input.click(Mouse.LEFT, at=row_at(app, joints))
    app.step()
    assert app.scene.name == "Apply Force"  # the first Joints sample by name


def test_tab_hides_the_list_and_clicks_then_reach_the_scene() -> None:
    app = open_testbed("hello-world")
    app.input.press(Key.TAB)
    app.step()
    assert not any(app.world.get(e, Text).visible for e in named(app.world, "sample-list"))
    app.input.click(Mouse.LEFT, at=row_at(app, 2))
    app.step()
    assert app.scene.name == "Hello World"


def test_escape_quits() -> None:
    app = open_testbed("hello-world")
    app.input.press(Key.ESCAPE)
    frames = app.frame_count
    app.run(frames=100)  # headless: stops at quit
    assert app.frame_count == frames + 1 and not app.running
