"""Immediate-mode debug drawing: lines, arrows, circles, boxes and text for one frame.

Call it from any system or script, every frame you want the shape shown; nothing is
kept (Bevy's gizmos, Unity's ``Debug.DrawLine``)::

    gizmos = world.resource(kge.Gizmos)
    gizmos.line((0, 0), (2, 1), color=(255, 80, 80))
    gizmos.arrow(body_pos, body_pos + velocity)
    gizmos.circle(target, 0.5)
    gizmos.text(pos, f"hp {hp}")

How long a shape lives:

* drawn from frame code (``on_update``, UPDATE/LATE/INPUT systems, a test between
  frames): until the next frame starts;
* drawn from fixed-step code (``on_fixed_update``, FIXED systems): until the next
  fixed step starts, so at 144 frames a second and 60 steps it does not flicker,
  and while the game is paused it stays;
* ``duration=`` seconds of game time: that long, whichever code drew it.

Everything is plain numpy data, so it works headless: a test reads
:meth:`Gizmos.segments` and :meth:`Gizmos.texts`, and a window draws them on top of
the world (one vertex list of lines per frame, see :mod:`kge.render.gizmos`).
``enabled = False`` makes every call return at once (a release build).

>>> g = Gizmos()
>>> g.line((0, 0), (1, 0)); g.circle((0, 0), 1.0, segments=8)
>>> len(g.segments()[0])       # one line + 8 circle sides
9
>>> g.line((0, 0), (float("nan"), 0))
Traceback (most recent call last):
...
kge.errors.ValidationError: Gizmos.line: end must be finite numbers, got (nan, 0)
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from kge.errors import ValidationError

Vec2 = tuple[float, float]
RGBA = tuple[int, int, int, int]
WHITE: RGBA = (255, 255, 255, 255)

#: where a shape lives: until the next frame, the next fixed step, or a time
FRAME, STEP, TIMED = 0, 1, 2


@dataclass(slots=True, frozen=True)
class GizmoText:
    """One text gizmo: ``position`` in metres (or window pixels with ``screen``)."""

    position: Vec2
    text: str
    color: RGBA
    size: float
    screen: bool


def _point(value: Any, call: str, what: str) -> Vec2:
    try:
        x, y = value
        fx, fy = float(x), float(y)
    except (TypeError, ValueError):
        raise ValidationError(f"Gizmos.{call}: {what} must be (x, y), got {value!r}") from None
    if not (math.isfinite(fx) and math.isfinite(fy)):
        raise ValidationError(f"Gizmos.{call}: {what} must be finite numbers, got {value!r}")
    return fx, fy


def _color(value: Any, call: str) -> RGBA:
    try:
        parts = [int(v) for v in value]
    except (TypeError, ValueError):
        raise ValidationError(
            f"Gizmos.{call}: color must be (r, g, b[, a]), got {value!r}"
        ) from None
    if len(parts) == 3:
        parts.append(255)
    if len(parts) != 4 or any(not 0 <= v <= 255 for v in parts):
        raise ValidationError(
            f"Gizmos.{call}: color must be 3 or 4 numbers in 0..255, got {value!r}"
        )
    return (parts[0], parts[1], parts[2], parts[3])


def _positive(value: Any, call: str, what: str) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValidationError(f"Gizmos.{call}: {what} must be a number, got {value!r}") from None
    if not (math.isfinite(v) and v > 0):
        raise ValidationError(f"Gizmos.{call}: {what} must be > 0, got {value!r}")
    return v


class _Buffer:
    """Segments and texts of one lifetime."""

    __slots__ = ("chunks", "colors", "expiry", "flat", "flat_colors", "text_expiry", "texts")

    def __init__(self) -> None:
        self.flat: list[float] = []  # x0, y0, x1, y1 of single segments
        self.flat_colors: list[RGBA] = []
        self.chunks: list[tuple[np.ndarray, RGBA]] = []  # (k, 4) segment arrays
        self.expiry: list[float] = []  # per flat segment, then per chunk (TIMED only)
        self.texts: list[GizmoText] = []
        self.text_expiry: list[float] = []

    def clear(self) -> None:
        self.flat.clear()
        self.flat_colors.clear()
        self.chunks.clear()
        self.expiry.clear()
        self.texts.clear()
        self.text_expiry.clear()

    def count(self) -> int:
        return len(self.flat_colors) + sum(len(c) for c, _ in self.chunks)


class Gizmos:
    """The world's immediate-mode debug drawing (a resource; see the module docstring)."""

    def __init__(self) -> None:
        self.enabled = True
        #: game time (seconds) used for ``duration``; the debug plugin keeps it current
        self.now = 0.0
        #: True while a fixed step runs (the debug plugin's systems set it)
        self.in_step = False
        self._buffers = (_Buffer(), _Buffer(), _Buffer())

    # -- drawing ---------------------------------------------------------------------------
    def _buffer(self, duration: float | None, call: str) -> tuple[_Buffer, float]:
        if duration is None:
            return self._buffers[STEP if self.in_step else FRAME], 0.0
        d = _positive(duration, call, "duration")
        return self._buffers[TIMED], self.now + d

    def line(self, start: Any, end: Any, color: Any = WHITE, *,
             duration: float | None = None) -> None:
        """A segment from ``start`` to ``end`` (metres)."""
        if not self.enabled:
            return
        a, b = _point(start, "line", "start"), _point(end, "line", "end")
        c = WHITE if color is WHITE else _color(color, "line")
        buf, until = self._buffer(duration, "line")
        buf.flat.extend((a[0], a[1], b[0], b[1]))
        buf.flat_colors.append(c)
        if duration is not None:
            buf.expiry.append(until)

    def lines(self, segments: Any, color: Any = WHITE, *, duration: float | None = None) -> None:
        """Many segments at once: an (n, 4) array of x0, y0, x1, y1 (or (n, 2, 2))."""
        if not self.enabled:
            return
        arr = np.asarray(segments, dtype=float)
        if arr.ndim == 3 and arr.shape[1:] == (2, 2):
            arr = arr.reshape(-1, 4)
        if arr.ndim != 2 or arr.shape[1] != 4:
            raise ValidationError(
                f"Gizmos.lines: segments must be (n, 4) or (n, 2, 2), got shape {arr.shape}"
            )
        if not np.isfinite(arr).all():
            raise ValidationError("Gizmos.lines: segments must be finite numbers")
        if not len(arr):
            return
        self._chunk(arr, _color(color, "lines"), duration, "lines")

    def polyline(self, points: Any, color: Any = WHITE, *, closed: bool = False,
                 duration: float | None = None) -> None:
        """Segments joining ``points`` in order (``closed``: back to the first)."""
        if not self.enabled:
            return
        pts = np.asarray(points, dtype=float)
        if pts.ndim != 2 or pts.shape[1] != 2 or len(pts) < 2:
            raise ValidationError("Gizmos.polyline: points must be two or more (x, y) pairs")
        if not np.isfinite(pts).all():
            raise ValidationError("Gizmos.polyline: points must be finite numbers")
        ends = np.roll(pts, -1, axis=0) if closed else pts[1:]
        starts = pts if closed else pts[:-1]
        self._chunk(np.hstack([starts, ends]), _color(color, "polyline"), duration, "polyline")

    def _chunk(self, arr: np.ndarray, color: RGBA, duration: float | None, call: str) -> None:
        buf, until = self._buffer(duration, call)
        buf.chunks.append((arr, color))
        if duration is not None:
            buf.expiry.append(until)

    def arrow(self, start: Any, end: Any, color: Any = WHITE, *, head: float | None = None,
              duration: float | None = None) -> None:
        """A line with an arrow head at ``end`` (``head``: its length, default a quarter
        of the arrow, at most 0.3 m)."""
        if not self.enabled:
            return
        a, b = _point(start, "arrow", "start"), _point(end, "arrow", "end")
        dx, dy = b[0] - a[0], b[1] - a[1]
        length = math.hypot(dx, dy)
        size = min(0.25 * length, 0.3) if head is None else _positive(head, "arrow", "head")
        segs = [(a[0], a[1], b[0], b[1])]
        if length > 0:
            ux, uy = dx / length, dy / length
            for side in (1.0, -1.0):
                c, s = math.cos(side * 2.6), math.sin(side * 2.6)  # ~150 degrees back
                segs.append((b[0], b[1], b[0] + size * (c * ux - s * uy),
                             b[1] + size * (s * ux + c * uy)))  # fmt: skip
        self._chunk(np.array(segs), _color(color, "arrow"), duration, "arrow")

    def circle(self, center: Any, radius: float, color: Any = WHITE, *, segments: int = 32,
               duration: float | None = None) -> None:
        """A circle outline of ``radius`` metres."""
        if not self.enabled:
            return
        cx, cy = _point(center, "circle", "center")
        r = _positive(radius, "circle", "radius")
        n = int(segments)
        if not 3 <= n <= 1024:
            raise ValidationError(f"Gizmos.circle: segments must be in 3..1024, got {segments!r}")
        t = np.linspace(0.0, 2.0 * math.pi, n + 1)
        xs, ys = cx + r * np.cos(t), cy + r * np.sin(t)
        arr = np.stack([xs[:-1], ys[:-1], xs[1:], ys[1:]], axis=1)
        self._chunk(arr, _color(color, "circle"), duration, "circle")

    def rect(self, center: Any, size: Any, color: Any = WHITE, *, angle: float = 0.0,
             duration: float | None = None) -> None:
        """A rectangle outline: ``size`` = (width, height) metres, turned by ``angle``."""
        if not self.enabled:
            return
        cx, cy = _point(center, "rect", "center")
        w, h = _point(size, "rect", "size")
        if w < 0 or h < 0:
            raise ValidationError(f"Gizmos.rect: size must be >= 0, got {size!r}")
        c, s = math.cos(angle), math.sin(angle)
        corners = [(-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2)]
        pts = [(cx + c * x - s * y, cy + s * x + c * y) for x, y in corners]
        self.polyline(pts, color, closed=True, duration=duration)

    def cross(self, center: Any, size: float = 0.2, color: Any = WHITE, *,
              duration: float | None = None) -> None:
        """A small + marking a point (``size`` metres across)."""
        if not self.enabled:
            return
        x, y = _point(center, "cross", "center")
        h = _positive(size, "cross", "size") / 2
        arr = np.array([(x - h, y, x + h, y), (x, y - h, x, y + h)])
        self._chunk(arr, _color(color, "cross"), duration, "cross")

    def text(self, position: Any, text: Any, color: Any = WHITE, *, size: float = 12.0,
             screen: bool = False, duration: float | None = None) -> None:
        """``text`` at ``position`` (metres; window pixels from the bottom-left with
        ``screen=True``), ``size`` in points."""
        if not self.enabled:
            return
        pos = _point(position, "text", "position")
        item = GizmoText(pos, str(text), _color(color, "text"), _positive(size, "text", "size"),
                         bool(screen))  # fmt: skip
        buf, until = self._buffer(duration, "text")
        buf.texts.append(item)
        if duration is not None:
            buf.text_expiry.append(until)

    # -- reading (the renderer, tests) ----------------------------------------------------------
    def segments(self) -> tuple[np.ndarray, np.ndarray]:
        """Every live segment: ((n, 4) float x0, y0, x1, y1; (n, 4) uint8 RGBA)."""
        segs: list[np.ndarray] = []
        cols: list[np.ndarray] = []
        for buf in self._buffers:
            if buf.flat_colors:
                segs.append(np.asarray(buf.flat, float).reshape(-1, 4))
                cols.append(np.asarray(buf.flat_colors, np.uint8))
            for arr, color in buf.chunks:
                segs.append(arr)
                cols.append(np.broadcast_to(np.asarray(color, np.uint8), (len(arr), 4)))
        if not segs:
            return np.zeros((0, 4)), np.zeros((0, 4), np.uint8)
        return np.concatenate(segs), np.concatenate(cols)

    def texts(self) -> list[GizmoText]:
        """Every live text gizmo."""
        return [t for buf in self._buffers for t in buf.texts]

    def __len__(self) -> int:
        """How many segments and texts are live."""
        return sum(b.count() + len(b.texts) for b in self._buffers)

    # -- lifetimes (the debug plugin's systems) ------------------------------------------------
    def begin_frame(self, now: float) -> None:
        """A frame starts: frame shapes go, timed ones past their time go."""
        self.in_step = False
        self.now = now
        self._buffers[FRAME].clear()
        self.expire(now)

    def begin_step(self) -> None:
        """A fixed step starts: the previous step's shapes go."""
        self.in_step = True
        self._buffers[STEP].clear()

    def end_step(self) -> None:
        self.in_step = False

    def clear(self) -> None:
        """Forget every shape now."""
        for buf in self._buffers:
            buf.clear()

    def expire(self, now: float) -> None:
        """Drop the timed shapes whose time is up at game time ``now``."""
        self.now = now
        timed = self._buffers[TIMED]
        if timed.expiry:
            n_flat = len(timed.flat_colors)
            keep = [i for i, t in enumerate(timed.expiry) if t > now]
            if len(keep) < len(timed.expiry):
                flat_keep = [i for i in keep if i < n_flat]
                chunk_keep = [i - n_flat for i in keep if i >= n_flat]
                timed.flat = [v for i in flat_keep for v in timed.flat[4 * i : 4 * i + 4]]
                timed.flat_colors = [timed.flat_colors[i] for i in flat_keep]
                timed.chunks = [timed.chunks[i] for i in chunk_keep]
                timed.expiry = [timed.expiry[i] for i in keep]
        if timed.text_expiry:
            keep = [i for i, t in enumerate(timed.text_expiry) if t > now]
            timed.texts = [timed.texts[i] for i in keep]
            timed.text_expiry = [timed.text_expiry[i] for i in keep]

    def __repr__(self) -> str:
        return f"<Gizmos {len(self)} live>"


def bulk_circles(centers: Iterable[Sequence[float]], radius: float,
                 segments: int = 16) -> np.ndarray:
    """(n * segments, 4) segments of circles of one radius around each centre (one call
    for many: ``gizmos.lines(bulk_circles(points, 0.1), color)``).

    >>> bulk_circles([(0, 0), (5, 0)], 1.0, 4).shape
    (8, 4)
    """
    c = np.asarray(list(centers), float).reshape(-1, 2)
    t = np.linspace(0.0, 2.0 * math.pi, segments + 1)
    ring = np.stack([np.cos(t), np.sin(t)], axis=1) * radius
    a = (c[:, None, :] + ring[None, :-1, :]).reshape(-1, 2)
    b = (c[:, None, :] + ring[None, 1:, :]).reshape(-1, 2)
    return np.hstack([a, b])
