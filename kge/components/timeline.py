"""Keyframe timelines as data: property, method-call and sound tracks (an AnimationPlayer).

A :class:`Timeline` is an immutable set of tracks over a length of seconds:

====================  ===========================================================
``Keys``              ``(time, value)`` keys of one component field, interpolated
                      ``"linear"``, ``"cubic"`` (Catmull-Rom through the keys) or
                      ``"step"`` (hold each key: the only mode for non-numbers)
``Calls``             ``(time, "method", *args)``: calls that method of the entity's
                      Behaviour script when the playhead passes ``time``
``Sounds``            ``(time, sound)``: plays the sound (``Audio.play``) at ``time``
====================  ===========================================================

A :class:`TimelinePlayer` component holds named timelines and which one plays
(``play``, ``stop``, ``pause``, ``resume``, ``seek``, ``speed``, ``loop`` from the
timeline); the timeline system keeps every player's playhead in numpy arrays,
evaluates each property track for all the players of a timeline at once, fires the
calls and sounds the playhead crossed (a long frame skips none), and emits
:class:`~kge.animation.events.TimelineFinished` (hook ``on_timeline_end``) when a
timeline that does not loop reaches its end.

>>> from kge.components.sprite import Sprite
>>> fade_in = Timeline([Keys(Sprite, "opacity", [(0.0, 0), (0.5, 255)])])
>>> fade_in.length
0.5
>>> Keys(Sprite, "opacity", [(0.5, 255), (0.2, 0)])
Traceback (most recent call last):
...
kge.errors.ValidationError: Keys(Sprite.opacity).keys: times must increase, got 0.2 after 0.5
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, ClassVar

from kge.components.audio import sound_ref
from kge.components.tracked import Check, Tracked
from kge.errors import ComponentTypeError, ValidationError
from kge.validate import at_most, boolean, finite, integer, name_map, non_negative

#: the longest timeline, seconds (a day)
MAX_LENGTH = 86_400.0
#: the most keys one track may have
MAX_KEYS = 100_000
#: the fastest playback either way
MAX_SPEED = 1e3
INTERPOLATIONS = ("step", "linear", "cubic")
#: widest interpolated value: an RGBA colour
WIDTH = 4


def _time(value: Any, owner: str, i: int) -> float:
    t = non_negative(value, owner, f"keys[{i}] time")
    return at_most(t, MAX_LENGTH, owner, f"keys[{i}] time", "s")


def _key_list(keys: Any, owner: str) -> list[tuple[Any, ...]]:
    if isinstance(keys, (str, bytes)) or not isinstance(keys, Sequence):
        raise ComponentTypeError(f"{owner}.keys must be a list of (time, ...) tuples, got {keys!r}")
    if not keys:
        raise ValidationError(f"{owner}.keys: a track needs at least one key")
    if len(keys) > MAX_KEYS:
        raise ValidationError(f"{owner}.keys: at most {MAX_KEYS:,} keys, got {len(keys):,}")
    out = []
    last = -1.0
    for i, key in enumerate(keys):
        if not isinstance(key, (tuple, list)) or len(key) < 2:
            raise ComponentTypeError(f"{owner}.keys[{i}] must be (time, ...), got {key!r}")
        t = _time(key[0], owner, i)
        if t <= last:
            raise ValidationError(f"{owner}.keys: times must increase, got {t:g} after {last:g}")
        last = t
        out.append((t, *key[1:]))
    return out


def numbers(value: Any) -> list[float] | None:
    """``value`` as 1 to 4 finite floats (a number, vector or colour), or None."""
    items = list(value) if isinstance(value, (tuple, list)) else [value]
    if not 1 <= len(items) <= WIDTH:
        return None
    out = []
    for v in items:
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            return None
        f = float(v)
        if not math.isfinite(f):
            return None
        out.append(f)
    return out


def _field_of(component: Any, name: Any, owner: str) -> None:
    if not isinstance(component, type):
        raise ComponentTypeError(f"{owner}: component must be a component class, got "
                                 f"{component!r}")  # fmt: skip
    if not isinstance(name, str) or not name or name.startswith("_"):
        raise ValidationError(f"{owner}: field must be a public field name, got {name!r}")
    known = dataclasses.is_dataclass(component) and any(
        f.name == name for f in dataclasses.fields(component)
    )
    prop = getattr(component, name, None)
    if not known and not (isinstance(prop, property) and prop.fset is not None):
        raise ValidationError(f"{owner}: {component.__name__} has no field {name!r}")


@dataclass(slots=True, frozen=True)
class Keys:
    """A property track: ``component.field`` takes ``keys`` = [(time, value), ...]."""

    component: type
    field: str
    keys: Sequence[tuple[Any, ...]]
    interp: str = "linear"

    def __post_init__(self) -> None:
        owner = f"Keys({getattr(self.component, '__name__', '?')}.{self.field})"
        _field_of(self.component, self.field, owner)
        keys = _key_list(self.keys, owner)
        if self.interp not in INTERPOLATIONS:
            raise ValidationError(f"{owner}.interp must be one of {', '.join(INTERPOLATIONS)}, "
                                  f"got {self.interp!r}")  # fmt: skip
        width = None
        check = getattr(self.component, "_checks", {}).get(self.field)
        for i, key in enumerate(keys):
            if len(key) != 2:
                raise ComponentTypeError(f"{owner}.keys[{i}] must be (time, value), got {key!r}")
            value = key[1]
            if check is not None:  # the field's own rule: an opacity of 300 is refused here
                value = check(value, owner, f"keys[{i}] value")
            nums = numbers(value)
            if self.interp != "step":
                if nums is None:
                    raise ValidationError(
                        f"{owner}.keys[{i}]: {value!r} is not a number, vector or colour; "
                        "interpolate numbers, or use interp='step' to hold values"
                    )
                if width is not None and len(nums) != width:
                    raise ValidationError(f"{owner}.keys[{i}]: {len(nums)} numbers where the "
                                          f"first key has {width}")  # fmt: skip
                width = len(nums)
            keys[i] = (key[0], value)
        object.__setattr__(self, "keys", tuple(keys))

    @property
    def end(self) -> float:
        return self.keys[-1][0]


@dataclass(slots=True, frozen=True)
class Calls:
    """A method-call track: ``keys`` = [(time, "method", *args), ...] on the entity's
    Behaviour script."""

    keys: Sequence[tuple[Any, ...]]

    def __post_init__(self) -> None:
        keys = _key_list(self.keys, "Calls")
        for i, key in enumerate(keys):
            name = key[1]
            if not isinstance(name, str) or not name.isidentifier() or name.startswith("_"):
                raise ValidationError(
                    f"Calls.keys[{i}]: {name!r} is not a public method name of a script"
                )
        object.__setattr__(self, "keys", tuple(keys))

    @property
    def end(self) -> float:
        return float(self.keys[-1][0])


@dataclass(slots=True, frozen=True)
class Sounds:
    """A sound track: ``keys`` = [(time, sound), ...] played with ``volume`` on ``bus``."""

    keys: Sequence[tuple[Any, ...]]
    volume: float = 1.0
    bus: str = "sfx"

    def __post_init__(self) -> None:
        keys = _key_list(self.keys, "Sounds")
        for i, key in enumerate(keys):
            if len(key) != 2:
                raise ComponentTypeError(f"Sounds.keys[{i}] must be (time, sound), got {key!r}")
            keys[i] = (key[0], sound_ref(key[1], "Sounds", f"keys[{i}] sound"))
        object.__setattr__(self, "keys", tuple(keys))
        v = finite(self.volume, "Sounds", "volume")
        if not 0.0 <= v <= 1.0:
            raise ValidationError(f"Sounds.volume must be in [0, 1], got {v!r}")
        if not isinstance(self.bus, str) or not self.bus:
            raise ValidationError(f"Sounds.bus must be a bus name, got {self.bus!r}")

    @property
    def end(self) -> float:
        return float(self.keys[-1][0])


Track = Keys | Calls | Sounds


@dataclass(slots=True, frozen=True)
class Timeline:
    """Tracks over ``length`` seconds (default: the last key); ``loop`` plays it forever."""

    tracks: Sequence[Track]
    length: float | None = None
    loop: bool = False

    def __post_init__(self) -> None:
        if isinstance(self.tracks, (Keys, Calls, Sounds)) or not isinstance(
            self.tracks, Sequence
        ):
            raise ComponentTypeError(f"Timeline.tracks must be a list of tracks, got "
                                     f"{self.tracks!r}")  # fmt: skip
        tracks = tuple(self.tracks)
        if not tracks:
            raise ValidationError("Timeline.tracks: a timeline needs at least one track")
        for i, tr in enumerate(tracks):
            if not isinstance(tr, (Keys, Calls, Sounds)):
                raise ComponentTypeError(
                    f"Timeline.tracks[{i}] must be Keys, Calls or Sounds, got {tr!r}"
                )
        object.__setattr__(self, "tracks", tracks)
        last = max(tr.end for tr in tracks)
        if self.length is None:
            length = last
        else:
            length = at_most(non_negative(self.length, "Timeline", "length"), MAX_LENGTH,
                             "Timeline", "length", "s")  # fmt: skip
            if length < last:
                raise ValidationError(
                    f"Timeline.length {length:g} s is shorter than its last key at {last:g} s"
                )
        boolean(self.loop, "Timeline", "loop")
        if self.loop and length <= 0.0:
            raise ValidationError("Timeline: a looping timeline needs a length > 0")
        object.__setattr__(self, "length", float(length))


def _timelines(value: Any, owner: str, name: str) -> dict[str, Timeline]:
    return name_map(value, Timeline, owner, name)


def _speed(value: Any, owner: str, name: str) -> float:
    v = finite(value, owner, name)
    return math.copysign(at_most(abs(v), MAX_SPEED, owner, name), v)


def _seek(value: Any, owner: str, name: str) -> float | None:
    if value is None:
        return None
    return at_most(non_negative(value, owner, name), MAX_LENGTH, owner, name, "s")


def _current(value: Any, owner: str, name: str) -> str | None:
    if value is not None and (not isinstance(value, str) or not value):
        raise ComponentTypeError(f"{owner}.{name} must be a timeline name, got {value!r}")
    return value


@dataclass(slots=True)
class TimelinePlayer(Tracked):
    """Named timelines and which one plays (see the module docstring).

    ``play(name)`` starts one from 0 (``current`` plays at spawn when ``playing``);
    ``seek(t)`` moves the playhead (calls and sounds between are not fired);
    ``speed`` scales time (negative plays backwards, calls fire going back).
    """

    #: the world checks the tracks' components and methods against the entity
    _world_fields: ClassVar[frozenset[str]] = frozenset({"timelines", "current"})
    _checks: ClassVar[dict[str, Check]] = {
        "timelines": _timelines,
        "current": _current,
        "speed": _speed,
        "playing": boolean,
        "serial": integer,
        "seek_to": _seek,
    }

    timelines: dict[str, Timeline]
    current: str | None = None
    speed: float = 1.0
    playing: bool = True
    #: bumped by play()/stop()/seek(): the system restarts (or moves) the playhead
    serial: int = 0
    #: where the next restart puts the playhead (seek), seconds
    seek_to: float | None = None

    def __post_init__(self) -> None:
        if self.current is None:
            object.__setattr__(self, "current", next(iter(self.timelines)))
        self._name(self.current, "current")

    def _name(self, name: Any, what: str) -> str:
        if name not in self.timelines:
            known = ", ".join(sorted(self.timelines))
            raise ValidationError(
                f"{self._owner()}.{what}: unknown timeline {name!r}; the timelines are: {known}"
            )
        return str(name)

    def play(self, name: str | None = None) -> None:
        """Play timeline ``name`` (default: the current one) from its start."""
        name = self._name(self.current if name is None else name, "play")
        self.current = name  # the world checks the entity can take its tracks
        self.seek_to = None
        self.playing = True
        self.serial += 1

    def seek(self, seconds: float) -> None:
        """Move the playhead of the current timeline to ``seconds`` (clamped to it)."""
        self.seek_to = _seek(seconds, self._owner(), "seek")
        self.serial += 1

    def stop(self) -> None:
        """Back to the start, still (the properties take their values at time 0)."""
        self.seek_to = 0.0
        self.playing = False
        self.serial += 1

    def pause(self) -> None:
        self.playing = False

    def resume(self) -> None:
        self.playing = True


__all__ = ["Calls", "Keys", "Sounds", "Timeline", "TimelinePlayer", "Track", "numbers"]
