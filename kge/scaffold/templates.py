"""The files of a new project (``kge new``): ``{pkg}`` in a path and ``{{pkg}}``,
``{{name}}``, ``{{title}}`` in a text are replaced by the project's names."""

from __future__ import annotations

PYPROJECT = '''[build-system]
requires = ["setuptools>=77"]
build-backend = "setuptools.build_meta"

[project]
name = "{{name}}"
version = "0.1.0"
description = "{{title}}: a game made with kge"
requires-python = ">=3.11"
# kge 2 is installed from its source folder (pip install -e path/to/kge) before this
dependencies = ["kge>=2.0.0a1"]

[project.optional-dependencies]
dev = ["pytest>=8"]

[tool.setuptools.packages.find]
include = ["{{pkg}}*"]

[tool.pytest.ini_options]
testpaths = ["tests"]
'''

GAME = '''"""{{title}}: walk, jump, pick up the coin.

One scene (``level``), one Behaviour (``Player``), art and sound made in code.
"""

from __future__ import annotations

from dataclasses import dataclass

from kge import (
    App, Audio, Behaviour, Box, Camera, CharacterBody, Circle, Collider, Input, Key, Script,
    SensorBegin, Sprite, Text, Transform, World, solid,
)
from kge.sound import tone

PLAYER_COLOR = (90, 200, 255, 255)
COIN_COLOR = (255, 210, 60, 255)
JUMP = tone(660, 0.08, shape="square")  # a sound made in code


@dataclass(slots=True)
class Score:
    """A resource: coins picked up."""

    coins: int = 0


class Player(Script):
    """Arrows or A/D walk; space jumps when standing; touching the coin takes it."""

    speed = 4.0  # metres per second

    def on_fixed_update(self, dt: float) -> None:
        """Each fixed step, just before the character moves (docs/character.md)."""
        keys = self.world.resource(Input)
        body = self.get(CharacterBody)
        walk = keys.axis((Key.A, Key.LEFT), (Key.D, Key.RIGHT)) * self.speed
        body.velocity = (walk, body.velocity[1])  # keep velocity[1]: gravity and jumps
        body.jump = keys.held(Key.SPACE)  # jumps when pressed while standing
        if body.jumped:  # the last step started a jump
            self.world.resource(Audio).play(JUMP)

    def on_sensor_begin(self, event: SensorBegin) -> None:
        coin = event.collider_a  # the sensor: the coin this player touched
        if self.world.exists(coin):
            self.world.despawn(coin)
            score = self.world.resource(Score)
            score.coins += 1
            for _, (hud,) in self.world.query(Text):
                hud.text = f"coins: {score.coins}"


def level(world: World) -> None:
    """The ground, the player and one coin."""
    world.insert_resource(Score())
    world.spawn(Camera(center=(0.0, 2.0), pixels_per_meter=48))
    ground = Sprite(solid(4, 4, (80, 90, 110)), size=(16, 1))
    world.spawn(Transform(0, -0.5), Collider(Box(8, 0.5)), ground)
    world.spawn(
        Transform(-4, 1), CharacterBody(Box(0.4, 0.4), jump_speed=6.0),
        Sprite(solid(4, 4, PLAYER_COLOR), size=(0.8, 0.8)), Behaviour(Player()),
    )
    world.spawn(
        Transform(3, 0.6), Collider(Circle(0.3), sensor=True),
        Sprite(solid(4, 4, COIN_COLOR), size=(0.6, 0.6)),
    )
    world.spawn(Text("coins: 0", size=18, screen_space=True, offset=(12, 520), anchor=(0, 1)))


def main(frames: int | None = None, screenshot: str | None = None) -> App:
    """Open a window (headless without a display) and play."""
    app = App(level, title="{{title}}")
    app.run(frames=frames, screenshot=screenshot)
    return app
'''

MAIN = '''"""python -m {{pkg}} [FRAMES] [--screenshot FILE]: play (stop after FRAMES frames,
saving the last one as a PNG: how tests and exported builds are checked headless)."""

import argparse

from {{pkg}}.game import main

parser = argparse.ArgumentParser(prog="{{pkg}}", description="{{title}}")
parser.add_argument("frames", nargs="?", type=int, help="stop after this many frames")
parser.add_argument("--screenshot", help="save the last frame as this PNG")
args = parser.parse_args()
main(args.frames, args.screenshot)
'''

TEST = '''"""{{title}}'s rules, tested headless with kge's pytest fixtures."""

from kge import Key, Transform
from kge.testing import step_until

from {{pkg}}.game import Score, level

PLAYER = 3  # camera 1, ground 2, player 3, coin 4


def test_the_player_lands_on_the_ground(kge_app):
    app = kge_app(level)
    app.step(60)
    assert abs(app.world.get(PLAYER, Transform).y - 0.4) < 0.05


def test_walking_right_picks_up_the_coin(kge_app):
    app = kge_app(level)
    app.input.press(Key.RIGHT)
    step_until(app, lambda: app.world.resource(Score).coins == 1, timeout=4.0)
    assert not app.world.exists(4)


def test_space_jumps(kge_app):
    app = kge_app(level)
    app.step(60)
    app.input.press(Key.SPACE)
    app.step(10)
    assert app.world.get(PLAYER, Transform).y > 0.8
'''

README = '''# {{title}}

A game made with kge 2, a data-oriented 2D game engine for Python. kge 2 installs
from its source folder (`pip install -e path/to/kge`); the package index's `kge` is the
unrelated KGE 1.0.

```sh
pip install -e .          # in the virtual environment that has kge
python -m {{pkg}}          # play: arrows or A/D walk, space jumps
pytest                    # the tests, headless
```
'''

FILES: dict[str, str] = {
    "pyproject.toml": PYPROJECT,
    "README.md": README,
    "{pkg}/__init__.py": '"""{{title}}: a game made with kge."""\n',
    "{pkg}/__main__.py": MAIN,
    "{pkg}/game.py": GAME,
    "tests/test_game.py": TEST,
}
