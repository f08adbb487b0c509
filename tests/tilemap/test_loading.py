"""TMX and JSON maps, external tilesets, image collections, infinite maps, groups, units."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from kge.testbed import png
from kge.tilemap import load_map
from kge.tilemap.model import FLIP_H, TILED_FLIP_H
from kge.tilemap.writer import GroupSpec, TileLayerSpec, TilesetSpec, write_json_map, write_map

from .conftest import Stepper
from .maps import GROUND, ONE_WAY, floor, sheet, tileset, write_level


def _grid() -> np.ndarray:
    g = floor(40, 24)
    g[3, 5] = ONE_WAY | TILED_FLIP_H
    return g


def test_tmx_with_embedded_and_external_tilesets_agree(tmp_path: Path, sim: Stepper) -> None:
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    a = load_map(sim.world, write_level(tmp_path / "a", _grid()))
    b = load_map(sim.world, write_level(tmp_path / "b", _grid(), external="tiles.tsx"))
    for m in (a, b):
        lay = m.layer("Ground")
        assert lay.gids[3, 5] == ONE_WAY and lay.flags[3, 5] == FLIP_H
        assert m.properties(GROUND) == {"solid": True, "friction": 0.6}
    assert np.array_equal(a.layer("Ground").gids, b.layer("Ground").gids)


@pytest.mark.parametrize("chunk", [None, 8])
def test_json_maps_finite_and_infinite(tmp_path: Path, sim: Stepper, chunk: int | None) -> None:
    png.write(tmp_path / "tiles.png", sheet())
    ts = TilesetSpec("tiles", "tiles.png", 16, 16, columns=4, count=8, image_size=(64, 32))
    write_json_map(tmp_path / "m.json", 16, 16, ts, _grid().tolist(), chunk=chunk)
    m = load_map(sim.world, tmp_path / "m.json", solid_layers=["Ground"])
    lay = m.layer("Ground")
    assert lay.gids.shape == (24, 40)
    assert lay.gids[3, 5] == ONE_WAY and lay.flags[3, 5] == FLIP_H
    assert m.bounds == (0.0, 0.0, 40.0, 24.0)
    assert len(m.collider_entities) == 2  # the floor outline (solid layer) and the one-way tile


def test_image_collection_tileset(tmp_path: Path, sim: Stepper) -> None:
    img = np.zeros((32, 16, 4), np.uint8)
    img[...] = (10, 20, 30, 255)
    png.write(tmp_path / "tall.png", img)
    coll = TilesetSpec(
        "things",
        None,
        16,
        32,
        count=1,
        tiles={0: {"image": "tall.png", "image_size": (16, 32), "properties": {"solid": True}}},
    )
    g = np.zeros((4, 4), np.int64)
    g[3, 1] = 1
    write_map(tmp_path / "c.tmx", 16, 16, [coll], [TileLayerSpec("L", g)])
    m = load_map(sim.world, tmp_path / "c.tmx")
    t = m.data.tiles
    assert t.images[int(t.image[1])].name == "tall.png"
    assert tuple(t.rect[1]) == (0, 0, 16, 32)
    assert m.tile_at((1.5, 0.5)) == 1


def test_group_layers_combine_style(tmp_path: Path, sim: Stepper) -> None:
    png.write(tmp_path / "tiles.png", sheet())
    inner = TileLayerSpec("Deco", floor(10, 5), opacity=0.5, offset=(4, 0))
    write_map(
        tmp_path / "g.tmx",
        16,
        16,
        [tileset()],
        [GroupSpec("Back", [inner], opacity=0.5, offset=(8, 16))],
    )
    m = load_map(sim.world, tmp_path / "g.tmx")
    lay = m.layer("Back/Deco")
    assert lay.style.opacity == pytest.approx(0.25)
    assert lay.style.offset == (12.0, 16.0)


def test_pixels_per_meter_and_origin(tmp_path: Path, sim: Stepper) -> None:
    m = load_map(
        sim.world, write_level(tmp_path, floor(20, 10)), pixels_per_meter=32, origin=(-5.0, 2.0)
    )
    assert m.bounds == (-5.0, 2.0, 5.0, 7.0)  # 20 tiles of 16 px at 32 px/m = 10 m
    assert m.cell_at((-4.9, 2.1)) == (0, 9)
    assert m.tile_at((-4.9, 2.1)) == GROUND and m.tile_at((-4.9, 2.6)) == 0
    assert m.cell_center(0, 9) == pytest.approx((-4.75, 2.25))
    assert m.cell_at((100.0, 0.0)) is None


def test_unload_removes_everything(tmp_path: Path, sim: Stepper) -> None:
    objs = [{"id": 1, "name": "a", "x": 0, "y": 0, "width": 16, "height": 16}]
    before = set(sim.world.entities())
    m = load_map(sim.world, write_level(tmp_path, floor(20), objs))
    assert len(sim.world.entities()) > len(before)
    m.unload()
    sim.world.flush()
    assert set(sim.world.entities()) == before


def test_with_the_plugin_map_names_resolve_through_the_asset_store(tmp_path: Path) -> None:
    from kge.assets import Assets
    from kge.systems.physics import PhysicsPlugin
    from kge.systems.tilemap import TilemapPlugin
    from kge.tilemap import TilemapError
    from kge.world import World

    (tmp_path / "levels").mkdir()
    write_level(tmp_path / "levels", floor(12), name="one.tmx")
    world = World()
    world.insert_resource(Assets(tmp_path))
    world.add_plugins(PhysicsPlugin(), TilemapPlugin())
    m = load_map(world, "levels/one.tmx")  # not relative to the working directory
    assert m.path == tmp_path / "levels" / "one.tmx" and m.data.cols == 12
    with pytest.raises(TilemapError, match=r"map file 'levels/two.tmx' not found: .*"):
        load_map(world, "levels/two.tmx")
