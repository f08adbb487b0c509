"""The CCD's screening shortcuts answer exactly what the slow paths answer.

* :class:`~kge.physics.ccd.sorted_boxes.SortedBoxes` (a window of rows sorted by
  left edge, plus the rows written since the sort) against a full pass over the
  table, through writes, frees, appended rows, NaN and infinite boxes and queries;
* :class:`~kge.physics.ccd.obstacles.Nearby` (the rows found around a fast body,
  reused for its own and its neighbours' reach tests) against the table;
* :func:`~kge.physics.ccd.sweep.bounds_of` against pymunk's ``BB.merge``;
* the whole arming decision of :class:`ContinuousCollision` in a crowded scene
  against one that has no Nearby hints (every query a full pass).
"""

from __future__ import annotations

import math
import random

import numpy as np
import pymunk
import pytest

from kge.physics.ccd import ContinuousCollision
from kge.physics.ccd import obstacles as obstacles_module
from kge.physics.ccd.obstacles import Obstacles
from kge.physics.ccd.sorted_boxes import SortedBoxes, _full_pass
from kge.physics.ccd.sweep import bounds_of
from kge.physics.cp.static_bulk import add_shapes, chain_segments

_SPECIAL = [math.nan, math.inf, -math.inf]


def _random_box(rng: random.Random) -> tuple[float, float, float, float]:
    x, y = rng.uniform(-50, 50), rng.uniform(-50, 50)
    w = rng.choice([0.0, rng.uniform(0, 2), rng.uniform(0, 30)])
    h = rng.uniform(0, 3)
    box = [x, y, x + w, y + h]
    if rng.random() < 0.03:
        box[rng.randrange(4)] = rng.choice(_SPECIAL)
    return (box[0], box[1], box[2], box[3])


def _queries(rng: random.Random, k: int) -> tuple[np.ndarray, ...]:
    x = np.array([rng.uniform(-60, 60) for _ in range(k)])
    y = np.array([rng.uniform(-60, 60) for _ in range(k)])
    r = np.array([rng.choice([0.0, rng.uniform(0, 5), rng.uniform(0, 40)]) for _ in range(k)])
    for a in (x, y, r):
        if rng.random() < 0.1:
            a[rng.randrange(k)] = rng.choice(_SPECIAL)
    with np.errstate(invalid="ignore"):  # inf - inf: a NaN query edge, meant
        return x - r, y - r, x + r, y + r


@pytest.mark.parametrize("seed", range(6))
def test_sorted_boxes_match_a_full_pass_through_writes_and_frees(seed: int) -> None:
    rng = random.Random(seed)
    box = np.full((64, 4), np.nan)
    index = SortedBoxes(min_rows=0)
    m = 0
    for _ in range(120):
        action = rng.random()
        if action < 0.45 or m == 0:  # write some rows (new ones appended, or rewrites)
            rows = [rng.randrange(m + 3) for _ in range(rng.randrange(1, 12))]
            m = max(m, max(rows) + 1)
            if m > len(box):
                box = np.concatenate([box, np.full((len(box), 4), np.nan)])
            box[rows] = [_random_box(rng) for _ in rows]
            index.touched(rows)
        elif action < 0.6:  # free rows: NaN, never touched (as Obstacles drops them)
            rows = [rng.randrange(m) for _ in range(rng.randrange(1, 6))]
            box[rows] = np.nan
        elif action < 0.62:  # empty the table
            box[:] = np.nan
            index.clear()
            m = 0
            continue
        k = rng.choice([1, 2, 3, 8, 9, 30])
        left, bottom, right, top = _queries(rng, k)
        want = _naive(box[:m], left, bottom, right, top)
        for got in (
            index.overlapping(box, m, left, bottom, right, top),
            _full_pass(box[:m], left, bottom, right, top),
        ):
            assert got[0].tolist() == want[0].tolist()
            assert got[1].tolist() == want[1].tolist()


def _naive(
    box: np.ndarray, left: np.ndarray, bottom: np.ndarray, right: np.ndarray, top: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    pairs = [
        (q, r)
        for q in range(len(left))
        for r in range(len(box))
        if box[r, 0] <= right[q] and box[r, 2] >= left[q] and box[r, 1] <= top[q]
        and box[r, 3] >= bottom[q]
    ]
    return np.array([q for q, _ in pairs], dtype=int), np.array([r for _, r in pairs], dtype=int)


def test_sorted_boxes_search_only_a_window_of_a_large_table() -> None:
    """A query over a long row of boxes looks at the boxes near it (plus the loose ones)."""
    n = 10_000
    x = np.arange(n, dtype=float)
    box = np.stack([x, np.zeros(n), x + 0.5, np.ones(n)], axis=1)
    index = SortedBoxes()
    q, rows = index.overlapping(box, n, np.array([100.2]), np.array([0.0]),
                                np.array([103.1]), np.array([0.5]))
    assert q.tolist() == [0, 0, 0, 0] and rows.tolist() == [100, 101, 102, 103]
    assert index._order is not None and index.span < 0.51
    box[5000] = (101.0, 0.0, 101.1, 0.2)  # a row moved next to the query
    index.touched([5000])
    _, rows = index.overlapping(box, n, np.array([100.2]), np.array([0.0]),
                                np.array([103.1]), np.array([0.5]))
    assert rows.tolist() == [100, 101, 102, 103, 5000]


def _scene() -> tuple[pymunk.Space, pymunk.Body, list[pymunk.Shape]]:
    space = pymunk.Space()
    ground = pymunk.Body(body_type=pymunk.Body.STATIC)
    mover = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    space.add(ground, mover)
    shapes: list[pymunk.Shape] = []
    for k in range(8):  # scenes side by side, as the batched LunarLander lays them
        points = [(32.0 * k + 2.0 * i, 0.4 * (i % 3)) for i in range(11)]
        shapes += chain_segments(ground, points, False, 0.01, 0.0)
    paddle = pymunk.Poly.create_box(mover, (2.0, 0.2))
    shapes.append(paddle)
    add_shapes(space, shapes)
    mover.position = (40.0, 3.0)
    space.reindex_shapes_for_body(mover)
    return space, mover, shapes


def _refreshed(space: pymunk.Space) -> Obstacles:
    obs = Obstacles(space)
    bodies = list(space.bodies)
    ids = np.array([b.id for b in bodies], np.int64)
    pose = np.array([(b.position.x, b.position.y, b.angle) for b in bodies], float)
    obs.refresh(ids, pose, np.zeros((len(bodies), 3)), 0)
    return obs


@pytest.mark.parametrize("seed", range(4))
def test_nearby_answers_what_the_table_answers(seed: int) -> None:
    space, _, _ = _scene()
    obs = _refreshed(space)
    rng = random.Random(seed)
    for _ in range(200):
        k = rng.randrange(1, 4)
        x = np.array([rng.uniform(-5, 270) for _ in range(k)])
        y = np.array([rng.uniform(-3, 8) for _ in range(k)])
        r = np.array([rng.uniform(0, 9) for _ in range(k)])
        around = obs.nearby(x, y, r)
        near_any = obs.near_any(x, y, r)
        assert [bool(a.rows) for a in around] == near_any.tolist()
        for j, near in enumerate(around):
            # the reach square (inside the wide one) from the rows found
            inner = float(r[j]) * rng.random()
            assert near.overlaps(float(x[j]), float(y[j]), inner) == bool(
                obs.near_any(x[j : j + 1], y[j : j + 1], np.array([inner]))[0]
            )
            # a body's box grown by its motion, inside the square or (sometimes) not
            cx, cy = float(x[j]) + rng.uniform(-3, 3), float(y[j]) + rng.uniform(-3, 3)
            box = pymunk.BB(cx - 0.3, cy - 0.2, cx + 0.3, cy + 0.4)
            still, moving = rng.uniform(0, 3), rng.uniform(0, 5)
            assert obs.candidates(box, still, moving, near) == obs.candidates(box, still, moving)


def test_nearby_outside_its_square_falls_back_to_the_table() -> None:
    space, _, _ = _scene()
    obs = _refreshed(space)
    near = obs.nearby(np.array([500.0]), np.array([0.0]), np.array([1.0]))[0]
    assert near.rows == []
    box = pymunk.BB(1.0, -0.5, 1.5, 0.5)  # far from the square, on the first chain
    assert obs.candidates(box, 0.1, 0.1, near) == obs.candidates(box, 0.1, 0.1) != []


def test_bounds_of_merges_as_pymunk_does() -> None:
    space = pymunk.Space()
    body = pymunk.Body(1.0, 1.0)
    body.position = (3.0, -2.0)
    body.angle = 0.7
    shapes = (
        pymunk.Circle(body, 0.5, (1.0, 0.0)),
        pymunk.Poly.create_box(body, (2.0, 0.3)),
        pymunk.Segment(body, (-1.0, -1.0), (2.0, 0.5), 0.05),
    )
    space.add(body, *shapes)
    for s in shapes:
        s.cache_bb()
    merged = shapes[0].bb
    for s in shapes[1:]:
        merged = merged.merge(s.bb)
    assert bounds_of(shapes) == tuple(merged)
    assert bounds_of(()) is None


def _crowd(ccd_hints: bool) -> list[tuple[float, ...]]:
    """Balls thrown at chains and a moving paddle; the armed set and poses per step."""
    space, mover, _ = _scene()
    mover.velocity = (-30.0, 0.0)
    ccd = ContinuousCollision(space)
    rng = random.Random(5)
    balls = []
    for k in range(40):
        body = pymunk.Body()
        body.position = (rng.uniform(0, 260), rng.uniform(1, 6))
        body.velocity = (rng.uniform(-150, 150), rng.uniform(-150, 40))
        body.angular_velocity = rng.uniform(-80, 80)
        shape = pymunk.Circle(body, 0.1) if k % 2 else pymunk.Poly.create_box(body, (0.3, 0.2))
        shape.density = 1.0
        space.add(body, shape)
        balls.append(body)
    for body in balls:
        ccd.track(body, bullet=body is balls[0])
    space.gravity = (0.0, -10.0)
    out = []
    for _ in range(40):
        armed = ccd.before_step(1 / 60, 4)
        for _ in range(4):
            space.step(1 / 240)
        ccd.after_step(1 / 60)
        out.append((armed, *(c for b in balls for c in (*b.position, b.angle))))
    return out


def test_arming_and_sweeps_are_the_same_without_the_nearby_hints(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    fast = _crowd(True)
    assert any(row[0] for row in fast)  # the scene does arm bodies
    plain = Obstacles.candidates

    def no_hint(self: Obstacles, box: pymunk.BB, still: float, moving: float,
                near: obstacles_module.Nearby | None = None) -> list[pymunk.Shape]:
        return plain(self, box, still, moving)

    monkeypatch.setattr(Obstacles, "candidates", no_hint)
    assert _crowd(False) == fast


def _indexed_like_the_space(obs: Obstacles, space: pymunk.Space, bodies: list[pymunk.Body]) -> None:
    """Every shape of these bodies in the space has its row, box and kind; none other has."""
    for body in bodies:
        for shape in body.shapes:
            row = obs.row_of.get(shape)
            if shape.space is not space or body.body_type == pymunk.Body.DYNAMIC:
                assert row is None
                continue
            assert row is not None
            bb = shape.bb
            assert tuple(obs.box[row]) == (bb.left, bb.bottom, bb.right, bb.top)
            assert bool(obs.kinematic[row]) == (body.body_type == pymunk.Body.KINEMATIC)


def test_reclassify_of_a_relaid_or_retyped_body_indexes_what_the_space_holds() -> None:
    space = pymunk.Space()
    moon = pymunk.Body(body_type=pymunk.Body.STATIC)
    other = pymunk.Body(body_type=pymunk.Body.STATIC)
    space.add(moon, other)
    first = chain_segments(moon, [(float(i), 0.0) for i in range(6)], False, 0.01, 0.0)
    add_shapes(space, first)
    obs = _refreshed(space)
    obs.reclassify(moon)
    _indexed_like_the_space(obs, space, [moon, other])
    for step in range(3):  # re-laid: the old segments leave, new ones join
        space.remove(*first)
        first = chain_segments(moon, [(float(i), 1.0 + step) for i in range(6)], False, 0.01,
                               0.0)
        add_shapes(space, first)
        obs.reclassify(moon)
        _indexed_like_the_space(obs, space, [moon, other])
    # a shape moved to another body while out of the space, then added back
    moved = first[0]
    space.remove(moved)
    moved.body = other
    space.add(moved)
    obs.reclassify(moon)
    obs.reclassify(other)
    _indexed_like_the_space(obs, space, [moon, other])
    # the kind changes in place: kinematic, then dynamic
    moon.body_type = pymunk.Body.KINEMATIC
    obs.reclassify(moon)
    _indexed_like_the_space(obs, space, [moon, other])
    moon.body_type = pymunk.Body.DYNAMIC
    obs.reclassify(moon)
    _indexed_like_the_space(obs, space, [moon, other])


def test_a_replaced_collider_is_not_swept() -> None:
    """pymunk keeps a removed shape on its body: tracking must see only the space's."""
    space = pymunk.Space()
    body = pymunk.Body()
    old = pymunk.Poly.create_box(body, (4.0, 4.0))
    old.density = 1.0
    space.add(body, old)
    ccd = ContinuousCollision(space)
    ccd.track(body)
    space.remove(old)
    new = pymunk.Circle(body, 0.1)
    new.density = 1.0
    space.add(new)
    assert old in body.shapes  # what pymunk does
    ccd.track(body)
    info = ccd._tracked[body.id]
    assert info.shapes == (new,)
    assert [part.shape for part in info.parts] == [new]
    assert info.core == pytest.approx(0.1)


def test_nearby_rows_that_left_the_space_are_skipped_until_the_table_is_empty() -> None:
    """Rows found by nearby() whose shapes then leave the space: every later question
    skips them, also once dropping the last of them has emptied the table."""
    space = pymunk.Space()
    ground = pymunk.Body(body_type=pymunk.Body.STATIC)
    space.add(ground)
    segments = chain_segments(ground, [(float(i), 0.0) for i in range(4)], False, 0.01, 0.0)
    add_shapes(space, segments)
    obs = _refreshed(space)
    near = obs.nearby(np.array([1.5]), np.array([0.0]), np.array([5.0]))[0]
    assert len(near.rows) == 3
    space.remove(*segments)
    assert obs.candidates(pymunk.BB(2.5, -0.1, 2.6, 0.1), 0.0, 0.0, near) == []  # drops one
    assert obs.live == 2
    assert obs.candidates(pymunk.BB(0.0, -0.1, 3.0, 0.1), 0.1, 0.1, near) == []  # the rest
    assert obs.live == 0 and obs.shapes == []
    assert obs.candidates(pymunk.BB(0.0, -0.1, 3.0, 0.1), 0.1, 0.1, near) == []
