"""The candidate pairs of one step: each character against what it could touch.

Every character's box, grown by how far it may move this step, is queried against
the static pieces' grid, a grid of the moving pieces and a grid of the other
characters (:mod:`kge.character.grid`). Pairs whose collision filters refuse each
other (Box2D's rule: same non-zero group collides iff positive, else category and
mask both ways) and sensors are dropped; what is left is gathered into
:class:`Pairs`, sorted by character, with the obstacle's world vertices ready for
the narrow phase. Another character is an obstacle with a soft touch: it is not
cast against (two characters walking into each other both move, then part), only
pushed out of by half the overlap, each side doing its half.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kge.character.batch import Batch
from kge.character.grid import Grid, _ranges
from kge.character.narrowphase import signed_distance
from kge.character.obstacles import CELL, Pieces

#: separation kept from every surface, metres (Box2D's linear slop)
SKIN = 0.005
#: pieces within this of the kept separation touch the character
MARGIN = 0.01
#: pair kinds beyond the body kinds of kge.character.obstacles
CHARACTER = 3


def collides(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Box2D's filter rule for rows of (category, mask, group) bits."""
    same = (a[:, 2] == b[:, 2]) & (a[:, 2] != 0)
    by_bits = ((a[:, 0] & b[:, 1]) != 0) & ((b[:, 0] & a[:, 1]) != 0)
    return np.where(same, a[:, 2] > 0, by_bits)


def _pad(v: np.ndarray, n: int) -> np.ndarray:
    if v.shape[1] == n:
        return v
    return np.concatenate([v, np.repeat(v[:, -1:], n - v.shape[1], axis=1)], axis=1)


@dataclass(slots=True)
class Pairs:
    """P (character, obstacle) pairs sorted by character."""

    char: np.ndarray  # (P,) row in the batch
    verts: np.ndarray  # (P, n, 2) obstacle core vertices, world
    radius: np.ndarray  # (P,)
    target: np.ndarray  # (P,) separation to keep
    collider: np.ndarray  # (P,) collider entity (the other character's entity)
    body: np.ndarray  # (P,) body entity, -1 for the implicit static body
    child: np.ndarray  # (P,)
    kind: np.ndarray  # (P,) STATIC, KINEMATIC, DYNAMIC or CHARACTER
    oneway: np.ndarray  # (P, 3) up x, up y, min cos; NaN when not one-way
    simple: np.ndarray  # (P,) both cores have at most two vertices (the closed form)
    first: np.ndarray  # (C,) first pair of each character
    count: np.ndarray  # (C,)
    #: pairs a character may currently meet (one-way platforms it is not above, or drops
    #: through, are switched off for the step)
    live: np.ndarray

    def __len__(self) -> int:
        return len(self.char)

    def of(self, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(pair indices, index into ``rows``) of the live pairs of characters ``rows``."""
        idx = _ranges(self.first[rows], self.count[rows])
        at = np.repeat(np.arange(len(rows)), self.count[rows])
        keep = self.live[idx]
        return idx[keep], at[keep]

    def measure(self, batch: Batch, idx: np.ndarray, pos: np.ndarray
                ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(distance, normal, point on the obstacle) of pairs ``idx`` with their
        characters at ``pos`` (one row per pair)."""
        a = batch.vertices(self.char[idx], pos)
        return signed_distance(a, batch.radius[self.char[idx]], self.verts[idx], self.radius[idx],
                               self.simple[idx])


def _from_pieces(pieces: Pieces, grid: Grid, batch: Batch, qlo: np.ndarray, qhi: np.ndarray
                 ) -> tuple[np.ndarray, ...] | None:
    c, p = grid.pairs(qlo, qhi)
    if len(c) == 0:
        return None
    keep = ~pieces.sensor[p] & collides(batch.bits[c], pieces.bits[p])
    c, p = c[keep], p[keep]
    if len(c) == 0:
        return None
    return (c, pieces.gather(p), pieces.radius[p], np.full(len(c), SKIN), pieces.collider[p],
            pieces.body[p], pieces.child[p], pieces.kind[p].astype(np.int64), pieces.oneway[p],
            (pieces.count[p] <= 2) & batch.small[c])


def _from_characters(batch: Batch, qlo: np.ndarray, qhi: np.ndarray, colliders: np.ndarray
                     ) -> tuple[np.ndarray, ...] | None:
    grid = Grid(batch.pos + batch.lo, batch.pos + batch.hi, CELL)
    c, o = grid.pairs(qlo, qhi)
    keep = (c != o) & collides(batch.bits[c], batch.bits[o])
    c, o = c[keep], o[keep]
    if len(c) == 0:
        return None
    n = len(c)
    return (c, batch.vertices(o, batch.pos[o]), batch.radius[o], np.zeros(n), colliders[o],
            batch.entity[o], np.zeros(n, np.int64), np.full(n, CHARACTER, np.int64),
            np.full((n, 3), np.nan), batch.small[o] & batch.small[c])


def build(batch: Batch, static: Pieces, moving: Pieces, reach: np.ndarray,
          colliders: np.ndarray) -> Pairs:
    """The pairs of every character whose box grown by ``reach`` (C,) meets something.

    ``colliders`` (C,) names each character's collider entity (what other characters'
    pairs report as the collider met).
    """
    qlo = batch.pos + batch.lo - reach[:, None]
    qhi = batch.pos + batch.hi + reach[:, None]
    parts = []
    if len(static) and static.grid is not None:
        parts.append(_from_pieces(static, static.grid, batch, qlo, qhi))
    if len(moving):
        lo, hi = moving.bounds()
        parts.append(_from_pieces(moving, Grid(lo, hi, CELL), batch, qlo, qhi))
    if len(batch) > 1:
        parts.append(_from_characters(batch, qlo, qhi, colliders))
    found = [p for p in parts if p is not None]
    c_count = len(batch)
    if not found:
        z = np.zeros(0, np.int64)
        return Pairs(z, np.zeros((0, 1, 2)), np.zeros(0), np.zeros(0), z, z, z, z,
                     np.zeros((0, 3)), np.zeros(0, bool), np.zeros(c_count, np.int64),
                     np.zeros(c_count, np.int64), np.zeros(0, bool))
    n = max(p[1].shape[1] for p in found)
    cols = [np.concatenate([p[i] if i != 1 else _pad(p[1], n) for p in found])
            for i in range(10)]
    order = np.argsort(cols[0], kind="stable")
    char, verts, radius, target, collider, body, child, kind, oneway, simple = (
        x[order] for x in cols
    )
    first = np.searchsorted(char, np.arange(c_count), "left")
    count = np.searchsorted(char, np.arange(c_count), "right") - first
    return Pairs(char, verts, radius, target, collider, body, child, kind, oneway, simple,
                 first, count, np.ones(len(char), bool))
