"""Box-overlap queries on a table of boxes in O(log m + hits) instead of O(m).

:class:`~kge.physics.ccd.obstacles.Obstacles` keeps one box per static or
kinematic shape. Asking "which boxes overlap this square?" with a full numpy
pass costs a few microseconds per query *per thousand rows*, and a fast body
asks it several times a step (its own reach, every neighbour's). Here the rows
are kept sorted by their left edge: a row overlapping ``[left, right]`` in x
has its own left edge in ``[left - span, right]`` (``span``: the widest row), a
window found by binary search, so a query only tests the rows in that window.

The sort is not redone at every change. Rows written since it was made are
*loose*: always tested, whatever the window says, and left out of the window
(their sorted left edge may be stale). A row that was freed keeps its stale
place in the window, but its box is NaN, which fails every test. When the
loose rows outnumber an eighth of the table the sort is redone (O(m log m),
about 10 µs for 1,000 rows), so a replaced chain or a moving kinematic body
costs a few loose rows, not a sort per step.

Every candidate is tested with the same float expressions a full pass uses,
so the answers are exactly the full pass's, in ascending row order; small
tables (below :data:`MIN_ROWS`) simply take the full pass.

>>> import numpy as np
>>> box = np.array([[0.0, 0.0, 1.0, 1.0], [5.0, 0.0, 6.0, 1.0], [np.nan] * 4])
>>> index = SortedBoxes(min_rows=0)
>>> q, rows = index.overlapping(box, 3, np.array([0.5, 9.0]), np.array([0.5, 0.0]),
...                             np.array([0.5, 9.5]), np.array([0.5, 0.5]))
>>> q.tolist(), rows.tolist()
([0], [0])
"""

from __future__ import annotations

from bisect import bisect_left, bisect_right
from collections.abc import Iterable

import numpy as np

#: tables with fewer rows are answered by a full pass: below a few thousand rows a
#: full pass (a handful of numpy calls) costs less than the search and its upkeep
MIN_ROWS = 4096
#: up to this many queries are searched with Python's bisect, more in numpy
_FEW = 8
_NONE = np.empty(0, dtype=np.intp)
#: (queries x rows) compared at once by the full pass (bounds temporary memory)
_CHUNK = 1 << 16


class SortedBoxes:
    """The rows of a box table (left, bottom, right, top), sorted by left edge.

    The owner calls :meth:`touched` with every row whose box it writes (or
    :meth:`clear` when it empties the table) and asks :meth:`overlapping`.
    """

    __slots__ = (
        "_covered", "_is_loose", "_lefts", "_lefts_list", "_loose", "_loose_rows", "_order",
        "_order_list", "min_rows", "span",
    )

    def __init__(self, min_rows: int = MIN_ROWS) -> None:
        self.min_rows = min_rows
        self._order: np.ndarray | None = None  # the rows with a box, by ascending left edge
        self._order_list: list[int] = []
        self._lefts = np.empty(0)  # their left edges when sorted
        self._lefts_list: list[float] = []
        self._covered = 0  # rows sorted or loose: later rows are new to the index
        self.span = 0.0  # widest sorted row (padded, see _build)
        self._loose: set[int] = set()  # rows written since the sort
        self._loose_rows: np.ndarray | None = None  # _loose as a sorted array (cached)
        self._is_loose = np.zeros(0, dtype=bool)

    def touched(self, rows: Iterable[int]) -> None:
        """These rows' boxes were (re)written: test them on their own until the next sort."""
        if self._order is not None:
            self._loose.update(rows)
            self._loose_rows = None

    def clear(self) -> None:
        """Forget the sort (the table was emptied or reallocated)."""
        self._order = None
        self._loose.clear()
        self._loose_rows = None

    def overlapping(
        self,
        box: np.ndarray,
        m: int,
        left: np.ndarray,
        bottom: np.ndarray,
        right: np.ndarray,
        top: np.ndarray,
    ) -> tuple[np.ndarray, np.ndarray]:
        """(query, row) of every pair where row ``< m`` of ``box`` overlaps query
        rectangle ``[left, right] x [bottom, top]`` (edges touching count), sorted
        by query then row. ``box`` must be the table the rows were sorted from."""
        k = len(left)
        if m == 0 or k == 0:
            return _NONE, _NONE
        if m < self.min_rows:
            return _full_pass(box[:m], left, bottom, right, top)
        self._refresh(box, m)
        low = _below(left, self.span)
        if k <= _FEW:
            query, rows = self._few(low, right)
        else:
            query, rows = self._many(low, right)
        if not len(rows):
            return _NONE, _NONE
        b = box[rows]
        hit = (
            (b[:, 0] <= right[query])
            & (b[:, 2] >= left[query])
            & (b[:, 1] <= top[query])
            & (b[:, 3] >= bottom[query])
        )
        query, rows = query[hit], rows[hit]
        if len(rows) > 1:
            by = np.lexsort((rows, query))
            query, rows = query[by], rows[by]
        return query, rows

    def _few(self, low: np.ndarray, right: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The windows of a few queries, found with Python's bisect (numpy calls cost
        more than the search itself at this size)."""
        lefts, order, loose = self._lefts_list, self._order_list, self._loose
        extra = sorted(loose)
        query: list[int] = []
        rows: list[int] = []
        for j, (lo_x, hi_x) in enumerate(zip(low.tolist(), right.tolist(), strict=True)):
            window = order[bisect_left(lefts, lo_x) : bisect_right(lefts, hi_x)]
            if loose:
                window = [r for r in window if r not in loose]
                window += extra
            rows += window
            query += [j] * len(window)
        return np.array(query, dtype=np.intp), np.array(rows, dtype=np.intp)

    def _many(self, low: np.ndarray, right: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The windows of many queries, in numpy."""
        assert self._order is not None
        k = len(low)
        lo = np.searchsorted(self._lefts, low, "left")
        hi = np.searchsorted(self._lefts, right, "right")
        counts = np.maximum(hi - lo, 0)
        total = int(counts.sum())
        query = np.repeat(np.arange(k), counts)
        ends = np.cumsum(counts)
        rows = self._order[np.arange(total) + np.repeat(lo - (ends - counts), counts)]
        loose = self._loose_array()
        if len(loose):
            keep = ~self._is_loose[rows]
            rows = np.concatenate([rows[keep], np.tile(loose, k)])
            query = np.concatenate([query[keep], np.repeat(np.arange(k), len(loose))])
        return query, rows

    def _refresh(self, box: np.ndarray, m: int) -> None:
        """Sort again when the loose rows are too many (or the table shrank); rows
        appended since the sort are loose."""
        if (
            self._order is None
            or self._covered > m  # the table shrank: rows past m are gone
            or len(self._loose) + m - self._covered > max(32, m >> 3)
        ):
            self._build(box, m)
        elif self._covered < m:
            self._loose.update(range(self._covered, m))
            self._loose_rows = None
            self._covered = m

    def _build(self, box: np.ndarray, m: int) -> None:
        lefts = box[:m, 0]
        width = box[:m, 2] - lefts
        used = np.flatnonzero(~np.isnan(width))  # free rows (NaN) need no place
        order = used[np.argsort(lefts[used], kind="stable")]
        self._order = order
        self._order_list = order.tolist()
        self._lefts = lefts[order]
        self._lefts_list = self._lefts.tolist()
        self._covered = m
        if len(used):
            # padded by far more than the rounding of right - left, so a row whose
            # right edge reaches a query always has its left edge inside the window
            magnitude = float(np.abs(box[used]).max())
            self.span = float(width[used].max()) + 1e-9 * (1.0 + magnitude)
        else:
            self.span = 0.0
        self._loose.clear()
        self._loose_rows = None
        self._is_loose = np.zeros(max(m, len(box)), dtype=bool)

    def _loose_array(self) -> np.ndarray:
        rows = self._loose_rows
        if rows is None:
            rows = np.fromiter(sorted(self._loose), dtype=np.intp, count=len(self._loose))
            self._loose_rows = rows
            if len(rows) and rows[-1] >= len(self._is_loose):
                self._is_loose = np.zeros(int(rows[-1]) + 1, dtype=bool)
            self._is_loose[:] = False
            self._is_loose[rows] = True
        return rows


def _below(left: np.ndarray, span: float) -> np.ndarray:
    """The lowest left edge a row overlapping ``left`` may have, rounded downwards."""
    with np.errstate(invalid="ignore"):  # inf - inf, for an infinite query or span
        low = left - span
        low = low - 1e-9 * (1.0 + np.abs(low))
    # inf - inf: a NaN would end the window at the NaN rows; the whole table instead
    return np.where(np.isnan(low), -np.inf, low)


def _full_pass(
    box: np.ndarray, left: np.ndarray, bottom: np.ndarray, right: np.ndarray, top: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """What :meth:`SortedBoxes.overlapping` answers, by testing every row (chunked):
    x first over the table, then y on the pairs that pass (few, in a world laid out
    along x), the same four comparisons in two rounds."""
    m = len(box)
    step = max(1, _CHUNK // m)
    queries, rows = [], []
    bl, bb, br, bt = (box[:, i] for i in range(4))
    for i in range(0, len(left), step):
        s = slice(i, i + step)
        q, r = np.nonzero((bl <= right[s, None]) & (br >= left[s, None]))
        q += i
        keep = (bb[r] <= top[q]) & (bt[r] >= bottom[q])
        queries.append(q[keep])
        rows.append(r[keep])
    if len(queries) == 1:
        return queries[0], rows[0]
    return np.concatenate(queries), np.concatenate(rows)
