"""Collide and slide for many characters at once (Box2D v3's mover loop).

Each iteration, for every character still moving:

1. **collide**: the pairs within reach are measured where the character is; those
   it touches (within :data:`~kge.character.contacts.MARGIN` of the separation it
   keeps) become planes;
2. **solve**: the move still wanted is pushed out of the planes
   (:func:`kge.character.planes.solve`), so it slides along what it touches;
3. **cast**: the solved move is swept against every pair (exact time of impact,
   :func:`kge.character.narrowphase.time_of_impact`) and the character advances to
   the first contact, or all the way.

A character that reached the end of its solved move is done; one that hit
something goes round again from there, up to its ``max_slides``. Nothing here can
end inside a surface: every advance stops short of the first impact, whatever the
speed. What blocked each character (planes that pushed, surfaces hit) is returned,
for the contact flags and to clip the velocity.

Platformers classify what they touch (:func:`walkable`): a surface facing up within
``max_floor_angle`` is a floor, and so is an edge no higher above the feet than
``step_height`` (a rounded shape rolls up onto a step as its slide pushes it up the
edge); a steeper slope is a wall that also blocks sideways motion into it, so it
cannot be walked up, only slid down.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from kge.character import planes
from kge.character.batch import Batch
from kge.character.contacts import CHARACTER, MARGIN, SKIN, Pairs
from kge.character.narrowphase import time_of_impact

#: casts stop within this above the separation kept (m)
CAST_TOLERANCE = 1e-3
#: moves shorter than this are no move (m)
TINY_MOVE = 1e-12


@dataclass(slots=True)
class Blocks:
    """What stopped or deflected the characters: one row per plane that pushed or
    surface hit, in order (``row`` is the character's row in the batch)."""

    row: list[np.ndarray] = field(default_factory=list)
    normal: list[np.ndarray] = field(default_factory=list)
    point: list[np.ndarray] = field(default_factory=list)
    pair: list[np.ndarray] = field(default_factory=list)
    #: the character's position when it met it (for the height of the contact)
    at: list[np.ndarray] = field(default_factory=list)

    def add(self, row: np.ndarray, normal: np.ndarray, point: np.ndarray, pair: np.ndarray,
            at: np.ndarray) -> None:
        if len(row):
            self.row.append(row)
            self.normal.append(normal)
            self.point.append(point)
            self.pair.append(pair)
            self.at.append(at)

    def arrays(self) -> tuple[np.ndarray, ...]:
        """(row, normal, point, pair, position) concatenated."""
        if not self.row:
            return (np.zeros(0, np.int64), np.zeros((0, 2)), np.zeros((0, 2)),
                    np.zeros(0, np.int64), np.zeros((0, 2)))
        return (np.concatenate(self.row), np.concatenate(self.normal),
                np.concatenate(self.point), np.concatenate(self.pair), np.concatenate(self.at))


def walkable(batch: Batch, rows: np.ndarray, pos: np.ndarray, normal: np.ndarray,
             point: np.ndarray) -> np.ndarray:
    """Which contacts of platformers ``rows`` (at ``pos``) are floors: facing up within
    the floor angle, or an edge at most ``step_height`` above the feet facing up at all."""
    up = batch.up[rows]
    nu = np.einsum("pd,pd->p", normal, up)
    height = np.einsum("pd,pd->p", point - pos, up) - batch.foot[rows]
    edge = (nu > 1e-9) & (height <= batch.step[rows] + 1e-6)
    return batch.platformer[rows] & ((nu >= batch.floor_cos[rows]) | edge)


def _plane_offsets(pairs: Pairs, idx: np.ndarray, sd: np.ndarray, n: np.ndarray,
                   want: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """How far along its normal each plane needs the move to go, and how far it may
    push (see planes.solve): surfaces without limit; another character pushes itself
    out of half the overlap and stops its own move into the other, no more (so three
    characters squeezed together settle instead of pushing each other for ever)."""
    offset = pairs.target[idx] - sd
    limit = np.full(len(idx), np.inf)
    soft = pairs.kind[idx] == CHARACTER
    if soft.any():
        offset = np.where(soft, np.where(sd < 0.0, -0.5 * sd, -sd), offset)
        into = np.maximum(-np.einsum("pd,pd->p", n[soft], want[soft]), 0.0)
        limit[soft] = np.maximum(offset[soft], 0.0) + into
    return offset, limit


def _steep_walls(batch: Batch, pairs: Pairs, rows: np.ndarray, pos: np.ndarray, idx: np.ndarray,
                 at: np.ndarray, n: np.ndarray, point: np.ndarray, offset: np.ndarray,
                 limit: np.ndarray
                 ) -> tuple[np.ndarray, ...]:
    """A platformer does not walk up a slope too steep to stand on: each such slope it
    touches also stops its sideways motion into it, as an upright wall would (falling
    down the slope is left alone, so it still slides off)."""
    r = rows[at]
    up = batch.up[r]
    nu = np.einsum("pd,pd->p", n, up)
    steep = batch.platformer[r] & (nu > 1e-9) & (pairs.kind[idx] != CHARACTER)
    if steep.any():
        steep &= ~walkable(batch, r, pos, n, point)
    if not steep.any():
        return idx, at, n, offset, limit, np.zeros(0, np.int64)
    side = n[steep] - nu[steep, None] * up[steep]
    side /= np.hypot(side[:, 0], side[:, 1])[:, None]
    # the upright twins go first: the solver then never lifts the move up the slope only
    # to take the sideways part back (what an unconverged pass would leave is a climb)
    return (np.concatenate([idx[steep], idx]), np.concatenate([at[steep], at]),
            np.concatenate([side, n]), np.concatenate([np.minimum(offset[steep], 0.0), offset]),
            np.concatenate([limit[steep], limit]), np.flatnonzero(steep))


def cast(batch: Batch, pairs: Pairs, rows: np.ndarray, pos: np.ndarray, delta: np.ndarray,
         start: tuple[np.ndarray, ...] | None = None
         ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Sweep characters ``rows`` from ``pos`` by ``delta`` (one row each) against their
    pairs (not other characters): (fraction, hit pair or -1, normal and point at the hit).

    ``start`` may pass what is known at ``pos``: (pair indices, index into rows,
    distances, normals, points).
    """
    m = len(rows)
    frac = np.ones(m)
    hit_pair = np.full(m, -1, np.int64)
    normal = np.zeros((m, 2))
    point = np.zeros((m, 2))
    if start is None:
        idx, at = pairs.of(rows)
        known = None
    else:
        idx, at, *known = start
    solid = pairs.kind[idx] != CHARACTER
    idx, at = idx[solid], at[solid]
    if len(idx) == 0:
        return frac, hit_pair, normal, point
    if known is None:
        sd, n, q = pairs.measure(batch, idx, pos[at])
    else:
        sd, n, q = (k[solid] for k in known)
    c = pairs.char[idx]
    a = batch.vertices(c, pos[at])
    t, hit, hn, hp = time_of_impact(
        a, batch.radius[c], pairs.verts[idx], pairs.radius[idx], delta[at], pairs.target[idx],
        tolerance=CAST_TOLERANCE, start=(sd, n, q), simple=pairs.simple[idx],
    )
    if not hit.any():
        return frac, hit_pair, normal, point
    idx, at, t, hn, hp = idx[hit], at[hit], t[hit], hn[hit], hp[hit]
    # the earliest hit of each row (ties: the first pair, which is the lowest entity)
    order = np.lexsort((idx, t, at))
    at_sorted = at[order]
    first = np.ones(len(order), bool)
    first[1:] = at_sorted[1:] != at_sorted[:-1]
    best = order[first]
    frac[at[best]] = t[best]
    hit_pair[at[best]] = idx[best]
    normal[at[best]] = hn[best]
    point[at[best]] = hp[best]
    return frac, hit_pair, normal, point


def slide(batch: Batch, pairs: Pairs, rows: np.ndarray, pos: np.ndarray, delta: np.ndarray,
          slides: np.ndarray, blocks: Blocks) -> np.ndarray:
    """Move characters ``rows`` from ``pos`` by ``delta`` with collide-and-slide; returns
    where they end (what stopped them is added to ``blocks``)."""
    pos = pos.copy()
    goal = pos + delta
    active = np.arange(len(rows))
    for it in range(int(slides.max(initial=0))):
        active = active[slides[active] > it]
        if len(active) == 0:
            break
        r = rows[active]
        here = pos[active]
        idx, at = pairs.of(r)
        sd, n, q = pairs.measure(batch, idx, here[at])
        near = sd < pairs.target[idx] + MARGIN
        p_idx, p_at, p_n, p_q = idx[near], at[near], n[near], q[near]
        want = goal[active] - here
        offset, limit = _plane_offsets(pairs, p_idx, sd[near], p_n, want[p_at])
        real_n = p_n
        p_idx, p_at, p_n, offset, limit, src = _steep_walls(
            batch, pairs, r, here[p_at], p_idx, p_at, p_n, p_q, offset, limit
        )
        moves, push = planes.solve(want, p_n, offset, p_at, limit)
        pushed = (push > 0.0) & (pairs.kind[p_idx] != CHARACTER)
        # (a steep wall's upright twin comes first; when it pushes, the slope blocked)
        by = np.concatenate([src, np.arange(len(p_q))])[pushed]
        blocks.add(r[p_at[pushed]], real_n[by], p_q[by], p_idx[pushed], here[p_at[pushed]])
        frac, hit_pair, hit_n, hit_q = cast(batch, pairs, r, here, moves, (idx, at, sd, n, q))
        pos[active] += frac[:, None] * moves
        hit = hit_pair >= 0
        blocks.add(r[hit], hit_n[hit], hit_q[hit], hit_pair[hit], pos[active][hit])
        length = np.hypot(moves[:, 0], moves[:, 1])
        # done: reached the end of the solved move, or nothing left to move
        done = ~hit | (length < TINY_MOVE)
        active = active[~done]
    return pos


def touching(batch: Batch, pairs: Pairs, rows: np.ndarray, pos: np.ndarray
             ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The pairs characters ``rows`` touch at ``pos``: (pair, index into rows, distance,
    normal, point on the obstacle)."""
    idx, at = pairs.of(rows)
    sd, n, point = pairs.measure(batch, idx, pos[at])
    near = sd < pairs.target[idx] + MARGIN
    return idx[near], at[near], sd[near], n[near], point[near]


def snap_down(batch: Batch, pairs: Pairs, rows: np.ndarray, pos: np.ndarray, length: np.ndarray
              ) -> tuple[np.ndarray, np.ndarray]:
    """Cast characters ``rows`` down (against their ``up``) by ``length``; those that
    meet a floor within it move onto it. Returns (new positions, snapped mask)."""
    down = -batch.up[rows] * length[:, None]
    frac, hit_pair, normal, point = cast(batch, pairs, rows, pos, down)
    landed = pos + frac[:, None] * down
    floor = (hit_pair >= 0) & walkable(batch, rows, landed, normal, point)
    out = pos.copy()
    out[floor] = landed[floor]
    return out, floor


def step_up(batch: Batch, pairs: Pairs, rows: np.ndarray, start: np.ndarray, delta: np.ndarray,
            plain: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Try the move again as up, across, down (climbing a ledge of at most
    ``step_height``); keep it where it lands on a floor farther along than ``plain``
    (where the plain slide ended). Returns (positions, stepped mask)."""
    up = batch.up[rows]
    height = batch.step[rows]
    scratch = Blocks()
    one = np.ones(len(rows), np.int64)
    raised = slide(batch, pairs, rows, start, up * height[:, None], one, scratch)
    lift = np.einsum("md,md->m", raised - start, up)
    across = delta - np.einsum("md,md->m", delta, up)[:, None] * up
    moved = slide(batch, pairs, rows, raised, across, batch.slides[rows], scratch)
    fall = lift + SKIN + MARGIN
    landed, floor = snap_down(batch, pairs, rows, moved, fall)
    ahead = across / np.maximum(np.hypot(across[:, 0], across[:, 1]), 1e-300)[:, None]
    gain = np.einsum("md,md->m", landed - plain, ahead)
    ok = floor & (lift > SKIN) & (gain > 1e-4)
    out = plain.copy()
    out[ok] = landed[ok]
    return out, ok
