"""Map objects become entities: transforms, properties, colliders, spawners."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import pytest

from kge.components.collider import Collider
from kge.components.name import Name
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Chain, Circle, Polygon
from kge.components.sprite import Sprite
from kge.components.tilemap import MapObject
from kge.components.transform import Transform
from kge.tilemap import Spawn, Spawners, TilemapWarning, load_map

from .conftest import Stepper
from .maps import COIN, floor, write_level

OBJECTS: list[dict[str, Any]] = [
    {"id": 1, "name": "start", "class": "PlayerStart", "kind": "point", "x": 48, "y": 120},
    {
        "id": 2,
        "name": "gold",
        "class": "Coin",
        "x": 64,
        "y": 32,
        "width": 16,
        "height": 16,
        "properties": {"value": 7},
    },
    {
        "id": 3,
        "name": "crate",
        "x": 96,
        "y": 64,
        "width": 32,
        "height": 16,
        "properties": {"collider": True, "body": "dynamic", "friction": 0.4},
    },
    {
        "id": 4,
        "name": "ball",
        "kind": "ellipse",
        "x": 0,
        "y": 0,
        "width": 16,
        "height": 16,
        "properties": {"collider": True, "sensor": True},
    },
    {
        "id": 5,
        "name": "wedge",
        "kind": "polygon",
        "x": 160,
        "y": 80,
        "points": [(0, 0), (32, 0), (0, -16)],
        "properties": {"collider": True},
    },
    {
        "id": 6,
        "name": "rail",
        "kind": "polyline",
        "x": 16,
        "y": 16,
        "points": [(0, 0), (16, 0), (32, 16)],
        "properties": {"collider": True},
    },
    {"id": 7, "name": "tilted", "x": 0, "y": 160, "width": 32, "height": 16, "rotation": 90},
    {"id": 8, "name": "coin tile", "gid": COIN, "x": 128, "y": 48, "width": 16, "height": 16},
]


def _by_name(world: Any) -> dict[str, int]:
    return {mo.name: e for e, (mo,) in world.query(MapObject)}


def test_objects_spawn_with_transform_and_properties(tmp_path: Path, sim: Stepper) -> None:
    m = load_map(sim.world, write_level(tmp_path, floor(20), OBJECTS), unknown="ignore")
    w = sim.world
    e = _by_name(w)
    assert len(m.objects) == len(OBJECTS)
    # the map is 10 tiles (10 m) high; Tiled's y=120 px is 7.5 tiles down -> 2.5 m up
    assert w.get(e["start"], Transform).position == pytest.approx((3.0, 2.5))
    gold = w.get(e["gold"], MapObject)
    assert (gold.cls, gold.kind, gold.properties) == ("Coin", "rectangle", {"value": 7})
    # rectangles are placed at their centre: x 64..80 px, y 32..48 px (down)
    assert w.get(e["gold"], Transform).position == pytest.approx((4.5, 7.5))
    assert not w.has(e["gold"], Collider)
    crate = w.get(e["crate"], Collider)
    assert isinstance(crate.shape, Box) and crate.shape.half_width == pytest.approx(1.0)
    assert crate.friction == pytest.approx(0.4)
    assert w.get(e["crate"], RigidBody).type == BodyType.DYNAMIC
    ball = w.get(e["ball"], Collider)
    assert isinstance(ball.shape, Circle) and ball.sensor
    wedge = w.get(e["wedge"], Collider).shape
    assert isinstance(wedge, Polygon)
    assert sorted(wedge.vertices) == sorted([(0.0, 0.0), (2.0, 0.0), (0.0, 1.0)])
    rail = w.get(e["rail"], Collider).shape
    assert isinstance(rail, Chain) and not rail.loop and rail.vertices[-1] == (2.0, -1.0)
    # Tiled turns clockwise about the top-left corner: 90 degrees points the box down
    tilted = w.get(e["tilted"], Transform)
    assert tilted.angle == pytest.approx(-math.pi / 2)
    assert tilted.position == pytest.approx((-0.5, 0.0 - 1.0))
    coin = w.get(e["coin tile"], MapObject)
    assert coin.cls == "Coin" and coin.properties == {"value": 5}  # from the tile
    assert w.get(e["coin tile"], Transform).position == pytest.approx((8.5, 7.5))
    sprite = w.get(e["coin tile"], Sprite)
    assert sprite.region == (48, 0, 16, 16) and sprite.size == (1.0, 1.0)
    sim.step(30)
    assert w.get(e["crate"], Transform).y < 6.0  # the dynamic crate falls


def test_spawners_receive_properties_and_add_components(tmp_path: Path, sim: Stepper) -> None:
    spawners = Spawners()
    seen: list[dict[str, Any]] = []

    @spawners.register("Coin", collider=True, sensor=True)
    def coin(spawn: Spawn) -> list[Any]:
        seen.append(spawn.properties)
        return [Name(f"coin {spawn.properties['value']}")]

    spawners.register("PlayerStart", lambda spawn: [RigidBody(), Collider(Circle(0.4))])
    load_map(sim.world, write_level(tmp_path, floor(20), OBJECTS), spawners=spawners)
    e = _by_name(sim.world)
    assert {"value": 7, "collider": True, "sensor": True} in seen
    assert sim.world.get(e["gold"], Name).value == "coin 7"
    assert sim.world.get(e["gold"], Collider).sensor  # the class's defaults
    assert sim.world.get(e["coin tile"], Name).value == "coin 5"
    assert sim.world.get(e["start"], RigidBody).type == BodyType.DYNAMIC


def test_a_class_without_spawner_warns_once(tmp_path: Path, sim: Stepper) -> None:
    with pytest.warns(TilemapWarning, match="class 'Coin' has no registered spawner") as rec:
        load_map(
            sim.world,
            write_level(tmp_path, floor(20), OBJECTS),
            spawners={"PlayerStart": lambda s: None},
        )
    assert sum("'Coin'" in str(r.message) for r in rec) == 1
    assert {r.filename for r in rec} == {__file__}  # it points at the load_map call
