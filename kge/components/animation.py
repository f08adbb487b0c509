"""Sprite animation as data: ``Clip`` (frames and timing) and ``Animator`` (which clip plays).

A :class:`Clip` is an immutable list of frames, each a :class:`FrameRef` (an
image, and which part of it) with a duration in seconds, plus how it repeats
(:class:`Loop`):

==================  ==========================================================
``Loop.LOOP``       frame 0 again after the last, forever
``Loop.ONCE``       plays once, then shows frame 0 and stops (a finished event)
``Loop.HOLD``       plays once, then holds the last frame (a finished event)
``Loop.PING_PONG``  0, 1, ..., n-1, n-2, ..., 1, 0, 1, ... forever
==================  ==========================================================

Clips come from a sheet grid (:meth:`Clip.grid`), a list of images
(:meth:`Clip.images`), an Aseprite-style tag list (:meth:`Clip.tags`) or a GIF
(``kge.animation.gif_clip``, durations from the file). ``events`` names frames:
``events={3: "footstep"}`` emits an :class:`~kge.animation.AnimationEvent` each
time frame 3 is entered.

An :class:`Animator` sits beside a :class:`~kge.components.sprite.Sprite` and
holds named clips, the one playing, a queue and a small transition table; the
animation system advances every animator at once with numpy on game time, and
draws the current frame through a texture atlas (the Sprite still decides
layer, size, anchor, tint and opacity).

>>> walk = Clip.grid("hero.png", (8, 4), frames=range(8, 16), fps=12, events={2: "step"})
>>> len(walk.frames), round(walk.duration, 4)
(8, 0.6667)
>>> anim = Animator({"walk": walk, "idle": Clip.grid("hero.png", (8, 4), frames=[0])})
>>> anim.play("run")
Traceback (most recent call last):
...
kge.errors.ValidationError: Animator.play: unknown clip 'run'; the clips are: idle, walk
>>> Clip.grid("hero.png", (8, 4), frames=[32])
Traceback (most recent call last):
...
kge.errors.ValidationError: Clip.frames[0]: frame 32 is outside the 8x4 sheet (0..31)
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Any, ClassVar

from kge.components.conditions import met as condition_met
from kge.components.conditions import parse as parse_condition
from kge.components.tracked import Check, Tracked
from kge.deprecation import enum_value
from kge.errors import ComponentTypeError, ValidationError
from kge.validate import (
    at_most,
    boolean,
    finite,
    integer,
    name_map,
    non_negative,
    positive,
)


class Loop(StrEnum):
    """How a :class:`Clip` repeats (see the module docstring)."""

    LOOP = "loop"
    ONCE = "once"
    HOLD = "hold"
    PING_PONG = "ping_pong"


LOOP_MODES = tuple(Loop)
Rect4 = tuple[int, int, int, int]
#: the shortest and longest frame, seconds (fps from 1e-6 to 1e6)
MIN_FRAME, MAX_FRAME = 1e-6, 1e6
#: the fastest playback speed (a clip's, an animator's)
MAX_SPEED = 1e3
#: the longest cross-fade between two clips, seconds
MAX_FADE = 3600.0
#: the most frames one clip may have, and the most cells a sheet grid may have per side
MAX_FRAMES = 10_000
MAX_GRID = 65_536


def _cell_count(value: Any, owner: str, field: str) -> int:
    v = integer(value, owner, field)
    if not 1 <= v <= MAX_GRID:
        raise ValidationError(f"{owner}.{field} must be in 1..{MAX_GRID}, got {v}")
    return v


def _pixels(value: Any, owner: str, field: str, low: int) -> int:
    v = integer(value, owner, field)
    if not low <= v <= 2**31 - 1:
        raise ValidationError(f"{owner}.{field} must be an int >= {low}, got {v}")
    return v


def _frame_seconds(value: Any, owner: str, field: str) -> float:
    v = positive(value, owner, field)
    if not MIN_FRAME <= v <= MAX_FRAME:
        raise ValidationError(
            f"{owner}.{field} must be in [{MIN_FRAME:g}, {MAX_FRAME:g}] seconds per frame, "
            f"got {v!r}"
        )
    return v


def fade_seconds(value: Any, owner: str, field: str) -> float:
    """A cross-fade's length: 0 (a cut) up to :data:`MAX_FADE` seconds."""
    return at_most(non_negative(value, owner, field), MAX_FADE, owner, field, "s")


def _clip_speed(value: Any, owner: str, field: str) -> float:
    return at_most(positive(value, owner, field), MAX_SPEED, owner, field)


@dataclass(slots=True, frozen=True)
class FrameRef:
    """One frame's pixels: ``image`` (asset name/path or in-memory image) and which part.

    ``region`` is ``(x, y, w, h)`` pixels from the image's top-left; or ``grid`` =
    (columns, rows) with ``index`` counted row by row from the top-left, cells
    ``margin`` pixels from the edge and ``spacing`` pixels apart; or ``gif_frame``,
    the frame number inside an animated GIF. With none of them, the whole image.
    """

    image: Any
    region: Rect4 | None = None
    grid: tuple[int, int] | None = None
    index: int = 0
    margin: int = 0
    spacing: int = 0
    gif_frame: int | None = None

    def __post_init__(self) -> None:
        owner = "FrameRef"
        if self.image is None or isinstance(self.image, (bool, int, float, bytes)) or (
            isinstance(self.image, str) and not self.image
        ):
            raise ComponentTypeError(
                f"{owner}.image must be an asset name, a path or an image, got {self.image!r}"
            )
        if self.region is not None:
            if not isinstance(self.region, (tuple, list)) or len(self.region) != 4:
                raise ComponentTypeError(
                    f"{owner}.region must be (x, y, w, h), got {self.region!r}"
                )
            x, y, w, h = (
                _pixels(v, owner, f"region[{i}]", 1 if i >= 2 else 0)
                for i, v in enumerate(self.region)
            )
            object.__setattr__(self, "region", (x, y, w, h))
        if self.grid is not None:
            if not isinstance(self.grid, (tuple, list)) or len(self.grid) != 2:
                raise ComponentTypeError(f"{owner}.grid must be (columns, rows), got {self.grid!r}")
            cols, rows = (_cell_count(v, owner, f"grid[{i}]") for i, v in enumerate(self.grid))
            object.__setattr__(self, "grid", (cols, rows))
            index = integer(self.index, owner, "index")
            if not 0 <= index < cols * rows:
                raise ValidationError(
                    f"{owner}.index: frame {index} is outside the {cols}x{rows} sheet "
                    f"(0..{cols * rows - 1})"
                )
        _pixels(self.margin, owner, "margin", 0)
        _pixels(self.spacing, owner, "spacing", 0)
        if self.gif_frame is not None:
            _pixels(self.gif_frame, owner, "gif_frame", 0)

    def rect(self, width: int, height: int) -> Rect4:
        """The (x, y, w, h) pixel rectangle from the image's **bottom**-left (OpenGL rows).

        >>> FrameRef("s.png", grid=(4, 2), index=5).rect(64, 32)
        (16, 0, 16, 16)
        >>> FrameRef("s.png", grid=(2, 1), index=1, margin=1, spacing=2).rect(12, 6)
        (7, 1, 4, 4)
        """
        if self.grid is not None:
            cols, rows = self.grid
            m, s = self.margin, self.spacing
            w = (width - 2 * m - (cols - 1) * s) // cols
            h = (height - 2 * m - (rows - 1) * s) // rows
            if w < 1 or h < 1:
                raise ValidationError(
                    f"FrameRef: a {width}x{height} image has no room for a {cols}x{rows} grid "
                    f"with margin {m} and spacing {s}"
                )
            col, row = self.index % cols, self.index // cols
            x = m + col * (w + s)
            top = m + row * (h + s)
            return (x, height - top - h, w, h)
        if self.region is not None:
            x, y, w, h = self.region
            if x + w > width or y + h > height:
                raise ValidationError(
                    f"FrameRef.region {self.region!r} is outside the {width}x{height} image"
                )
            return (x, height - y - h, w, h)
        return (0, 0, width, height)


def _durations(n: int, duration: Any, fps: Any, owner: str) -> tuple[float, ...]:
    if n == 0:
        raise ValidationError(f"{owner}: a clip needs at least one frame (got an empty list)")
    if n > MAX_FRAMES:
        raise ValidationError(f"{owner}: a clip has at most {MAX_FRAMES:,} frames, got {n:,}")
    if fps is not None:
        if duration is not None:
            raise ValidationError(f"{owner}: give duration= or fps=, not both")
        f = positive(fps, owner, "fps")
        if not 1.0 / MAX_FRAME <= f <= 1.0 / MIN_FRAME:
            raise ValidationError(
                f"{owner}.fps must be in [{1.0 / MAX_FRAME:g}, {1.0 / MIN_FRAME:g}], got {f!r}"
            )
        return (1.0 / f,) * n
    if duration is None:
        duration = 0.1
    if isinstance(duration, (int, float)) and not isinstance(duration, bool):
        return (_frame_seconds(duration, owner, "duration"),) * n
    try:
        values = list(duration)
    except TypeError:
        raise ComponentTypeError(
            f"{owner}.duration must be seconds or a list of seconds per frame, got {duration!r}"
        ) from None
    if len(values) != n:
        raise ValidationError(
            f"{owner}.duration has {len(values)} values for {n} frames (one per frame)"
        )
    return tuple(_frame_seconds(v, owner, f"duration[{i}]") for i, v in enumerate(values))


def _events(events: Any, n: int, owner: str) -> tuple[tuple[int, str], ...]:
    if events is None:
        return ()
    if not isinstance(events, Mapping):
        raise ComponentTypeError(f"{owner}.events must be {{frame: name}}, got {events!r}")
    out = []
    for k, name in events.items():
        i = integer(k, owner, "events")
        if not 0 <= i < n:
            raise ValidationError(f"{owner}.events: frame {i} is outside the clip's {n} frames")
        if not isinstance(name, str) or not name:
            raise ValidationError(f"{owner}.events[{i}] must be a non-empty name, got {name!r}")
        out.append((i, name))
    return tuple(sorted(out))


@dataclass(slots=True, frozen=True)
class Clip:
    """Frames, their durations (s), a loop mode, a speed, flips and named frame events."""

    frames: tuple[FrameRef, ...]
    durations: tuple[float, ...]
    loop: Loop = Loop.LOOP
    speed: float = 1.0
    flip_x: bool = False
    flip_y: bool = False
    events: tuple[tuple[int, str], ...] = ()

    def __post_init__(self) -> None:
        owner = "Clip"
        if not isinstance(self.frames, tuple) or not self.frames:
            raise ValidationError(f"{owner}.frames: a clip needs at least one frame")
        if len(self.frames) > MAX_FRAMES:
            raise ValidationError(
                f"{owner}.frames: a clip has at most {MAX_FRAMES:,} frames, "
                f"got {len(self.frames):,}"
            )
        if not isinstance(self.durations, tuple):
            raise ComponentTypeError(f"{owner}.durations must be a tuple of seconds per frame")
        for i, f in enumerate(self.frames):
            if not isinstance(f, FrameRef):
                raise ComponentTypeError(f"{owner}.frames[{i}] must be a FrameRef, got {f!r}")
        if len(self.durations) != len(self.frames):
            raise ValidationError(
                f"{owner}.durations has {len(self.durations)} values for {len(self.frames)} frames"
            )
        for i, d in enumerate(self.durations):
            _frame_seconds(d, owner, f"durations[{i}]")
        object.__setattr__(self, "loop", enum_value(Loop, self.loop, owner, "loop"))
        _clip_speed(self.speed, owner, "speed")
        boolean(self.flip_x, owner, "flip_x")
        boolean(self.flip_y, owner, "flip_y")

    @property
    def duration(self) -> float:
        """One pass through the frames, in seconds at speed 1."""
        return math.fsum(self.durations)

    # -- constructors ---------------------------------------------------------------
    @classmethod
    def grid(
        cls,
        image: Any,
        grid: tuple[int, int],
        frames: Iterable[int] | None = None,
        *,
        margin: int = 0,
        spacing: int = 0,
        duration: float | Sequence[float] | None = None,
        fps: float | None = None,
        loop: Loop | str = Loop.LOOP,
        speed: float = 1.0,
        flip_x: bool = False,
        flip_y: bool = False,
        events: Mapping[int, str] | None = None,
    ) -> Clip:
        """Frames of a sheet cut in ``grid`` = (columns, rows), counted row by row from the
        top-left; ``frames`` picks and orders them (default: all)."""
        owner = "Clip"
        if not isinstance(grid, (tuple, list)) or len(grid) != 2:
            raise ComponentTypeError(f"{owner}.grid must be (columns, rows), got {grid!r}")
        cols, rows = (integer(v, owner, f"grid[{i}]") for i, v in enumerate(grid))
        if cols < 1 or rows < 1:
            raise ValidationError(f"{owner}.grid must be (columns >= 1, rows >= 1), got {grid!r}")
        m = integer(margin, owner, "margin")
        s = integer(spacing, owner, "spacing")
        if m < 0 or s < 0:
            raise ValidationError(f"{owner}: margin and spacing must be >= 0, got {m}, {s}")
        if cols > MAX_GRID or rows > MAX_GRID:
            raise ValidationError(
                f"{owner}.grid must be at most {MAX_GRID} cells a side, got {grid!r}"
            )
        if frames is None and cols * rows > MAX_FRAMES:
            raise ValidationError(
                f"{owner}.grid {cols}x{rows} has {cols * rows:,} cells, more frames than a clip "
                f"may have ({MAX_FRAMES:,}): pick them with frames="
            )
        picked = list(range(cols * rows)) if frames is None else list(itertools.islice(
            frames, MAX_FRAMES + 1))
        refs = []
        for i, k in enumerate(picked):
            k = integer(k, owner, f"frames[{i}]")
            if not 0 <= k < cols * rows:
                raise ValidationError(
                    f"{owner}.frames[{i}]: frame {k} is outside the {cols}x{rows} sheet "
                    f"(0..{cols * rows - 1})"
                )
            refs.append(FrameRef(image, grid=(cols, rows), index=k, margin=m, spacing=s))
        return cls._make(refs, duration, fps, loop, speed, flip_x, flip_y, events)

    @classmethod
    def images(
        cls,
        images: Sequence[Any],
        *,
        duration: float | Sequence[float] | None = None,
        fps: float | None = None,
        loop: Loop | str = Loop.LOOP,
        speed: float = 1.0,
        flip_x: bool = False,
        flip_y: bool = False,
        events: Mapping[int, str] | None = None,
    ) -> Clip:
        """One frame per image (asset names/paths or in-memory images of one size)."""
        if isinstance(images, (str, bytes)) or not isinstance(images, Sequence):
            raise ComponentTypeError(f"Clip.images needs a list of images, got {images!r}")
        for i, img in enumerate(images):
            if img is None or isinstance(img, (int, float, bool)) or img == "":
                raise ComponentTypeError(f"Clip.images[{i}] is not an image: {img!r}")
        refs = [FrameRef(img) for img in images]
        return cls._make(refs, duration, fps, loop, speed, flip_x, flip_y, events)

    @classmethod
    def tags(
        cls,
        image: Any,
        grid: tuple[int, int],
        tags: Mapping[str, tuple[int, int]],
        **options: Any,
    ) -> dict[str, Clip]:
        """Aseprite-style tags: ``{"walk": (0, 7), "jump": (8, 11)}`` (inclusive frame ranges
        of one sheet) -> one clip per tag, all with the same ``options``."""
        out = {}
        for name, span in tags.items():
            if not isinstance(span, (tuple, list)) or len(span) != 2:
                raise ComponentTypeError(f"Clip.tags[{name!r}] must be (first, last), got {span!r}")
            first, last = (integer(v, "Clip", f"tags[{name!r}]") for v in span)
            if last < first:
                raise ValidationError(f"Clip.tags[{name!r}]: last frame {last} < first {first}")
            out[name] = cls.grid(image, grid, range(first, last + 1), **options)
        return out

    @classmethod
    def _make(
        cls,
        refs: list[FrameRef],
        duration: Any,
        fps: Any,
        loop: Loop | str,
        speed: float,
        flip_x: bool,
        flip_y: bool,
        events: Mapping[int, str] | None,
    ) -> Clip:
        durs = _durations(len(refs), duration, fps, "Clip")
        mode = enum_value(Loop, loop, "Clip", "loop")
        return cls(
            tuple(refs), durs, mode, _clip_speed(speed, "Clip", "speed"), flip_x, flip_y,
            _events(events, len(refs), "Clip"),
        )  # fmt: skip


@dataclass(slots=True, frozen=True)
class Transition:
    """Switch from clip ``src`` to ``dst`` while ``when`` holds, or, with ``when=None``,
    when ``src`` finishes (``src="*"``: from any clip).

    ``when`` is a parameter name (truthy), ``"not name"``, a comparison
    (``"speed > 0.1"``, ``"state == jump"``) or clauses joined by ``and``; see
    :mod:`kge.components.conditions`. It is checked when the Transition is made.

    ``fade`` > 0 cross-fades: the outgoing clip runs on, drawn over the incoming one
    and fading out over ``fade`` seconds of game time (0: a cut).
    """

    src: str
    dst: str
    when: str | None = None
    fade: float = 0.0

    def __post_init__(self) -> None:
        for name in ("src", "dst"):
            value = getattr(self, name)
            if not isinstance(value, str) or not value:
                raise ComponentTypeError(f"Transition.{name} must be a clip name, got {value!r}")
        if self.when is not None:
            if not isinstance(self.when, str):
                raise ComponentTypeError(
                    f"Transition.when must be a parameter name or None (or a condition such as "
                    f"'speed > 0.1'), got {self.when!r}"
                )
            parse_condition(self.when)
        object.__setattr__(self, "fade", fade_seconds(self.fade, "Transition", "fade"))

    def holds(self, params: Mapping[str, Any]) -> bool:
        """Does ``when`` hold for these parameters? (False for an end transition.)"""
        return self.when is not None and condition_met(self.when, params)


def _clips(value: Any, owner: str, field: str) -> dict[str, Clip]:
    return name_map(value, Clip, owner, field)


def _has(obj: object, name: str) -> bool:
    try:
        getattr(obj, name)
    except AttributeError:  # a slot not yet set (inside __init__)
        return False
    return True


def _speed(value: Any, owner: str, field: str) -> float:
    """Any finite speed up to MAX_SPEED either way: negative plays the clips backwards."""
    v = finite(value, owner, field)
    at_most(abs(v), MAX_SPEED, owner, field)
    return v


def _params(value: Any, owner: str, field: str) -> dict[str, Any]:
    if not isinstance(value, dict):
        raise ComponentTypeError(f"{owner}.{field} must be a dict, got {value!r}")
    return value


def _serial(value: Any, owner: str, field: str) -> int:
    return integer(value, owner, field)


@dataclass(slots=True)
class Animator(Tracked):
    """Named clips and which one plays. See the module docstring.

    ``play(name)`` starts a clip from its first frame (``restart=False`` keeps a
    clip that is already playing); ``queue(name)`` plays one after the current
    finishes; ``pause()`` / ``resume()`` freeze time; ``stop()`` shows frame 0 and
    stops. ``speed`` multiplies every clip's own speed; a negative speed plays
    backwards (a clip started then begins at its end; frame events fire as the
    playhead crosses their frame going back; a ``once`` clip ends at its start).
    ``set(param, value)`` feeds the transition table. ``play(name, fade=0.2)``
    cross-fades from the clip shown into ``name`` over 0.2 s (``fade`` keeps that
    length until the next ``play``; the outgoing clip fires no more events).
    """

    #: new clips are checked against their images by the animation plugin
    _world_fields: ClassVar[frozenset[str]] = frozenset({"clips"})

    _checks: ClassVar[dict[str, Check]] = {
        "clips": _clips,
        "speed": _speed,
        "playing": boolean,
        "params": _params,
        "serial": _serial,
        "stopped": boolean,
        "fade": fade_seconds,
    }

    clips: dict[str, Clip]
    current: str | None = None
    speed: float = 1.0
    playing: bool = True
    transitions: tuple[Transition, ...] = ()
    params: dict[str, Any] = field(default_factory=dict)
    queued: list[str] = field(default_factory=list)
    #: bumped by play()/stop(): the system restarts the clip when it changes
    serial: int = 0
    stopped: bool = False
    #: the cross-fade (seconds) of the latest play(): the system fades when serial changes
    fade: float = 0.0

    def __setattr__(self, name: str, value: Any) -> None:
        # ``current`` must name a clip, and new ``clips`` must still hold ``current``: rules
        # across two fields, so they are checked here rather than in the per-field table
        if name == "current" and value is not None and _has(self, "clips"):
            self._check_name(value, "current")
        elif name == "transitions" and _has(self, "clips"):
            value = self._check_transitions(value)
        elif name == "queued" and _has(self, "clips"):
            if not isinstance(value, list):
                raise ComponentTypeError(f"{self._owner()}.queued must be a list of clip names")
            for i, q in enumerate(value):
                self._check_name(q, f"queued[{i}]")
        elif name == "clips" and _has(self, "current") and self.current is not None:
            clips = _clips(value, self._owner(), "clips")
            if self.current not in clips:
                raise ValidationError(
                    f"{self._owner()}.clips: the new clips lack the current clip "
                    f"{self.current!r}; play() one of them first or include it"
                )
        Tracked.__setattr__(self, name, value)

    def __post_init__(self) -> None:
        if self.current is None:
            object.__setattr__(self, "current", next(iter(self.clips)))
        self._check_name(self.current, "current")
        object.__setattr__(self, "transitions", self._check_transitions(self.transitions))
        if not isinstance(self.queued, list):
            raise ComponentTypeError("Animator.queued must be a list of clip names")
        for i, q in enumerate(self.queued):
            self._check_name(q, f"queued[{i}]")

    def _check_transitions(self, value: Any) -> tuple[Transition, ...]:
        try:
            trs = tuple(value)
        except TypeError:
            raise ComponentTypeError(
                f"{self._owner()}.transitions must be a sequence of Transitions, got {value!r}"
            ) from None
        for i, tr in enumerate(trs):
            if not isinstance(tr, Transition):
                raise ComponentTypeError(
                    f"{self._owner()}.transitions[{i}] must be a Transition, got {tr!r}"
                )
            if tr.src != "*":
                self._check_name(tr.src, f"transitions[{i}].src")
            self._check_name(tr.dst, f"transitions[{i}].dst")
        return trs

    def _check_name(self, name: Any, what: str) -> str:
        if name not in self.clips:
            known = ", ".join(sorted(self.clips))
            raise ValidationError(
                f"{self._owner()}.{what}: unknown clip {name!r}; the clips are: {known}"
            )
        return str(name)

    def play(self, name: str, *, restart: bool = True, fade: float = 0.0) -> None:
        """Play clip ``name`` from its first frame (no-op if it plays and not ``restart``);
        ``fade`` > 0 cross-fades into it from the frame shown over that many seconds."""
        self._check_name(name, "play")
        fade = fade_seconds(fade, self._owner(), "play(fade)")
        if not restart and name == self.current and self.playing and not self.stopped:
            return
        self.fade = fade
        self.queued.clear()
        self.current = name
        self.playing = True
        self.stopped = False
        self.serial += 1

    def queue(self, name: str) -> None:
        """Play clip ``name`` when the current (and earlier queued) clips finish."""
        self._check_name(name, "queue")
        self.queued.append(name)

    def pause(self) -> None:
        self.playing = False

    def resume(self) -> None:
        self.playing = True

    def stop(self) -> None:
        """Show the current clip's first frame and stop."""
        self.fade = 0.0
        self.stopped = True
        self.playing = False
        self.serial += 1

    def restart(self) -> None:
        """The current clip again from its first frame."""
        self.play(str(self.current))

    def set(self, param: str, value: Any) -> None:
        """Set a transition parameter (read by the transitions' ``when`` conditions)."""
        self.params[param] = value
