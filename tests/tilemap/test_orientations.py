"""Every orientation's geometry (map <-> world, cells, outlines) and its tile colliders."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from kge import Collider, RigidBody, Transform
from kge.components.shapes import Chain, Circle, Polygon
from kge.components.tilemap import TileCollider
from kge.testbed import png
from kge.tilemap import load_map
from kge.tilemap.writer import TileLayerSpec, TilesetSpec, write_map

from . import corpus
from .conftest import Stepper

TW, TH = 32, 16  # isometric tiles: 1 m wide at the default scale


def write_iso(folder: Path, grid: np.ndarray) -> Path:
    """An isometric map: gid 1 solid, gid 2 one-way, gid 3 decoration."""
    sheet = np.zeros((TH, 3 * TW, 4), np.uint8)
    sheet[..., :3] = 120
    sheet[..., 3] = 255
    png.write(folder / "iso.png", sheet)
    ts = TilesetSpec("iso", "iso.png", TW, TH, columns=3, count=3, image_size=(3 * TW, TH),
                     tiles={0: {"properties": {"solid": True}},
                            1: {"properties": {"one_way": True}}})  # fmt: skip
    path = folder / "iso.tmx"
    write_map(path, TW, TH, [ts], [TileLayerSpec("Ground", grid)], orientation="isometric")
    return path


@pytest.mark.parametrize("orientation", corpus.ORIENTATIONS)
def test_map_world_and_cell_helpers_agree_in_every_orientation(
    tmp_path: Path, sim: Stepper, orientation: str
) -> None:
    m = load_map(sim.world, corpus.write(tmp_path, orientation, "tmx-1.10-gzip"))
    for px, py in [(0.0, 0.0), (17.5, 3.25), (100.0, 40.0)]:
        assert m.world_to_map(*m.map_to_world(px, py)) == pytest.approx((px, py))
    for r in range(corpus.ROWS):
        for c in range(corpus.COLS):
            centre = m.cell_center(c, r)
            assert m.cell_at(centre) == (c, r)
            outline = m.cell_outline(c, r)
            assert len(outline) == (6 if orientation == "hexagonal" else 4)
            assert np.mean(outline, axis=0) == pytest.approx(centre)
    assert m.cell_at((-50.0, -50.0)) is None


def _drop(sim: Stepper, x: float, y: float, steps: int = 240) -> float:
    ball = sim.world.spawn(
        Transform(x, y), RigidBody(), Collider(Circle(0.1), density=1.0)
    )
    sim.step(steps)
    return sim.world.get(ball, Transform).y


def test_isometric_solid_cells_merge_into_outlines_on_the_diamonds(
    tmp_path: Path, sim: Stepper
) -> None:
    grid = np.zeros((8, 8), np.int64)
    grid[2:6, 1:5] = 1  # a 4 x 4 block of solid cells: one outline
    grid[7, 7] = 1  # and a lone one: another
    grid[0, 6] = 2  # a one-way tile: its own diamond
    grid[1, 1] = 3  # decoration: nothing
    m = load_map(sim.world, write_iso(tmp_path, grid))
    kinds = sorted(sim.world.get(e, TileCollider).kind for e in m.collider_entities)
    assert kinds == ["one_way", "outline", "outline"]
    block = next(
        e for e in m.collider_entities
        if sim.world.get(e, TileCollider).cells == (1, 2, 5, 6)
    )  # fmt: skip
    chain = sim.world.get(block, Collider).shape
    assert isinstance(chain, Chain)
    # the outline's corners are the block's outer diamond corners, in world metres
    corners = {m.cell_outline(1, 2)[0], m.cell_outline(4, 2)[1], m.cell_outline(4, 5)[2],
               m.cell_outline(1, 5)[3]}  # fmt: skip
    got = {tuple(round(v, 9) for v in p) for p in chain.vertices}
    assert {tuple(round(v, 9) for v in p) for p in corners} <= got
    # a ball dropped straight onto the block's top corner (the apex of its big diamond)
    # stays there, on the outline; over an empty cell it falls through
    apex = m.cell_outline(1, 2)[0]
    rest = _drop(sim, apex[0], apex[1] + 2.0)
    assert rest - 0.1 == pytest.approx(apex[1], abs=0.02)
    far = m.cell_center(6, 1)  # empty
    assert _drop(sim, far[0], far[1] + 1.0, 120) < far[1] - 2.0


def test_isometric_tile_edits_retrace_only_what_they_touch(tmp_path: Path, sim: Stepper) -> None:
    grid = np.zeros((8, 8), np.int64)
    grid[2:6, 1:5] = 1
    grid[7, 7] = 1
    m = load_map(sim.world, write_iso(tmp_path, grid))
    lone = next(
        e for e in m.collider_entities if sim.world.get(e, TileCollider).cells == (7, 7, 8, 8)
    )
    m.set_tile("Ground", 3, 3, 0)  # a hole in the block: an outer loop and an inner one
    sim.world.flush()
    cells = sorted(sim.world.get(e, TileCollider).cells for e in m.collider_entities)
    assert cells.count((1, 2, 5, 6)) == 1 and (3, 3, 4, 4) in cells
    assert lone in m.collider_entities  # untouched outline, same entity
    m.set_tile("Ground", 6, 0, 2)  # a one-way tile: one diamond
    sim.world.flush()
    (e,) = [e for e in m.collider_entities if sim.world.get(e, TileCollider).kind == "one_way"]
    assert isinstance(sim.world.get(e, Collider).shape, Polygon)


@pytest.mark.parametrize("orientation", ["staggered", "hexagonal"])
def test_staggered_and_hexagonal_solid_cells_are_their_own_shapes(
    tmp_path: Path, sim: Stepper, orientation: str
) -> None:
    m = load_map(sim.world, corpus.write(tmp_path, orientation, "json-1.10"))
    solid = int(np.count_nonzero(corpus.grid() == 1))  # the corpus's tile 0 (gid 1) is solid
    polys = [e for e in m.collider_entities if sim.world.get(e, TileCollider).kind == "cell"]
    assert len(polys) == solid
    e = polys[0]
    c, r = sim.world.get(e, TileCollider).cells[:2]
    shape = sim.world.get(e, Collider).shape
    assert isinstance(shape, Polygon)
    assert len(shape.vertices) == (6 if orientation == "hexagonal" else 4)
    t = sim.world.get(e, Transform)
    assert (t.x, t.y) == pytest.approx(m.cell_center(c, r))
