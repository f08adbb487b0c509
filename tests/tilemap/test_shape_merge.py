"""Tiles whose collision-editor shapes fill the tile join their neighbours' merged outline."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from kge.components.collider import Collider
from kge.components.shapes import Box, Chain
from kge.components.tilemap import TileCollider
from kge.testbed import png
from kge.tilemap import load_map
from kge.tilemap.model import TileShape
from kge.tilemap.parse import covers_tile
from kge.tilemap.writer import TileLayerSpec, TilesetSpec, write_map

from .conftest import Stepper

T = 16
SOLID_PROP, HALVES, SQUARE_POLY, THREE_QUARTERS = 1, 2, 3, 4  # gids (firstgid 1)


def _write(folder: Path, grid: np.ndarray) -> Path:
    png.write(folder / "t.png", np.full((T, 4 * T, 4), 200, np.uint8))
    tiles: dict[int, dict[str, Any]] = {
        0: {"properties": {"solid": True}},
        1: {  # two half-height rectangles: together the whole tile
            "collision": [
                {"kind": "rectangle", "x": 0, "y": 0, "width": T, "height": T / 2},
                {"kind": "rectangle", "x": 0, "y": T / 2, "width": T, "height": T / 2},
            ]
        },
        2: {  # the whole tile drawn as a polygon
            "collision": [
                {"kind": "polygon", "x": 0, "y": 0, "points": [(0, 0), (T, 0), (T, T), (0, T)]}
            ]
        },
        3: {  # the bottom three quarters only: a collider of its own
            "collision": [
                {"kind": "rectangle", "x": 0, "y": T / 4, "width": T, "height": 3 * T / 4}
            ]
        },
    }
    ts = TilesetSpec("t", "t.png", T, T, columns=4, count=4, image_size=(4 * T, T), tiles=tiles)
    path = folder / "m.tmx"
    write_map(path, T, T, [ts], [TileLayerSpec("Ground", grid)])
    return path


def test_full_box_shapes_merge_and_partial_ones_stay_apart(tmp_path: Path, sim: Stepper) -> None:
    g = np.zeros((6, 10), np.int64)
    g[5, :] = [SOLID_PROP, SOLID_PROP, HALVES, HALVES, SQUARE_POLY, SOLID_PROP,
               THREE_QUARTERS, SOLID_PROP, SOLID_PROP, SOLID_PROP]  # fmt: skip
    m = load_map(sim.world, _write(tmp_path, g))
    kinds = sorted(
        (sim.world.get(e, TileCollider).kind, sim.world.get(e, TileCollider).cells)
        for e in m.collider_entities
    )
    # cols 0-5 one outline (the shape tiles joined it), col 6 its own box, cols 7-9 an outline
    assert kinds == [("outline", (0, 5, 6, 6)), ("outline", (7, 5, 10, 6)), ("tile", (6, 5, 7, 6))]
    for e in m.collider_entities:
        shape = sim.world.get(e, Collider).shape
        if sim.world.get(e, TileCollider).kind == "outline":
            assert isinstance(shape, Chain) and len(shape.vertices) == 4  # a plain rectangle
        else:
            assert isinstance(shape, Box) and shape.half_height == pytest.approx(0.375)


def test_a_box_slides_over_merged_shape_tiles_without_a_bump(tmp_path: Path, sim: Stepper) -> None:
    from kge.components.rigidbody import RigidBody
    from kge.components.transform import Transform

    g = np.zeros((6, 40), np.int64)
    g[5, :] = np.tile([SOLID_PROP, HALVES, SQUARE_POLY, HALVES], 10)
    load_map(sim.world, _write(tmp_path, g))
    box = sim.world.spawn(
        Transform(3.0, 1.515), RigidBody(velocity=(5.0, 0.0)), Collider(Box(0.5, 0.5), friction=0.0)
    )
    worst = 0.0
    for _ in range(360):  # 6 s at 5 m/s: across 30 tiles
        sim.step()
        worst = max(worst, abs(sim.world.get(box, RigidBody).velocity[1]))
    assert sim.world.get(box, Transform).x > 32.0 and worst < 0.05


@pytest.mark.parametrize(
    ("shapes", "full"),
    [
        ([TileShape("rectangle", 0, 0, 16, 16)], True),
        ([TileShape("rectangle", 0, 0, 8, 16), TileShape("rectangle", 8, 0, 8, 16)], True),
        ([TileShape("rectangle", 0, 0, 16, 16), TileShape("rectangle", 4, 4, 4, 4)], True),
        ([TileShape("rectangle", 0, 0, 8, 16), TileShape("rectangle", 9, 0, 7, 16)], False),
        ([TileShape("rectangle", 0, 0, 16, 17)], False),  # sticks out of the tile
        ([TileShape("rectangle", 0, 0, 16, 16), TileShape("ellipse", 0, 0, 4, 4)], False),
        ([TileShape("polygon", 0, 0, points=((0, 0), (16, 0), (16, 16)))], False),
        ([TileShape("polygon", 2, 0, points=((-2, 0), (14, 0), (14, 16), (-2, 16)))], True),
        ([], False),
    ],
)
def test_covers_tile(shapes: list[TileShape], full: bool) -> None:
    assert covers_tile(shapes, 16, 16) is full
