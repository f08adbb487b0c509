"""Outlines of solid tile regions as few closed loops, all in numpy.

Why: one box per tile makes a floor of 50 tiles into 50 colliders, and a box
sliding across it catches on the seams between them (the "ghost collision"
Box2D's chain shapes exist to avoid). Tracing the boundary of every connected
solid region instead gives one closed chain per outline, with a vertex only
where the outline turns: a flat floor of any length is one segment, and the
chain's neighbour information makes the joins smooth.

The trace works on grid corners (column, row), row 0 at the top as in Tiled.
Every cell edge between a solid and an empty cell is a directed boundary edge
with the solid cell on its right (on screen, y down), so each outline is a
permutation cycle of edges. Where two solid cells touch only at a corner the
walk turns right, keeping them separate outlines. Cycles are found and ordered
with pointer jumping (log2(edges) numpy passes), never a Python walk per edge.

>>> solid = np.array([[1, 1, 1],
...                   [1, 0, 1],
...                   [1, 1, 1]], bool)
>>> [loop.tolist() for loop in trace_loops(solid)]
[[[0, 0], [3, 0], [3, 3], [0, 3]], [[2, 1], [1, 1], [1, 2], [2, 2]]]
"""

from __future__ import annotations

import numpy as np

# directions, clockwise on screen (y down): east, south, west, north
_DX = np.array([1, 0, -1, 0], np.int64)
_DY = np.array([0, 1, 0, -1], np.int64)


def trace_loops(solid: np.ndarray) -> list[np.ndarray]:
    """Closed outlines of the True cells of ``solid`` as (k, 2) int arrays of (col, row) corners.

    Only corners where the outline turns are listed. Outer outlines run one way
    and the outlines of holes the other; loops come sorted by their first edge.
    """
    rows, cols = solid.shape
    if rows == 0 or cols == 0 or not solid.any():
        return []
    pad = np.zeros((rows + 2, cols + 2), bool)
    pad[1:-1, 1:-1] = solid
    # horizontal edges: between padded rows r-1 and r, at corner row r-1 (unpadded)
    up, down = pad[:-1, 1:-1], pad[1:, 1:-1]
    hr, hc = np.nonzero(up != down)  # corner row hr, column hc..hc+1
    h_east = down[hr, hc]  # solid below: walk east
    # vertical edges: between padded columns c-1 and c, at corner column c-1
    left, right = pad[1:-1, :-1], pad[1:-1, 1:]
    vr, vc = np.nonzero(left != right)
    v_south = left[vr, vc]  # solid on the left (west): walk south
    # start corner and direction of every edge
    sx = np.concatenate([np.where(h_east, hc, hc + 1), vc])
    sy = np.concatenate([hr, np.where(v_south, vr, vr + 1)])
    d = np.concatenate([np.where(h_east, 0, 2), np.where(v_south, 1, 3)]).astype(np.int64)
    n = len(d)
    width = cols + 1
    start = sy * width + sx
    end = (sy + _DY[d]) * width + (sx + _DX[d])
    # outgoing edge by (corner, direction)
    out = np.full((rows + 1) * width * 4, -1, np.int64)
    out[start * 4 + d] = np.arange(n)
    right_turn = out[end * 4 + (d + 1) % 4]
    straight = out[end * 4 + d]
    left_turn = out[end * 4 + (d + 3) % 4]
    nxt = np.where(right_turn >= 0, right_turn, np.where(straight >= 0, straight, left_turn))
    # label each cycle by its smallest edge id (pointer jumping)
    label = np.arange(n)
    jump = nxt.copy()
    span = 1
    while span < n:
        label = np.minimum(label, label[jump])
        jump = jump[jump]
        span *= 2
    # order inside each cycle: distance to the cycle's last edge (list ranking)
    is_first = label == np.arange(n)
    last = is_first[nxt]  # the next edge starts the cycle again
    succ = np.where(last, np.arange(n), nxt)
    dist = (~last).astype(np.int64)
    span = 1
    while span < n:
        dist = dist + dist[succ]
        succ = succ[succ]
        span *= 2
    order = np.lexsort((-dist, label))
    # keep edges whose direction differs from the previous edge's: their start is a corner
    prev = np.empty(n, np.int64)
    prev[nxt] = np.arange(n)
    corner = d != d[prev]
    order = order[corner[order]]
    lab = label[order]
    cuts = np.flatnonzero(np.diff(lab)) + 1
    xy = np.stack([sx[order], sy[order]], axis=1)
    return list(np.split(xy, cuts))
