"""Colour values shared by sprites, shapes and text: integers 0-255, as on screen.

Why integers: every image editor and colour picker shows 0-255, and pyglet
stores vertex colours as normalised bytes, so no conversion can drift.

>>> rgba((255, 0, 0), "Rect", "color")
(255, 0, 0, 255)
>>> rgba((300, 0, 0), "Rect", "color")
Traceback (most recent call last):
...
kge.errors.ValidationError: Rect.color[0] must be an int in 0..255, got 300
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from kge.errors import ComponentTypeError, ValidationError

RGB = tuple[int, int, int]
RGBA = tuple[int, int, int, int]
#: what a ``color`` field accepts; it always holds the RGBA form (alpha 255 added)
Color = RGB | RGBA


def _channel(value: Any, owner: str, field: str) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        try:
            import numpy as np

            if isinstance(value, np.integer):
                value = int(value)
            else:
                raise TypeError
        except TypeError:
            raise ComponentTypeError(
                f"{owner}.{field} must be an int in 0..255, got {type(value).__name__} {value!r}"
            ) from None
    if not 0 <= value <= 255:
        raise ValidationError(f"{owner}.{field} must be an int in 0..255, got {value!r}")
    return int(value)


def _channels(value: Any, owner: str, field: str, sizes: tuple[int, ...]) -> tuple[int, ...]:
    if isinstance(value, (str, bytes)) or not isinstance(value, Sequence):
        raise ComponentTypeError(
            f"{owner}.{field} must be a tuple of {' or '.join(map(str, sizes))} ints 0..255, "
            f"got {type(value).__name__} {value!r}"
        )
    if len(value) not in sizes:
        raise ValidationError(
            f"{owner}.{field} must have {' or '.join(map(str, sizes))} channels, got {value!r}"
        )
    return tuple(_channel(v, owner, f"{field}[{i}]") for i, v in enumerate(value))


def rgb(value: Any, owner: str, field: str) -> RGB:
    """An (r, g, b) tuple of ints 0-255."""
    r, g, b = _channels(value, owner, field, (3,))
    return (r, g, b)


def rgba(value: Any, owner: str, field: str) -> RGBA:
    """An (r, g, b, a) tuple of ints 0-255; an (r, g, b) gets alpha 255."""
    c = _channels(value, owner, field, (3, 4))
    return (c[0], c[1], c[2], c[3] if len(c) == 4 else 255)


def byte(value: Any, owner: str, field: str) -> int:
    """One int 0-255 (opacity)."""
    return _channel(value, owner, field)
