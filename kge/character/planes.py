"""Box2D v3's plane solver and velocity clip, for many characters at once.

Each contact is a plane: a unit normal ``n`` (pointing away from the surface) and an
offset, meaning "after the move ``d``, ``n . d`` must be at least ``offset``". A
surface the character touches at the separation it keeps gives offset 0 (it may
slide along but not into it); one it overlaps gives a positive offset (it is pushed
out); one a little way off gives a negative offset (it may come that close).

:func:`solve` is ``b2SolvePlanes``: starting from the wanted move, each plane in
turn pushes the move out along its normal by what it lacks, with the push accumulated
per plane and never negative (a plane only pushes, it never pulls back into a
surface). A few Gauss-Seidel passes settle two or three planes (a floor and a wall,
a V-shaped gap). :func:`clip` is ``b2ClipVector``: the velocity loses what points
into each plane that pushed, so speed does not build up against a wall.

>>> import numpy as np
>>> floor, wall = (0.0, 1.0), (-1.0, 0.0)
>>> moves, push = solve(np.array([[1.0, -1.0]]), np.array([floor, wall]),
...                     np.zeros(2), np.array([0, 0]))
>>> moves.tolist(), (push > 0).tolist()
([[0.0, 0.0]], [True, True])
>>> clip(np.array([[3.0, -2.0]]), np.array([floor]), np.array([0])).tolist()
[[3.0, 0.0]]
"""

from __future__ import annotations

import numpy as np

#: Gauss-Seidel passes at most (Box2D's b2SolvePlanes uses 20)
PASSES = 20
#: total push (m) below which the passes stop
TOLERANCE = 1e-7
#: a plane is met when the move is at most this far short of it (m): rounding in the
#: distances never makes a resting character push (and creep) by a few ulps; a plane
#: that does push pushes all the way
SLACK = 1e-12


def ranks(owner: np.ndarray) -> np.ndarray:
    """Each item's position among the items of the same owner, in order (owner sorted
    or not)."""
    n = len(owner)
    if n == 0:
        return np.zeros(0, np.int64)
    order = np.argsort(owner, kind="stable")
    sorted_owner = owner[order]
    first = np.searchsorted(sorted_owner, sorted_owner, "left")
    rank = np.empty(n, np.int64)
    rank[order] = np.arange(n) - first
    return rank


def solve(
    delta: np.ndarray, normal: np.ndarray, offset: np.ndarray, owner: np.ndarray,
    limit: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """(moves (M, 2), push of each plane (Q,)): each row's ``delta`` moved out of its
    planes (``owner[q]`` is the row of plane q). ``limit`` caps how far each plane may
    push in all (Box2D's ``pushLimit``: a soft surface gives way, and two that cannot
    both be met no longer push each other for ever); None: no cap."""
    moves = delta.copy()
    q = len(owner)
    push = np.zeros(q)
    if q == 0:
        return moves, push
    if limit is None:
        limit = np.full(q, np.inf)
    rank = ranks(owner)
    many = np.bincount(owner, minlength=len(delta))[owner] > 1
    one = np.flatnonzero(~many)
    if len(one):  # one plane for the row: the push is exact in one pass
        rows = owner[one]
        sep = np.einsum("qd,qd->q", normal[one], moves[rows]) - offset[one]
        push[one] = np.minimum(np.where(sep < -SLACK, -sep, 0.0), limit[one])
        moves[rows] += push[one, None] * normal[one]
    several = np.flatnonzero(many)
    if len(several) == 0:
        return moves, push
    owners = owner[several]
    rows = np.unique(owners)
    slot = np.searchsorted(rows, owners)
    r = rank[several]
    m, k = len(rows), int(r.max()) + 1
    n_pad = np.zeros((m, k, 2))
    o_pad = np.full((m, k), -np.inf)  # padding never pushes
    cap = np.zeros((m, k))
    n_pad[slot, r] = normal[several]
    o_pad[slot, r] = offset[several]
    cap[slot, r] = limit[several]
    acc = np.zeros((m, k))
    d = moves[rows]
    live = np.arange(m)
    for _ in range(PASSES):
        total = np.zeros(len(live))
        dl = d[live]
        for j in range(k):
            nj = n_pad[live, j]
            sep = nj[:, 0] * dl[:, 0] + nj[:, 1] * dl[:, 1] - o_pad[live, j]
            sep = np.where(np.abs(sep) > SLACK, sep, 0.0)
            before = acc[live, j]
            new = np.clip(before - sep, 0.0, cap[live, j])
            acc[live, j] = new
            step = new - before
            dl += step[:, None] * nj
            total += np.abs(step)
        d[live] = dl
        live = live[total >= TOLERANCE]  # rows whose planes still moved it go round again
        if len(live) == 0:
            break
    moves[rows] = d
    push[several] = acc[slot, r]
    return moves, push


def clip(velocity: np.ndarray, normal: np.ndarray, owner: np.ndarray) -> np.ndarray:
    """``velocity`` (M, 2) with the part into each plane removed, planes in order."""
    v = velocity.copy()
    if len(owner) == 0:
        return v
    rank = ranks(owner)
    for r in range(int(rank.max()) + 1):
        sel = rank == r
        rows, n = owner[sel], normal[sel]
        vn = np.einsum("qd,qd->q", v[rows], n)
        v[rows] -= np.minimum(vn, 0.0)[:, None] * n
    return v
