"""The defend-the-centre shooter played headless with scripted input."""

import math
from pathlib import Path

import numpy as np
import pytest
import shooter  # examples/shooter.py

from kge import App, Behaviour, Key, Mouse, Sprite, Text, Transform
from kge.components.camera import Camera
from kge.testbed.samples.build import named


def start(seed: int = 3) -> App:
    app = App(shooter.menu, headless=True, size=shooter.SIZE)
    app.input.press(Key.SPACE)
    app.step()
    app.input.release(Key.SPACE)  # KGE starts on key *up*
    app.step()
    app.replace_scene(shooter.game, seed=seed)  # same scene, seeded for a repeatable test
    return app


def hud(app: App) -> str:
    return app.world.get(named(app.world, "score")[0], Text).text


def screen(app: App, p: tuple[float, float]) -> tuple[float, float]:
    cam = app.world.try_resource(Camera) or Camera()
    return cam.world_to_screen(p, app.size)


def test_space_on_the_menu_starts_the_game() -> None:
    app = App(shooter.menu, headless=True, size=shooter.SIZE)
    app.input.press(Key.SPACE)
    app.step()
    app.input.release(Key.SPACE)
    app.step()
    assert named(app.world, "ship") and hud(app) == "Score : 0"


def test_firing_at_an_approaching_enemy_kills_it_and_scores() -> None:
    app = start()
    while not named(app.world, "enemy"):
        app.step()
    killed = False
    for _ in range(60 * 8):
        enemies = named(app.world, "enemy")
        if enemies:
            t = app.world.get(enemies[0], Transform)
            app.input.move_mouse(*screen(app, (t.x, t.y)))  # aim at the first enemy
            if not app.input.mouse_held(Mouse.LEFT):
                app.input.mouse_down(Mouse.LEFT)
        app.step()
        if hud(app) != "Score : 0":
            killed = True
            break
    assert killed, "holding fire at an enemy should kill it"
    assert named(app.world, "ship"), "the ship survives when it shoots first"


def test_ship_faces_the_mouse() -> None:
    app = start()
    app.input.move_mouse(*screen(app, (3.0, 0.0)))
    app.step()
    ship = app.world.get(named(app.world, "ship")[0], Transform)
    assert math.isclose(ship.angle, -math.pi / 2, abs_tol=1e-6)  # nose (+y) turned to +x


def test_contact_with_an_enemy_ends_the_game_and_r_restarts_at_zero() -> None:
    app = start()
    for _ in range(60 * 30):
        app.step()
        if named(app.world, "game-over"):
            break
    assert named(app.world, "game-over"), "an unopposed enemy reaches the ship"
    assert not named(app.world, "ship")
    app.input.press(Key.R)
    app.step()
    assert named(app.world, "ship") and hud(app) == "Score : 0"
    assert not named(app.world, "game-over")


def test_shots_leaving_the_frame_are_removed() -> None:
    app = start()
    app.input.move_mouse(*screen(app, (0.0, 5.0)))
    app.input.mouse_down(Mouse.LEFT)
    app.step(6)
    app.input.mouse_up(Mouse.LEFT)
    assert named(app.world, "shot")
    app.step(60 * 4 + 30)  # 3 m/s: past the 11 m frame after about 3.5 s
    for e in named(app.world, "shot"):
        assert abs(app.world.get(e, Transform).y) < shooter.FRAME_HALF + 0.2


def test_enemies_fly_nose_first_and_shots_are_laser_bolts() -> None:
    from kge.testing import read_png

    # the art: the enemy's nose is at the top of its image (local +y, where it flies)
    alpha = read_png(Path(shooter.__file__).parent / "assets" / "enemy.png")[..., 3] > 0
    widths = alpha.sum(axis=1)
    rows = np.nonzero(widths)[0]
    mass_row = float((widths * np.arange(len(widths))).sum() / widths.sum())
    # an arrowhead's area sits towards its tail: nose at the top means the mass is low
    assert (mass_row - rows[0]) / (rows[-1] - rows[0]) > 0.5
    assert alpha[rows[0], 20:28].any()  # and the tip is centred
    # the game: an enemy's local +y points at the ship; a shot carries the laser sprite
    app = start()
    app.step(90)
    for e in named(app.world, "enemy"):
        t = app.world.get(e, Transform)
        nose = (-math.sin(t.angle), math.cos(t.angle))
        to_ship = (-t.x, -t.y)
        assert nose[0] * to_ship[0] + nose[1] * to_ship[1] > 0
    ship_script = app.world.get(named(app.world, "ship")[0], Behaviour).script
    shot = ship_script.fire(0.3)
    assert app.world.get(shot, Sprite).image == "laser.png"
    assert app.world.get(shot, Transform).angle == pytest.approx(0.3)
