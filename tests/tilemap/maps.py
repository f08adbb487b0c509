"""Generated tile sheets and maps for the tilemap tests (no third-party art)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from kge.testbed import png
from kge.tilemap.writer import ObjectLayerSpec, TileLayerSpec, TilesetSpec, write_map

T = 16  # tile pixels
#: one flat colour per tile of the 4x2 sheet (local ids 0..7)
COLORS = [
    (200, 60, 40),
    (40, 200, 60),
    (40, 60, 200),
    (220, 220, 40),
    (200, 40, 200),
    (40, 200, 200),
    (120, 120, 120),
    (250, 250, 250),
]
GROUND, ONE_WAY, SLOPE, COIN, ANIM_A, ANIM_B, DECOR, MARK = range(1, 9)  # gids (firstgid 1)


def sheet() -> np.ndarray:
    img = np.zeros((2 * T, 4 * T, 4), np.uint8)
    for i, c in enumerate(COLORS):
        r, col = divmod(i, 4)
        img[r * T : (r + 1) * T, col * T : (col + 1) * T] = (*c, 255)
    # tile 7 (MARK) has a black top-left quarter, to see flips
    img[T : T + T // 2, 3 * T : 3 * T + T // 2] = (0, 0, 0, 255)
    return img


#: ANIM_A's frames as Tiled lists them: (tile id, milliseconds)
ANIMATION = [(4, 100), (5, 100)]


def tileset(
    external: str | None = None, animation: list[tuple[int, int]] | None = None
) -> TilesetSpec:
    return TilesetSpec(
        "tiles",
        "tiles.png",
        T,
        T,
        columns=4,
        count=8,
        image_size=(4 * T, 2 * T),
        external=external,
        tiles={
            0: {"properties": {"solid": True, "friction": 0.6}},
            1: {"properties": {"one_way": True}},
            2: {
                "collision": [
                    {"kind": "polygon", "x": 0, "y": 0, "points": [(0, 16), (16, 0), (16, 16)]}
                ]
            },
            3: {"class": "Coin", "properties": {"value": 5}},
            4: {"animation": animation or ANIMATION},
        },
    )


def write_level(
    folder: Path,
    grid: np.ndarray,
    objects: list[dict[str, Any]] | None = None,
    name: str = "level.tmx",
    external: str | None = None,
    extra_layers: list[Any] | None = None,
    animation: list[tuple[int, int]] | None = None,
) -> Path:
    png.write(folder / "tiles.png", sheet())
    layers: list[Any] = [TileLayerSpec("Ground", grid)]
    layers += extra_layers or []
    if objects is not None:
        layers.append(ObjectLayerSpec("Objects", objects))
    path = folder / name
    write_map(path, T, T, [tileset(external, animation)], layers)
    return path


def floor(cols: int = 60, rows: int = 10) -> np.ndarray:
    """A flat floor of GROUND along the bottom row."""
    g = np.zeros((rows, cols), np.int64)
    g[-1, :] = GROUND
    return g
