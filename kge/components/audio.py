"""Sound as data: what an entity plays, what it plays when hit, and who listens.

* :class:`AudioSource` — a sound attached to an entity. ``play_on_start`` plays
  it once when the entity appears; it stops when the entity is despawned or its
  scene closes. ``positional=True`` pans it left/right and fades it with
  distance from the listener (see :mod:`kge.audio.spatial`).
* :class:`ImpactSound` — plays when one of the entity's colliders begins a
  contact at ``hit_threshold`` or faster (the approach speed along the normal, as
  in the Box2D manual's pre-solve example), louder the faster the hit.
* :class:`AudioListener` — marks the entity whose Transform is the "ears".
  Without one, the first Camera is the listener, else the world origin.

``sound`` is an asset name (resolved by the world's asset store), a path, or a
:class:`~kge.assets.SoundData` made in code; never a pyglet object, so scenes
stay headless and copyable. Fields are validated on every assignment, and a
playing source follows changes to ``volume``, ``pitch`` and ``loop``.

>>> AudioSource("hit.wav", volume=0.5).volume
0.5
>>> AudioSource("hit.wav", volume=2)
Traceback (most recent call last):
...
kge.errors.ValidationError: AudioSource.volume must be in [0.0, 1.0], got 2.0
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Any, ClassVar

from kge.components.tracked import Check, Tracked
from kge.deprecation import renamed_fields
from kge.errors import ComponentTypeError, ValidationError
from kge.sound import SoundData, SoundRef
from kge.validate import at_most, boolean, in_range, non_negative, positive


def sound_ref(value: Any, owner: str, field: str) -> SoundRef:
    """An asset name, a path or generated :class:`SoundData` (no pyglet objects)."""
    if isinstance(value, SoundData):
        return value
    if isinstance(value, os.PathLike):
        value = os.fspath(value)
    if isinstance(value, str):
        if not value.strip():
            raise ValidationError(f"{owner}.{field} must name a sound file, got {value!r}")
        return value
    raise ComponentTypeError(
        f"{owner}.{field} must be an asset name, a path or kge.assets.SoundData, got "
        f"{type(value).__name__} (components hold data, never pyglet objects)"
    )


def _volume(value: Any, owner: str, field: str) -> float:
    return in_range(value, 0.0, 1.0, owner, field)


#: the highest playback rate (three octaves up): the rate every player accepts
MAX_PITCH = 8.0
#: the longest fade, seconds
MAX_FADE = 1e6


def pitch(value: Any, owner: str, field: str) -> float:
    """A playback rate in (0, :data:`MAX_PITCH`]."""
    v = positive(value, owner, field)
    if v > MAX_PITCH:
        raise ValidationError(f"{owner}.{field} must be in (0, {MAX_PITCH:g}], got {v!r}")
    return v


def fade_seconds(value: Any, owner: str, field: str) -> float:
    """A fade's length in [0, :data:`MAX_FADE`] seconds."""
    return at_most(non_negative(value, owner, field), MAX_FADE, owner, field, "s")


def _distance(value: Any, owner: str, field: str) -> float:
    return positive(value, owner, field)


@dataclass(slots=True)
class AudioSource(Tracked):
    """A sound an entity plays. Distances are metres from the listener.

    Positional sources are at full volume within ``min_distance``, silent beyond
    ``max_distance`` and fade linearly between. ``streaming`` decodes while
    playing (long music files) instead of decoding the whole file up front.
    """

    _checks: ClassVar[dict[str, Check]] = {
        "sound": sound_ref,
        "volume": _volume,
        "pitch": pitch,
        "loop": boolean,
        "play_on_start": boolean,
        "positional": boolean,
        "min_distance": _distance,
        "max_distance": _distance,
        "streaming": boolean,
    }

    sound: SoundRef
    volume: float = 1.0
    pitch: float = 1.0
    loop: bool = False
    play_on_start: bool = False
    positional: bool = False
    min_distance: float = 1.0
    max_distance: float = 30.0
    streaming: bool = False

    def __post_init__(self) -> None:
        self._check_distances(self.min_distance, self.max_distance)

    def __setattr__(self, name: str, value: Any) -> None:
        if name in ("min_distance", "max_distance") and hasattr(self, "max_distance"):
            value = _distance(value, self._owner(), name)
            lo = value if name == "min_distance" else self.min_distance
            hi = value if name == "max_distance" else self.max_distance
            self._check_distances(lo, hi)
        Tracked.__setattr__(self, name, value)

    def _check_distances(self, lo: float, hi: float) -> None:
        if lo >= hi:
            raise ValidationError(
                f"{self._owner()}.max_distance ({hi}) must be greater than min_distance ({lo})"
            )


@renamed_fields(min_speed=("hit_threshold", None, None))  # one name for one speed
@dataclass(slots=True)
class ImpactSound(Tracked):
    """Play ``sound`` when this entity's collider hits something hard enough.

    A contact qualifies when its approach speed (m/s, along the normal, at first
    touch) is at least ``hit_threshold`` (the name ``Collider`` and ``BurstOnHit``
    use for the same speed; ``min_speed`` before kge 2.0.0a2). The volume is
    ``volume * min(1, speed / max_speed)``: a hit at ``max_speed`` or faster plays at
    full ``volume``.
    ``cooldown`` (seconds of game time) keeps a rattling contact from replaying
    the sound at every bounce; 0 plays every qualifying hit.

    >>> ImpactSound("thud.wav", hit_threshold=1.0, max_speed=8.0).gain(4.0)
    0.5
    """

    _checks: ClassVar[dict[str, Check]] = {
        "sound": sound_ref,
        "hit_threshold": non_negative,
        "max_speed": positive,
        "volume": _volume,
        "pitch": pitch,
        "positional": boolean,
        "cooldown": non_negative,
    }

    sound: SoundRef
    hit_threshold: float = 1.0
    max_speed: float = 10.0
    volume: float = 1.0
    pitch: float = 1.0
    positional: bool = False
    cooldown: float = 0.0

    def __post_init__(self) -> None:
        self._check_speeds(self.hit_threshold, self.max_speed)

    def __setattr__(self, name: str, value: Any) -> None:
        if name in ("hit_threshold", "max_speed") and hasattr(self, "max_speed"):
            value = self._checks[name](value, self._owner(), name)
            lo = value if name == "hit_threshold" else self.hit_threshold
            hi = value if name == "max_speed" else self.max_speed
            self._check_speeds(lo, hi)
        Tracked.__setattr__(self, name, value)

    def _check_speeds(self, lo: float, hi: float) -> None:
        if hi < lo:
            raise ValidationError(
                f"{self._owner()}.max_speed ({hi}) must be >= hit_threshold ({lo})"
            )

    def gain(self, speed: float) -> float:
        """The volume a hit at ``speed`` plays at (0 below ``hit_threshold``)."""
        if speed < self.hit_threshold:
            return 0.0
        return self.volume * min(1.0, speed / self.max_speed)


def _optional_positive(value: Any, owner: str, name: str) -> float | None:
    return None if value is None else positive(value, owner, name)


@dataclass(slots=True)
class AudioListener(Tracked):
    """Marks the entity (with a Transform) that hears positional sounds.

    ``pan_width`` is the horizontal distance (m) from the listener at which a
    sound is panned fully to one side; None takes half the camera's view width
    when a camera is known, else 10 m.
    """

    # every write is checked, not only the constructor's (a NaN width pans to NaN)
    _checks: ClassVar[dict[str, Check]] = {"pan_width": _optional_positive}

    pan_width: float | None = None
