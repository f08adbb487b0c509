"""Every timeline player's playhead in numpy arrays; keyframe tracks sampled in bulk.

One row per :class:`~kge.components.timeline.TimelinePlayer` (entity): the timeline
slot it plays, its time, speed and flags. :meth:`TimelineState.advance` moves every
playing row by ``dt`` at once (loops wrap, others stop at their ends), counts the call
and sound keys crossed between the old and the new time (so a long frame skips none,
and a loop that laps twice fires twice), and :func:`sample` evaluates one property
track for all the rows playing its timeline with one ``np.searchsorted``.

Interpolation between keys ``(t0, v0)`` and ``(t1, v1)`` at time ``t``:

* ``step``: ``v0`` until ``t1``;
* ``linear``: ``v0 + (v1 - v0) * u`` with ``u = (t - t0) / (t1 - t0)``;
* ``cubic``: a cubic Hermite curve through the keys whose tangents are the slopes
  between each key's neighbours (Catmull-Rom on uneven times; one-sided at the ends).

Before the first key a track holds the first value; after the last, the last.

>>> times = np.array([0.0, 1.0, 3.0])
>>> values = np.array([[0.0], [10.0], [30.0]])
>>> sample(times, values, np.array([-1.0, 0.5, 2.0, 9.0]), LINEAR)[:, 0].tolist()
[0.0, 5.0, 20.0, 30.0]
>>> sample(times, values, np.array([0.5, 2.0]), STEP)[:, 0].tolist()
[0.0, 10.0]
>>> sample(times, values, np.array([1.0, 2.0]), CUBIC)[:, 0].tolist()
[10.0, 20.0]
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kge.components.timeline import Calls, Keys, Sounds, Timeline, numbers

STEP, LINEAR, CUBIC = 0, 1, 2
_INTERP = {"step": STEP, "linear": LINEAR, "cubic": CUBIC}
#: time slack: a key due at exactly t (summed steps land 1e-16 short) fires at t
EPS = 1e-9


def sample(times: np.ndarray, values: np.ndarray, t: np.ndarray, interp: int) -> np.ndarray:
    """Values (len(t), width) of the track ``times`` -> ``values`` at times ``t``."""
    k = len(times)
    if k == 1:
        return np.repeat(values[:1], len(t), axis=0)
    i0 = np.clip(np.searchsorted(times, t + EPS, side="right") - 1, 0, k - 2)
    if interp == STEP:
        idx = np.where(t + EPS >= times[i0 + 1], i0 + 1, i0)
        return values[idx]
    t0, t1 = times[i0], times[i0 + 1]
    h = t1 - t0
    u = np.clip((t - t0) / h, 0.0, 1.0)[:, None]
    v0, v1 = values[i0], values[i0 + 1]
    if interp == LINEAR:
        return v0 + (v1 - v0) * u
    slopes = tangents(times, values)
    m0, m1 = slopes[i0] * h[:, None], slopes[i0 + 1] * h[:, None]
    u2, u3 = u * u, u * u * u
    return ((2 * u3 - 3 * u2 + 1) * v0 + (u3 - 2 * u2 + u) * m0
            + (-2 * u3 + 3 * u2) * v1 + (u3 - u2) * m1)  # fmt: skip


def tangents(times: np.ndarray, values: np.ndarray) -> np.ndarray:
    """Each key's slope (value per second): between its neighbours, one-sided at the ends."""
    out = np.empty_like(values)
    out[1:-1] = (values[2:] - values[:-2]) / (times[2:] - times[:-2])[:, None]
    out[0] = (values[1] - values[0]) / (times[1] - times[0])
    out[-1] = (values[-1] - values[-2]) / (times[-1] - times[-2])
    return out


@dataclass(slots=True)
class PropertyTrack:
    """One ``Keys`` track, compiled: key times, numeric values (or held objects)."""

    track: Keys
    times: np.ndarray
    values: np.ndarray | None  # (keys, width) floats; None: held objects (step only)
    interp: int
    ints: bool  # every key is an int: round what is written
    vector: bool  # the field holds a tuple
    #: written without re-validation (decided by the system on first use)
    raw: bool | None = None

    def at(self, t: np.ndarray) -> list[object]:
        """The field's value at each time of ``t`` (ready to assign)."""
        if self.values is None:
            i = np.clip(np.searchsorted(self.times, t + EPS, side="right") - 1, 0,
                        len(self.times) - 1)  # fmt: skip
            keys = self.track.keys
            return [keys[j][1] for j in i.tolist()]
        rows = sample(self.times, self.values, t, self.interp)
        if self.ints:
            rows = np.rint(rows)
        if self.vector:
            cast = int if self.ints else float
            return [tuple(cast(v) for v in r) for r in rows.tolist()]
        col = rows[:, 0]
        return [int(v) for v in col.tolist()] if self.ints else col.tolist()


@dataclass(slots=True)
class TimelineInfo:
    """A registered timeline: its slot, length, loop, property tracks and timed keys."""

    slot: int
    timeline: Timeline
    length: float
    loop: bool
    properties: list[PropertyTrack]
    #: (time, track index, key index) of every call and sound key, by time
    cues: list[tuple[float, int, int]]


def _compile(track: Keys) -> PropertyTrack:
    times = np.array([k[0] for k in track.keys], float)
    nums = [numbers(k[1]) for k in track.keys]
    numeric = all(n is not None for n in nums) and len({len(n or ()) for n in nums}) == 1
    first = track.keys[0][1]
    vector = isinstance(first, (tuple, list))
    values = np.array(nums, float) if numeric else None
    ints = numeric and all(
        isinstance(v, int) for k in track.keys for v in (k[1] if vector else (k[1],))
    )
    return PropertyTrack(track, times, values, _INTERP[track.interp], ints, vector)


class TimelineTable:
    """Registered timelines (immutable: registered once by identity)."""

    def __init__(self) -> None:
        self.infos: list[TimelineInfo] = []
        self._by_id: dict[int, TimelineInfo] = {}
        self.length = np.zeros(0)
        self.loop = np.zeros(0, bool)
        self.has_cues = np.zeros(0, bool)

    def register(self, timeline: Timeline) -> TimelineInfo:
        info = self._by_id.get(id(timeline))
        if info is not None and info.timeline is timeline:
            return info
        props: list[PropertyTrack] = []
        cues: list[tuple[float, int, int]] = []
        for ti, track in enumerate(timeline.tracks):
            if isinstance(track, Keys):
                props.append(_compile(track))
            elif isinstance(track, (Calls, Sounds)):
                cues.extend((float(k[0]), ti, ki) for ki, k in enumerate(track.keys))
        cues.sort()
        length = float(timeline.length or 0.0)
        info = TimelineInfo(len(self.infos), timeline, length, timeline.loop, props, cues)
        self.infos.append(info)
        self._by_id[id(timeline)] = info
        self.length = np.append(self.length, length)
        self.loop = np.append(self.loop, timeline.loop)
        self.has_cues = np.append(self.has_cues, bool(cues))
        return info


@dataclass(slots=True)
class Advance:
    """What one :meth:`TimelineState.advance` found."""

    cues: list[tuple[int, TimelineInfo, int, int]]  # (row, info, track index, key index)
    finished: np.ndarray  # rows whose timeline reached its end in this pass
    moved: np.ndarray  # rows whose properties must be written (moved or touched)


_ARRAYS = ("entity", "slot", "time", "speed", "playing", "finished", "fresh", "touched")


class TimelineState:
    """One row per timeline player: slot, time, speed, flags (see the module docstring)."""

    def __init__(self) -> None:
        self.table = TimelineTable()
        self.rows: dict[int, int] = {}
        self.entity = np.zeros(0, np.int64)
        self.slot = np.zeros(0, np.intp)
        self.time = np.zeros(0)
        self.speed = np.zeros(0)
        self.playing = np.zeros(0, bool)
        self.finished = np.zeros(0, bool)
        self.fresh = np.zeros(0, bool)  # started since the last pass: keys at the start due
        self.touched = np.zeros(0, bool)  # started or moved: write its properties

    def __len__(self) -> int:
        return len(self.entity)

    def add(self, entity: int) -> int:
        row = self.rows.get(entity)
        if row is not None:
            return row
        row = self.rows[entity] = len(self.entity)
        for name, value in zip(_ARRAYS, (entity, 0, 0.0, 1.0, False, False, False, False),
                               strict=True):  # fmt: skip
            arr = getattr(self, name)
            setattr(self, name, np.append(arr, np.array([value], arr.dtype)))
        return row

    def remove(self, entity: int) -> None:
        row = self.rows.pop(entity, None)
        if row is None:
            return
        last = len(self.entity) - 1
        if row != last:
            self.rows[int(self.entity[last])] = row
            for name in _ARRAYS:
                arr = getattr(self, name)
                arr[row] = arr[last]
        for name in _ARRAYS:
            setattr(self, name, getattr(self, name)[:last])

    def start(self, row: int, slot: int, at: float | None) -> None:
        """Row ``row`` plays timeline ``slot`` from its start (its end when playing
        backwards), or from ``at`` seconds (a seek: the keys there do not fire)."""
        length = float(self.table.length[slot])
        self.slot[row] = slot
        self.finished[row] = False
        self.touched[row] = True
        if at is None:
            self.time[row] = length if self.speed[row] < 0 else 0.0
            self.fresh[row] = True
        else:
            self.time[row] = min(max(at, 0.0), length)
            self.fresh[row] = False

    def advance(self, dt: float) -> Advance:
        """Move every playing row by ``dt`` seconds (see the module docstring)."""
        n = len(self.entity)
        if n == 0:
            return Advance([], np.zeros(0, np.intp), np.zeros(0, np.intp))
        t = self.table
        slot = self.slot
        length, loop = t.length[slot], t.loop[slot]
        rate = np.where(self.playing & ~self.finished, self.speed, 0.0)
        before = self.time
        after = before + rate * dt
        rev = rate < 0
        cues: list[tuple[int, TimelineInfo, int, int]] = []
        if t.has_cues[slot].any():
            lo = np.where(rev, after - EPS, np.where(self.fresh, before - EPS, before + EPS))
            hi = np.where(rev, np.where(self.fresh, before + EPS, before - EPS), after + EPS)
            cues = self._crossed(lo, hi, length, loop, rev)
        span = np.where(length > 0, length, 1.0)
        wrapped = np.where(loop, after - np.floor((after + EPS) / span) * span, after)
        wrapped = np.clip(wrapped, 0.0, length)
        ended = ~loop & ~self.finished & (rate != 0) & np.where(
            rev, after <= EPS, after + EPS >= length
        )
        moved = np.flatnonzero((rate != 0) | self.touched)
        self.time = wrapped
        self.finished |= ended
        self.fresh[:] = False
        self.touched[:] = False
        return Advance(cues, np.flatnonzero(ended), moved)

    def _crossed(self, lo: np.ndarray, hi: np.ndarray, length: np.ndarray, loop: np.ndarray,
                 rev: np.ndarray) -> list[tuple[int, TimelineInfo, int, int]]:  # fmt: skip
        """Cue keys in (lo, hi] per row, looping rows counting every lap; ordered by
        entity, then playhead order (latest first going backwards)."""
        found: list[tuple[int, float, int, TimelineInfo, int, int]] = []
        t = self.table
        active = hi > lo
        for s in np.unique(self.slot[active & t.has_cues[self.slot]]).tolist():
            info = t.infos[s]
            rows = np.flatnonzero(active & (self.slot == s))
            a, b, lp = lo[rows], hi[rows], loop[rows]
            span = max(info.length, EPS)
            for time, ti, ki in info.cues:
                laps = np.floor((b - time) / span) - np.floor((a - time) / span)
                once = ((a < time) & (time <= b)).astype(float)
                count = np.where(lp, laps, once).astype(np.int64)
                first = np.floor((a - time) / span) + 1  # the first lap crossed
                for j in np.flatnonzero(count > 0).tolist():
                    r = int(rows[j])
                    sign = -1.0 if rev[r] else 1.0
                    for k in range(int(count[j])):
                        at = time + span * (float(first[j]) + k) if lp[j] else time
                        found.append((int(self.entity[r]), sign * at, r, info, ti, ki))
        found.sort(key=lambda f: (f[0], f[1]))
        return [(r, info, ti, ki) for _, _, r, info, ti, ki in found]
