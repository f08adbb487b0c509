"""The bulk chain path (kge.physics.cp.static_bulk) makes shapes pymunk treats as its own."""

from __future__ import annotations

import gc
import math
import pickle
import weakref
from typing import Any

import numpy as np
import pymunk
import pytest

from kge.physics.ccd.obstacles import Obstacles
from kge.physics.cp.static_bulk import (
    add_shapes,
    chain_ends,
    chain_segments,
    reinit_segments,
    remove_shapes,
)

LOOP = [(0.0, 0.0), (4.0, 0.0), (4.0, 1.0), (2.0, 1.0), (2.0, 3.0), (0.0, 3.0)]


def _space() -> tuple[pymunk.Space, pymunk.Body]:
    space = pymunk.Space()
    body = pymunk.Body(body_type=pymunk.Body.STATIC)
    space.add(body)
    return space, body


def test_segments_match_pymunks_own() -> None:
    space, body = _space()
    pf = pymunk.ShapeFilter(categories=2, mask=5)
    segs = chain_segments(body, LOOP, True, 0.01, 0.5, pf, False)
    assert len(segs) == len(LOOP)
    for i, s in enumerate(segs):
        ref = pymunk.Segment(None, LOOP[i], LOOP[(i + 1) % len(LOOP)], 0.01)
        assert type(s) is pymunk.Segment
        assert (s.a, s.b, s.radius) == (ref.a, ref.b, ref.radius)
        assert s.friction == 0.5 and s.filter == pf and not s.sensor
        assert s.body is body and s.space is None
        assert not any(k.startswith("kge_") for k in vars(s))  # kge's data is in its table
    assert set(body.shapes) == set(segs)
    twin = pickle.loads(pickle.dumps(segs[2]))  # pymunk's own pickling works on them
    assert (twin.a, twin.b, twin.friction, twin.filter) == (segs[2].a, segs[2].b, 0.5, pf)
    add_shapes(space, segs)
    assert all(s.space is space for s in segs)
    # queries find the segment object itself (the user-data handle is set)
    hit = space.point_query_nearest((3.0, 0.05), 0.2, pymunk.ShapeFilter())
    assert hit is not None and hit.shape is segs[0]
    ray = space.segment_query_first((1.0, 2.0), (3.0, 2.0), 0.0, pymunk.ShapeFilter())
    assert ray is not None and ray.shape is segs[3]  # the (2,1)-(2,3) wall


def _slide(bulk: bool) -> list[tuple[float, float, float]]:
    """A box pushed along a 60-segment open floor: its (x, y, vy) every step."""
    space, body = _space()
    floor = [(-30.0 + i, 0.0) for i in range(61)]
    if bulk:
        add_shapes(space, chain_segments(body, floor, False, 0.01, 0.0))
    else:  # pymunk's documented way, neighbours as kge set them before the bulk path
        n = len(floor)
        for i in range(n - 1):
            s = pymunk.Segment(body, floor[i], floor[i + 1], 0.01)
            s.set_neighbors(floor[i - 1] if i > 0 else floor[i], floor[min(i + 2, n - 1)])
            space.add(s)
    box = pymunk.Body(1.0, pymunk.moment_for_box(1.0, (1.0, 1.0)))
    box.position = (-25.0, 0.51)
    box.velocity = (5.0, 0.0)
    space.add(box, pymunk.Poly.create_box(box, (1.0, 1.0)))
    space.gravity = (0.0, -10.0)
    out = []
    for _ in range(300):
        space.step(1 / 60)
        out.append((box.position.x, box.position.y, box.velocity.y))
    return out


def test_open_chain_neighbours_match_pymunks_set_neighbors() -> None:
    """Same segments, same neighbours: the same trajectory to the last bit."""
    bulk, plain = _slide(True), _slide(False)
    assert bulk == plain and bulk[-1][0] > -20.0  # crossed several chain vertices


def test_many_segments_add_in_bulk_and_are_freed() -> None:
    space, body = _space()
    n = 200
    pts = [(math.cos(2 * math.pi * i / n) * 10, math.sin(2 * math.pi * i / n) * 10) for i in range(n)]
    segs = chain_segments(body, pts, True, 0.0, 0.2)
    add_shapes(space, segs)  # the bulk path (16 or more shapes)
    assert len(space.shapes) == n and all(s.space is space for s in segs)
    assert space.point_query_nearest((10.0, 0.0), 0.1, pymunk.ShapeFilter()) is not None
    refs = [weakref.ref(s) for s in segs]
    space.remove(*segs)
    del segs
    body._shapes.clear()  # (what a body's removal from kge does to its shapes)
    space.step(1 / 60)  # pymunk lets go of removed shapes after a step
    gc.collect()
    assert all(r() is None for r in refs)  # freed through the finaliser
    space.step(1 / 60)


def test_add_shapes_refuses_and_rolls_back() -> None:
    space, body = _space()
    pts = [(float(i), 0.0) for i in range(60)]
    segs = chain_segments(body, pts, False, 0.0, 0.0)
    add_shapes(space, segs[:20])
    with pytest.raises(AssertionError, match="already added"):
        add_shapes(space, segs[20:] + segs[:1])  # 39 fresh ones, then one already in
    assert len(space.shapes) == 20 and all(s.space is None for s in segs[20:])
    other = pymunk.Body(body_type=pymunk.Body.STATIC)  # not in the space
    loose = chain_segments(other, pts, False, 0.0, 0.0)
    with pytest.raises(AssertionError, match="body must be added"):
        add_shapes(space, loose)
    assert len(space.shapes) == 20


def test_obstacle_rows_in_bulk_equal_one_by_one() -> None:
    space, body = _space()
    pts = [(float(i), float(i % 3)) for i in range(40)]
    segs = chain_segments(body, pts, False, 0.05, 0.0)
    add_shapes(space, segs)
    dyn = pymunk.Body(1.0, 1.0)
    ball = pymunk.Circle(dyn, 0.5)
    space.add(dyn, ball)
    bulk, single = Obstacles(space), Obstacles(space)
    bulk._classify_many([*segs, ball])
    for s in segs:
        single._classify(s)
    assert bulk.live == single.live == len(segs) and ball not in bulk.row_of
    for s in segs:
        bb = s.bb
        want = (bb.left, bb.bottom, bb.right, bb.top)
        assert tuple(bulk.box[bulk.row_of[s]]) == want == tuple(single.box[single.row_of[s]])
    assert not np.any(bulk.kinematic[: bulk.live])


def test_obstacle_rows_are_reused_after_removals() -> None:
    space, body = _space()
    first = chain_segments(body, [(float(i), 0.0) for i in range(41)], False, 0.0, 0.0)
    add_shapes(space, first)
    obs = Obstacles(space)
    obs._classify_many(first)
    space.remove(*first[:10])
    obs._classify_many(first[:10])  # out of the space: their rows are freed
    assert obs.live == 30 and len(obs._free) == 10
    more = chain_segments(body, [(float(i), 5.0) for i in range(21)], False, 0.0, 0.0)
    add_shapes(space, more)
    obs._classify_many(more)  # 10 rows reused, 10 appended
    assert obs.live == 50 and not obs._free and len(obs.shapes) == 50
    for s in [*first[10:], *more]:
        row = obs.row_of[s]
        assert obs.shapes[row] is s
        bb = s.bb
        assert tuple(obs.box[row]) == (bb.left, bb.bottom, bb.right, bb.top)
    assert sorted(obs._owner_rows[body.id]) == sorted(obs.row_of.values())


def _read(space: pymunk.Space) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    bodies = list(space.bodies)
    ids = np.array([b.id for b in bodies], np.int64)
    pose = np.array([(b.position.x, b.position.y, b.angle) for b in bodies], float)
    return ids, pose, np.zeros((len(bodies), 3))


def test_a_new_static_owner_does_not_reread_every_other_box() -> None:
    """Adding one static collider next to a big static index re-reads only its own boxes."""
    space = pymunk.Space()
    obs = Obstacles(space)
    for k in range(50):
        body = pymunk.Body(body_type=pymunk.Body.STATIC)
        space.add(body)
        add_shapes(space, chain_segments(body, [(float(i), k * 2.0) for i in range(21)],
                                         False, 0.0, 0.0))
        obs.reclassify(body)
    for order in (0, 0, 0):
        obs.refresh(*_read(space), order)  # settled: every owner seen, nothing moved
    assert obs.live == 50 * 20
    counted: list[int] = []
    bulk = obs._classify_many

    def counting(shapes: Any) -> None:
        shapes = list(shapes)
        counted.append(len(shapes))
        bulk(shapes)

    obs._classify_many = counting  # type: ignore[method-assign]
    body = pymunk.Body(body_type=pymunk.Body.STATIC)
    space.add(body)
    add_shapes(space, chain_segments(body, [(float(i), -5.0) for i in range(21)],
                                     False, 0.0, 0.0))
    obs.reclassify(body)
    obs.refresh(*_read(space), 1)
    obs.refresh(*_read(space), 1)
    assert obs.live == 51 * 20
    assert sum(counted) <= 5 * 20  # the new owner's 20 shapes a few times, not 1,020
    # and a static body that does move still has its boxes re-read
    first = next(iter(space.bodies))
    first.position = (0.0, 100.0)
    space.reindex_shapes_for_body(first)
    counted.clear()
    obs.refresh(*_read(space), 1)
    s = next(iter(first.shapes))
    assert obs.box[obs.row_of[s]][1] >= 99.0 and sum(counted) == 20


def _resting_ball(space: pymunk.Space) -> pymunk.Body:
    ball = pymunk.Body(1.0, 1.0)
    ball.position = (1.0, 0.5)
    space.add(ball, pymunk.Circle(ball, 0.5))
    space.gravity = (0.0, -10.0)
    for _ in range(5):
        space.step(1 / 60)
    return ball


def _removed_with_callbacks(bulk: bool) -> None:
    space, body = _space()
    segs = chain_segments(body, [(0.0, 0.0), (2.0, 0.0), (4.0, 0.0)], False, 0.0, 0.0)
    add_shapes(space, segs)
    ball = _resting_ball(space)
    (circle,) = ball.shapes
    ended: list[object] = []

    def separate(arb: pymunk.Arbiter, _space: pymunk.Space, _data: Any) -> None:
        ended.append(arb.shapes)
        _space.remove(circle)  # a removal asked from the callback: done after

    space.on_collision(separate=separate)
    stray = pymunk.Segment(body, (0.0, 5.0), (1.0, 5.0), 0.0)  # never added: skipped
    if bulk:
        remove_shapes(space, [*segs, stray])
    else:
        space.remove(*segs)
    assert ended and all(seg.space is None for seg in segs)
    assert set(space.shapes) == set() and circle.space is None
    add_shapes(space, segs)  # and they can go back in
    assert [s.space for s in segs] == [space] * 2


@pytest.mark.parametrize("bulk", [True, False], ids=["remove_shapes", "space.remove"])
def test_remove_shapes_is_space_remove(bulk: bool) -> None:
    """Same callbacks, bookkeeping and deferred removals as pymunk's own remove."""
    _removed_with_callbacks(bulk)


def test_remove_shapes_in_a_locked_space_waits_for_the_step_end() -> None:
    space, body = _space()
    segs = chain_segments(body, [(0.0, 0.0), (2.0, 0.0), (4.0, 0.0)], False, 0.0, 0.0)
    add_shapes(space, segs)
    _resting_ball(space)
    during: list[bool] = []

    def post_solve(arb: pymunk.Arbiter, _space: pymunk.Space, _data: Any) -> None:
        remove_shapes(_space, segs)
        during.append(segs[0].space is _space)

    space.on_collision(post_solve=post_solve)
    space.step(1 / 60)
    assert during and all(during)
    assert all(s.space is None for s in segs)


def test_reinit_segments_makes_new_segments_in_place() -> None:
    space, body = _space()
    old = [(0.0, 0.0), (2.0, 1.0), (4.0, 0.0), (6.0, 1.0)]
    new = [(0.0, -1.0), (3.0, 2.0), (5.0, 2.0), (8.0, -1.0)]
    pf = pymunk.ShapeFilter(categories=2, mask=5)
    segs = chain_segments(body, old, False, 0.01, 0.5, None, False)
    add_shapes(space, segs)
    with pytest.raises(ValueError, match="in a space"):
        reinit_segments(segs, body, chain_ends(new, False), 0.01, 0.5)
    assert [(s.a, s.b) for s in segs] == [(old[i], old[i + 1]) for i in range(3)]
    space.remove(*segs)
    with pytest.raises(ValueError, match="pairs of ends"):
        reinit_segments(segs[:2], body, chain_ends(new, False), 0.01, 0.5)
    reinit_segments(segs, body, chain_ends(new, False), 0.02, 0.3, pf, True)
    fresh = chain_segments(body, new, False, 0.02, 0.3, pf, True)
    for s, f in zip(segs, fresh, strict=True):
        assert (s.a, s.b, s.normal, s.radius, s.friction, s.filter, s.sensor) == (
            f.a, f.b, f.normal, f.radius, f.friction, f.filter, f.sensor)
    add_shapes(space, segs)
    hit = space.point_query_nearest((4.0, 2.0), 0.1, pymunk.ShapeFilter(categories=5))
    assert hit is not None and hit.shape is segs[1]  # the user-data handle is set again
