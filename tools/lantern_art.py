"""Lantern Woods' art, sounds and level, drawn in code (``tools/make_assets.py`` writes them).

Every image is an (h, w, 4) uint8 RGBA array, rows top-down, a pure function of
this module (seeded noise only). The level is a Tiled map written with
:func:`kge.tilemap.writer.write_map`, so it opens in Tiled as it is.

Pixel art is 16 px to the tile; the game's camera shows a tile (1 m) as 48 px.

>>> fox_sheet().shape            # 10 frames of 24 x 24: idle 0-1, run 2-7, jump 8, fall 9
(24, 240, 4)
>>> tiles().shape
(16, 112, 4)
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from kge.sound import SoundData, melody, mix, tone
from kge.tilemap.writer import (
    ImageLayerSpec,
    ObjectLayerSpec,
    TileLayerSpec,
    TilesetSpec,
    write_map,
)

T = 16  #: tile size, pixels
F = 24  #: fox frame size, pixels
FOX_TAGS = {"idle": (0, 1), "run": (2, 7), "jump": (8, 8), "fall": (9, 9)}
#: tile gids in the level (local id + 1)
DIRT, GRASS, STONE, PLANK, MUSHROOM, FERN, FLOWER = 1, 2, 3, 4, 5, 6, 7
TILE_COUNT = 7
SKY_TOP = (14, 18, 44)  #: the sky's top colour (the game's clear colour matches it)
LEVEL_COLS, LEVEL_ROWS = 150, 20


def _grid(h: int, w: int) -> tuple[np.ndarray, np.ndarray]:
    y, x = np.mgrid[0:h, 0:w].astype(float) + 0.5
    return x, y


def _noise(h: int, w: int, seed: int) -> np.ndarray:
    return np.random.default_rng(seed).random((h, w))


def _paint(img: np.ndarray, mask: np.ndarray, color: tuple[int, ...]) -> None:
    rgba = color if len(color) == 4 else (*color, 255)
    img[mask] = rgba


def _segment(x: np.ndarray, y: np.ndarray, p: tuple[float, float], q: tuple[float, float]
             ) -> np.ndarray:
    ex, ey = q[0] - p[0], q[1] - p[1]
    t = np.clip(((x - p[0]) * ex + (y - p[1]) * ey) / (ex * ex + ey * ey), 0.0, 1.0)
    return np.hypot(x - (p[0] + t * ex), y - (p[1] + t * ey))


# -- the fox ---------------------------------------------------------------------------
ORANGE, DARK_ORANGE, CREAM, BROWN = (236, 120, 40), (176, 74, 24), (250, 236, 210), (60, 34, 24)


def _fox(frame: int) -> np.ndarray:
    """One 24 x 24 frame, facing right: body, head with ears, bushy tail, four legs."""
    x, y = _grid(F, F)
    img = np.zeros((F, F, 4), np.uint8)
    if frame <= 1:  # idle: breathing
        bob, phase, spread, tail = 0.5 * frame, 0.0, 0.0, 0.5 * frame
    elif frame <= 7:  # run: six phases
        phase = 2 * math.pi * (frame - 2) / 6
        bob, spread, tail = 1.0 * abs(math.sin(phase)), 3.0, math.sin(phase)
    elif frame == 8:  # jump: legs tucked forward, tail up
        bob, phase, spread, tail = -1.0, 0.6, 2.0, -2.0
    else:  # fall: legs reaching down, tail high
        bob, phase, spread, tail = 0.0, -0.6, 2.0, -3.0
    body_y = 14.0 + bob
    # legs first (behind the body): two pairs swinging in opposite phase
    for hip, offset in ((8.0, 0.0), (15.0, math.pi)):
        swing = spread * math.sin(phase + offset)
        foot = (hip + swing, 21.5 if frame < 8 else 20.0)
        leg = _segment(x, y, (hip, body_y + 1), foot) < 1.2
        _paint(img, leg, BROWN)
    # tail: a thick curve to the left, white tip
    tail_d = np.hypot((x - 4.0) / 4.5, (y - (body_y - 2.5 + tail)) / 2.6)
    _paint(img, tail_d < 1.0, ORANGE)
    _paint(img, (tail_d < 1.0) & (x < 2.5), CREAM)
    # body
    body = np.hypot((x - 11.5) / 6.0, (y - body_y) / 3.6) < 1.0
    _paint(img, body, ORANGE)
    _paint(img, body & (y > body_y + 1.6), DARK_ORANGE)
    # head, snout, chest, ears, eye, nose
    hx, hy = 18.0, body_y - 4.0
    _paint(img, np.hypot(x - hx, y - hy) < 3.6, ORANGE)
    _paint(img, np.hypot((x - (hx + 3.2)) / 2.4, (y - (hy + 1.2)) / 1.4) < 1.0, CREAM)
    _paint(img, np.hypot(x - (hx - 2.0), y - (hy + 3.4)) < 2.0, CREAM)
    for ex in (hx - 1.8, hx + 1.0):
        ear = (y < hy - 1.5) & (y > hy - 6.0) & (abs(x - ex) < (y - (hy - 6.0)) * 0.45)
        _paint(img, ear, DARK_ORANGE)
    _paint(img, (abs(x - (hx + 1.0)) < 0.6) & (abs(y - (hy - 0.6)) < 0.6), (20, 16, 24))
    _paint(img, (abs(x - (hx + 5.0)) < 0.8) & (abs(y - (hy + 0.8)) < 0.7), (20, 16, 24))
    return img


def fox_sheet() -> np.ndarray:
    """Ten frames in one row (tags in :data:`FOX_TAGS`)."""
    return np.concatenate([_fox(i) for i in range(10)], axis=1)


# -- tiles -----------------------------------------------------------------------------
def _tile(kind: int) -> np.ndarray:
    x, y = _grid(T, T)
    n = _noise(T, T, 100 + kind)
    img = np.zeros((T, T, 4), np.uint8)
    dirt = np.stack([70 + 25 * n, 46 + 16 * n, 34 + 10 * n, np.full_like(n, 255)], -1)
    if kind in (DIRT, GRASS):
        img[:] = dirt.astype(np.uint8)
        _paint(img, n > 0.93, (104, 80, 60))
        if kind == GRASS:
            blade = y < 4.0 + 2.0 * np.sin(x * 1.7) ** 2
            _paint(img, blade, (58, 132, 64))
            _paint(img, blade & (y < 2.0), (96, 176, 84))
    elif kind == STONE:
        img[:] = np.stack([86 + 30 * n, 90 + 30 * n, 104 + 30 * n, np.full_like(n, 255)],
                          -1).astype(np.uint8)
        joints = (np.abs(y - 8) < 0.6) | ((np.abs(x - 8) < 0.6) & (y < 8)) | (
            (np.abs(x - 1) < 0.6) & (y > 8))
        _paint(img, joints, (50, 52, 64))
    elif kind == PLANK:
        board = y < 5.0
        _paint(img, board, (150, 104, 60))
        _paint(img, board & (y < 1.5), (196, 150, 96))
        _paint(img, board & (np.abs(x - 12.5) < 0.6), (90, 60, 36))
        _paint(img, (y >= 5) & (y < 9) & (np.abs(x - 3.5) < 1.0), (110, 76, 44))
    elif kind == MUSHROOM:  # glows: drawn on the unlit layer
        cap = np.hypot((x - 8) / 5.0, (y - 9) / 3.2) < 1.0
        _paint(img, (np.abs(x - 8) < 1.3) & (y > 9) & (y < 16), (200, 230, 230))
        _paint(img, cap & (y < 10), (70, 230, 220))
        _paint(img, cap & (y < 10) & (n > 0.8), (210, 255, 250))
    elif kind == FERN:
        for k in range(5):
            a = math.pi * (0.15 + 0.175 * k)
            leaf = _segment(x, y, (8, 16), (8 - 7 * math.cos(a), 16 - 9 * math.sin(a))) < 0.9
            _paint(img, leaf, (40, 110 + 12 * k, 60))
    elif kind == FLOWER:
        _paint(img, (np.abs(x - 8) < 0.6) & (y > 8), (60, 130, 60))
        petals = np.hypot(x - 8, y - 7) < 3.0
        _paint(img, petals, (250, 180, 220))
        _paint(img, np.hypot(x - 8, y - 7) < 1.2, (255, 230, 120))
    return img


def tiles() -> np.ndarray:
    """The tile sheet: one row, local ids 0..6 = gids DIRT..FLOWER."""
    return np.concatenate([_tile(g) for g in range(1, TILE_COUNT + 1)], axis=1)


# -- things ----------------------------------------------------------------------------
def jar() -> np.ndarray:
    """A firefly jar (16 x 16): glass, a cork and a warm glow inside."""
    x, y = _grid(T, T)
    img = np.zeros((T, T, 4), np.uint8)
    glass = (np.abs(x - 8) < 5.0) & (y > 4) & (y < 15.5)
    _paint(img, glass, (150, 200, 220, 120))
    glow = np.hypot(x - 8, y - 10) < 3.5
    _paint(img, glow, (255, 230, 120, 255))
    _paint(img, np.hypot(x - 8, y - 10) < 1.6, (255, 255, 220, 255))
    _paint(img, (np.abs(x - 8) < 3.5) & (y > 1.5) & (y <= 4), (150, 104, 60, 255))
    return img


def shrine() -> np.ndarray:
    """The stone lantern at the end of the woods (32 x 48); its window is dark until lit."""
    x, y = _grid(48, 32)
    img = np.zeros((48, 32, 4), np.uint8)
    n = _noise(48, 32, 7)
    stone = np.stack([100 + 30 * n, 104 + 30 * n, 116 + 30 * n, np.full_like(n, 255)], -1)
    parts = (
        (np.abs(x - 16) < 13) & (y > 44),  # base
        (np.abs(x - 16) < 4) & (y > 28) & (y <= 44),  # post
        (np.abs(x - 16) < 10) & (y > 14) & (y <= 28),  # light box
        (np.abs(x - 16) < 15 - (14 - y) * 0.9) & (y > 4) & (y <= 14),  # roof
        (np.abs(x - 16) < 2) & (y <= 4),  # finial
    )
    for part in parts:
        img[part] = stone[part].astype(np.uint8)
    _paint(img, (np.abs(x - 16) < 6) & (y > 17) & (y < 26), (30, 24, 30, 255))
    return img


def _stars(h: int, w: int, seed: int) -> np.ndarray:
    return _noise(h, w, seed) > 0.996


def sky(w: int = 640, h: int = 400) -> np.ndarray:
    """Night sky: a gradient from SKY_TOP to violet at the horizon, stars and a moon."""
    x, y = _grid(h, w)
    t = (y / h)[..., None]
    top, low = np.array(SKY_TOP, float), np.array((70, 52, 110), float)
    img = np.concatenate([top + (low - top) * t ** 1.5, np.full((h, w, 1), 255.0)], -1)
    stars = _stars(h, w, 3) & (y < h * 0.7)
    img[stars, :3] = (230, 230, 255)
    moon = np.hypot(x - w * 0.7, y - h * 0.25)
    img[moon < 22, :3] = (246, 240, 214)
    img[(moon < 22) & (np.hypot(x - w * 0.7 - 9, y - h * 0.25 - 6) < 5), :3] = (220, 214, 190)
    halo = np.clip(1.0 - (moon - 22) / 40, 0, 1)[..., None] * (moon >= 22)[..., None]
    img[..., :3] += halo * 40
    return np.clip(img, 0, 255).astype(np.uint8)


def _ridge(w: int, h: int, base: float, waves: list[tuple[float, float, float]],
           color: tuple[int, int, int], seed: int, trees: float = 0.0) -> np.ndarray:
    """A silhouette: ground below a wavy ridge line (periodic in x), optional pine tops."""
    y = _grid(h, w)[1]
    line = np.full(w, float(base))
    xs = np.arange(w) + 0.5
    for amp, period, phase in waves:
        line += amp * np.sin(2 * math.pi * xs / period + phase)
    if trees:
        rng = np.random.default_rng(seed)
        for cx in np.arange(8, w, trees):
            cx += rng.uniform(-trees / 3, trees / 3)
            tall = rng.uniform(18, 42)
            half = tall * 0.28
            d = np.abs(xs - cx)
            tip = line[int(min(cx, w - 1))] - tall
            line = np.minimum(line, np.where(d < half, tip + d * tall / half, np.inf))
    img = np.zeros((h, w, 4), np.uint8)
    img[y >= line[None, :]] = (*color, 255)
    return img


def hills(w: int = 960, h: int = 260) -> np.ndarray:
    return _ridge(w, h, 150, [(18, 480, 0.3), (9, 240, 1.1), (4, 96, 2.0)], (38, 36, 74), 1)


def far_trees(w: int = 1600, h: int = 300) -> np.ndarray:
    return _ridge(w, h, 200, [(8, 400, 0.7), (5, 160, 0.2)], (24, 30, 52), 2, trees=22.0)


# -- sounds ----------------------------------------------------------------------------
RATE = 22050


def night_music() -> SoundData:
    """Four bars of a slow pentatonic lullaby over a drone, loopable (8 kHz: it is soft)."""
    scale = [293.66, 329.63, 392.0, 440.0, 493.88, 587.33]
    rng = np.random.default_rng(11)
    notes = [(scale[int(i)], 0.375) for i in rng.integers(0, len(scale), 16)]
    lead = melody(notes, volume=0.16, shape="triangle", rate=8000)
    drone = melody([(146.83, 3.0), (130.81, 3.0)], volume=0.12, shape="sine", rate=8000)
    return mix(lead, drone)


def sounds() -> dict[str, SoundData]:
    return {
        "lantern_jump.wav": tone(380, 0.14, shape="square", slide_to=720, volume=0.22, rate=RATE),
        "lantern_land.wav": tone(90, 0.08, shape="noise", volume=0.25, release=0.05, rate=RATE),
        "lantern_jar.wav": melody([(880.0, 0.06), (1174.66, 0.06), (1760.0, 0.12)],
                                  volume=0.25, shape="sine", rate=RATE),
        "lantern_lit.wav": melody([(587.33, 0.12), (739.99, 0.12), (880.0, 0.12),
                                   (1174.66, 0.4)], volume=0.3, shape="triangle", rate=RATE),
        "lantern_music.wav": night_music(),
    }


def images() -> dict[str, np.ndarray]:
    return {
        "lantern_fox.png": fox_sheet(),
        "lantern_tiles.png": tiles(),
        "lantern_jar.png": jar(),
        "lantern_shrine.png": shrine(),
        "lantern_sky.png": sky(),
        "lantern_hills.png": hills(),
        "lantern_trees.png": far_trees(),
    }


# -- the level -------------------------------------------------------------------------
#: (column, width, height above the base floor) of raised ground; gaps; one-way planks
HILLS = [(20, 6, 2), (34, 4, 1), (52, 10, 3), (80, 5, 2), (104, 8, 1), (126, 6, 3)]
GAPS = [(28, 31), (45, 48), (70, 73), (93, 97), (116, 119)]
PLANKS = [(12, 12, 16), (12, 40, 44), (10, 57, 61), (12, 84, 89), (13, 98, 102),
          (12, 112, 115), (10, 130, 134)]
FLOOR = 16  #: the base floor's top row


def level_grids() -> tuple[np.ndarray, np.ndarray]:
    """(ground, decor) tile grids, (rows, cols) of gids."""
    g = np.zeros((LEVEL_ROWS, LEVEL_COLS), np.int64)
    top = np.full(LEVEL_COLS, FLOOR)
    for c, w, hgt in HILLS:
        top[c : c + w] = FLOOR - hgt
    for c in range(LEVEL_COLS):
        g[top[c] + 1 :, c] = DIRT
        g[top[c], c] = GRASS
    for a, b in GAPS:
        g[:, a:b] = 0
        top[a:b] = LEVEL_ROWS
    g[:, 0] = STONE
    g[:, -1] = STONE
    for row, a, b in PLANKS:
        g[row, a:b] = PLANK
    decor = np.zeros_like(g)
    rng = np.random.default_rng(5)
    for c in range(2, LEVEL_COLS - 2):
        if top[c] < LEVEL_ROWS and g[top[c] - 1, c] == 0 and rng.random() < 0.3:
            decor[top[c] - 1, c] = int(rng.choice([MUSHROOM, FERN, FERN, FLOWER]))
    return g, decor


def _object(i: int, cls: str, col: float, row: float, w: float = 0.0, h: float = 0.0,
            **props: Any) -> dict[str, Any]:
    o: dict[str, Any] = {"id": i, "name": cls.lower(), "class": cls, "x": col * T, "y": row * T}
    if w:
        o.update(width=w * T, height=h * T)
    else:
        o["kind"] = "point"
    if props:
        o["properties"] = props
    return o


def level_objects() -> list[dict[str, Any]]:
    """Player start, firefly jars above planks and hills, the shrine at the end."""
    objs = [_object(1, "PlayerStart", 3, FLOOR - 1)]
    spots = [(row - 1, (a + b) / 2) for row, a, b in PLANKS]
    spots += [(FLOOR - hgt - 1, c + w / 2) for c, w, hgt in HILLS]
    for k, (row, col) in enumerate(sorted(spots, key=lambda s: s[1])):
        objs.append(_object(10 + k, "Jar", col - 0.5, row - 0.5, 1, 1, collider=True,
                            sensor=True))
    objs.append(_object(2, "Shrine", LEVEL_COLS - 6, FLOOR - 3, 2, 3, collider=True,
                        sensor=True))
    return objs


def write_level(folder: Path) -> Path:
    """Write ``lantern_woods.tmx`` into ``folder`` (beside the images it names)."""
    ground, decor = level_grids()
    tileset = TilesetSpec(
        "woods", "lantern_tiles.png", T, T, columns=TILE_COUNT, count=TILE_COUNT,
        image_size=(TILE_COUNT * T, T),
        tiles={
            DIRT - 1: {"properties": {"solid": True, "friction": 0.9}},
            GRASS - 1: {"properties": {"solid": True, "friction": 0.9}},
            STONE - 1: {"properties": {"solid": True, "friction": 0.9}},
            PLANK - 1: {"properties": {"one_way": True},
                        "collision": [{"kind": "rectangle", "x": 0, "y": 0, "width": 16,
                                       "height": 5}]},
        },
    )
    path = folder / "lantern_woods.tmx"
    write_map(path, T, T, [tileset], [
        ImageLayerSpec("Sky", "lantern_sky.png", offset=(-160, -200), parallax=(0.05, 0.1)),
        ImageLayerSpec("Hills", "lantern_hills.png", offset=(-120, -40), parallax=(0.25, 0.4)),
        ImageLayerSpec("Far trees", "lantern_trees.png", offset=(-80, -60), parallax=(0.5, 0.7)),
        TileLayerSpec("Decor", decor, properties={"collision": False}),
        TileLayerSpec("Ground", ground),
        ObjectLayerSpec("Objects", level_objects()),
    ])
    return path
