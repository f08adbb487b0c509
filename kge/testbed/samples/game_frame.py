"""The game-frame sample: a whole game's frame at once, the scene ``kge bench`` times.

A 200 x 50 tile Tiled level written by code (rock terrain with hills, ledges and
pits; merged chain colliders), 300 crates and balls with sprites resting and
tumbling on it, 30 animated walkers, rain and two torches (about 2,780 live
particles), 4 lights (two casting shadows) and a 10-widget HUD whose values stay
put. Every system of a game runs in it: physics with continuous collision,
animation, particles, lights, tile-map drawing and UI.
"""

from __future__ import annotations

import math
import tempfile
from pathlib import Path
from typing import Any

import numpy as np

from kge.components import Name, Transform
from kge.components.animation import Animator, Clip
from kge.components.camera import Camera
from kge.components.collider import Collider
from kge.components.lights import Light, Lighting
from kge.components.particles import Blend, EmitBox, EmitCircle, ParticleEmitter
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Circle
from kge.components.sprite import Sprite
from kge.components.ui import Button, Label, Panel, ProgressBar, UINode
from kge.testbed import paint, png
from kge.testbed.art import as_image, walk_sheet
from kge.testbed.registry import sample
from kge.tilemap import load_map
from kge.tilemap.writer import TileLayerSpec, TilesetSpec, write_map
from kge.world import World

T = 16  #: tile pixels (one tile is one metre)
COLS, ROWS = 200, 50
ROCK, GRASS = 1, 2  # gids
BODIES, WALKERS, LIGHTS, HUD_WIDGETS = 300, 30, 4, 10
#: rain: 1,190 drops a second living 2 s; torches: 2 x 200 a second living 1 s (~2,780 live)
RAIN_RATE, RAIN_LIFE, TORCH_RATE, TORCH_LIFE = 1190.0, 2.0, 200.0, 1.0
VIEW = (100.0, 12.0)  #: the camera's centre (m)


def level_grid(cols: int = COLS, rows: int = ROWS) -> np.ndarray:
    """The level's tiles, row 0 at the top: rolling rock hills under grass, two pits,
    side walls and a few floating ledges."""
    x = np.arange(cols)
    ground = (8 + 3 * np.sin(x / 9.0) + 2 * np.sin(x / 23.0 + 1.0)).astype(int)
    g = np.zeros((rows, cols), np.int64)
    depth = rows - 1 - np.arange(rows)[:, None]  # 0 at the bottom row
    g[depth < ground[None, :]] = ROCK
    top = rows - ground  # the row of each column's surface tile
    g[top, x] = GRASS
    for a in (60, 140):  # two pits, three tiles wide, down to the bedrock
        g[: rows - 2, a : a + 3] = 0
    g[:, 0] = ROCK
    g[:, -1] = ROCK
    for c0 in range(15, cols - 15, 25):  # ledges 12 tiles above the ground
        row = int(top[c0 + 3]) - 12
        g[row, c0 : c0 + 7] = ROCK
    return g


def _sheet() -> np.ndarray:
    img = np.zeros((T, 2 * T, 4), np.uint8)
    img[:, :T] = (110, 80, 50, 255)
    img[:, T:] = (110, 80, 50, 255)
    img[0:4, T:] = (60, 170, 60, 255)
    return img


def write_level(folder: Path) -> Path:
    """Write ``frame_level.tmx`` (and its tile sheet) into ``folder``."""
    folder.mkdir(parents=True, exist_ok=True)
    png.write(folder / "frame_tiles.png", _sheet())
    tiles = TilesetSpec("frame", "frame_tiles.png", T, T, columns=2, count=2,
                        image_size=(2 * T, T),
                        tiles={0: {"properties": {"solid": True, "friction": 0.7}},
                               1: {"properties": {"solid": True, "friction": 0.7}}})
    path = folder / "frame_level.tmx"
    write_map(path, T, T, [tiles], [TileLayerSpec("Ground", level_grid())])
    return path


_FOLDER: list[Path] = []


def level_path() -> Path:
    """The level, written once per process into a temporary folder."""
    if not _FOLDER:
        _FOLDER.append(Path(tempfile.mkdtemp(prefix="kge-frame-")))
        write_level(_FOLDER[0])
    return _FOLDER[0] / "frame_level.tmx"


def _surface(grid: np.ndarray, col: int) -> float:
    """Height (m) of the top of column ``col``'s ground."""
    solid = np.nonzero(grid[:, col])[0]
    below = solid[solid > ROWS - 30]
    return float(ROWS - (below[0] if len(below) else ROWS))


def _bodies(world: World, grid: np.ndarray, count: int) -> None:
    crate = as_image(paint.crate(32))
    orb = as_image(paint.orb(32))
    rng = np.random.default_rng(11)
    for i in range(count):
        col = 4 + (i * 37) % (COLS - 8)
        x = col + 0.5 + float(rng.uniform(-0.3, 0.3))
        y = _surface(grid, col) + 1.0 + (i // (COLS - 8) * 37 % 7) * 1.1 + float(rng.uniform(0, 3))
        if i % 3 == 0:
            world.spawn(Transform(x, y), RigidBody(), Collider(Circle(0.3), friction=0.5),
                        Sprite(orb, size=(0.6, 0.6)))  # fmt: skip
        else:
            world.spawn(Transform(x, y, float(rng.uniform(0, math.pi))), RigidBody(),
                        Collider(Box(0.35, 0.35), friction=0.6),
                        Sprite(crate, size=(0.7, 0.7)))  # fmt: skip


def _walkers(world: World, grid: np.ndarray, count: int) -> None:
    sheet = as_image(walk_sheet())
    walk = Clip.grid(sheet, (8, 1), fps=12)
    for i in range(count):
        col = int(VIEW[0]) - 18 + (i * 36) // count
        world.spawn(Transform(col + 0.5, _surface(grid, col) + 0.5),
                    Sprite(sheet, size=(1.0, 1.0), layer=2),
                    Animator({"walk": walk}, speed=0.8 + 0.02 * i), Name("walker"))  # fmt: skip


def _particles(world: World) -> None:
    world.spawn(Transform(VIEW[0], VIEW[1] + 14.0), Name("rain"), ParticleEmitter(
        rate=RAIN_RATE, shape=EmitBox(44.0, 0.1), direction=-math.pi / 2, speed=(9.0, 11.0),
        lifetime=RAIN_LIFE, size=0.06, color=(170, 190, 230), opacity=153, flat=True,
        max_particles=3000, prewarm=RAIN_LIFE, seed=3))  # fmt: skip
    for k, x in enumerate((VIEW[0] - 8.0, VIEW[0] + 8.0)):
        world.spawn(Transform(x, VIEW[1] - 1.0), Name("torch"), ParticleEmitter(
            rate=TORCH_RATE, lifetime=TORCH_LIFE, speed=(1.0, 2.5), spread=0.5,
            direction=math.pi / 2, acceleration=(0.0, 2.0), shape=EmitCircle(0.2),
            size=(0.15, 0.05), color=((255, 230, 120), (255, 70, 0)), opacity=(255, 0),
            blend=Blend.ADDITIVE, max_particles=300, prewarm=TORCH_LIFE, seed=5 + k))  # fmt: skip


def _lights(world: World) -> None:
    world.insert_resource(Lighting(ambient=(70, 70, 95)))
    for k, (dx, dy, shadows) in enumerate(((-8.0, -1.0, True), (8.0, -1.0, True),
                                           (-16.0, 6.0, False), (16.0, 6.0, False))):
        world.spawn(Transform(VIEW[0] + dx, VIEW[1] + dy), Name("light"), Light(
            radius=9.0, color=(255, 200 + 10 * k, 150 + 20 * k), intensity=1.1,
            shadows=shadows))  # fmt: skip


def hud(world: World) -> list[int]:
    """Ten widgets in a panel at the top: labels, a health bar, a button; values fixed."""
    bar = world.spawn(UINode(anchor="top", offset=(0, -8), layout="row", spacing=10,
                             padding=6), Panel())  # fmt: skip
    out = [bar]
    for text in ("score 1200", "coins 37", "lives 3", "level 4-2", "time 02:41",
                 "ammo 12/60", "x2 combo"):
        out.append(world.spawn(UINode(parent=bar), Label(text, size=14)))
    out.append(world.spawn(UINode(parent=bar, width=120, height=14), ProgressBar(0.7)))
    out.append(world.spawn(UINode(parent=bar, height=24), Button("Pause")))
    return out


@sample("Benchmarks", "Game Frame",
        help="A whole game's frame: a 200 x 50 Tiled level, 300 bodies with sprites, 30 "
             "animated sprites, rain and torches, 4 lights, a 10-widget HUD.",
        camera=(VIEW[0], VIEW[1], 1.0))
def game_frame(world: World, bodies: int = BODIES, walkers: int = WALKERS) -> None:
    world.insert_resource(Camera(center=VIEW, pixels_per_meter=24))
    load_map(world, level_path(), unknown="ignore")
    grid = level_grid()
    _bodies(world, grid, bodies)
    _walkers(world, grid, walkers)
    _particles(world)
    _lights(world)
    hud(world)


@game_frame.claim
def _bodies_stay_in_the_level(app: Any) -> None:
    world = app.world
    ys = [t.y for _, (t, _b) in world.query(Transform, RigidBody)]
    assert len(ys) == BODIES
    assert min(ys) > -1.0, f"a body fell through the level: y = {min(ys)}"
