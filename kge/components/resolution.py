"""``Resolution``: draw the game at a design size, fitted to whatever window it gets.

Insert it as a resource and the game's screen coordinates (cameras, HUD text,
screen-space UI, the mouse) are *design pixels*, ``width`` x ``height``, whatever the
window's size or pixel density:

* ``ScaleMode.LETTERBOX`` scales the design uniformly to fit and centres it, with
  bars of ``bars`` colour on the two other sides; everything is drawn at the
  window's resolution (sharp text and edges);
* ``ScaleMode.STRETCH`` fills the window, scaling x and y separately;
* ``ScaleMode.INTEGER`` scales by the largest whole number that fits (1 at least)
  and draws the game into a design-sized texture first, magnified with nearest
  filtering: pixel-perfect pixel art (with ``snap``, sprites and the camera sit on
  whole design pixels).

``snap`` rounds the camera and every sprite to whole design pixels (no shimmer when
pixel art moves slowly). Sizes are validated: zero, negative or beyond 16384 pixels
raise at the call.

>>> r = Resolution(320, 180)
>>> r.fit((1280, 800))                       # letterboxed: 4x, 40-pixel bars above and below
(0.0, 40.0, 1280.0, 720.0)
>>> r.to_design((640.0, 400.0), (1280, 800))
(160.0, 90.0)
>>> Resolution(320, 180, mode=ScaleMode.INTEGER).fit((1000, 600))
(20.0, 30.0, 960.0, 540.0)
>>> Resolution(0, 180)
Traceback (most recent call last):
...
kge.errors.ValidationError: Resolution.width must be 1..16384 pixels, got 0
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import StrEnum
from typing import Any, ClassVar

from kge.components.color import RGB, rgb
from kge.components.tracked import Check, Tracked
from kge.errors import ValidationError
from kge.validate import Vec2, boolean, choice, integer

#: the largest design size, pixels per side
MAX_SIZE = 16384


class ScaleMode(StrEnum):
    """How a design resolution is fitted to the window (see the module docstring)."""

    LETTERBOX = "letterbox"  #: scaled uniformly to fit, bars on the other sides
    STRETCH = "stretch"  #: x and y scaled separately to fill the window
    INTEGER = "integer"  #: the largest whole-number scale, pixel-perfect

Rect = tuple[float, float, float, float]


def _side(value: Any, owner: str, field: str) -> int:
    v = integer(value, owner, field)
    if not 1 <= v <= MAX_SIZE:
        raise ValidationError(f"{owner}.{field} must be 1..{MAX_SIZE} pixels, got {v}")
    return v


@dataclass(slots=True)
class Resolution(Tracked):
    """The design size and how it is fitted to the window (see the module docstring)."""

    _checks: ClassVar[dict[str, Check]] = {
        "width": _side, "height": _side, "mode": choice(ScaleMode), "snap": boolean, "bars": rgb,
    }  # fmt: skip

    width: int
    height: int
    mode: ScaleMode = ScaleMode.LETTERBOX
    snap: bool = False
    bars: RGB = (0, 0, 0)

    @property
    def size(self) -> tuple[int, int]:
        return (self.width, self.height)

    def scale(self, window: tuple[float, float]) -> Vec2:
        """Window pixels per design pixel along x and y."""
        sx, sy = window[0] / self.width, window[1] / self.height
        if self.mode == "stretch":
            return (sx, sy)
        k = min(sx, sy)
        if self.mode == "integer" and k >= 1.0:
            k = float(math.floor(k + 1e-9))
        return (k, k)

    def fit(self, window: tuple[float, float]) -> Rect:
        """Where the design area goes in a window of that size: (x, y, width, height)."""
        sx, sy = self.scale(window)
        w, h = self.width * sx, self.height * sy
        x, y = (window[0] - w) / 2, (window[1] - h) / 2
        if self.mode == "integer":
            x, y = float(math.floor(x)), float(math.floor(y))
        return (x, y, w, h)

    def to_design(self, point: Vec2, window: tuple[float, float]) -> Vec2:
        """Window pixels -> design pixels (outside the design area: beyond 0..size)."""
        x, y, w, h = self.fit(window)
        return ((point[0] - x) * self.width / w, (point[1] - y) * self.height / h)

    def to_window(self, point: Vec2, window: tuple[float, float]) -> Vec2:
        """Design pixels -> window pixels."""
        x, y, w, h = self.fit(window)
        return (x + point[0] * w / self.width, y + point[1] * h / self.height)


def canvas_size(world: Any, window: tuple[int, int]) -> tuple[int, int]:
    """The size of the game's screen coordinates: the design size, else the window's."""
    res = world.try_resource(Resolution) if world is not None else None
    return res.size if res is not None else (int(window[0]), int(window[1]))
