"""Small value checks shared by components and systems.

Each check raises :class:`kge.errors.ValidationError` with the owner (entity,
component, field) in the message, so a bad value is reported at the call that
made it instead of as a NaN a thousand steps later. They return the value
converted to the canonical type (``float`` or ``tuple[float, float]``) so
callers can write ``self.x = finite(x, ...)``.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from kge.errors import ComponentTypeError, ValidationError

Vec2 = tuple[float, float]


def _label(owner: str, field: str) -> str:
    return f"{owner}.{field}" if owner else field


def number(value: Any, owner: str, field: str) -> float:
    """Return ``value`` as a float, refusing bools, strings and other non-numbers."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        try:
            import numpy as np  # numpy scalars are common in game code

            if isinstance(value, np.generic) and np.isreal(value):
                return float(value)
        except ImportError:  # pragma: no cover - numpy is a dependency
            pass
        raise ComponentTypeError(
            f"{_label(owner, field)} must be a number, got {type(value).__name__} {value!r}"
        )
    return float(value)


def finite(value: Any, owner: str, field: str) -> float:
    """A finite float (no NaN, no infinity)."""
    v = number(value, owner, field)
    if not math.isfinite(v):
        raise ValidationError(f"{_label(owner, field)} must be finite, got {v!r}")
    return v


def non_negative(value: Any, owner: str, field: str) -> float:
    v = finite(value, owner, field)
    if v < 0:
        raise ValidationError(f"{_label(owner, field)} must be >= 0, got {v!r}")
    return v


def positive(value: Any, owner: str, field: str) -> float:
    v = finite(value, owner, field)
    if v <= 0:
        raise ValidationError(f"{_label(owner, field)} must be > 0, got {v!r}")
    return v


def in_range(value: Any, lo: float, hi: float, owner: str, field: str) -> float:
    v = finite(value, owner, field)
    if not lo <= v <= hi:
        raise ValidationError(f"{_label(owner, field)} must be in [{lo}, {hi}], got {v!r}")
    return v


def vec2(value: Any, owner: str, field: str) -> Vec2:
    """A pair of finite floats, from any 2-sequence (tuple, list, pymunk Vec2d, numpy)."""
    if isinstance(value, (str, bytes)) or (not isinstance(value, Sequence) and not hasattr(
        value, "__len__"
    )):
        raise ComponentTypeError(
            f"{_label(owner, field)} must be an (x, y) pair, got {type(value).__name__} {value!r}"
        )
    try:
        n = len(value)
    except TypeError:
        n = -1
    if n != 2:
        raise ValidationError(f"{_label(owner, field)} must be an (x, y) pair, got {value!r}")
    return (finite(value[0], owner, f"{field}[0]"), finite(value[1], owner, f"{field}[1]"))


def boolean(value: Any, owner: str, field: str) -> bool:
    if not isinstance(value, bool):
        raise ComponentTypeError(
            f"{_label(owner, field)} must be True or False, got {type(value).__name__} {value!r}"
        )
    return value


def integer(value: Any, owner: str, field: str) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        try:
            import numpy as np

            if isinstance(value, np.integer):
                return int(value)
        except ImportError:  # pragma: no cover
            pass
        raise ComponentTypeError(
            f"{_label(owner, field)} must be an int, got {type(value).__name__} {value!r}"
        )
    return value
