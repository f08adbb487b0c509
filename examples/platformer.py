"""A small platformer: run, jump, collect coins, take the door.

The two levels are scene files made in the editor (``examples/levels/level1.scene.toml``,
``level2.scene.toml``; ``kge edit examples/levels/level1.scene.toml --game
examples/platformer.py`` opens one): each loads a Tiled map for its terrain (the ground
becomes a few merged chain outlines, the planks one-way platforms) and places the player,
the coins and the door as entities. ``examples/platformer_levels.py`` is the editing
session that made them, as a script. The door replaces the scene with the next level
(``app.replace_scene``); the score travels along as a scene argument.

The art around the tiles is painted in code (``kge.testbed.paint``) and drawn with
linear filtering: a dusk sky, hills repeated along the level (one sprite), the hero
and glowing coins, swapped in for the plain shapes the level files show in the editor.
The camera's post stack blooms the coins; a second camera draws a minimap of the level
in the corner. The player is a ``CharacterBody`` (docs/character.md).

Controls are named actions (``left``, ``right``, ``jump``, ``drop``, ``pause``) declared
once for the App (``App(..., bindings=...)``): left/right or A/D run, space/up/W jumps
(hold for higher), down/S drops through a plank, a gamepad's d-pad and A too. P, Escape
or Start pauses: the pause menu's Settings has tabs for the volumes, the controls (a
scroll view of rebinding buttons, with a reset that asks to confirm) and the UI size
(``game_menus.py``). Run it:
``python examples/platformer.py`` (headless it plays itself and prints a summary).
While it runs in a window, edit a level file or this script: the change takes effect.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import game_menus as ui  # imports kge_required first

import kge
from kge import (
    App,
    Behaviour,
    Camera,
    CharacterBody,
    InputMap,
    Key,
    Name,
    Script,
    SensorBegin,
    Sprite,
    Text,
    TextureFilter,
    TextureWrap,
    Transform,
    World,
    draw,
    from_array,
)
from kge.testbed import paint

WIDTH, HEIGHT = 960, 600
RUN_SPEED = 6.0
JUMP_SPEED = 11.0
#: the actions a player can rebind in the settings, with their default bindings
ACTIONS: ui.Bindings = {
    "left": ("key:LEFT", "key:A", "pad:dpleft"),
    "right": ("key:RIGHT", "key:D", "pad:dpright"),
    "jump": ("key:SPACE", "key:UP", "key:W", "pad:a"),
    "drop": ("key:DOWN", "key:S", "pad:dpdown"),
}


def bindings(actions: InputMap) -> None:
    """The game's controls (``App(..., bindings=bindings)``): the defaults the settings'
    Reset restores, and "pause" (P, Escape, Start)."""
    ui.bind_defaults(actions, ACTIONS)


@dataclass(slots=True)
class Score:
    coins: int = 0
    level: int = 1


LEVELS = Path(__file__).resolve().parent / "levels"


@kge.register_script
class Player(Script):
    """Runs with the arrows; jumps while standing (higher the longer space is held);
    down drops through the plank underfoot."""

    def on_start(self) -> None:
        # the controls' defaults also when the level file is played alone (the editor's Play)
        bindings(self.world.resource(InputMap))

    def on_fixed_update(self, dt: float) -> None:
        actions = self.world.resource(InputMap)  # rebindable in the settings
        body = self.get(CharacterBody)
        vx = RUN_SPEED * (float(actions.held("right")) - float(actions.held("left")))
        body.velocity = (vx, body.velocity[1])
        body.jump = actions.held("jump")
        body.drop_through = actions.held("drop")


class Referee(Script):
    """Sensor events of the step: the player takes coins and leaves through the door."""

    def on_fixed_update(self, dt: float) -> None:
        world = self.world
        for ev in world.events(SensorBegin):
            for a, b in ((ev.collider_a, ev.collider_b), (ev.collider_b, ev.collider_a)):
                if not (world.exists(a) and world.exists(b)) or not world.has(a, Behaviour):
                    continue
                name = world.try_get(b, Name)
                if name is None:
                    continue
                score = world.resource(Score)
                if name.value == "coin":
                    world.despawn(b)
                    score.coins += 1
                    _hud(world)
                elif name.value == "door":
                    nxt = 2 if score.level % 2 == 1 else 1
                    world.resource(App).replace_scene(
                        level, number=nxt, score=Score(score.coins, score.level + 1)
                    )
                    return


def _hud(world: World) -> None:
    score = world.resource(Score)
    for _, (t,) in world.query(Text):
        t.text = f"level {score.level}   coins {score.coins}"


HERO = from_array(paint.hero(64))
COIN = from_array(paint.orb(32))
SKY = from_array(paint.sky(256, 128))
HILLS = from_array(paint.hills(256, 96))


def dress(world: World) -> None:
    """The painted art over a loaded level: the hero and glowing coins (bright enough for
    the camera's bloom) in place of the files' plain shapes, a sky and hills behind, and
    a minimap camera in the corner."""
    for e in named(world, "player"):
        world.remove(e, draw.Rect)
        world.add(e, Sprite(HERO, size=(1.0, 1.0), filter=TextureFilter.LINEAR, layer=2))
    for e in named(world, "coin"):
        world.remove(e, draw.Circle)
        world.add(e, Sprite(COIN, size=(0.8, 0.8), filter=TextureFilter.LINEAR, layer=2))
    (camera,) = named(world, "camera")
    bounds = world.get(camera, Camera).bounds
    assert bounds is not None  # the level files bound their camera
    x0, y0, x1, y1 = bounds
    world.spawn(Camera(center=((x0 + x1) / 2, (y0 + y1) / 2), order=1,  # the minimap
                       pixels_per_meter=min(220.0 / (x1 - x0), 120.0 / (y1 - y0)),
                       viewport=(0.74, 0.76, 0.24, 0.22), background=(15, 20, 35)))  # fmt: skip
    w, h = x1 - x0, y1 - y0
    world.spawn(Transform((x0 + x1) / 2, (y0 + y1) / 2), Sprite(
        SKY, size=(w + 20.0, h + 20.0), filter=TextureFilter.LINEAR, layer=-10))  # fmt: skip
    world.spawn(Transform((x0 + x1) / 2, y0 + 3.0), Sprite(
        HILLS, size=(w + 20.0, 6.0), filter=TextureFilter.LINEAR, wrap=TextureWrap.REPEAT,
        tile=(16.0, 6.0), layer=-9))  # fmt: skip


def level(world: World, number: int = 1, score: Score | None = None) -> None:
    """Load level ``number``'s scene file and dress it; the HUD and the referee are the
    game's code."""
    bindings(world.resource(InputMap))  # (already declared by main(); tests start here)
    world.insert_resource(score or Score())
    kge.load_scene(world, LEVELS / f"level{number}.scene.toml")
    dress(world)
    world.spawn(Behaviour(Referee()))
    world.spawn(Behaviour(ui.PauseKey(title, tuple(ACTIONS))))  # P / Esc / Start: the menu
    hud = Text("", size=16, color=(255, 255, 255, 255), screen_space=True, anchor=(0.0, 1.0))
    hud.offset = (12.0, float(HEIGHT - 10))
    world.spawn(Transform(), hud)
    _hud(world)


def title(world: World) -> None:
    """The title screen: Play fades into the first level; Settings; Quit."""
    ui.title_menu(world, "PLATFORMER", "Arrows or A/D run, Space jumps, Down drops; "
                  "P pauses. Rebind the keys in Settings.", level, tuple(ACTIONS))  # fmt: skip


def named(world: World, name: str) -> list[int]:
    return [e for e, (n,) in world.query(Name) if n.value == name]


def play(app: App, levels: int, seconds: float = 60.0) -> None:
    """A self-playing run: right, a jump every 2/3 s, no jumps in the last 8 m of a level."""
    app.input.press(Key.RIGHT)
    for i in range(int(seconds * 60)):
        players = named(app.world, "player")
        x = app.world.get(players[0], Transform).x if players else 0.0
        near_door = x > _door_x(app.world) - 8.0
        if i % 40 == 0 and not near_door:
            app.input.press(Key.SPACE)
        elif i % 40 == 20 or near_door:
            app.input.release(Key.SPACE)
        app.step()
        if app.world.resource(Score).level > levels:
            return


def _door_x(world: World) -> float:
    doors = named(world, "door")
    return world.get(doors[0], Transform).x if doors else float("inf")


def main() -> None:
    app = App(title, title="kge platformer", size=(WIDTH, HEIGHT), background=(90, 140, 200),
              bindings=bindings)  # fmt: skip
    if not app.headless:
        app.run()
        return
    app.replace_scene(level)
    play(app, levels=2)
    score = app.world.resource(Score)
    print(f"kge {kge.__version__} platformer, headless: level {score.level}, {score.coins} coins")
    app.close()


if __name__ == "__main__":
    main()
