"""Tile map samples: levels written by code as Tiled maps, loaded with ``load_map``.

:func:`write_levels` writes the two platformer levels (generated tiles only)
that ``examples/platformer.py`` plays: a floor with gaps (animated water at their
bottom), one-way ledges, coins and a door leading to the second level.
"""

from __future__ import annotations

import tempfile
from pathlib import Path
from typing import Any

import numpy as np

from kge.components import Name, Transform
from kge.components.collider import Collider
from kge.components.material import Material, Shader
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Circle
from kge.components.tween import Tween
from kge.systems.animation import tweens_of
from kge.testbed import png
from kge.testbed.registry import sample
from kge.testbed.samples.build import named
from kge.tilemap import load_map, maps_in
from kge.tilemap.writer import ObjectLayerSpec, TileLayerSpec, TilesetSpec, write_map
from kge.world import World

T = 16
ROCK, LEDGE, COIN, DOOR, GRASS, WATER = 1, 2, 3, 4, 5, 6  # gids
TILES = 7  # tiles in the sheet (the 7th is WATER's second frame)


def _sheet() -> np.ndarray:
    img = np.zeros((T, TILES * T, 4), np.uint8)
    img[:, 0:T] = (110, 80, 50, 255)  # rock
    img[2:6, T : 2 * T] = (230, 200, 90, 255)  # ledge: a plank at the top
    yy, xx = np.mgrid[0:T, 0:T]
    ring = (xx - 7.5) ** 2 + (yy - 7.5) ** 2 < 30
    img[:, 2 * T : 3 * T][ring] = (250, 220, 40, 255)  # coin
    img[:, 3 * T : 4 * T] = (70, 40, 20, 255)  # door
    img[:, 4 * T : 5 * T] = (110, 80, 50, 255)
    img[0:4, 4 * T : 5 * T] = (60, 170, 60, 255)  # grass on rock
    # water, two frames: the lighter band moves down (an animated tile, Tiled-style)
    img[:, 5 * T : 7 * T] = (30, 70, 160, 255)
    img[2:6, 5 * T : 6 * T] = (80, 140, 220, 255)
    img[8:12, 6 * T : 7 * T] = (80, 140, 220, 255)
    return img


def _tileset() -> TilesetSpec:
    return TilesetSpec(
        "platformer",
        "platformer.png",
        T,
        T,
        columns=TILES,
        count=TILES,
        image_size=(TILES * T, T),
        tiles={
            0: {"properties": {"solid": True, "friction": 0.8}},
            1: {
                "properties": {"one_way": True},
                "collision": [{"kind": "rectangle", "x": 0, "y": 2, "width": 16, "height": 4}],
            },
            2: {"class": "Coin", "properties": {"value": 1}},
            3: {"class": "Door"},
            4: {"properties": {"solid": True, "friction": 0.8}},
            5: {"animation": [(5, 400), (6, 400)]},  # water: played by kge.animation
        },
    )


def _level(
    cols: int, gaps: list[tuple[int, int]], ledges: list[tuple[int, int, int]]
) -> np.ndarray:
    g = np.zeros((15, cols), np.int64)
    g[12, :] = GRASS
    g[13:, :] = ROCK
    for a, b in gaps:
        g[12:, a:b] = 0
    g[:, 0] = ROCK
    g[:, -1] = ROCK
    for row, a, b in ledges:
        g[row, a:b] = LEDGE
    return g


#: (columns, gaps (from, to), ledges (row, from, to), the level the door leads to)
LEVEL_SPECS: list[tuple[int, list[tuple[int, int]], list[tuple[int, int, int]], str]] = [
    (40, [(12, 14)], [(9, 5, 10), (7, 16, 22), (5, 25, 30)], "level2.tmx"),
    (60, [(18, 21), (35, 38)], [(9, 8, 13), (7, 14, 18), (9, 24, 30), (6, 40, 46)],
     "level1.tmx"),
]


def write_terrain(folder: Path) -> tuple[Path, Path]:
    """The platformer's two levels as terrain only (ground, ledges, water; no objects):
    ``terrain1.tmx`` and ``terrain2.tmx`` and the tile sheet, for scene files that place
    the player, coins and door themselves (examples/levels)."""
    folder.mkdir(parents=True, exist_ok=True)
    png.write(folder / "platformer.png", _sheet())
    out = []
    for i, (cols, gaps, ledges, _) in enumerate(LEVEL_SPECS):
        grid = _level(cols, gaps, ledges)
        water = np.zeros_like(grid)
        for a, b in gaps:
            water[13:, a:b] = WATER
        path = folder / f"terrain{i + 1}.tmx"
        write_map(path, T, T, [_tileset()], [
            TileLayerSpec("Water", water, properties={"collision": False}),
            TileLayerSpec("Ground", grid),
        ])
        out.append(path)
    return out[0], out[1]


def write_levels(folder: Path) -> tuple[Path, Path]:
    """Write level1.tmx and level2.tmx (and the tile sheet) into ``folder``."""
    folder.mkdir(parents=True, exist_ok=True)
    png.write(folder / "platformer.png", _sheet())
    paths = []
    for i, (cols, gaps, ledges, target) in enumerate(LEVEL_SPECS):
        grid = _level(cols, gaps, ledges)
        objects: list[dict[str, Any]] = [
            {
                "id": 1,
                "name": "start",
                "class": "PlayerStart",
                "kind": "point",
                "x": 3 * T,
                "y": 11 * T,
            },
            {
                "id": 2,
                "name": "door",
                "gid": DOOR,
                "x": (cols - 3) * T,
                "y": 12 * T,
                "width": T,
                "height": 2 * T,
                "properties": {"collider": True, "sensor": True, "to": target},
            },
        ]
        for k, (row, a, b) in enumerate(ledges):
            for c in range(a, b, 2):
                objects.append(
                    {
                        "id": 10 + 10 * k + c,
                        "name": "coin",
                        "gid": COIN,
                        "x": c * T,
                        "y": row * T,
                        "width": T,
                        "height": T,
                        "properties": {"collider": True, "sensor": True},
                    }
                )
        water = np.zeros_like(grid)
        for a, b in gaps:
            water[13:, a:b] = WATER  # the bottom of every gap: decoration, no collision
        name = "level1.tmx" if i == 0 else "level2.tmx"
        path = folder / name
        write_map(
            path,
            T,
            T,
            [_tileset()],
            [
                TileLayerSpec("Water", water, properties={"collision": False}),
                TileLayerSpec("Ground", grid),
                ObjectLayerSpec("Objects", objects),
            ],
        )
        paths.append(path)
    return paths[0], paths[1]


def cave_cells(n: int, seed: int = 1, fill: float = 0.52) -> np.ndarray:
    """An n x n boolean grid of cellular-automaton caves (``fill`` 0.52: ~60 % solid)."""
    rng = np.random.default_rng(seed)
    g: np.ndarray = rng.random((n, n)) < fill
    for _ in range(4):
        p = np.pad(g, 1, constant_values=True).astype(np.int8)
        s = np.zeros((n, n), np.int8)
        for dy in (-1, 0, 1):
            for dx in (-1, 0, 1):
                s += p[1 + dy : 1 + dy + n, 1 + dx : 1 + dx + n]
        g = s >= 5
    return g


_FOLDER: list[Path] = []


def levels() -> tuple[Path, Path]:
    """The levels, written once per process into a temporary folder."""
    if not _FOLDER:
        _FOLDER.append(Path(tempfile.mkdtemp(prefix="kge-levels-")))
        write_levels(_FOLDER[0])
    return _FOLDER[0] / "level1.tmx", _FOLDER[0] / "level2.tmx"


@sample(
    "Tilemaps",
    "Platformer Level",
    help="A Tiled level: merged ground outlines, one-way ledges, coins, a door (sensors) "
    "and animated water tiles.",
    camera=(20.0, 7.0, 0.5),
)
def platformer_level(world: World) -> None:
    load_map(world, levels()[0], unknown="ignore")
    for i, x in enumerate((3.0, 6.5, 12.5)):
        world.spawn(
            Transform(x, 10.0),
            RigidBody(),
            Collider(Box(0.4, 0.4), friction=0.3),
            Name(f"crate {i}"),
        )


@platformer_level.claim
def _crates_land_on_ground_plank_and_through_a_gap(app: Any) -> None:
    world = app.world
    y = [world.get(named(world, f"crate {i}")[0], Transform).y for i in range(3)]
    assert abs(y[0] - 3.4) < 0.05, f"the first crate rests on the ground (top y = 3): {y[0]}"
    # the plank's collision band is 4 px under a 2 px gap: its top is 6 - 2/16 m
    assert abs(y[1] - (6.0 - 2 / 16 + 0.4)) < 0.05, f"the second rests on the plank: {y[1]}"
    assert y[2] < 0.0, f"the third falls through the gap in the ground: {y[2]}"


RIPPLE = Shader("""
uniform float strength;
vec4 effect(vec4 color, sampler2D tex, vec2 uv, vec2 world)
{
    // bright bands running along the water, and a shimmer that moves with time
    float wave = 0.5 + 0.5 * sin(world.x * 2.5 - time * 3.0 + 2.0 * sin(world.y * 4.0));
    vec4 c = texture(tex, uv) * color;
    return vec4(c.rgb * (0.8 + strength * wave), c.a);
}""", name="ripple")


@sample(
    "Tilemaps",
    "Rippling Water",
    help="The level's water layer drawn with a Material: a shader whose bands move with "
    "time, its strength tweened up and down (TileMap.set_material).",
    camera=(28.0, 2.5, 1.2),
)
def rippling_water(world: World) -> None:
    m = load_map(world, levels()[0], unknown="ignore")
    ripple = Material(RIPPLE, {"strength": 0.2})
    m.set_material("Water", ripple)
    # the same Material on an entity, so a tween can drive it (nothing else draws it there)
    holder = world.spawn(Name("ripple strength"), ripple)
    tweens_of(world).start(holder, Tween(Material, "uniforms.strength", 0.9, 1.5,
                                         ease="sine_in_out", repeat=-1, yoyo=True))  # fmt: skip


@rippling_water.claim
def _the_water_layer_has_its_material_and_it_moves(app: Any) -> None:
    (tmap,) = maps_in(app.world).maps
    strength = tmap.materials["Water"].uniforms["strength"]
    assert 0.2 < strength <= 0.9, f"the tween drives the layer's material: {strength}"


@sample(
    "Tilemaps",
    "Caves",
    help="A generated 100x100 cave map (one outline per region) with balls raining in.",
    camera=(50.0, 50.0, 0.12),
)
def caves(world: World) -> None:
    folder = Path(tempfile.mkdtemp(prefix="kge-caves-"))
    g = cave_cells(100, seed=4)
    png.write(folder / "platformer.png", _sheet())
    write_map(
        folder / "caves.tmx", T, T, [_tileset()], [TileLayerSpec("Rock", np.where(g, ROCK, 0))]
    )
    load_map(world, folder / "caves.tmx")
    for i in range(60):
        x, y = 5.0 + (i % 10) * 9.0, 60.0 + (i // 10) * 6.0
        world.spawn(
            Transform(x, y), RigidBody(), Collider(Circle(0.3), restitution=0.2), Name("ball")
        )


@caves.claim
def _balls_stay_inside_the_cave_outlines(app: Any) -> None:
    world = app.world
    for e in named(world, "ball"):
        x, y = world.get(e, Transform).position
        assert 0.0 < x < 100.0 and 0.0 < y < 100.0, f"a ball left the map through a wall: {x, y}"


def _iso_sheet() -> np.ndarray:
    """Two 32 x 16 diamonds: a grey floor and a brown wall with a lighter top edge."""
    img = np.zeros((16, 64, 4), np.uint8)
    y, x = np.mgrid[0:16, 0:32] + 0.5
    diamond = np.abs(x - 16) / 16 + np.abs(y - 8) / 8 <= 1.0
    img[:, :32][diamond] = (150, 150, 160, 255)
    img[:, 32:][diamond] = (120, 80, 50, 255)
    img[:, 32:][diamond & (y < 5)] = (170, 120, 80, 255)
    return img


@sample(
    "Tilemaps",
    "Isometric Room",
    help="An isometric Tiled map seen from above: its walls merge into outlines on the "
    "diamonds, and pucks slide without gravity, bouncing off them.",
)
def isometric_room(world: World, n: int = 12) -> None:
    folder = Path(tempfile.mkdtemp(prefix="kge-iso-"))
    png.write(folder / "iso.png", _iso_sheet())
    ts = TilesetSpec("iso", "iso.png", 32, 16, columns=2, count=2, image_size=(64, 16),
                     tiles={1: {"properties": {"solid": True}}})  # fmt: skip
    walls = np.zeros((n, n), np.int64)
    walls[[0, -1], :] = walls[:, [0, -1]] = 2
    walls[n // 2 - 1 : n // 2 + 1, n // 2 - 1 : n // 2 + 1] = 2  # a pillar in the middle
    layers = [TileLayerSpec("Floor", np.ones((n, n), np.int64)), TileLayerSpec("Walls", walls)]
    write_map(folder / "room.tmx", 32, 16, [ts], layers, orientation="isometric")
    room = load_map(world, folder / "room.tmx")
    for i, (col, row) in enumerate(((2, 2), (2, n - 3), (n - 3, 2), (n - 3, n - 3), (3, 7))):
        world.spawn(
            Transform(*room.cell_center(col, row)),
            RigidBody(gravity_scale=0.0, velocity=(2.0 - i, 1.5 if i % 2 else -1.5)),
            Collider(Circle(0.12), restitution=1.0, friction=0.0),
            Name("puck"),
        )


@isometric_room.claim
def _pucks_stay_in_the_room(app: Any) -> None:
    world = app.world
    (room,) = maps_in(world).maps
    n = room.data.cols
    for e in named(world, "puck"):
        cell = room.cell_at(world.get(e, Transform).position)
        assert cell is not None and 0 < cell[0] < n - 1 and 0 < cell[1] < n - 1, (
            f"a puck crossed a wall: cell {cell}"
        )
        assert room.tile("Walls", *cell) == 0, f"a puck is inside a wall cell {cell}"
