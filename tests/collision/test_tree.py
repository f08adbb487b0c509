"""The dynamic AABB tree: Box2D's fat boxes, queries and ray casts, and its structure."""

from __future__ import annotations

import random

import pytest

from kge.collision import AABB, aabb, ray_cast
from kge.collision.tree import DynamicTree
from kge.errors import ComponentTypeError, ValidationError
from tests.collision.reference import TOL, close, data, shape


def _world_tree() -> tuple[DynamicTree, list[tuple[object, list[float]]]]:
    tree = DynamicTree()
    placed = []
    for i, f in enumerate(data()["tree"]["fixtures"]):
        s = shape(f["shape"])
        placed.append((s, f["pose"]))
        pid = tree.insert(aabb(s, f["pose"]), i)
        fat = tree.fat_aabb(pid)
        assert close(fat.lower, f["fat_lower"]) and close(fat.upper, f["fat_upper"]), f
    tree.validate()
    return tree, placed


def test_fat_boxes_and_queries_match_box2d_world_query_aabb() -> None:
    tree, _placed = _world_tree()
    nonempty = 0
    for q in data()["tree"]["queries"]:
        hits = sorted(tree.user_data(p) for p in tree.query((q["lower"], q["upper"])))
        assert hits == q["hits"], q
        nonempty += bool(hits)
    assert nonempty > 10


def _cast(tree: DynamicTree, placed: list, p1: list, p2: list, closest: bool) -> list:
    """b2World::RayCast on the tree: exact hits through the tree's callback protocol."""
    hits = []

    def callback(a, b, max_fraction, proxy):
        i = tree.user_data(proxy)
        s, at = placed[i]
        hit = ray_cast(s, at, a, b, max_fraction=max_fraction)
        if hit is None:
            return max_fraction  # Box2D's wrapper: no hit leaves the ray as it is
        hits.append((i, hit))
        return hit.fraction if closest else 1.0

    tree.ray_cast(p1, p2, callback)
    return hits


def test_ray_casts_match_box2d_world_ray_cast() -> None:
    tree, placed = _world_tree()
    some = 0
    for r in data()["tree"]["rays"]:
        got = _cast(tree, placed, r["p1"], r["p2"], closest=True)
        if r["closest"] is None:
            assert not got
        else:
            i, hit = got[-1]  # clipping makes the last reported hit the closest
            assert i == r["closest"]["fixture"]
            assert hit.fraction == pytest.approx(r["closest"]["fraction"], abs=TOL)
            assert close(hit.point, r["closest"]["point"], 1e-4)
            some += 1
        every = sorted(i for i, _ in _cast(tree, placed, r["p1"], r["p2"], closest=False))
        assert every == [h["fixture"] for h in r["all"]]
    assert some > 10


def test_moves_predict_displacement_like_box2d() -> None:
    reinserted = kept = 0
    for m in data()["tree"]["motions"]:
        s = shape(m["shape"])
        tree = DynamicTree()
        pid = tree.insert(aabb(s, m["start_pose"]))
        fat = tree.fat_aabb(pid)
        assert close(fat.lower, m["start_fat_lower"]) and close(fat.upper, m["start_fat_upper"])
        for st in m["steps"]:
            # b2Fixture::Synchronize: the box swept over the step, moved by the step's motion
            swept = aabb(s, st["pose_before"]).union(aabb(s, st["pose_after"]))
            shift = (st["pose_after"][0] - st["pose_before"][0],
                     st["pose_after"][1] - st["pose_before"][1])
            if tree.move(pid, swept, shift):
                reinserted += 1
            else:
                kept += 1
            fat = tree.fat_aabb(pid)
            assert close(fat.lower, st["fat_lower"], 1e-4), st
            assert close(fat.upper, st["fat_upper"], 1e-4), st
    assert reinserted > 10 and kept > 10


def test_random_churn_keeps_the_tree_valid_and_queries_exact() -> None:
    rng = random.Random(7)
    tree = DynamicTree()
    boxes: dict[int, tuple[tuple[float, float], tuple[float, float]]] = {}
    for step in range(3000):
        roll = rng.random()
        if roll < 0.5 or not boxes:
            x, y = rng.uniform(0, 50), rng.uniform(0, 50)
            box = ((x, y), (x + rng.uniform(0.1, 2), y + rng.uniform(0.1, 2)))
            boxes[tree.insert(box, step)] = box
        elif roll < 0.8:
            pid = rng.choice(list(boxes))
            dx, dy = rng.uniform(-1, 1), rng.uniform(-1, 1)
            (lx, ly), (ux, uy) = boxes[pid]
            boxes[pid] = ((lx + dx, ly + dy), (ux + dx, uy + dy))
            tree.move(pid, boxes[pid], (dx, dy))
        else:
            pid = rng.choice(list(boxes))
            tree.remove(pid)
            del boxes[pid]
    tree.validate()
    assert len(tree) == len(boxes)
    assert tree.max_balance <= 1
    assert tree.height <= 2 * max(1, len(boxes)).bit_length()  # AVL: O(log n)
    for _ in range(100):
        x, y = rng.uniform(0, 50), rng.uniform(0, 50)
        q = ((x, y), (x + 3, y + 3))
        got = set(tree.query(q))
        # every proxy whose real box overlaps is found; the rest overlap its fat box
        exact = {p for p, ((lx, ly), (ux, uy)) in boxes.items()
                 if not (lx > x + 3 or ly > y + 3 or ux < x or uy < y)}
        assert exact <= got
        assert all(tree.fat_aabb(p).overlaps(AABB(*q)) for p in got)


def test_query_callback_can_stop_early_and_ray_callback_protocol() -> None:
    tree = DynamicTree()
    ids = [tree.insert(((float(i), 0.0), (i + 0.5, 1.0)), i) for i in range(10)]
    seen: list[int] = []

    def three(proxy: int) -> bool:
        seen.append(proxy)
        return len(seen) < 3

    tree.query(((-1.0, -1.0), (20.0, 2.0)), three)
    assert len(seen) == 3
    assert len(tree.query(((-1.0, -1.0), (20.0, 2.0)), lambda p: None)) == 10  # None goes on
    calls: list[int] = []

    def answering(value: float):
        def callback(p1, p2, fraction, proxy):
            calls.append(proxy)
            return value
        return callback

    tree.ray_cast((-1.0, 0.5), (20.0, 0.5), answering(0.0))
    assert len(calls) == 1  # 0: stop
    calls.clear()
    tree.ray_cast((-1.0, 0.5), (20.0, 0.5), answering(-1.0))
    assert sorted(calls) == sorted(ids)  # negative: skip this proxy, keep the ray
    calls.clear()
    # clip at x = 0 (fraction 1/21 of -1..20): boxes further along are culled
    tree.ray_cast((-1.0, 0.5), (20.0, 0.5), answering(1.0 / 21.0))
    assert len(calls) < 10
    assert all(tree.fat_aabb(p).lower[0] <= 0.0 for p in calls[1:])


def test_bad_proxy_ids_and_boxes_are_refused() -> None:
    tree = DynamicTree()
    pid = tree.insert(((0.0, 0.0), (1.0, 1.0)))
    tree.remove(pid)
    with pytest.raises(ValidationError, match="not in this tree"):
        tree.remove(pid)
    with pytest.raises(ComponentTypeError, match="proxy id must be an int"):
        tree.fat_aabb("0")
    with pytest.raises(ValidationError, match="must not exceed"):
        tree.insert(((1.0, 0.0), (0.0, 1.0)))
    with pytest.raises(ValidationError, match="finite"):
        tree.insert(((float("nan"), 0.0), (1.0, 1.0)))
    with pytest.raises(ValidationError, match="zero-length"):
        tree.ray_cast((0.0, 0.0), (0.0, 0.0), lambda *a: 1.0)
    assert len(tree) == 0


def test_pairs_are_the_overlapping_fat_boxes() -> None:
    rng = random.Random(11)
    tree = DynamicTree()
    leaves = []
    for i in range(300):
        x, y = rng.uniform(0, 30), rng.uniform(0, 30)
        leaves.append(tree.insert(((x, y), (x + rng.uniform(0.2, 2), y + rng.uniform(0.2, 2))), i))
    leaves.sort()
    brute = sorted((a, b) for i, a in enumerate(leaves) for b in leaves[i + 1:]
                   if tree.fat_aabb(a).overlaps(tree.fat_aabb(b)))
    assert tree.pairs() == brute and len(brute) > 50
    movers = leaves[:10]
    assert tree.pairs(movers) == [p for p in brute if p[0] in movers or p[1] in movers]
