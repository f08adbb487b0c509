"""A small platformer on Tiled maps written by code: run, jump, collect coins, take the door.

The two levels are Tiled maps (TMX) written by
``kge.testbed.samples.tilemaps.write_levels`` from generated tiles, then loaded
with ``kge.load_map``: the ground becomes a few merged chain outlines, the
planks one-way platforms, and the map's objects (player start, coins, door)
entities through a spawner registry. The door replaces the scene with the next
level (``app.replace_scene``); the score travels along as a scene argument.

Keys: left/right (or A/D) run, space/up jumps. Run it:
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
    Box,
    Camera,
    Collider,
    Input,
    Key,
    MapObject,
    Physics,
    RigidBody,
    Script,
    SensorBegin,
    Spawn,
    Spawners,
    Text,
    Transform,
    World,
)
from kge.components import drawables as draw
from kge.testbed.samples.tilemaps import levels

WIDTH, HEIGHT = 960, 600
RUN_SPEED = 6.0
JUMP_SPEED = 11.0


@dataclass(slots=True)
class Score:
    coins: int = 0
    level: int = 1


class Player(Script):
    """Runs with the arrows, jumps when something is under its feet."""

    def on_fixed_update(self, dt: float) -> None:
        inp = self.world.resource(Input)
        rb = self.get(RigidBody)
        vx = RUN_SPEED * inp.axis((Key.LEFT, Key.A), (Key.RIGHT, Key.D))
        vy = rb.velocity[1]
        if inp.any_held(Key.SPACE, Key.UP) and self.grounded() and vy <= 0.1:
            vy = JUMP_SPEED
        rb.velocity = (vx, vy)

    def grounded(self) -> bool:
        t = self.transform
        physics = self.world.resource(Physics)
        for dx in (-0.35, 0.0, 0.35):
            hit = physics.raycast((t.x + dx, t.y - 0.45), (t.x + dx, t.y - 0.6))
            if hit is not None:
                return True
        return False


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


def player_start(spawn: Spawn) -> list[Any]:
    return [
        RigidBody(fixed_rotation=True),
        Collider(Box(0.4, 0.45), friction=0.0, density=1.0),
        draw.Rect(0.8, 0.9, color=(220, 60, 60, 255), layer=1),
        Behaviour(Player()),
    ]


SPAWNERS = Spawners({"PlayerStart": player_start, "Coin": lambda s: None, "Door": lambda s: None})


def level(world: World, path: Path | None = None, score: Score | None = None) -> None:
    world.insert_resource(score or Score())
    m = kge.load_map(world, path or levels()[0], spawners=SPAWNERS)
    player = next(e for e in m.objects if world.get(e, MapObject).cls == "PlayerStart")
    world.insert_resource(Camera(pixels_per_meter=40, follow=player, bounds=m.bounds))
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
