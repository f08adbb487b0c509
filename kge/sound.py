"""Sounds made in code: short tones, noise bursts and little melodies.

Games need blips and beeps long before they have an audio artist, and tests
need sounds that exist on every machine. A :class:`SoundData` is plain data
(16-bit PCM samples and a sample rate), so it can sit in an ``AudioSource``
component like an asset name can; the audio system turns it into a pyglet
source the first time it plays. ``tools/make_assets.py`` writes the example
games' WAV files with the same functions.

>>> beep = tone(440.0, 0.25, rate=8000)
>>> beep.duration, beep.frames
(0.25, 2000)
>>> wav = beep.to_wav()
>>> wav[:4], wav[8:12]
(b'RIFF', b'WAVE')
"""

from __future__ import annotations

import io
import math
import os
import random
import struct
import wave
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Literal

from kge.errors import ValidationError

Shape = Literal["sine", "square", "triangle", "saw", "noise"]

_MAX = 32767


@dataclass(frozen=True, slots=True)
class SoundData:
    """Mono or stereo 16-bit PCM held in memory. ``name`` is for messages only."""

    samples: bytes
    rate: int = 22050
    channels: int = 1
    name: str = field(default="generated", compare=False)  #: for messages; not identity

    def __post_init__(self) -> None:
        if not isinstance(self.samples, bytes):
            raise ValidationError(f"SoundData.samples must be bytes, got {type(self.samples)}")
        if self.channels not in (1, 2):
            raise ValidationError(f"SoundData.channels must be 1 or 2, got {self.channels!r}")
        if not 1000 <= self.rate <= 192000:
            raise ValidationError(f"SoundData.rate must be in [1000, 192000], got {self.rate!r}")
        if not self.samples:
            raise ValidationError("SoundData.samples is empty: a sound needs at least one frame")
        if len(self.samples) % (2 * self.channels):
            raise ValidationError("SoundData.samples must hold whole 16-bit frames")
        if not self.samples:  # no player can start a sound of no frames
            raise ValidationError("SoundData.samples is empty: a sound needs at least one frame")

    @property
    def frames(self) -> int:
        return len(self.samples) // (2 * self.channels)

    @property
    def duration(self) -> float:
        """Length in seconds."""
        return self.frames / self.rate

    def to_wav(self) -> bytes:
        """The sound as a complete WAV file (what pyglet's built-in decoder reads)."""
        buf = io.BytesIO()
        with wave.open(buf, "wb") as out:
            out.setnchannels(self.channels)
            out.setsampwidth(2)
            out.setframerate(self.rate)
            out.writeframes(self.samples)
        return buf.getvalue()

    def write_wav(self, path: str) -> None:
        with open(path, "wb") as f:
            f.write(self.to_wav())

    def __add__(self, other: SoundData) -> SoundData:
        """Concatenate two sounds of the same format."""
        if (self.rate, self.channels) != (other.rate, other.channels):
            raise ValidationError("only sounds with the same rate and channels can be joined")
        return SoundData(self.samples + other.samples, self.rate, self.channels, self.name)


def _wave(shape: Shape, rng: random.Random) -> Callable[[float], float]:
    """One period of ``shape`` as a function of phase in [0, 1)."""
    if shape == "sine":
        return lambda p: math.sin(2.0 * math.pi * p)
    if shape == "square":
        return lambda p: 1.0 if p < 0.5 else -1.0
    if shape == "triangle":
        return lambda p: 4.0 * p - 1.0 if p < 0.5 else 3.0 - 4.0 * p
    if shape == "saw":
        return lambda p: 2.0 * p - 1.0
    if shape == "noise":
        return lambda p: rng.uniform(-1.0, 1.0)
    raise ValidationError(f"tone shape must be sine/square/triangle/saw/noise, got {shape!r}")


def tone(
    frequency: float,
    seconds: float,
    *,
    volume: float = 0.5,
    shape: Shape = "sine",
    slide_to: float | None = None,
    attack: float = 0.005,
    release: float = 0.05,
    rate: int = 22050,
    seed: int = 1,
) -> SoundData:
    """A single note with a linear attack/release envelope.

    ``slide_to`` glides the pitch to another frequency (laser "pew", falling
    "bomb"); ``shape="noise"`` gives explosions and hits. The envelope avoids the
    click a hard start or stop makes.
    """
    if not (frequency > 0 and seconds > 0 and 0 <= volume <= 1):
        raise ValidationError(
            f"tone() needs frequency > 0, seconds > 0 and volume in [0, 1], got "
            f"{frequency!r}, {seconds!r}, {volume!r}"
        )
    rng = random.Random(seed)
    fn = _wave(shape, rng)
    n = max(1, round(seconds * rate))
    end_freq = frequency if slide_to is None else slide_to
    a = max(1, round(attack * rate))
    r = max(1, round(release * rate))
    phase = 0.0
    out = bytearray()
    pack = struct.Struct("<h").pack
    for i in range(n):
        t = i / n
        env = min(1.0, i / a, (n - i) / r)
        out += pack(int(_MAX * volume * env * fn(phase)))
        phase = (phase + (frequency + (end_freq - frequency) * t) / rate) % 1.0
    return SoundData(bytes(out), rate, 1, f"tone {frequency:g} Hz")


def silence(seconds: float, rate: int = 22050) -> SoundData:
    return SoundData(b"\0\0" * max(1, round(seconds * rate)), rate, 1, "silence")


def melody(
    notes: Sequence[tuple[float, float]],
    *,
    volume: float = 0.4,
    shape: Shape = "triangle",
    rate: int = 22050,
) -> SoundData:
    """Notes as ``(frequency, seconds)`` pairs, frequency 0 for a rest.

    >>> melody([(440, 0.1), (0, 0.1), (660, 0.1)], rate=8000).duration
    0.3
    """
    parts = [
        tone(f, s, volume=volume, shape=shape, rate=rate) if f > 0 else silence(s, rate)
        for f, s in notes
    ]
    if not parts:
        raise ValidationError("melody() needs at least one note")
    result = parts[0]
    for p in parts[1:]:
        result = result + p
    return SoundData(result.samples, rate, 1, "melody")


def mix(*sounds: SoundData) -> SoundData:
    """Sum mono sounds of one rate (clipped to 16 bits), as long as the longest.

    >>> mix(tone(220, 0.1, rate=8000), tone(330, 0.2, rate=8000)).duration
    0.2
    """
    if not sounds or any(s.channels != 1 or s.rate != sounds[0].rate for s in sounds):
        raise ValidationError("mix() needs one or more mono sounds of the same rate")
    n = max(s.frames for s in sounds)
    total = [0] * n
    for s in sounds:
        for i, v in enumerate(struct.unpack(f"<{s.frames}h", s.samples)):
            total[i] += v
    out = struct.pack(f"<{n}h", *(max(-32768, min(_MAX, v)) for v in total))
    return SoundData(out, sounds[0].rate, 1, "mix")


SoundRef = str | os.PathLike[str] | SoundData
"""What ``AudioSource``, ``ImpactSound`` and ``audio.play`` accept: a name, a path or data."""
