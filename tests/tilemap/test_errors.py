"""Bad maps get a TilemapError naming file, layer and object, and leave the world as it was."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from kge.tilemap import Spawners, TilemapError, load_map
from kge.tilemap.writer import TilesetSpec, write_map

from .conftest import Stepper
from .maps import GROUND, floor, write_level


def _count(sim: Stepper) -> int:
    sim.world.flush()
    return len(sim.world.entities())


def test_missing_map_file(tmp_path: Path, sim: Stepper) -> None:
    with pytest.raises(TilemapError, match="nope.tmx.*not found"):
        load_map(sim.world, tmp_path / "nope.tmx")


def test_missing_external_tileset(tmp_path: Path, sim: Stepper) -> None:
    path = write_level(tmp_path, floor(), external="tiles.tsx")
    (tmp_path / "tiles.tsx").unlink()
    with pytest.raises(TilemapError, match=r"level.tmx.*tiles.tsx.*not found"):
        load_map(sim.world, path)


def test_missing_tileset_image(tmp_path: Path, sim: Stepper) -> None:
    path = write_level(tmp_path, floor())
    (tmp_path / "tiles.png").unlink()
    with pytest.raises(TilemapError, match=r"tileset 'tiles': image .*tiles.png.* not found"):
        load_map(sim.world, path)


def test_unknown_orientation(tmp_path: Path, sim: Stepper) -> None:
    ts = TilesetSpec("t", "tiles.png", 16, 16, columns=4, count=8, image_size=(64, 32))
    from kge.tilemap.writer import TileLayerSpec

    write_map(
        tmp_path / "ob.tmx", 16, 16, [ts], [TileLayerSpec("L", floor())], orientation="oblique"
    )
    with pytest.raises(TilemapError, match="orientation 'oblique' is not a Tiled orientation"):
        load_map(sim.world, tmp_path / "ob.tmx")


def test_corrupt_zstd_layer(tmp_path: Path, sim: Stepper) -> None:
    path = write_level(tmp_path, floor())
    text = path.read_text()
    start = text.index('<data encoding="csv">')
    end = text.index("</data>")
    path.write_text(text[:start] + '<data encoding="base64" compression="zstd">AAAA' + text[end:])
    with pytest.raises(TilemapError, match=r"level.tmx: layer 'Ground': corrupt zstd data"):
        load_map(sim.world, path)


def test_tile_id_in_no_tileset(tmp_path: Path, sim: Stepper) -> None:
    g = floor()
    g[2, 7] = 99
    with pytest.raises(
        TilemapError, match=r"layer 'Ground': tile id 99 at column 7, row 2 is in no tileset"
    ):
        load_map(sim.world, write_level(tmp_path, g))


def test_unknown_class_as_error(tmp_path: Path, sim: Stepper) -> None:
    objs = [{"id": 4, "name": "boss", "class": "Dragon", "x": 0, "y": 0, "width": 16, "height": 16}]
    before = _count(sim)
    with pytest.raises(
        TilemapError,
        match=r"layer 'Objects': object 4 \('boss'\): class 'Dragon' has no registered spawner",
    ):
        load_map(sim.world, write_level(tmp_path, floor(), objs), unknown="error")
    assert _count(sim) == before


def test_a_raising_spawner_leaves_nothing(tmp_path: Path, sim: Stepper) -> None:
    objs = [
        {"id": 1, "name": "ok", "class": "Coin", "x": 0, "y": 0, "width": 16, "height": 16},
        {"id": 2, "name": "bad", "class": "Trap", "x": 16, "y": 0, "width": 16, "height": 16},
    ]

    def trap(spawn: Any) -> None:
        raise KeyError("damage")

    before = _count(sim)
    with pytest.raises(
        TilemapError,
        match=r"level.tmx: layer 'Objects': object 2 \('bad'\): spawner .*trap.* raised KeyError",
    ):
        load_map(
            sim.world,
            write_level(tmp_path, floor(), objs),
            spawners=Spawners({"Coin": lambda s: None, "Trap": trap}),
        )
    assert _count(sim) == before


def test_a_component_refused_at_spawn_leaves_nothing(tmp_path: Path, sim: Stepper) -> None:
    # a spawner returning a bad component: refused by the world's validators at spawn
    from kge.components.joints import DistanceJoint

    objs = [{"id": 1, "name": "rope", "class": "Rope", "x": 0, "y": 0, "width": 16, "height": 16}]
    before = _count(sim)
    with pytest.raises(TilemapError, match=r"level.tmx: layer 'Objects': object 1 \('rope'\)"):
        load_map(
            sim.world,
            write_level(tmp_path, floor(), objs),
            spawners={"Rope": lambda s: [DistanceJoint(10**9, 10**9 + 1)]},
        )
    assert _count(sim) == before


def test_bad_edits_change_nothing(tmp_path: Path, sim: Stepper) -> None:
    m = load_map(sim.world, write_level(tmp_path, floor()))
    grid = m.layer("Ground").gids.copy()
    for args, msg in [
        (("Ground", 99, 0, GROUND), r"col must be an int in \[0, 60\)"),
        (("Ground", 0, 0, 1234), "tile id 1234 is in no tileset"),
        (("Ground", 0, 0, -1), "gid must be an int >= 0"),
        (("Sky", 0, 0, GROUND), "no tile layer 'Sky'"),
    ]:
        with pytest.raises(TilemapError, match=msg):
            m.set_tile(*args)
    assert np.array_equal(m.layer("Ground").gids, grid)


def test_loading_inside_a_locked_world_is_refused_cleanly(tmp_path: Path, sim: Stepper) -> None:
    path = write_level(tmp_path, floor())
    before = _count(sim)
    with sim.world.locked(), pytest.raises(TilemapError, match="inside a physics callback"):
        load_map(sim.world, path)
    assert _count(sim) == before
