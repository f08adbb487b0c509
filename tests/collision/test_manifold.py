"""Contact manifolds against b2Collide* and b2WorldManifold."""

from __future__ import annotations

import math
from collections import Counter

import pytest

from kge.collision import collide, point_states
from kge.collision.geometry import convex
from kge.collision.pose import pose
from kge.components.shapes import Box, Chain, Circle, Edge, Polygon
from tests.collision.reference import NORMAL_TOL, close, data, shapes

#: local and world points agree to 0.1 mm (float32 clipping of metre-sized shapes)
POINT_TOL = 1e-4


def _expected_separations(c: dict, a_radius: float, b_radius: float) -> list[float]:
    """Box2D's b2WorldManifold separations from the *measured* local form.

    pybox2d does not expose ``separations``; Box2D defines them from the local
    form as below, so the measured local form gives the expected values.
    """
    xa, xb = pose(c["pose_a"]), pose(c["pose_b"])
    if c["type"] == "circles":
        pa, pb = xa.apply(tuple(c["local_point"])), xb.apply(tuple(c["points"][0]["local_point"]))
        return [math.dist(pa, pb) - a_radius - b_radius]
    ref, inc, r_ref, r_inc = (xa, xb, a_radius, b_radius) if c["type"] == "face_a" else (
        xb, xa, b_radius, a_radius)
    n = ref.rotate(tuple(c["local_normal"]))
    plane = ref.apply(tuple(c["local_point"]))
    out = []
    for p in c["points"]:
        q = inc.apply(tuple(p["local_point"]))
        out.append((q[0] - plane[0]) * n[0] + (q[1] - plane[1]) * n[1] - r_ref - r_inc)
    return out


def _radius(s: object) -> float:
    return s.radius if isinstance(s, Circle) else 0.01


def test_manifolds_match_box2d() -> None:
    seen: Counter[tuple[str, int]] = Counter()
    for c in data()["manifold"]:
        a, b = shapes()[c["a"]], shapes()[c["b"]]
        m = collide(a, c["pose_a"], b, c["pose_b"], child_a=c["child_a"], child_b=c["child_b"])
        assert m.point_count == c["point_count"], c
        seen[(type(a).__name__ + "-" + type(b).__name__, m.point_count)] += 1
        if not m:
            continue
        assert m.type == c["type"], c
        if m.type != "circles":
            assert close(m.local_normal, c["local_normal"], NORMAL_TOL), c
        assert close(m.local_point, c["local_point"], POINT_TOL), c
        for got, want in zip(m.local_points, c["points"], strict=True):
            assert close(got.local_point, want["local_point"], POINT_TOL), c
            assert got.id.key == want["key"], c
        assert close(m.normal, c["normal"], NORMAL_TOL), c
        for got_p, want_p in zip(m.points, c["world_points"], strict=True):
            assert close(got_p, want_p, POINT_TOL), c
        want_s = _expected_separations(c, _radius(a), _radius(b))
        assert m.separations == pytest.approx(want_s, abs=POINT_TOL)
    # every b2Collide* function is exercised, with 0, 1 and 2 points where possible
    for pair in ("Circle-Circle", "Polygon-Circle", "Box-Box", "Polygon-Polygon", "Edge-Circle",
                 "Edge-Box", "Chain-Circle", "Chain-Polygon"):
        assert seen[(pair, 0)] and seen[(pair, 1)], pair
    for pair in ("Box-Box", "Polygon-Polygon", "Edge-Box", "Chain-Box"):
        assert seen[(pair, 2)], pair


def test_reversed_order_gives_the_same_contact_seen_from_b() -> None:
    """Shapes of different kinds passed B first: the canonical manifold, A and B exchanged.

    (Two polygons are not symmetric in Box2D itself: A's face is preferred unless
    B's separates clearly better, so reversing them is a different question.)
    """
    checked = 0
    for c in data()["manifold"]:
        a, b = shapes()[c["a"]], shapes()[c["b"]]
        if not c["point_count"] or convex(a).kind == convex(b).kind:
            continue
        fwd = collide(a, c["pose_a"], b, c["pose_b"], child_a=c["child_a"], child_b=c["child_b"])
        rev = collide(b, c["pose_b"], a, c["pose_a"], child_a=c["child_b"], child_b=c["child_a"])
        assert rev.normal == pytest.approx((-fwd.normal[0], -fwd.normal[1]), abs=1e-12)
        flat = [x for p in sorted(rev.points) for x in p]
        assert flat == pytest.approx([x for p in sorted(fwd.points) for x in p], abs=1e-12)
        assert sorted(rev.separations) == pytest.approx(sorted(fwd.separations), abs=1e-12)
        assert {p.id.flipped() for p in rev.local_points} == {p.id for p in fwd.local_points}
        checked += 1
    assert checked > 100


def test_box_resting_on_a_box_has_two_points_on_the_face() -> None:
    m = collide(Box(2.0, 0.5), (0.0, 0.0, 0.0), Box(0.5, 0.5), (0.3, 0.99, 0.0))
    assert m.type == "face_a" and m.normal == pytest.approx((0.0, 1.0))
    assert sorted(p[0] for p in m.points) == pytest.approx([-0.2, 0.8])
    # the polygon skins (0.01 m each) overlap by 0.01 m more than the cores do
    assert m.separations == pytest.approx((-0.03, -0.03))


def test_a_ball_rolling_over_a_chain_join_gets_one_contact() -> None:
    chain = Chain([(-2.0, 0.0), (0.0, 0.0), (2.0, 0.0)])
    ball_at = (0.1, 0.45, 0.0)  # just past the shared vertex, penetrating both segments
    contacts = [collide(chain, (0, 0, 0), Circle(0.5), ball_at, child_a=i) for i in (0, 1)]
    assert sum(m.point_count for m in contacts) == 1
    lone = [collide(Edge((-2.0, 0.0), (0.0, 0.0)), (0, 0, 0), Circle(0.5), ball_at),
            collide(Edge((0.0, 0.0), (2.0, 0.0)), (0, 0, 0), Circle(0.5), ball_at)]
    assert sum(m.point_count for m in lone) == 2  # lone edges know no neighbours


def test_a_box_sliding_along_a_chain_does_not_catch_on_the_join() -> None:
    chain = Chain([(-4.0, 0.0), (0.0, 0.0), (4.0, 0.0)])
    box_at = (0.0, 0.49, 0.0)  # straddling the join
    for child in (0, 1):
        m = collide(chain, (0, 0, 0), Box(0.5, 0.5), box_at, child_a=child)
        assert m.normal == pytest.approx((0.0, 1.0), abs=1e-9)


def test_edges_never_collide_with_edges() -> None:
    m = collide(Edge((-1, 0), (1, 0)), (0, 0, 0), Edge((0, -1), (0, 1)), (0, 0, 0))
    assert not m and m.point_count == 0


def test_separated_shapes_have_empty_manifolds() -> None:
    tri = Polygon([(1.0, 0.0), (0.0, 1.0), (-1.0, -1.0)])
    assert not collide(tri, (0, 0, 0), tri, (3.0, 0.0, 0.0))
    assert not collide(tri, (0, 0, 0), Circle(0.5), (0.0, 3.0, 0.0))
    assert collide(tri, (0, 0, 0), Circle(0.5), (0.0, 1.4, 0.0))


def test_point_states_match_box2d_get_point_states() -> None:
    kinds: Counter[str] = Counter()
    for c in data()["point_states"]:
        a, b = shapes()[c["a"]], shapes()[c["b"]]
        m1 = collide(a, c["pose_a"], b, c["pose_b1"], child_a=c["child_a"])
        m2 = collide(a, c["pose_a"], b, c["pose_b2"], child_a=c["child_a"])
        before, after = point_states(m1, m2)
        assert list(before) == c["states1"] and list(after) == c["states2"], c
        kinds.update(before + after)
    assert kinds["persist"] > 50 and kinds["add"] > 10 and kinds["remove"] > 10


def test_point_states_of_a_box_rocking_on_a_box() -> None:
    ground = Box(2.0, 0.5)
    flat = collide(ground, (0, 0, 0), Box(0.5, 0.5), (0.0, 0.99, 0.0))
    tipped = collide(ground, (0, 0, 0), Box(0.5, 0.5), (0.0, 1.1, 0.3))  # one corner down
    assert flat.point_count == 2 and tipped.point_count == 1
    before, after = point_states(flat, tipped)
    assert sorted(before) == ["persist", "remove"] and after == ("persist",)
    assert point_states(flat, flat) == (("persist", "persist"), ("persist", "persist"))
