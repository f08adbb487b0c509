"""Post-processing effects: what a camera does to its picture before it reaches the screen.

Give a camera a stack: ``Camera(post=(Bloom(), ColorGrade(saturation=1.2), Vignette()))``.
The camera then draws into a texture of its own, each effect is a full-screen
shader pass over the previous one's output, in order, and the last pass lands in
the camera's viewport. A :class:`~kge.components.material.Material` in the stack is a
custom pass: its shader's ``effect(color, tex, uv, pixel)`` gets the picture so far
(``color`` is the pixel's colour, ``pixel`` its position in pixels).

Effects are mutable and validated like components, so tweens animate them by
targeting the effect itself: ``tweens.start(bloom, Tween(Bloom, "intensity", 2.0, 0.3))``.

>>> Bloom(threshold=0.8).intensity
1.0
>>> Vignette(strength=2.0)
Traceback (most recent call last):
...
kge.errors.ValidationError: Vignette.strength must be in [0.0, 1.0], got 2.0
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from kge.components.color import RGB, rgb
from kge.components.tracked import Check, Tracked
from kge.validate import boolean, in_range


def _range(lo: float, hi: float) -> Check:
    def check(value: Any, owner: str, field: str) -> float:
        return in_range(value, lo, hi, owner, field)

    return check


@dataclass(slots=True)
class PostEffect(Tracked):
    """Base of the built-in effects; ``enabled=False`` skips the pass."""

    enabled: bool = True


@dataclass(slots=True)
class Bloom(PostEffect):
    """Bright parts glow: pixels above ``threshold`` (0..1 luminance), blurred over
    ``radius`` design pixels, added back times ``intensity``."""

    _checks: ClassVar[dict[str, Check]] = {
        "enabled": boolean, "threshold": _range(0.0, 1.0), "intensity": _range(0.0, 10.0),
        "radius": _range(0.5, 64.0), "softness": _range(0.0, 1.0),
    }  # fmt: skip

    threshold: float = 0.6
    intensity: float = 1.0
    radius: float = 6.0
    #: how gradually pixels near the threshold start to glow (0: a hard cut)
    softness: float = 0.5


@dataclass(slots=True)
class ColorGrade(PostEffect):
    """Brightness (added), contrast and saturation (1: unchanged), gamma and a tint."""

    _checks: ClassVar[dict[str, Check]] = {
        "enabled": boolean, "brightness": _range(-1.0, 1.0), "contrast": _range(0.0, 4.0),
        "saturation": _range(0.0, 4.0), "gamma": _range(0.1, 5.0), "tint": rgb,
    }  # fmt: skip

    brightness: float = 0.0
    contrast: float = 1.0
    saturation: float = 1.0
    gamma: float = 1.0
    tint: RGB = (255, 255, 255)


@dataclass(slots=True)
class Vignette(PostEffect):
    """Darkens (or tints) the corners: ``strength`` at the edge, from ``radius`` (0 at
    the centre, 1 at the middle of a side) over ``softness``."""

    _checks: ClassVar[dict[str, Check]] = {
        "enabled": boolean, "strength": _range(0.0, 1.0), "radius": _range(0.0, 2.0),
        "softness": _range(0.01, 2.0), "color": rgb,
    }  # fmt: skip

    strength: float = 0.5
    radius: float = 0.75
    softness: float = 0.45
    color: RGB = (0, 0, 0)


@dataclass(slots=True)
class CRT(PostEffect):
    """An old screen: ``scanlines`` (darkening of every other design pixel row),
    ``curvature`` (barrel distortion, black outside), colour ``aberration`` (pixels)."""

    _checks: ClassVar[dict[str, Check]] = {
        "enabled": boolean, "scanlines": _range(0.0, 1.0), "curvature": _range(0.0, 0.5),
        "aberration": _range(0.0, 16.0),
    }  # fmt: skip

    scanlines: float = 0.3
    curvature: float = 0.08
    aberration: float = 1.0


POST_EFFECTS: tuple[type, ...] = (Bloom, ColorGrade, Vignette, CRT)
