"""Every animator's playback state in numpy arrays, advanced in one pass per frame.

Why: a scene may hold thousands of animated sprites. Keeping their time and
frame in per-entity Python objects would cost a Python call each per frame;
here one row per animator lives in flat arrays and :meth:`ClipState.advance`
moves them all with a handful of numpy operations:

* every clip used is registered once in a :class:`ClipTable`: its frames are
  laid end to end in global arrays (``ping_pong`` clips expanded to
  0..n-1..1 so they are plain loops), with each frame's *end* time offset by
  the clip's base, so the frame shown at clip time ``t`` for all rows at once is
  one ``np.searchsorted(frame_end, base[clip] + t)``;
* each row's time is the clip time since it started, scaled by the animator's
  and the clip's speed; loops wrap it, ``once``/``hold`` clips finish;
* frame events and finished events are found by counting crossings of the
  frames' start times between the previous and the new time, so a long frame
  (a slow machine, a large time scale) never skips an event;
* a cross-fade (``Animator.play(name, fade=0.2)``, ``Transition(..., fade=0.2)``)
  keeps the outgoing clip running in a second set of columns (``from_clip``,
  ``from_time``, ``from_shown``) while ``fade_t`` climbs to ``fade_len``; the
  renderer draws the outgoing frame over the incoming one at ``1 - weight``;
* the table holds only clips some row plays: :meth:`ClipState.compact` drops the
  others once they outnumber the live ones, so a game that spawns entities with
  clips of their own keeps a table the size of what is alive, and registering a
  clip rebuilds the arrays once per frame, not once per clip.

Frames are identified by *source ids* (one per distinct :class:`FrameRef`), which
the renderer maps to atlas texture coordinates; this module needs no GL.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kge.components.animation import Clip, FrameRef

#: time slack: a frame due at exactly t (summed fixed steps land 1e-16 short) shows at t
EPS = 1e-9
MODES = {"loop": 0, "ping_pong": 0, "once": 1, "hold": 2}
LOOP, ONCE, HOLD = 0, 1, 2


@dataclass(slots=True)
class ClipInfo:
    """One registered clip: its slot, expanded frame order and events."""

    slot: int
    clip: Clip
    order: list[int]  # expanded frame order (original frame indices)
    #: (start time inside the clip, original frame, event name), expanded
    events: list[tuple[float, int, str]]


class ClipTable:
    """Registered clips and frame sources, as flat numpy arrays (see the module docstring)."""

    def __init__(self) -> None:
        self.sources: list[FrameRef] = []
        self._source_ids: dict[FrameRef, int] = {}
        self.infos: list[ClipInfo] = []
        self._by_id: dict[int, ClipInfo] = {}
        self._keep: list[Clip] = []
        self._ends: list[float] = []
        self._src: list[int] = []
        self._orig: list[int] = []
        self._first: list[int] = []
        self._len: list[int] = []
        self._total: list[float] = []
        self._base: list[float] = []
        self._mode: list[int] = []
        self._speed: list[float] = []
        self._variant: list[int] = []
        self._has_events: list[bool] = []
        self._next_base = 0.0
        self.version = 0
        self._stale = False
        self._arrays()

    def __len__(self) -> int:
        """How many clips are registered."""
        return len(self.infos)

    def ensure(self) -> None:
        """Rebuild the numpy arrays if clips were registered since the last call."""
        if self._stale:
            self._stale = False
            self._arrays()
            self.version += 1

    def first_frame(self, slot: int) -> int:
        """The global index of clip ``slot``'s first frame (valid before :meth:`ensure`)."""
        return self._first[slot]

    def _arrays(self) -> None:
        self.frame_end = np.array(self._ends, float)
        self.frame_src = np.array(self._src, np.intp)
        self.frame_orig = np.array(self._orig, np.intp)
        self.first = np.array(self._first, np.intp)
        self.length = np.array(self._len, np.intp)
        self.total = np.array(self._total, float)
        self.base = np.array(self._base, float)
        self.mode = np.array(self._mode, np.int8)
        self.speed = np.array(self._speed, float)
        self.variant = np.array(self._variant, np.intp)
        self.has_events = np.array(self._has_events, bool)

    def source_id(self, ref: FrameRef) -> int:
        sid = self._source_ids.get(ref)
        if sid is None:
            sid = self._source_ids[ref] = len(self.sources)
            self.sources.append(ref)
        return sid

    def register(self, clip: Clip) -> ClipInfo:
        """The slot of ``clip`` (registered on first use; clips are immutable)."""
        info = self._by_id.get(id(clip))
        if info is not None:
            return info
        n = len(clip.frames)
        order = list(range(n))
        if clip.loop == "ping_pong":
            order += list(range(n - 2, 0, -1))
        durs = [clip.durations[i] for i in order]
        total = math.fsum(durs)
        slot = len(self.infos)
        starts = np.concatenate([[0.0], np.cumsum(durs)[:-1]])
        named = dict(clip.events)
        events = [(float(starts[j]), i, named[i]) for j, i in enumerate(order) if i in named]
        info = ClipInfo(slot, clip, order, events)
        self.infos.append(info)
        self._by_id[id(clip)] = info
        self._keep.append(clip)  # ids stay unique while the table lives
        base = self._next_base
        self._first.append(len(self._ends))
        self._len.append(len(order))
        acc = 0.0
        for k, i in enumerate(order):
            acc += durs[k]
            self._ends.append(base + acc)
            self._src.append(self.source_id(clip.frames[i]))
            self._orig.append(i)
        # the next clip's frames start well after this one's last end, so that a
        # query just below ``base + total`` never lands in the next clip
        self._next_base = base + total + 1.0 + total * 1e-9
        self._total.append(total)
        self._base.append(base)
        self._mode.append(MODES[clip.loop])
        self._speed.append(clip.speed)
        self._variant.append(int(clip.flip_x) | (int(clip.flip_y) << 1))
        self._has_events.append(bool(events))
        self._stale = True  # the arrays are rebuilt once, by ensure(), for many new clips
        return info

    def rebuilt(self, slots: list[int]) -> tuple[ClipTable, np.ndarray]:
        """A table of only the clips ``slots`` (in that order), and old slot -> new slot
        (-1 for the dropped ones). Frame sources keep their ids: the renderer's atlas
        regions stay valid."""
        table = ClipTable()
        table.sources = self.sources
        table._source_ids = self._source_ids
        remap = np.full(len(self.infos), -1, np.intp)
        for slot in slots:
            remap[slot] = table.register(self.infos[slot].clip).slot
        table.ensure()
        table.version = self.version + 1
        return table, remap


@dataclass(slots=True, frozen=True)
class CrossFade:
    """A cross-fade under way: the outgoing ``clip``, the ``frame`` of it shown, and
    ``weight``, how much of the incoming clip shows (0 at the cut, 1 when done)."""

    clip: str
    frame: int
    weight: float


@dataclass(slots=True)
class Crossings:
    """What one :meth:`ClipState.advance` found: frame events and finished rows."""

    events: list[tuple[int, int, str, int]]  # (row, clip slot, name, original frame), ordered
    finished: np.ndarray  # rows whose once/hold clip ended in this pass


class ClipState:
    """One row per animator (entity): clip slot, time, speed, flags, frame shown."""

    def __init__(self, table: ClipTable) -> None:
        self.table = table
        self.rows: dict[int, int] = {}  # entity -> row
        self.entity = np.zeros(0, np.int64)
        self.clip = np.zeros(0, np.intp)
        self.time = np.zeros(0, float)
        self.speed = np.zeros(0, float)
        self.playing = np.zeros(0, bool)
        self.finished = np.zeros(0, bool)
        self.fresh = np.zeros(0, bool)  # started since the last pass: frame 0's events due
        self.shown = np.zeros(0, np.intp)  # global frame index shown
        # a cross-fade: the outgoing clip (-1: none), its time, rate and frame, the fade's
        # elapsed and total seconds (game time)
        self.from_clip = np.zeros(0, np.intp)
        self.from_time = np.zeros(0, float)
        self.from_rate = np.zeros(0, float)
        self.from_shown = np.zeros(0, np.intp)
        self.fade_t = np.zeros(0, float)
        self.fade_len = np.zeros(0, float)
        self.version = 0  # bumped when rows are added, removed or moved

    def __len__(self) -> int:
        return len(self.entity)

    def add(self, entity: int) -> int:
        row = self.rows.get(entity)
        if row is None:
            self.add_many([entity])
            row = self.rows[entity]
        return row

    def add_many(self, entities: list[int]) -> None:
        """Rows for many entities at once (a wave of spawns costs one concatenate)."""
        new = [e for e in dict.fromkeys(entities) if e not in self.rows]
        if not new:
            return
        n0, k = len(self.entity), len(new)
        for i, e in enumerate(new):
            self.rows[e] = n0 + i
        self.entity = np.concatenate([self.entity, np.array(new, np.int64)])
        self.clip = np.concatenate([self.clip, np.zeros(k, np.intp)])
        self.time = np.concatenate([self.time, np.zeros(k)])
        self.speed = np.concatenate([self.speed, np.ones(k)])
        self.playing = np.concatenate([self.playing, np.zeros(k, bool)])
        self.finished = np.concatenate([self.finished, np.zeros(k, bool)])
        self.fresh = np.concatenate([self.fresh, np.zeros(k, bool)])
        self.shown = np.concatenate([self.shown, np.zeros(k, np.intp)])
        self.from_clip = np.concatenate([self.from_clip, np.full(k, -1, np.intp)])
        self.from_shown = np.concatenate([self.from_shown, np.zeros(k, np.intp)])
        for name in ("from_time", "from_rate", "fade_t", "fade_len"):
            setattr(self, name, np.concatenate([getattr(self, name), np.zeros(k)]))
        self.version += 1

    def remove(self, entity: int) -> None:
        """Drop ``entity``'s row (the last row moves into its place)."""
        row = self.rows.pop(entity, None)
        if row is None:
            return
        last = len(self.entity) - 1
        arrays = ("entity", "clip", "time", "speed", "playing", "finished", "fresh", "shown",
                  "from_clip", "from_time", "from_rate", "from_shown", "fade_t", "fade_len")
        if row != last:
            moved = int(self.entity[last])
            for name in arrays:
                arr = getattr(self, name)
                arr[row] = arr[last]
            self.rows[moved] = row
        for name in arrays:
            setattr(self, name, getattr(self, name)[:last])
        self.version += 1

    def start(self, row: int, slot: int, *, stopped: bool = False, fade: float = 0.0) -> None:
        """Row ``row`` plays clip ``slot`` from its first frame (``stopped``: shows it, still);
        a row of negative speed plays it backwards from its end. ``fade`` > 0 cross-fades
        from what the row showed (that clip runs on, fading out over ``fade`` seconds)."""
        if fade > 0.0 and not stopped:
            t = self.table
            t.ensure()
            old = int(self.clip[row])
            moving = bool(self.playing[row]) and not bool(self.finished[row])
            self.from_clip[row] = old
            once_over = bool(self.finished[row]) and int(t.mode[old]) == ONCE
            self.from_time[row] = 0.0 if once_over else self.time[row]  # it shows frame 0
            self.from_rate[row] = self.speed[row] * t.speed[old] if moving else 0.0
            self.from_shown[row] = self.shown[row]
            self.fade_t[row] = 0.0
            self.fade_len[row] = fade
        else:
            self.end_fade(row)
        self.clip[row] = slot
        self.time[row] = 0.0
        self.finished[row] = stopped
        self.fresh[row] = not stopped
        self.shown[row] = self.table.first_frame(slot)
        if self.speed[row] < 0 and not stopped:
            self.table.ensure()
            self.seek(row, float(self.table.total[slot]))

    def end_fade(self, row: int) -> None:
        """Row ``row`` shows its clip alone (a cross-fade, if any, is over)."""
        self.from_clip[row] = -1
        self.fade_t[row] = self.fade_len[row] = 0.0

    def weight(self, row: int) -> float:
        """How much of the incoming clip ``row`` shows: 1 unless it cross-fades (0 -> 1)."""
        total = float(self.fade_len[row])
        return 1.0 if total <= 0.0 else min(float(self.fade_t[row]) / total, 1.0)

    def compact(self, slack: int = 32) -> bool:
        """Drop the clips no row plays once they outnumber the played ones (plus
        ``slack``), renumbering the rows' slots and frames; True if it did."""
        t = self.table
        fading = self.from_clip >= 0
        live = np.unique(np.concatenate([self.clip, self.from_clip[fading]])).tolist() if len(
            self.clip) else []
        if len(t) - len(live) <= max(len(live), slack if live else 0):
            return False
        t.ensure()
        table, remap = t.rebuilt(live)
        offset = self.shown - t.first[self.clip]
        self.clip = remap[self.clip]
        self.shown = table.first[self.clip] + offset
        if fading.any():
            src = self.from_clip[fading]
            inner = self.from_shown[fading] - t.first[src]
            self.from_clip[fading] = remap[src]
            self.from_shown[fading] = table.first[self.from_clip[fading]] + inner
        self.table = table
        self.version += 1
        return True

    def seek(self, row: int, time: float) -> None:
        """Put ``row`` at clip time ``time`` (clamped to the clip), showing its frame."""
        t = self.table
        t.ensure()
        slot = int(self.clip[row])
        total = float(t.total[slot])
        time = min(max(float(time), 0.0), total)
        self.time[row] = time
        first = int(t.first[slot])
        g = int(np.searchsorted(t.frame_end, t.base[slot] + time + EPS, side="right"))
        self.shown[row] = min(max(g, first), first + int(t.length[slot]) - 1)

    def local_frame(self, row: int) -> int:
        """The original frame index (inside its clip) shown by ``row``."""
        self.table.ensure()
        return int(self.table.frame_orig[self.shown[row]])

    def advance(self, dt: float) -> Crossings:
        """Move every playing row by ``dt`` seconds of game time; see the module docstring."""
        t = self.table
        t.ensure()
        n = len(self.entity)
        if n == 0 or not len(t.total):
            return Crossings([], np.zeros(0, np.intp))
        clip = self.clip
        rate = np.where(self.playing & ~self.finished, self.speed * t.speed[clip], 0.0)
        after = self.time + rate * dt
        rev = rate < 0  # playing backwards (a negative animator speed)
        # crossings are counted in (before, after] shifted by EPS like the frame lookup;
        # a fresh start counts from just below 0 so frame 0's events fire; backwards,
        # a frame start is crossed in [after, time)
        before = np.where(self.fresh, -EPS, self.time + EPS)
        total = t.total[clip]
        mode = t.mode[clip]
        looping = mode == LOOP
        events: list[tuple[int, int, str, int]] = []
        if t.has_events.any():
            lo = np.where(rev, after - EPS, before)
            hi = np.where(rev, self.time - EPS, after + EPS)
            events = self._events(lo, hi, total, looping, rev)
        ended = ~looping & ~self.finished & np.where(rev, after <= EPS, after + EPS >= total)
        finished_rows = np.flatnonzero(ended)
        # wrap loops (keeps precision over hours of play)
        laps = np.floor((after + EPS) / total)
        wrapped = np.where(looping, np.maximum(after - laps * total, 0.0), np.maximum(after, 0.0))
        self.time = wrapped
        self.finished |= ended
        local = np.where(looping, wrapped, np.minimum(wrapped, total))
        local = np.where(self.finished & (mode == ONCE), 0.0, local)
        first = t.first[clip]
        g = np.searchsorted(t.frame_end, t.base[clip] + local + EPS, side="right")
        self.shown = np.minimum(np.maximum(g, first), first + t.length[clip] - 1)
        self.fresh[:] = False
        if self.fade_len.any():
            self._fade(dt)
        return Crossings(events, finished_rows)

    def _fade(self, dt: float) -> None:
        """Cross-fades: the outgoing clips run on (without events) and fade out."""
        t = self.table
        rows = np.flatnonzero(self.fade_len > 0.0)
        self.fade_t[rows] += np.where(self.playing[rows], dt, 0.0)
        over = rows[self.fade_t[rows] >= self.fade_len[rows]]
        self.from_clip[over] = -1
        self.fade_t[over] = self.fade_len[over] = 0.0
        rows = np.flatnonzero(self.fade_len > 0.0)
        if not len(rows):
            return
        clip = self.from_clip[rows]
        total, looping = t.total[clip], t.mode[clip] == LOOP
        after = self.from_time[rows] + np.where(self.playing[rows], self.from_rate[rows], 0.) * dt
        laps = np.floor((after + EPS) / total)
        local = np.where(looping, after - laps * total, after)
        local = np.minimum(np.maximum(local, 0.0), total)
        self.from_time[rows] = local
        first = t.first[clip]
        g = np.searchsorted(t.frame_end, t.base[clip] + local + EPS, side="right")
        self.from_shown[rows] = np.minimum(np.maximum(g, first), first + t.length[clip] - 1)

    def _events(
        self, before: np.ndarray, after: np.ndarray, total: np.ndarray, looping: np.ndarray,
        backwards: np.ndarray | None = None,
    ) -> list[tuple[int, int, str, int]]:
        """Frame events crossed in (before, after], ordered by row then time (latest
        first for rows playing ``backwards``)."""
        t = self.table
        found: list[tuple[int, float, int, str, int]] = []
        with_events = t.has_events[self.clip]
        for slot in np.unique(self.clip[with_events]).tolist():
            info = t.infos[slot]
            rows = np.flatnonzero((self.clip == slot) & (after > before))
            if not len(rows):
                continue
            b, a, tot, lp = before[rows], after[rows], total[rows], looping[rows]
            for start, frame, name in info.events:
                looped = np.floor((a - start) / tot) - np.floor((b - start) / tot)
                single = ((b < start) & (start <= a)).astype(float)
                count = np.where(lp, looped, single).astype(np.int64)
                hit = count > 0
                for r, c in zip(rows[hit].tolist(), count[hit].tolist(), strict=True):
                    lap = float(total[r])
                    found.extend((r, start + k * lap, slot, name, frame) for k in range(c))
        sign = np.where(backwards, -1.0, 1.0) if backwards is not None else np.ones(len(before))
        found.sort(key=lambda item: (int(self.entity[item[0]]), sign[item[0]] * item[1]))
        return [(r, slot, name, frame) for r, _, slot, name, frame in found]
