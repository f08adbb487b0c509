"""Shadow geometry: every occluder edge extruded away from every light, in one numpy pass.

A light at L is blocked by an edge (a, b) in the quad a, b, b', a' where a' and b'
are a and b pushed away from L far enough to leave the light's radius. The union
of those quads is the light's shadow. For closed outlines (boxes, polygons,
circles) only the edges facing *away* from the light are extruded, so the
occluder itself stays lit and the quad count halves; open edges and chains are
two-sided and always extruded. Edges wholly outside a light's radius are skipped.

For L lights and E edges this is a few (L, E) array operations: no Python loop
over lights or edges.

>>> import numpy as np
>>> edges = np.array([[[1.0, -1.0], [1.0, 1.0]]])          # a wall at x = 1
>>> quads, owner = shadow_quads(np.array([[0.0, 0.0]]), np.array([5.0]), edges,
...                             np.array([False]))
>>> quads.shape, owner.tolist()
((1, 4, 2), [0])
>>> bool(quads[0, 2, 0] > 5.0 and quads[0, 3, 0] > 5.0)      # pushed past the radius
True
"""

from __future__ import annotations

import numpy as np


def shadow_quads(
    lights: np.ndarray, radii: np.ndarray, edges: np.ndarray, closed: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Shadow quads of ``lights`` (L, 2) with ``radii`` (L,) over ``edges`` (E, 2, 2).

    ``closed[e]`` is True for an edge of a counter-clockwise closed outline
    (outward normal on its right). Returns ``(quads, owner)``: (Q, 4, 2) corners
    a, b, b', a' and the index of the light each quad belongs to, sorted by light.
    """
    if len(lights) == 0 or len(edges) == 0:
        return np.zeros((0, 4, 2)), np.zeros(0, np.intp)
    a = edges[:, 0]  # (E, 2)
    b = edges[:, 1]
    la = a[None, :, :] - lights[:, None, :]  # (L, E, 2): light -> a
    lb = b[None, :, :] - lights[:, None, :]
    d = b - a
    normal = np.stack([d[:, 1], -d[:, 0]], axis=1)  # outward for CCW outlines
    facing_away = np.einsum("lek,ek->le", la, normal) > 0.0
    keep = facing_away | ~closed[None, :]
    # distance from the light to the segment, to skip edges out of reach
    dd = np.maximum(np.einsum("ek,ek->e", d, d), 1e-18)
    t = np.clip(-np.einsum("lek,ek->le", la, d) / dd, 0.0, 1.0)
    nearest = la + t[..., None] * d[None, :, :]
    r = radii[:, None]
    keep &= np.einsum("lek,lek->le", nearest, nearest) < r * r
    li, ei = np.nonzero(keep)
    if len(li) == 0:
        return np.zeros((0, 4, 2)), np.zeros(0, np.intp)
    va, vb = la[li, ei], lb[li, ei]
    push = (2.0 * radii[li])[:, None]
    na = np.maximum(np.hypot(va[:, 0], va[:, 1]), 1e-9)[:, None]
    nb = np.maximum(np.hypot(vb[:, 0], vb[:, 1]), 1e-9)[:, None]
    quads = np.empty((len(li), 4, 2))
    quads[:, 0] = a[ei]
    quads[:, 1] = b[ei]
    quads[:, 2] = b[ei] + vb / nb * push
    quads[:, 3] = a[ei] + va / na * push
    return quads, li


def quads_to_triangles(quads: np.ndarray) -> np.ndarray:
    """(Q, 4, 2) quads -> (Q * 6, 2) triangle vertices (a, b, b', a, b', a')."""
    return quads[:, [0, 1, 2, 0, 2, 3]].reshape(-1, 2)
