"""A uniform grid over axis-aligned boxes, built and queried in numpy (the broad phase).

Each box is filed under every cell it covers; a query box finds the boxes filed
under its cells, and the pairs that come back are exact box overlaps, each once,
sorted by query then by box (so the narrow phase always sees them in one order).
Boxes covering more than :data:`BIG` cells (a long ground edge, a big platform) are
kept in a short list tested against every query instead, so one huge box never
fills thousands of cells.

>>> import numpy as np
>>> g = Grid(np.array([[0.0, 0.0], [5.0, 0.0]]), np.array([[1.0, 1.0], [6.0, 1.0]]), 2.0)
>>> q, b = g.pairs(np.array([[0.5, 0.5]]), np.array([[5.5, 0.6]]))
>>> q.tolist(), b.tolist()
([0, 0], [0, 1])
"""

from __future__ import annotations

import numpy as np

#: boxes covering more cells than this are tested against every query
BIG = 16
_SHIFT = np.int64(1 << 32)


def _cells(lo: np.ndarray, hi: np.ndarray, size: float) -> tuple[np.ndarray, np.ndarray]:
    """For each box, its cell range: (first cell (n, 2), cell counts (n, 2))."""
    first = np.floor(lo / size).astype(np.int64)
    last = np.floor(hi / size).astype(np.int64)
    return first, last - first + 1


def _expand(first: np.ndarray, span: np.ndarray, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(row of each cell, cell key) for every cell covered by ``rows``."""
    count = span[rows, 0] * span[rows, 1]
    owner = np.repeat(rows, count)
    starts = np.cumsum(count) - count
    k = np.arange(int(count.sum()), dtype=np.int64) - np.repeat(starts, count)
    sx = span[owner, 0]
    cx = first[owner, 0] + k % sx
    cy = first[owner, 1] + k // sx
    return owner, cx * _SHIFT + (cy & 0xFFFFFFFF)


def _ranges(start: np.ndarray, count: np.ndarray) -> np.ndarray:
    """Concatenated ``arange(start[i], start[i] + count[i])``."""
    total = int(count.sum())
    if total == 0:
        return np.zeros(0, dtype=np.int64)
    offsets = np.cumsum(count) - count
    return np.repeat(start - offsets, count) + np.arange(total, dtype=np.int64)


class Grid:
    """Boxes ``lo``..``hi`` (n, 2) filed in square cells of ``size`` metres."""

    def __init__(self, lo: np.ndarray, hi: np.ndarray, size: float) -> None:
        self.size = float(size)
        self.lo = lo
        self.hi = hi
        n = len(lo)
        if n == 0:
            self.keys = np.zeros(0, dtype=np.int64)
            self.rows = np.zeros(0, dtype=np.int64)
            self.big = np.zeros(0, dtype=np.int64)
            return
        first, span = _cells(lo, hi, size)
        cells = span[:, 0] * span[:, 1]
        is_big = cells > BIG
        self.big = np.flatnonzero(is_big)
        owner, keys = _expand(first, span, np.flatnonzero(~is_big))
        order = np.argsort(keys, kind="stable")
        self.keys = keys[order]
        self.rows = owner[order]

    def __len__(self) -> int:
        return len(self.lo)

    def pairs(self, qlo: np.ndarray, qhi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(query index, box index) of every overlapping pair, unique and sorted."""
        nq = len(qlo)
        if nq == 0 or len(self.lo) == 0:
            empty = np.zeros(0, dtype=np.int64)
            return empty, empty
        parts_q, parts_b = [], []
        if len(self.keys):
            first, span = _cells(qlo, qhi, self.size)
            owner, keys = _expand(first, span, np.arange(nq))
            left = np.searchsorted(self.keys, keys, "left")
            right = np.searchsorted(self.keys, keys, "right")
            count = right - left
            parts_q.append(np.repeat(owner, count))
            parts_b.append(self.rows[_ranges(left, count)])
        if len(self.big):
            qq, bb = np.meshgrid(np.arange(nq), self.big, indexing="ij")
            parts_q.append(qq.ravel())
            parts_b.append(bb.ravel())
        q = np.concatenate(parts_q)
        b = np.concatenate(parts_b)
        keep = (
            (qlo[q, 0] <= self.hi[b, 0]) & (self.lo[b, 0] <= qhi[q, 0])
            & (qlo[q, 1] <= self.hi[b, 1]) & (self.lo[b, 1] <= qhi[q, 1])
        )
        q, b = q[keep], b[keep]
        if len(q) == 0:
            return q, b
        key = np.unique(q * np.int64(len(self.lo)) + b)
        n = np.int64(len(self.lo))
        return key // n, key % n
