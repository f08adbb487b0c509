"""Tile collision: merged outlines, no seams, one-way runs, tile shapes, local rebuilds."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from kge.components.collider import Collider
from kge.components.platform import OneWayPlatform
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Chain, Circle, Polygon
from kge.components.tilemap import TileCollider
from kge.components.transform import Transform
from kge.physics.resource import Physics
from kge.testbed.samples.tilemaps import cave_cells
from kge.tilemap import load_map
from kge.tilemap.outline import trace_loops

from .conftest import Stepper
from .maps import GROUND, ONE_WAY, SLOPE, floor, write_level


def _signed_area(loop: np.ndarray) -> float:
    x, y = loop[:, 0].astype(float), loop[:, 1].astype(float)
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def caves(n: int, seed: int) -> np.ndarray:
    return cave_cells(n, seed, fill=0.5)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_outlines_enclose_exactly_the_solid_cells(seed: int) -> None:
    solid = caves(60, seed)
    loops = trace_loops(solid)
    # outer outlines wind one way, holes the other: the signed areas add up to the solid area
    assert sum(_signed_area(lp) for lp in loops) == pytest.approx(solid.sum())
    # and every outline vertex is a turn (no collinear runs left)
    for lp in loops:
        d = np.diff(np.vstack([lp, lp[:1], lp[1:2]]), axis=0)
        turns = d[:-1, 0] * d[1:, 1] - d[:-1, 1] * d[1:, 0]
        assert np.all(turns != 0)
    assert len(loops) <= 0.05 * solid.sum()


def test_a_floor_of_sixty_tiles_is_one_collider(tmp_path: Path, sim: Stepper) -> None:
    m = load_map(sim.world, write_level(tmp_path, floor(60)))
    (e,) = m.collider_entities
    chain = sim.world.get(e, Collider).shape
    assert isinstance(chain, Chain) and chain.loop
    assert sorted(chain.vertices) == [(0.0, 0.0), (0.0, 1.0), (60.0, 0.0), (60.0, 1.0)]
    assert sim.world.get(e, Collider).friction == pytest.approx(0.6)  # the tile's property


def test_box_slides_across_fifty_tiles_without_a_bump(tmp_path: Path, sim: Stepper) -> None:
    load_map(sim.world, write_level(tmp_path, floor(60)))
    box = sim.world.spawn(
        Transform(3.0, 1.515), RigidBody(velocity=(5.0, 0.0)), Collider(Box(0.5, 0.5), friction=0.0)
    )
    worst = 0.0
    for _ in range(600):  # 10 s at 5 m/s: across 50 tiles
        sim.step()
        worst = max(worst, abs(sim.world.get(box, RigidBody).velocity[1]))
    assert sim.world.get(box, Transform).x > 52.0
    assert sim.world.get(box, RigidBody).velocity[0] == pytest.approx(5.0, abs=0.01)
    assert (
        worst < 0.05
    )  # the tolerance of kge's own chain test (tests/physics/test_edges_chains.py)


def test_one_way_tiles_are_merged_runs_with_a_platform(tmp_path: Path, sim: Stepper) -> None:
    g = floor(20)
    g[5, 3:8] = ONE_WAY
    g[5, 12] = ONE_WAY
    m = load_map(sim.world, write_level(tmp_path, g))
    runs = [e for e in m.collider_entities if sim.world.get(e, TileCollider).kind == "one_way"]
    assert len(runs) == 2
    assert all(sim.world.has(e, OneWayPlatform) for e in runs)
    widths = sorted(sim.world.get(e, Collider).shape.half_width * 2 for e in runs)  # type: ignore[union-attr]
    assert widths == [1.0, 5.0]
    # a ball shot up from below passes through the run and comes to rest on top of it
    ball = sim.world.spawn(
        Transform(5.0, 2.0), RigidBody(velocity=(0.0, 9.0)), Collider(Circle(0.25))
    )
    sim.step(240)
    assert sim.world.get(ball, Transform).y == pytest.approx(5.25, abs=0.05)


def test_tiles_with_collision_shapes_get_their_shape(tmp_path: Path, sim: Stepper) -> None:
    g = floor(10)
    g[8, 4] = SLOPE
    m = load_map(sim.world, write_level(tmp_path, g))
    (e,) = [e for e in m.collider_entities if sim.world.get(e, TileCollider).kind == "tile"]
    shape = sim.world.get(e, Collider).shape
    assert isinstance(shape, Polygon)
    t = sim.world.get(e, Transform)
    world_pts = sorted((round(t.x + x, 6), round(t.y + y, 6)) for x, y in shape.vertices)
    assert world_pts == [(4.0, 1.0), (5.0, 1.0), (5.0, 2.0)]  # the slope rises to the right


def _top(physics: Physics, x: float, high: float = 9.5) -> float | None:
    """Height of the first surface under (x, high), by a ray cast (chains are hollow)."""
    hits = physics.raycast((x, high), (x, -2.0))
    return None if hits is None else round(hits.point[1], 6)


def test_set_and_clear_tile_update_collision(tmp_path: Path, sim: Stepper) -> None:
    m = load_map(sim.world, write_level(tmp_path, floor(20)))
    physics = sim.world.resource(Physics)
    sim.step()
    assert _top(physics, 10.5) == 1.0
    m.clear_tile("Ground", 10, 9)
    sim.step()
    assert _top(physics, 10.5) is None
    assert _top(physics, 9.5) == 1.0 and _top(physics, 11.5) == 1.0
    assert len(m.collider_entities) == 2  # the floor split in two outlines
    # a box dropped into the hole falls through
    box = sim.world.spawn(Transform(10.5, 3.0), RigidBody(), Collider(Box(0.4, 0.4)))
    sim.step(120)
    assert sim.world.get(box, Transform).y < -1.0
    m.set_tile("Ground", 10, 9, GROUND)
    m.set_tile("Ground", 10, 5, GROUND)
    sim.step()
    assert _top(physics, 10.5) == 5.0 and _top(physics, 10.5, high=3.5) == 1.0
    assert m.tile_at((10.5, 4.5)) == GROUND
    assert len(m.collider_entities) == 2  # the floor again, and the new block


def test_local_rebuilds_match_a_full_trace(tmp_path: Path, sim: Stepper) -> None:
    grid = np.where(caves(40, 7), GROUND, 0)
    m = load_map(sim.world, write_level(tmp_path, grid))
    rng = np.random.default_rng(3)
    for _ in range(60):
        c, r = (int(v) for v in rng.integers(0, 40, 2))
        if m.tile("Ground", c, r):
            m.clear_tile("Ground", c, r)
        else:
            m.set_tile("Ground", c, r, GROUND)
    sim.world.flush()
    now = {sim.world.get(e, Collider).shape.vertices for e in m.collider_entities}  # type: ignore[union-attr]
    solid = m.layer("Ground").gids != 0
    u = m.units
    expected = set()
    for lp in trace_loops(solid):
        x, y = u.corners(lp[:, 0].astype(float), lp[:, 1].astype(float))
        expected.add(tuple(zip(x.tolist(), y.tolist(), strict=True)))
    assert now == expected


def test_a_tile_edit_respawns_only_the_outlines_it_changed(tmp_path: Path, sim: Stepper) -> None:
    grid = np.where(caves(60, 5), GROUND, 0)
    m = load_map(sim.world, write_level(tmp_path, grid))
    before = set(m.collider_entities)
    assert len(before) > 10
    rows, cols = np.nonzero(grid[1:-1, 1:-1] == 0)
    m.set_tile("Ground", int(cols[0]) + 1, int(rows[0]) + 1, GROUND)  # fill one empty cell
    after = set(m.collider_entities)
    assert len(before - after) <= 4 and len(after - before) <= 4  # the few outlines touching it
    assert len(before & after) >= len(before) - 4


def test_layer_and_tile_properties_set_material_and_filter(tmp_path: Path, sim: Stepper) -> None:
    from kge.tilemap.writer import TileLayerSpec

    g = floor(10)
    walls = np.zeros_like(g)
    walls[:, 0] = GROUND
    layer = TileLayerSpec(
        "Walls", walls, properties={"category_bits": 4, "mask_bits": 2, "restitution": 0.5}
    )
    m = load_map(sim.world, write_level(tmp_path, g, extra_layers=[layer]))
    by_layer = {sim.world.get(e, TileCollider).layer: e for e in m.collider_entities}
    wall = sim.world.get(by_layer["Walls"], Collider)
    assert (wall.filter.category_bits, wall.filter.mask_bits) == (4, 2)
    assert wall.restitution == 0.5 and wall.friction == pytest.approx(0.6)  # tile overrides
    ground = sim.world.get(by_layer["Ground"], Collider)
    assert ground.filter.category_bits == 1 and ground.restitution == 0.0
