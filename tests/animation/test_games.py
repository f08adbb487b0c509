"""The example games' animation: shooter explosions, thruster and shake; Pong's score pop."""

from __future__ import annotations

import pong  # examples/pong.py (this folder's conftest puts examples/ on the path)
import pytest
import shooter  # examples/shooter.py

from kge import Animations, App, Behaviour, CameraShake, Text, Transform
from kge.testbed.samples.build import named


def _referee(app: App) -> shooter.Referee:
    for _, (beh,) in app.world.query(Behaviour):
        if isinstance(beh.script, shooter.Referee):
            return beh.script
    raise AssertionError("no referee")


def test_a_kill_explodes_shakes_the_camera_and_the_blast_removes_itself() -> None:
    app = App(shooter.game, headless=True, size=shooter.SIZE, seed=1)
    app.step()
    enemy = shooter.spawn_enemy(app.world, 3.0, 2.0, 1.0)
    shot = app.world.spawn(Transform(3.0, 2.0), shooter.Name("shot"))
    _referee(app).kill(enemy, shot)
    app.step()
    (blast,) = named(app.world, "explosion")
    assert app.world.get(blast, Transform).position == (3.0, 2.0)
    assert app.world.resource(CameraShake).trauma > 0.2
    frames = []
    for _ in range(30):
        if not app.world.exists(blast):
            break
        frames.append(app.world.resource(Animations).frame(blast))
        app.step()
    assert not app.world.exists(blast)  # 8 frames at 20 fps: gone after 0.4 s
    assert frames[0] == 0 and max(frames) == 7 and sorted(frames) == frames
    assert 23 <= len(frames) <= 26


def test_the_thruster_flickers_behind_the_ship() -> None:
    app = App(shooter.game, headless=True, size=shooter.SIZE, seed=1)
    app.input.move_mouse(900, 350)  # aim right
    seen = set()
    for _ in range(30):
        app.step()
        seen.add(app.world.resource(Animations).frame(named(app.world, "thruster")[0]))
    ship = app.world.get(named(app.world, "ship")[0], Transform)
    flame = app.world.get(named(app.world, "thruster")[0], Transform)
    assert flame.angle == ship.angle and seen == {0, 1, 2, 3}
    nose = (-__import__("math").sin(ship.angle), __import__("math").cos(ship.angle))
    assert flame.x * nose[0] + flame.y * nose[1] < 0  # behind the nose


def test_pong_score_pops_and_settles() -> None:
    app = App(pong.pong, headless=True, seed=2)
    app.step()
    e = named(app.world, "score-player")[0]
    app.world.get(e, Behaviour).script.add()
    sizes = []
    for _ in range(40):
        app.step()
        sizes.append(app.world.get(e, Text).size)
    assert max(sizes) == pytest.approx(24.0, abs=0.5)
    assert sizes[-1] == 15.0 and app.world.get(e, Text).text == "1"
