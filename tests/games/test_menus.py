"""The games' UI: title menus, fades, see-through pause, settings, HUD corners, gamepads."""

from __future__ import annotations

import math

import pong  # examples/pong.py
import shooter  # examples/shooter.py

from kge import App, Audio, Button, Key, Label, Slider, Transform
from kge.testbed.samples.build import named
from kge.ui.interact import UIState


def click(app: App, text: str) -> None:
    world = app.world
    (button,) = [e for e, (b,) in world.query(Button) if b.text.startswith(text)]
    app.input.click(at=world.resource(UIState).layout.boxes[button].center)
    app.step()


def tap(app: App, key: int) -> None:
    app.input.press(key)
    app.step()
    app.input.release(key)


def ball_pose(app: App) -> tuple[float, float]:
    t = app.world.get(named(app.world, "ball")[0], Transform)
    return (t.x, t.y)


def test_play_fades_from_the_title_menu_into_a_match() -> None:
    app = App(pong.menu, headless=True, size=pong.SIZE)
    app.step()
    menu = app.world
    click(app, "Play")
    assert app.transition is not None and app.world is menu
    app.step(30)
    assert app.transition is None and named(app.world, "ball")


def test_hud_shows_the_scores_in_the_top_corners() -> None:
    app = App(pong.pong, headless=True, size=pong.SIZE, seed=1)
    app.step(60 * 15)
    boxes = app.world.resource(UIState).layout.boxes
    labels = {lbl.text.split()[0]: boxes[e] for e, (lbl,) in app.world.query(Label)}
    assert labels["You"].x == 16 and labels["You"].top == pong.SIZE[1] - 12
    assert labels["The"].right == pong.SIZE[0] - 16
    ai = next(lbl.text for _, (lbl,) in app.world.query(Label) if lbl.text.startswith("The AI"))
    assert ai != "The AI  0"


def test_pause_overlay_freezes_the_match_and_resume_returns_to_it() -> None:
    app = App(pong.pong, headless=True, size=pong.SIZE, seed=1)
    app.step(90)
    game = app.world
    tap(app, Key.P)
    app.step()
    assert app.world is not game and app.visible_worlds() == [game, app.world]
    before = [(t.x, t.y) for _, (t,) in game.query(Transform)]
    app.step(60)
    assert [(t.x, t.y) for _, (t,) in game.query(Transform)] == before
    tap(app, Key.ENTER)  # Resume has the focus
    app.step()
    assert app.world is game
    app.step(10)
    assert [(t.x, t.y) for _, (t,) in game.query(Transform)] != before


def test_settings_volume_slider_and_key_rebinding() -> None:
    app = App(pong.menu, headless=True, size=pong.SIZE)
    app.step()
    click(app, "Settings")
    app.step()
    world = app.world
    boxes = world.resource(UIState).layout.boxes
    music = min(e for e, _ in world.query(Slider))  # the first slider spawned
    b = boxes[music]
    app.input.click(at=(b.x + b.w / 2, b.center[1]))
    app.step()
    assert math.isclose(app.world.resource(Audio).music_volume, 0.5)
    from kge.testing import click as click_text

    click_text(app, "Controls")  # the settings' tabs: Audio, Controls, Display
    app.step()
    click(app, "up:")
    assert any(b.text == "up: press a key..." for _, (b,) in world.query(Button))
    tap(app, Key.I)
    app.step()
    assert app.actions.bindings("up") == ["key:I", "pad:dpup"]
    assert any(b.text == "up: I" for _, (b,) in world.query(Button))
    click(app, "Back")
    app.step()
    click(app, "Play")  # a match, with the new binding
    app.step(30)
    paddle = named(app.world, "paddle-left")[0]
    y = app.world.get(paddle, Transform).y
    app.input.press(Key.I)
    app.step(20)
    assert app.world.get(paddle, Transform).y > y + 1.0


def test_main_menu_from_the_pause_fades_back_to_the_title() -> None:
    app = App(pong.pong, headless=True, size=pong.SIZE, seed=1)
    app.step(10)
    tap(app, Key.ESCAPE)
    app.step()
    click(app, "Main menu")
    app.step(40)
    assert [s.name for s in app.scenes] == ["menu"]
    assert any(b.text == "Play" for _, (b,) in app.world.query(Button))


def test_a_gamepad_plays_pong() -> None:
    app = App(pong.pong, headless=True, size=pong.SIZE, seed=1)
    pad = app.input.connect_gamepad()
    paddle = named(app.world, "paddle-left")[0]
    y = app.world.get(paddle, Transform).y
    pad.press("dpup")
    app.step(20)
    assert app.world.get(paddle, Transform).y > y + 1.0
    pad.release("dpup")
    pad.move("lefty", -1.0)
    y = app.world.get(paddle, Transform).y
    app.step(20)
    assert app.world.get(paddle, Transform).y < y - 1.0
    pad.press("start")
    app.step()
    assert len(app.scenes) == 2  # paused


def test_a_gamepad_aims_and_fires_in_the_shooter() -> None:
    app = App(shooter.game, headless=True, size=shooter.SIZE, seed=3)
    pad = app.input.connect_gamepad()
    pad.move("rightx", 1.0)
    app.step()
    ship = app.world.get(named(app.world, "ship")[0], Transform)
    assert math.isclose(ship.angle, -math.pi / 2, abs_tol=1e-6)  # nose towards +x
    pad.press("a")
    app.step(3)
    assert named(app.world, "shot")


def test_shooter_hud_label_sits_in_the_top_left_corner_and_pause_works() -> None:
    app = App(shooter.game, headless=True, size=shooter.SIZE, seed=3)
    app.step()
    ((e, (lbl,)),) = list(app.world.query(Label))
    box = app.world.resource(UIState).layout.boxes[e]
    assert lbl.text == "Score : 0" and box.x == 16 and box.top == shooter.SIZE[1] - 12
    tap(app, Key.P)
    app.step()
    assert app.visible_worlds()[0].name == "game" and len(app.scenes) == 2
