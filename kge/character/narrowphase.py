"""Signed distance and time of impact of many pairs of rounded convex shapes, in numpy.

Every shape here is a *core* polygon (1 vertex for a circle, 2 for a capsule or an
edge, 3 to 16 for a box or polygon) grown by a radius: a circle's or capsule's
radius, the 0.01 m skin Box2D gives polygons and edges. A batch of ``P`` pairs is a
``(P, na, 2)`` array of A's core vertices, a ``(P, nb, 2)`` array of B's and the two
radii; shorter vertex lists are padded by repeating their last vertex, which adds
zero-length sides only (they never change a distance and are skipped as axes).

:func:`signed_distance` gives, for every pair at once, the distance between the two
rounded shapes (negative: how deep they overlap) and the unit normal that pushes A
out of B:

* cores apart: the closest pair among every vertex of one against every side of the
  other (for convex polygons the closest points are always such a pair);
* cores overlapping: the separating-axis test over every side normal of both, whose
  largest separation is minus the penetration depth, along that side's normal.

:func:`time_of_impact` moves A along a translation and finds, for every pair, the
first fraction at which the rounded shapes come within ``target`` of each other. The
distance between two convex shapes, one translating, is a convex function of time,
so Newton's step ``t += f(t) / -f'(t)`` (``f'`` is the normal times the translation)
never overshoots: every iterate is a time at which the shapes are still apart. It
stops within ``tolerance`` of ``target`` (typically in two to four iterations), and a
pair that runs out of iterations reports the safe time it reached.

>>> import numpy as np
>>> a = np.array([[[0.0, -0.5], [0.0, 0.5]]])        # a capsule's core segment
>>> b = np.array([[[-5.0, -1.0], [5.0, -1.0]]])      # a floor edge, 0.5 m below it
>>> sd, n, _ = signed_distance(a, np.array([0.3]), b, np.array([0.0]))
>>> round(float(sd[0]), 6), n[0].tolist()
(0.2, [0.0, 1.0])
>>> t, hit, _, _ = time_of_impact(a, np.array([0.3]), b, np.array([0.0]),
...                               np.array([[0.0, -1.0]]), np.array([0.0]))
>>> round(float(t[0]), 4), bool(hit[0])
(0.2, True)
"""

from __future__ import annotations

import numpy as np

#: sides shorter than this are padding (or degenerate) and are not separating axes
_SIDE = 1e-12
#: below this, two closest points coincide and the normal comes from the axes
_TOUCH = 1e-12


def _sides(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, ...]:
    """Each vertex's side to the next (cyclic), vertices along axis 0: (ex, ey, length
    squared, outward unit normal nx, ny, valid). Outward for counter-clockwise
    polygons; a two-vertex core (segment) has its two opposite normals, a one-vertex
    core none."""
    ex = np.concatenate((x[1:], x[:1])) - x  # (np.roll, without its generic overhead)
    ey = np.concatenate((y[1:], y[:1])) - y
    ll = ex * ex + ey * ey
    valid = ll > _SIDE * _SIDE
    inv = 1.0 / np.sqrt(np.where(valid, ll, 1.0))
    return ex, ey, np.where(valid, ll, 1.0), ey * inv, -ex * inv, valid


def _best(values: np.ndarray, larger: bool) -> tuple[np.ndarray, np.ndarray]:
    """(extreme, index) along axis 0 of a (k, P) array, with one elementwise pass per
    row (numpy's reductions along a short axis are slow)."""
    m = values[0].copy()
    at = np.zeros(values.shape[1], np.intp)
    for k in range(1, len(values)):
        better = values[k] > m if larger else values[k] < m
        np.copyto(m, values[k], where=better)
        at[better] = k
    return m, at


def signed_distance(
    a: np.ndarray, ra: np.ndarray, b: np.ndarray, rb: np.ndarray,
    simple: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(distance (P,), normal (P, 2), point on B's rounded surface (P, 2)) for each pair.

    ``normal`` is the unit direction moving A away from B (for touching or overlapping
    pairs, the direction that separates them fastest). ``simple`` may flag the pairs
    whose cores both have at most two vertices (a capsule or circle against an edge, a
    chain's segment or a circle: the common case), which take the closed form of
    :func:`_segments` instead of the general test.
    """
    if simple is None or not simple.any():
        return _convex(a, ra, b, rb)
    if simple.all():
        return _segments(a, ra, b, rb)
    out_d = np.empty(len(a))
    out_n = np.empty((len(a), 2))
    out_q = np.empty((len(a), 2))
    for mask, fn in ((simple, _segments), (~simple, _convex)):
        k = np.flatnonzero(mask)
        out_d[k], out_n[k], out_q[k] = fn(a[k], ra[k], b[k], rb[k])
    return out_d, out_n, out_q


def _segments(
    a: np.ndarray, ra: np.ndarray, b: np.ndarray, rb: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:func:`signed_distance` of cores of one or two vertices (segments or points):
    the closest points of two segments in closed form (Ericson, *Real-Time Collision
    Detection* 5.1.9). Crossing segments, whose depth needs the axes, go to the
    general test."""
    p0x, p0y, p1x, p1y = a[:, 0, 0], a[:, 0, 1], a[:, 1 % a.shape[1], 0], a[:, 1 % a.shape[1], 1]
    q0x, q0y, q1x, q1y = b[:, 0, 0], b[:, 0, 1], b[:, 1 % b.shape[1], 0], b[:, 1 % b.shape[1], 1]
    d1x, d1y = p1x - p0x, p1y - p0y
    d2x, d2y = q1x - q0x, q1y - q0y
    rx, ry = p0x - q0x, p0y - q0y
    aa = d1x * d1x + d1y * d1y
    ee = d2x * d2x + d2y * d2y
    ff = d2x * rx + d2y * ry
    cc = d1x * rx + d1y * ry
    bb = d1x * d2x + d1y * d2y
    a_ok = aa > _SIDE * _SIDE
    e_ok = ee > _SIDE * _SIDE
    safe_a = np.where(a_ok, aa, 1.0)
    safe_e = np.where(e_ok, ee, 1.0)
    denom = aa * ee - bb * bb
    s = np.where(denom > 1e-18 * np.maximum(aa * ee, 1e-300),
                 (bb * ff - cc * ee) / np.where(denom != 0.0, denom, 1.0), 0.0)
    np.clip(s, 0.0, 1.0, out=s)
    s = np.where(a_ok, np.where(e_ok, s, np.clip(-cc / safe_a, 0.0, 1.0)), 0.0)
    t = np.where(e_ok, (bb * s + ff) / safe_e, 0.0)
    low, high = t < 0.0, t > 1.0
    t = np.clip(t, 0.0, 1.0)
    s = np.where(a_ok & low, np.clip(-cc / safe_a, 0.0, 1.0), s)
    s = np.where(a_ok & high, np.clip((bb - cc) / safe_a, 0.0, 1.0), s)
    c1x, c1y = p0x + d1x * s, p0y + d1y * s
    c2x, c2y = q0x + d2x * t, q0y + d2y * t
    dx, dy = c1x - c2x, c1y - c2y
    gap = np.sqrt(dx * dx + dy * dy)
    apart = gap > _TOUCH
    inv = 1.0 / np.where(apart, gap, 1.0)
    normal = np.empty((len(a), 2))
    normal[:, 0] = dx * inv
    normal[:, 1] = dy * inv
    surface = np.empty((len(a), 2))
    surface[:, 0] = c2x + normal[:, 0] * rb
    surface[:, 1] = c2y + normal[:, 1] * rb
    sd = gap - ra - rb
    if not apart.all():  # touching or crossing cores: the axes decide
        k = np.flatnonzero(~apart)
        sd[k], normal[k], surface[k] = _convex(a[k], ra[k], b[k], rb[k])
    return sd, normal, surface


def _convex(
    a: np.ndarray, ra: np.ndarray, b: np.ndarray, rb: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:func:`signed_distance` of any convex cores (the general test)."""
    p = len(a)
    if p == 0:
        return np.zeros(0), np.zeros((0, 2)), np.zeros((0, 2))
    na, nb = a.shape[1], b.shape[1]
    # vertices along axis 0, pairs along the last (elementwise work over P at a time)
    ax, ay = np.ascontiguousarray(a[:, :, 0].T), np.ascontiguousarray(a[:, :, 1].T)
    bx, by = np.ascontiguousarray(b[:, :, 0].T), np.ascontiguousarray(b[:, :, 1].T)
    eax, eay, lla, nax, nay, va = _sides(ax, ay)
    ebx, eby, llb, nbx, nby, vb = _sides(bx, by)
    # w[i, j] = A_i - B_j: every vertex pair, shared by all the tests below
    wx = ax[:, None, :] - bx[None, :, :]
    wy = ay[:, None, :] - by[None, :, :]
    # separating axes: B's side normals (A beyond them) and A's (B beyond them)
    proj_b = wx * nbx[None] + wy * nby[None]  # (na, nb, P)
    sep_b = proj_b[0].copy()
    for i in range(1, na):
        np.minimum(sep_b, proj_b[i], out=sep_b)
    sep_b[~vb] = -np.inf
    proj_a = wx * nax[:, None] + wy * nay[:, None]
    sep_a = -proj_a[:, 0]
    for j in range(1, nb):
        np.minimum(sep_a, -proj_a[:, j], out=sep_a)
    sep_a[~va] = -np.inf
    best_b, jb = _best(sep_b, larger=True)
    best_a, ia = _best(sep_a, larger=True)
    cols = np.arange(p)
    use_b = best_b >= best_a
    sep = np.maximum(best_b, best_a)
    axis_x = np.where(use_b, nbx[jb, cols], -nax[ia, cols])
    axis_y = np.where(use_b, nby[jb, cols], -nay[ia, cols])
    # closest features. A's vertex i to B's side j: A_i - (B_j + t e_j) = w - t e_j
    t1 = (wx * ebx[None] + wy * eby[None]) / llb[None]
    np.clip(t1, 0.0, 1.0, out=t1)
    d1x = wx - t1 * ebx[None]
    d1y = wy - t1 * eby[None]
    # B's vertex j to A's side i: (A_i + t e_i) - B_j = w + t e_i
    t2 = -(wx * eax[:, None] + wy * eay[:, None]) / lla[:, None]
    np.clip(t2, 0.0, 1.0, out=t2)
    d2x = wx + t2 * eax[:, None]
    d2y = wy + t2 * eay[:, None]
    dd = np.concatenate(((d1x * d1x + d1y * d1y).reshape(na * nb, p),
                         (d2x * d2x + d2y * d2y).reshape(na * nb, p)))
    gap2, k = _best(dd, larger=False)
    gap = np.sqrt(gap2)
    second = k >= na * nb
    kk = np.where(second, k - na * nb, k)
    i, j = kk // nb, kk % nb
    diff_x = np.where(second, d2x[i, j, cols], d1x[i, j, cols])
    diff_y = np.where(second, d2y[i, j, cols], d1y[i, j, cols])
    # the point on B: A's point minus the difference
    t = np.where(second, t2[i, j, cols], 0.0)
    pbx = ax[i, cols] + t * eax[i, cols] - diff_x
    pby = ay[i, cols] + t * eay[i, cols] - diff_y
    # two points (circles) have no side to test: their gap decides
    deep = np.isfinite(sep) & (sep < 0.0)
    apart = ~deep & (gap > _TOUCH)
    inv = 1.0 / np.where(apart, gap, 1.0)
    normal = np.empty((p, 2))
    normal[:, 0] = np.where(apart, diff_x * inv, axis_x)
    normal[:, 1] = np.where(apart, diff_y * inv, axis_y)
    core = np.where(deep, sep, gap)
    # touching cores with no side normal (a circle's centre on another's): any direction
    none = ~apart & ~np.isfinite(sep)
    if none.any():
        normal[none] = (0.0, 1.0)
    surface = np.empty((p, 2))
    surface[:, 0] = pbx + normal[:, 0] * rb
    surface[:, 1] = pby + normal[:, 1] * rb
    return core - ra - rb, normal, surface


def time_of_impact(
    a: np.ndarray,
    ra: np.ndarray,
    b: np.ndarray,
    rb: np.ndarray,
    delta: np.ndarray,
    target: np.ndarray,
    *,
    tolerance: float = 1e-3,
    iterations: int = 20,
    start: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None,
    simple: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(fraction (P,), hit (P,), normal (P, 2) and point on B (P, 2) at the hit) of A
    moving by ``delta`` (P, 2).

    ``fraction`` is the first time in [0, 1] at which the distance drops to
    ``target`` (within ``tolerance`` above it); 1 with ``hit`` False when it never
    does. A pair already at ``target`` (or closer) is hit at 0 only if the motion
    goes deeper into it; moving along or away from a surface it touches is free, and
    one a little farther than ``target`` may close that gap.
    ``start`` may pass the distances, normals and points at time 0 when already known.
    """
    p = len(a)
    frac = np.ones(p)
    hit = np.zeros(p, dtype=bool)
    normal = np.zeros((p, 2))
    point = np.zeros((p, 2))
    if p == 0:
        return frac, hit, normal, point
    sd, n, q = start if start is not None else signed_distance(a, ra, b, rb, simple)
    f = sd - target
    rate = -np.einsum("pd,pd->p", n, delta)  # how fast the distance shrinks
    reach = np.hypot(delta[:, 0], delta[:, 1])
    inside = f <= 0.0
    blocked = inside & (rate > 1e-9 * np.maximum(reach, 1e-300))
    frac[blocked] = 0.0
    hit[blocked] = True
    normal[blocked] = n[blocked]
    point[blocked] = q[blocked]
    # pairs that could meet this move: apart, approaching, and within reach (a pair
    # already within the tolerance takes one step first: the move may not close it)
    live = ~inside & (rate > 0.0) & (f < reach)
    idx = np.flatnonzero(live)
    t = np.zeros(p)
    t[idx] = f[idx] / rate[idx]
    for _ in range(iterations):
        idx = idx[t[idx] < 1.0]
        if len(idx) == 0:
            break
        moved = a[idx] + (t[idx, None] * delta[idx])[:, None, :]
        sdi, ni, qi = signed_distance(moved, ra[idx], b[idx], rb[idx],
                                      None if simple is None else simple[idx])
        fi = sdi - target[idx]
        ri = -np.einsum("pd,pd->p", ni, delta[idx])
        done = fi <= tolerance
        if done.any():
            k = idx[done]
            frac[k] = t[k]
            hit[k] = True
            normal[k] = ni[done]
            point[k] = qi[done]
        going = ~done & (ri > 0.0)
        idx, fi, ri = idx[going], fi[going], ri[going]
        t[idx] += fi / ri
    # out of iterations: the time reached is still safe (the shapes are apart there)
    left = idx[t[idx] < 1.0] if len(idx) else idx
    if len(left):
        frac[left] = t[left]
        hit[left] = True
        moved = a[left] + (t[left, None] * delta[left])[:, None, :]
        _, normal[left], point[left] = signed_distance(
            moved, ra[left], b[left], rb[left], None if simple is None else simple[left]
        )
    return frac, hit, normal, point
