"""A small platformer on Tiled maps written by code: run, jump, collect coins, take the door.

The two levels are Tiled maps (TMX) written by
``kge.testbed.samples.tilemaps.write_levels`` from generated tiles, then loaded
with ``kge.load_map``: the ground becomes a few merged chain outlines, the
planks one-way platforms, and the map's objects (player start, coins, door)
entities through a spawner registry. The door replaces the scene with the next
level (``app.replace_scene``); the score travels along as a scene argument.

The art around the tiles is painted in code (``kge.testbed.paint``) and drawn with
linear filtering: a dusk sky, hills repeated along the level (one sprite), the hero
and glowing coins. The camera's post stack blooms the coins; a second camera draws
a minimap of the level in the corner.

Keys: left/right (or A/D) run, space/up jumps (hold for higher), down drops through a
plank. The player is a ``CharacterBody`` (docs/character.md). Run it:
``python examples/platformer.py`` (headless it plays itself and prints a summary).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import kge_required  # noqa: F401  (first: names the Python to use when kge is missing)

import kge
from kge import (
    App,
    Behaviour,
    Bloom,
    Box,
    Camera,
    CharacterBody,
    Input,
    Key,
    MapObject,
    Script,
    SensorBegin,
    Spawn,
    Spawners,
    Sprite,
    Text,
    TextureFilter,
    TextureWrap,
    Transform,
    World,
    from_array,
)
from kge.testbed import paint
from kge.testbed.samples.tilemaps import levels

WIDTH, HEIGHT = 960, 600
RUN_SPEED = 6.0
JUMP_SPEED = 11.0


@dataclass(slots=True)
class Score:
    coins: int = 0
    level: int = 1


class Player(Script):
    """Runs with the arrows; jumps while standing (higher the longer space is held);
    down drops through the plank underfoot."""

    def on_fixed_update(self, dt: float) -> None:
        inp = self.world.resource(Input)
        body = self.get(CharacterBody)
        body.velocity = (RUN_SPEED * inp.axis((Key.LEFT, Key.A), (Key.RIGHT, Key.D)),
                         body.velocity[1])
        body.jump = inp.any_held(Key.SPACE, Key.UP)
        body.drop_through = inp.any_held(Key.DOWN, Key.S)


class Referee(Script):
    """Sensor events of the step: the player takes coins and leaves through the door."""

    def on_fixed_update(self, dt: float) -> None:
        world = self.world
        for ev in world.events(SensorBegin):
            for a, b in ((ev.collider_a, ev.collider_b), (ev.collider_b, ev.collider_a)):
                if not (world.exists(a) and world.exists(b)) or not world.has(a, Behaviour):
                    continue
                obj = world.try_get(b, MapObject)
                if obj is None:
                    continue
                score = world.resource(Score)
                if obj.cls == "Coin":
                    world.despawn(b)
                    score.coins += 1
                    _hud(world)
                elif obj.cls == "Door":
                    nxt = levels()[1] if score.level == 1 else levels()[0]
                    world.resource(App).replace_scene(
                        level, path=nxt, score=Score(score.coins, score.level + 1)
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


def player_start(spawn: Spawn) -> list[Any]:
    return [
        CharacterBody(Box(0.4, 0.45), jump_speed=JUMP_SPEED),
        Sprite(HERO, size=(1.0, 1.0), filter=TextureFilter.LINEAR, layer=2),
        Behaviour(Player()),
    ]


def coin(spawn: Spawn) -> list[Any]:
    """A glowing orb instead of the tile: bright enough for the camera's bloom."""
    return [Sprite(COIN, size=(0.8, 0.8), filter=TextureFilter.LINEAR, layer=2)]


SPAWNERS = Spawners({"PlayerStart": player_start, "Coin": coin, "Door": lambda s: None})


def scenery(world: World, bounds: tuple[float, float, float, float]) -> None:
    """A painted sky behind the level and hills repeated along it (one sprite)."""
    x0, y0, x1, y1 = bounds
    w, h = x1 - x0, y1 - y0
    world.spawn(Transform((x0 + x1) / 2, (y0 + y1) / 2), Sprite(
        SKY, size=(w + 20.0, h + 20.0), filter=TextureFilter.LINEAR, layer=-10))  # fmt: skip
    world.spawn(Transform((x0 + x1) / 2, y0 + 3.0), Sprite(
        HILLS, size=(w + 20.0, 6.0), filter=TextureFilter.LINEAR, wrap=TextureWrap.REPEAT,
        tile=(16.0, 6.0), layer=-9))  # fmt: skip


def level(world: World, path: Path | None = None, score: Score | None = None) -> None:
    world.insert_resource(score or Score())
    m = kge.load_map(world, path or levels()[0], spawners=SPAWNERS)
    player = next(e for e in m.objects if world.get(e, MapObject).cls == "PlayerStart")
    world.spawn(Camera(pixels_per_meter=40, follow=player, bounds=m.bounds,
                       post=(Bloom(threshold=0.75, intensity=1.3, radius=10.0),)))  # fmt: skip
    x0, y0, x1, y1 = m.bounds
    world.spawn(Camera(center=((x0 + x1) / 2, (y0 + y1) / 2), order=1,  # the minimap
                       pixels_per_meter=min(220.0 / (x1 - x0), 120.0 / (y1 - y0)),
                       viewport=(0.74, 0.76, 0.24, 0.22), background=(15, 20, 35)))  # fmt: skip
    scenery(world, m.bounds)
    world.spawn(Behaviour(Referee()))
    hud = Text("", size=16, color=(255, 255, 255, 255), screen_space=True, anchor=(0.0, 1.0))
    hud.offset = (12.0, float(HEIGHT - 10))
    world.spawn(Transform(), hud)
    _hud(world)


def play(app: App, levels: int, seconds: float = 60.0) -> None:
    """A self-playing run: right, a jump every 2/3 s, no jumps in the last 8 m of a level."""
    app.input.press(Key.RIGHT)
    for i in range(int(seconds * 60)):
        players = [e for e, (m,) in app.world.query(MapObject) if m.cls == "PlayerStart"]
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
    doors = [e for e, (m,) in world.query(MapObject) if m.cls == "Door"]
    return world.get(doors[0], Transform).x if doors else float("inf")


def main() -> None:
    app = App(level, title="kge platformer", size=(WIDTH, HEIGHT), background=(90, 140, 200))
    if not app.headless:
        app.run()
        return
    play(app, levels=2)
    score = app.world.resource(Score)
    print(f"kge {kge.__version__} platformer, headless: level {score.level}, {score.coins} coins")
    app.close()


if __name__ == "__main__":
    main()
