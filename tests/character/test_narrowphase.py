"""The numpy narrow phase against kge.collision (Box2D's GJK) on random shapes."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kge import collision
from kge.character.narrowphase import signed_distance, time_of_impact
from kge.components.shapes import Box, Circle, Edge, Polygon

RNG = np.random.default_rng(7)


def _random_shape(rng: np.random.Generator):
    kind = rng.integers(4)
    if kind == 0:
        return Circle(float(rng.uniform(0.1, 1.0)))
    if kind == 1:
        return Box(float(rng.uniform(0.1, 1.0)), float(rng.uniform(0.1, 1.0)))
    if kind == 2:
        a = rng.uniform(-1, 1, 2)
        b = a + rng.uniform(0.2, 1.5) * np.array([math.cos(t := rng.uniform(0, 6.3)), math.sin(t)])
        return Edge(tuple(a.tolist()), tuple(b.tolist()))
    n = int(rng.integers(3, 9))
    angles = np.sort(rng.uniform(0, 2 * math.pi, n))
    pts = np.stack([np.cos(angles), np.sin(angles)], 1) * rng.uniform(0.3, 1.0)
    try:
        return Polygon([tuple(p) for p in pts.tolist()])
    except Exception:
        return Box(0.5, 0.3)


def _core(shape, pose):
    """World core vertices and radius as the narrow phase takes them."""
    conv = collision.geometry.convex(shape)
    x, y, a = pose
    c, s = math.cos(a), math.sin(a)
    v = np.array([(x + c * px - s * py, y + s * px + c * py) for px, py in conv.vertices])
    return v, conv.radius


def _batch(pairs):
    na = max(len(p[0]) for p in pairs)
    nb = max(len(p[2]) for p in pairs)

    def pad(v, n):
        return np.concatenate([v, np.repeat(v[-1:], n - len(v), 0)])

    a = np.array([pad(p[0], na) for p in pairs])
    b = np.array([pad(p[2], nb) for p in pairs])
    return a, np.array([p[1] for p in pairs]), b, np.array([p[3] for p in pairs])


def _pairs(n, spread=3.0):
    out = []
    for _ in range(n):
        sa, sb = _random_shape(RNG), _random_shape(RNG)
        pa = (0.0, 0.0, float(RNG.uniform(0, 6.3)))
        pb = (*RNG.uniform(-spread, spread, 2).tolist(), float(RNG.uniform(0, 6.3)))
        out.append((sa, pa, sb, pb))
    return out


def test_separated_distances_match_gjk() -> None:
    cases = _pairs(400)
    cores = [(*_core(sa, pa), *_core(sb, pb)) for sa, pa, sb, pb in cases]
    a, ra, b, rb = _batch(cores)
    sd, n, _ = signed_distance(a, ra, b, rb)
    checked = 0
    for k, (sa, pa, sb, pb) in enumerate(cases):
        out = collision.distance(sa, pa, sb, pb, use_radii=False)
        core = out.distance
        if core > 1e-6:
            checked += 1
            assert sd[k] == pytest.approx(core - ra[k] - rb[k], abs=1e-9)
            d = np.subtract(out.point_a, out.point_b)
            assert n[k] == pytest.approx(d / np.linalg.norm(d), abs=1e-6)
        else:
            assert sd[k] <= -ra[k] - rb[k] + 1e-9
        assert abs(np.linalg.norm(n[k]) - 1.0) < 1e-9
    assert checked > 150


def test_overlap_depth_pushes_exactly_out() -> None:
    """Moving A by the penetration along the normal leaves the cores just touching."""
    cases = _pairs(400, spread=0.8)
    deep = 0
    for sa, pa, sb, pb in cases:
        va, ra = _core(sa, pa)
        vb, rb = _core(sb, pb)
        a, ra_, b, rb_ = _batch([(va, ra, vb, rb)])
        sd, n, _ = signed_distance(a, ra_, b, rb_)
        core = sd[0] + ra + rb
        if core >= -1e-9:
            continue
        deep += 1
        moved = (pa[0] - core * n[0][0], pa[1] - core * n[0][1], pa[2])
        after = collision.distance(sa, moved, sb, pb, use_radii=False).distance
        assert after < 1e-6, (sa, sb, core)
        # and it was the shortest way out: half of it still overlaps
        half = (pa[0] - 0.5 * core * n[0][0], pa[1] - 0.5 * core * n[0][1], pa[2])
        assert collision.distance(sa, half, sb, pb, use_radii=False).distance < 1e-9
    assert deep > 40


def test_time_of_impact_is_safe_and_tight() -> None:
    """The fraction found leaves the shapes apart by target..target+tolerance."""
    cases = _pairs(300)
    cores = [(*_core(sa, pa), *_core(sb, pb)) for sa, pa, sb, pb in cases]
    a, ra, b, rb = _batch(cores)
    sd0 = signed_distance(a, ra, b, rb)[0]
    keep = sd0 > 0.05
    a, ra, b, rb = a[keep], ra[keep], b[keep], rb[keep]
    centre_b = b.mean(axis=1)
    delta = (centre_b - a.mean(axis=1)) * 1.5
    target = np.full(len(a), 0.005)
    frac, hit, _, _ = time_of_impact(a, ra, b, rb, delta, target)
    assert hit.mean() > 0.8
    moved = a + (frac[:, None] * delta)[:, None, :]
    sd = signed_distance(moved, ra, b, rb)[0]
    assert (sd[hit] >= 0.005 - 1e-9).all()
    assert (sd[hit] <= 0.005 + 1e-3 + 1e-9).all()
    # nothing is crossed before the fraction: sample the path
    for s in np.linspace(0.0, 1.0, 50):
        mid = a + ((s * frac)[:, None] * delta)[:, None, :]
        assert (signed_distance(mid, ra, b, rb)[0] >= 0.005 - 1e-9).all()


def test_a_thin_edge_is_never_crossed_at_speed() -> None:
    """A circle moving 10 m in one call across a zero-thickness edge stops before it."""
    a = np.array([[[0.0, 0.0]]])
    b = np.array([[[5.0, -1.0], [5.0, 1.0]]])
    frac, hit, n, point = time_of_impact(a, np.array([0.1]), b, np.array([0.0]),
                                  np.array([[10.0, 0.0]]), np.array([0.005]))
    assert hit[0] and 4.89 <= 10 * frac[0] <= 4.895 + 1e-3
    assert n[0].tolist() == [-1.0, 0.0] and point[0].tolist() == [5.0, 0.0]


def test_moving_along_a_touching_surface_is_free() -> None:
    a = np.array([[[0.0, -0.5], [0.0, 0.5]]])
    b = np.array([[[-5.0, -0.805], [5.0, -0.805]]])  # 5 mm below the capsule
    frac, hit, _, _ = time_of_impact(a, np.array([0.3]), b, np.array([0.0]),
                                  np.array([[1.0, 0.0]]), np.array([0.005]))
    assert not hit[0] and frac[0] == 1.0
    frac, hit, _, _ = time_of_impact(a, np.array([0.3]), b, np.array([0.0]),
                                  np.array([[1.0, -0.1]]), np.array([0.005]))
    assert hit[0] and frac[0] < 1e-9


def test_the_closed_form_for_segments_matches_the_general_test() -> None:
    """Capsules, circles, edges: the segment formula gives the general test's answers."""
    from kge.character.narrowphase import _convex, _segments

    rng = np.random.default_rng(11)
    n = 2000
    a = rng.uniform(-2, 2, (n, 2, 2))
    b = rng.uniform(-2, 2, (n, 2, 2))
    a[: n // 4, 1] = a[: n // 4, 0]  # points (circles)
    b[n // 8: n // 3, 1] = b[n // 8: n // 3, 0]
    b[n // 2: n // 2 + 50] = a[n // 2: n // 2 + 50] + np.array([0.3, 0.0])  # parallel
    ra, rb = rng.uniform(0, 0.5, n), rng.uniform(0, 0.5, n)
    sd1, n1, q1 = _segments(a, ra, b, rb)
    sd2, n2, q2 = _convex(a, ra, b, rb)
    assert np.allclose(sd1, sd2, atol=1e-9)
    apart = sd2 > -ra - rb + 1e-6
    assert np.allclose(n1[apart], n2[apart], atol=1e-6)
    unique = apart.copy()
    unique[n // 2: n // 2 + 50] = False  # parallel segments: many closest points
    assert np.allclose(q1[unique], q2[unique], atol=1e-6)
