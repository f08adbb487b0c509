"""Point tests, ray casts, AABBs and mass data against Box2D 2.3 (pybox2d) answers."""

from __future__ import annotations

import math

import pytest

from kge.collision import aabb, mass_data, ray_cast, test_point
from kge.collision.pose import pose
from kge.components.shapes import Box, Chain, Circle, Edge, Polygon
from tests.collision.reference import NORMAL_TOL, TOL, close, data, shapes


def test_test_point_matches_box2d() -> None:
    cases = data()["test_point"]
    inside = 0
    for c in cases:
        got = test_point(shapes()[c["shape"]], c["pose"], c["p"], child=c["child"])
        assert got == c["inside"], c
        inside += got
    assert 10 < inside < len(cases) - 10  # both answers are exercised


def test_ray_cast_matches_box2d() -> None:
    hits = 0
    for c in data()["ray_cast"]:
        s = shapes()[c["shape"]]
        got = ray_cast(s, c["pose"], c["p1"], c["p2"], max_fraction=c["max_fraction"],
                       child=c["child"])
        assert (got is not None) == c["hit"], c
        if got is None:
            continue
        hits += 1
        assert got.fraction == pytest.approx(c["fraction"], abs=TOL)
        p1, p2 = c["p1"], c["p2"]
        expected = (p1[0] + got.fraction * (p2[0] - p1[0]), p1[1] + got.fraction * (p2[1] - p1[1]))
        assert close(got.point, expected)
        normal = got.normal
        if isinstance(s, (Edge, Chain)):
            # Box2D 2.3's b2EdgeShape::RayCast forgets to rotate its normal into the
            # world frame: kge returns the world normal, so compare in the edge's frame
            normal = pose(c["pose"]).unrotate(normal)
        assert close(normal, c["normal"], NORMAL_TOL), c
    assert hits > 50


def test_aabb_matches_box2d() -> None:
    for c in data()["aabb"]:
        box = aabb(shapes()[c["shape"]], c["pose"], child=c["child"])
        assert close(box.lower, c["lower"]) and close(box.upper, c["upper"]), c


def test_mass_data_matches_box2d() -> None:
    for c in data()["mass"]:
        md = mass_data(shapes()[c["shape"]], (0.0, 0.0, 0.0), c["density"])
        # Box2D reports inertia about the body origin, kge about the centre of mass
        about_origin = md.inertia + md.mass * (md.center[0] ** 2 + md.center[1] ** 2)
        assert md.mass == pytest.approx(c["mass"], rel=1e-5, abs=1e-9)
        assert about_origin == pytest.approx(c["inertia_origin"], rel=1e-5, abs=1e-9)
        assert close(md.center, c["center"])


def test_mass_data_moves_the_centre_with_the_pose() -> None:
    md = mass_data(Circle(0.5, (1.0, 0.0)), (2.0, 3.0, math.pi / 2), density=2.0)
    assert md.center == pytest.approx((2.0, 4.0))
    assert md.mass == pytest.approx(2.0 * math.pi * 0.25)


def test_ray_starting_inside_does_not_report_but_edges_are_two_sided() -> None:
    assert ray_cast(Circle(1.0), (0, 0, 0), (0.5, 0.0), (5.0, 0.0)) is None
    assert ray_cast(Polygon([(1, 0), (0, 1), (-1, -1)]), (0, 0, 0), (0, 0), (5, 0)) is None
    edge = Edge((0.0, -1.0), (0.0, 1.0))
    left = ray_cast(edge, (0, 0, 0), (-1.0, 0.0), (1.0, 0.0))
    right = ray_cast(edge, (0, 0, 0), (1.0, 0.0), (-1.0, 0.0))
    assert left is not None and right is not None
    assert left.normal == pytest.approx((-1.0, 0.0)) and right.normal == pytest.approx((1.0, 0.0))


def test_max_fraction_clips_the_ray() -> None:
    box = Box(0.5, 0.5)
    assert ray_cast(box, (0, 0, 0), (-2.0, 0.0), (2.0, 0.0), max_fraction=0.3) is None
    hit = ray_cast(box, (0, 0, 0), (-2.0, 0.0), (2.0, 0.0), max_fraction=0.4)
    assert hit is not None and hit.fraction == pytest.approx(0.375)


def test_a_rotated_pose_rotates_the_answers() -> None:
    box = Box(2.0, 0.5)  # long along its local x
    hit = ray_cast(box, (0.0, 0.0, math.pi / 2), (-3.0, 1.5), (3.0, 1.5))
    assert hit is not None and hit.point == pytest.approx((-0.5, 1.5))
    assert hit.normal == pytest.approx((-1.0, 0.0))
    assert test_point(box, (0.0, 0.0, math.pi / 2), (0.0, 1.9))
    assert not test_point(box, (0.0, 0.0, 0.0), (0.0, 1.9))
    b = aabb(box, (0.0, 0.0, math.pi / 2))
    assert b.lower == pytest.approx((-0.51, -2.01)) and b.upper == pytest.approx((0.51, 2.01))


def test_edges_and_chains_contain_nothing_and_have_no_mass() -> None:
    chain = Chain([(0, 0), (1, 0), (1, 1)], loop=True)
    assert not test_point(chain, (0, 0, 0), (0.8, 0.2))
    assert mass_data(chain, (0, 0, 0), 5.0).mass == 0.0
    assert mass_data(Edge((0, 0), (1, 0))).mass == 0.0
