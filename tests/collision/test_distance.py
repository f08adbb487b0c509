"""GJK distance and closest points against b2Distance."""

from __future__ import annotations

import pytest

from kge.collision import SimplexCache, distance, overlap
from kge.collision.distance import gjk
from kge.collision.geometry import convex
from kge.collision.pose import pose
from kge.components.shapes import Box, Circle, Edge, Polygon
from tests.collision.reference import TOL, close, data, shapes

#: closest points of a face-face configuration are not unique: Box2D and kge may pick
#: different points of the same face pair. The distance is unique; points agree here.
POINT_TOL = 1e-4


def test_distance_matches_box2d() -> None:
    cases = data()["distance"]
    exact_iterations = 0
    touching = 0
    for c in cases:
        out = distance(shapes()[c["a"]], c["pose_a"], shapes()[c["b"]], c["pose_b"],
                       child_a=c["child_a"], child_b=c["child_b"], use_radii=c["use_radii"])
        assert out.distance == pytest.approx(c["distance"], abs=TOL), c
        assert close(out.point_a, c["point_a"], POINT_TOL), c
        assert close(out.point_b, c["point_b"], POINT_TOL), c
        assert abs(out.iterations - c["iterations"]) <= 1, c
        exact_iterations += out.iterations == c["iterations"]
        touching += out.distance == 0.0
    assert exact_iterations >= 0.97 * len(cases)  # float32 vs float64 may differ by one step
    assert 10 < touching < len(cases) - 100  # overlapping and separated pairs both tested


def test_radii_are_subtracted_including_the_polygon_skin() -> None:
    box, ball = Box(0.5, 0.5), Circle(0.25)
    with_radii = distance(box, (0, 0, 0), ball, (2.0, 0.0, 0.0))
    core = distance(box, (0, 0, 0), ball, (2.0, 0.0, 0.0), use_radii=False)
    assert core.distance == pytest.approx(1.5)
    assert with_radii.distance == pytest.approx(1.5 - 0.25 - 0.01)
    assert with_radii.point_a == pytest.approx((0.51, 0.0))
    assert with_radii.point_b == pytest.approx((1.75, 0.0))


def test_distance_is_symmetric_and_pose_aware() -> None:
    tri = Polygon([(1.0, 0.0), (0.0, 1.0), (-1.0, -1.0)])
    edge = Edge((-1.0, 0.0), (1.0, 0.0))
    ab = distance(tri, (0.0, 0.0, 0.3), edge, (0.5, 3.0, 1.0))
    ba = distance(edge, (0.5, 3.0, 1.0), tri, (0.0, 0.0, 0.3))
    assert ab.distance == pytest.approx(ba.distance)
    assert ab.point_a == pytest.approx(ba.point_b) and ab.point_b == pytest.approx(ba.point_a)


def test_a_warm_cache_converges_at_once() -> None:
    a, b = convex(Polygon([(1.0, 0.0), (0.0, 1.0), (-1.0, -1.0)])), convex(Box(0.5, 0.5))
    cache = SimplexCache()
    _pa, _pb, cold = gjk(a, pose((0, 0, 0)), b, pose((3.0, 0.5, 0.2)), cache)
    _pa, _pb, warm = gjk(a, pose((0, 0, 0)), b, pose((3.01, 0.5, 0.2)), cache)
    assert cold >= 2 and warm <= 1


def test_overlap_matches_box2d_test_overlap() -> None:
    cases = data()["overlap"]
    for c in cases:
        got = overlap(shapes()[c["a"]], c["pose_a"], shapes()[c["b"]], c["pose_b"],
                      child_a=c["child_a"], child_b=c["child_b"])
        assert got == c["overlap"], c
    assert 30 < sum(c["overlap"] for c in cases) < len(cases) - 30


def test_overlap_counts_the_skin() -> None:
    box = Box(0.5, 0.5)
    assert overlap(box, (0, 0, 0), box, (1.015, 0.0, 0.0))  # cores 1.5 cm apart, skins touch
    assert not overlap(box, (0, 0, 0), box, (1.03, 0.0, 0.0))
    assert overlap(Circle(1.0), (0, 0, 0), Edge((-1, 1), (1, 1)), (0, 0, 0))
