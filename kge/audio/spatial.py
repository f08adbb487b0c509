"""Positional sound in 2D: stereo pan and distance attenuation.

kge computes both itself instead of handing 3D positions to the audio driver,
because pyglet's PulseAudio and silent drivers ignore positions while OpenAL,
DirectSound and XAudio2 honour them: computing here gives the same loudness on
every driver and makes the result testable headless.

* **pan** in [-1, 1] is the horizontal offset from the listener divided by
  ``pan_width`` (the distance at which a sound is fully on one side; by default
  half the camera's view), so a sound left of the listener pans left.
* **gain** in [0, 1] is 1 within ``min_distance``, 0 beyond ``max_distance`` and
  linear in between (Unity's "linear rolloff"; easy to reason about in metres).

The pan reaches the driver as a point on the unit circle in front of the
listener (:func:`pan_to_position`), so drivers that do position sounds pan
them without adding their own distance fall-off.

>>> pan_and_gain((-4.0, 0.0), (0.0, 0.0), pan_width=8.0, min_distance=1.0, max_distance=7.0)
(-0.5, 0.5)
>>> pan_to_position(0.0)
(0.0, 0.0, -1.0)
"""

from __future__ import annotations

import math

Vec2 = tuple[float, float]


def pan_and_gain(
    source: Vec2,
    listener: Vec2,
    *,
    pan_width: float,
    min_distance: float,
    max_distance: float,
) -> tuple[float, float]:
    """Stereo pan and distance gain of a sound at ``source`` heard at ``listener``."""
    dx = source[0] - listener[0]
    dy = source[1] - listener[1]
    pan = max(-1.0, min(1.0, dx / pan_width)) if pan_width > 0 else 0.0
    distance = math.hypot(dx, dy)
    if distance <= min_distance:
        gain = 1.0
    elif distance >= max_distance:
        gain = 0.0
    else:
        gain = 1.0 - (distance - min_distance) / (max_distance - min_distance)
    return pan, gain


def pan_to_position(pan: float) -> tuple[float, float, float]:
    """A driver-space position at distance 1 whose azimuth gives stereo ``pan``.

    pyglet's listener sits at the origin facing -z with +x to its right.
    """
    p = max(-1.0, min(1.0, pan))
    return (p, 0.0, -math.sqrt(1.0 - p * p))
