"""Small value checks shared by components and systems.

Each check raises :class:`kge.errors.ValidationError` with the owner (entity,
component, field) in the message, so a bad value is reported at the call that
made it instead of as a NaN a thousand steps later. They return the value
converted to the canonical type (``float`` or ``tuple[float, float]``) so
callers can write ``self.x = finite(x, ...)``.

Validation runs on every component construction and field write, so each check
starts with a fast path for the value it almost always gets (a finite ``float``
is recognised by ``type(v) is float and v - v == 0.0``: NaN and infinities
give NaN there). :data:`FAST` maps a check to a predicate that is true only
for values the check would return unchanged, so :class:`~kge.components.
tracked.Tracked` can skip formatting the owner's name and calling the check.

>>> finite(1.5, "Transform", "x"), finite(2, "Transform", "x")
(1.5, 2.0)
>>> FAST[finite](float("inf")), FAST[vec2]((0.0, 1.0))
(False, True)
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from enum import Enum
from typing import Any, TypeVar

from kge.deprecation import enum_value
from kge.errors import ComponentTypeError, ValidationError

Vec2 = tuple[float, float]
E = TypeVar("E", bound=Enum)
T = TypeVar("T")


def _label(owner: str, field: str) -> str:
    return f"{owner}.{field}" if owner else field


def number(value: Any, owner: str, field: str) -> float:
    """Return ``value`` as a float, refusing bools, strings and other non-numbers.

    numpy's real scalars (``np.float32(2.5)``, ``np.int64(3)``) are numbers; its
    ``np.bool_`` is refused like ``True``, and complex numbers of any kind (even with
    a zero imaginary part) are not real numbers.

    >>> import numpy as np
    >>> number(np.float32(2.5), "Transform", "x")
    2.5
    >>> number(np.bool_(True), "Transform", "x")
    Traceback (most recent call last):
    ...
    kge.errors.ComponentTypeError: Transform.x must be a number, got bool np.True_
    """
    if type(value) is float:
        return value
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        try:
            import numpy as np  # numpy scalars are common in game code

            if isinstance(value, (np.floating, np.integer)):
                return float(value)
        except ImportError:  # pragma: no cover - numpy is a dependency
            pass
        raise ComponentTypeError(
            f"{_label(owner, field)} must be a number, got {type(value).__name__} {value!r}"
        )
    try:
        return float(value)
    except OverflowError:  # an int beyond float64 (10**400): say so, naming the field
        raise ValidationError(
            f"{_label(owner, field)} must be finite, got an int of {int(value).bit_length()} bits "
            "(beyond a float)"
        ) from None


def finite(value: Any, owner: str, field: str) -> float:
    """A finite float (no NaN, no infinity)."""
    if type(value) is float and value - value == 0.0:
        return value
    v = number(value, owner, field)
    if not math.isfinite(v):
        raise ValidationError(f"{_label(owner, field)} must be finite, got {v!r}")
    return v


def non_negative(value: Any, owner: str, field: str) -> float:
    if type(value) is float and value - value == 0.0 and value >= 0.0:
        return value
    v = finite(value, owner, field)
    if v < 0:
        raise ValidationError(f"{_label(owner, field)} must be >= 0, got {v!r}")
    return v


def positive(value: Any, owner: str, field: str) -> float:
    if type(value) is float and value - value == 0.0 and value > 0.0:
        return value
    v = finite(value, owner, field)
    if v <= 0:
        raise ValidationError(f"{_label(owner, field)} must be > 0, got {v!r}")
    return v


def at_most(value: float, limit: float, owner: str, field: str, unit: str = "") -> float:
    """``value`` (already checked finite) if it is no larger than ``limit``.

    Used for quantities whose products overflow float64 far beyond any game's
    range (mass times size squared): refusing them at the call beats NaN poses
    several steps later.

    >>> at_most(9.0, 8.0, "Sound", "pitch", "Hz")
    Traceback (most recent call last):
    ...
    kge.errors.ValidationError: Sound.pitch must be <= 8 Hz, got 9.0
    """
    if value > limit:
        units = f" {unit}" if unit else ""
        raise ValidationError(f"{_label(owner, field)} must be <= {limit:g}{units}, got {value!r}")
    return value


#: kge's world bound, metres: every position and joint anchor, world or local, lies
#: within it. Measured: joint anchors (lever arms) of 1e8 m give NaN within a step,
#: 2e7 m do not; a Transform at 1e160 m overflows every joint solve after it.
MAX_COORDINATE = 1e7

#: highest spring frequency a joint accepts (Hz); (2 pi f)^2 must stay far from overflow
MAX_FREQUENCY = 1e6


def coordinate(value: Any, owner: str, field: str) -> float:
    """A finite position coordinate within :data:`MAX_COORDINATE` metres of the origin."""
    v = finite(value, owner, field)
    if not -MAX_COORDINATE <= v <= MAX_COORDINATE:
        raise ValidationError(
            f"{_label(owner, field)} must lie within {MAX_COORDINATE:g} m of the origin "
            f"(kge's world bound), got {v!r}"
        )
    return v


def point(value: Any, owner: str, field: str) -> Vec2:
    """An (x, y) pair of :func:`coordinate` values (joint anchors, targets, offsets)."""
    if _is_bounded_pair(value):
        return value
    x, y = vec2(value, owner, field)
    if not (-MAX_COORDINATE <= x <= MAX_COORDINATE and -MAX_COORDINATE <= y <= MAX_COORDINATE):
        raise ValidationError(
            f"{_label(owner, field)} must lie within {MAX_COORDINATE:g} m of the origin "
            f"(kge's world bound), got {(x, y)!r}"
        )
    return (x, y)


#: the largest drawn size (metres): the width of kge's world
MAX_EXTENT = 2 * MAX_COORDINATE

#: the largest anchor component (a fraction of the drawn size: 0.5 is the middle)
MAX_ANCHOR = 1e3


def within(value: Any, limit: float, owner: str, field: str, unit: str = "") -> float:
    """A finite number within +-``limit``.

    >>> within(-3.0, 1e7, "UINode", "padding", " pixels")
    -3.0
    """
    v = finite(value, owner, field)
    if abs(v) > limit:
        raise ValidationError(
            f"{_label(owner, field)} must be within +-{limit:g}{unit}, got {v!r}"
        )
    return v


def entity_id(value: Any, owner: str, field: str) -> int:
    """An entity id (an int >= 0); whether it exists is the world's check."""
    n = integer(value, owner, field)
    if n < 0:
        raise ValidationError(f"{_label(owner, field)} must be an entity id (>= 0), got {n}")
    return n


def extent(value: Any, owner: str, field: str) -> float:
    """A drawn size in metres, in (0, :data:`MAX_EXTENT`] (float32 vertices stay finite)."""
    return at_most(positive(value, owner, field), MAX_EXTENT, owner, field, "m")


def anchor(value: Any, owner: str, field: str) -> Vec2:
    """An (x, y) anchor as fractions of a drawn size, each within +-:data:`MAX_ANCHOR`."""
    x, y = vec2(value, owner, field)
    if abs(x) > MAX_ANCHOR or abs(y) > MAX_ANCHOR:
        raise ValidationError(
            f"{_label(owner, field)} must be fractions within +-{MAX_ANCHOR:g}, got {(x, y)!r}"
        )
    return (x, y)


def frequency(value: Any, owner: str, field: str) -> float:
    """A spring frequency in [0, :data:`MAX_FREQUENCY`] Hz."""
    v = non_negative(value, owner, field)
    if v > MAX_FREQUENCY:
        raise ValidationError(f"{_label(owner, field)} must be <= {MAX_FREQUENCY:g} Hz, got {v!r}")
    return v


def choice(kind: type[E]) -> Callable[[Any, str, str], E]:
    """A check accepting a member of the enum ``kind`` (a mode, a blend, an alignment);
    its string value converts, with a DeprecationWarning.

    >>> from enum import StrEnum
    >>> class Mode(StrEnum):
    ...     A = "a"
    >>> choice(Mode)(Mode.A, "Thing", "mode")
    <Mode.A: 'a'>
    >>> choice(Mode)("c", "Thing", "mode")
    Traceback (most recent call last):
    ...
    kge.errors.ValidationError: Thing.mode must be one of Mode.A, got 'c'
    """

    def check(value: Any, owner: str, field: str) -> E:
        return enum_value(kind, value, owner, field)

    return check


def in_range(value: Any, lo: float, hi: float, owner: str, field: str) -> float:
    v = finite(value, owner, field)
    if not lo <= v <= hi:
        raise ValidationError(f"{_label(owner, field)} must be in [{lo}, {hi}], got {v!r}")
    return v


def name_map(value: Any, kind: type[T], owner: str, field: str) -> dict[str, T]:
    """A non-empty ``{name: kind}`` mapping (an animator's clips, a player's timelines).

    >>> name_map({"walk": 1.0}, float, "Animator", "clips")
    {'walk': 1.0}
    >>> name_map({"": 1.0}, float, "Animator", "clips")
    Traceback (most recent call last):
    ...
    kge.errors.ValidationError: Animator.clips: names must be non-empty strings
    """
    what = kind.__name__
    if not isinstance(value, Mapping) or not value:
        raise ValidationError(f"{owner}.{field} must be a non-empty {{name: {what}}} mapping")
    out: dict[str, T] = {}
    for name, item in value.items():
        if not isinstance(name, str) or not name:
            raise ValidationError(f"{owner}.{field}: names must be non-empty strings")
        if not isinstance(item, kind):
            raise ComponentTypeError(f"{owner}.{field}[{name!r}] must be a {what}, got {item!r}")
        out[name] = item
    return out


def vec2(value: Any, owner: str, field: str) -> Vec2:
    """A pair of finite floats, from any 2-sequence (tuple, list, pymunk Vec2d, numpy)."""
    if _is_float_pair(value):
        return value
    if isinstance(value, (str, bytes, set, frozenset, dict)) or not (
        isinstance(value, Sequence) or (hasattr(value, "__len__") and hasattr(value, "__getitem__"))
    ):  # a set or a dict has a length but no order: not a point
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
    if type(value) is bool:
        return value
    if not isinstance(value, bool):
        raise ComponentTypeError(
            f"{_label(owner, field)} must be True or False, got {type(value).__name__} {value!r}"
        )
    return value


def integer(value: Any, owner: str, field: str) -> int:
    if type(value) is int:
        return value
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


# -- fast paths -------------------------------------------------------------------------------


def _is_finite_float(v: Any) -> bool:
    return type(v) is float and v - v == 0.0


def _is_float_pair(v: Any) -> bool:
    """A tuple of two finite floats (what :func:`vec2` returns): accepted as it is."""
    if type(v) is not tuple or len(v) != 2:
        return False
    x, y = v
    return type(x) is float and type(y) is float and x - x == 0.0 and y - y == 0.0


def _is_bounded_pair(v: Any) -> bool:
    if type(v) is not tuple or len(v) != 2:
        return False
    x, y = v
    return (
        type(x) is float and type(y) is float
        and -MAX_COORDINATE <= x <= MAX_COORDINATE and -MAX_COORDINATE <= y <= MAX_COORDINATE
    )


def _is_bool(v: Any) -> bool:
    return type(v) is bool


FAST: dict[Callable[..., Any], Callable[[Any], bool]] = {
    finite: _is_finite_float,
    non_negative: lambda v: type(v) is float and v - v == 0.0 and v >= 0.0,
    positive: lambda v: type(v) is float and v - v == 0.0 and v > 0.0,
    vec2: _is_float_pair,
    boolean: _is_bool,
    integer: lambda v: type(v) is int,
    coordinate: lambda v: type(v) is float and -MAX_COORDINATE <= v <= MAX_COORDINATE,
    point: _is_bounded_pair,
}
"""check -> predicate that is True only for values the check returns unchanged.

A predicate may say False for a valid value (an ``int`` for :func:`finite`):
the check itself then runs, converts, or raises its usual message.
"""

#: the same tests as :data:`FAST`, as Python expressions for generated code: ``{v}`` is
#: the value, ``{type}`` / ``{float}`` / ``{bool}`` / ``{int}`` name the builtins (a field
#: may be called ``type``)
FAST_EXPR: dict[Callable[..., Any], str] = {
    finite: "{type}({v}) is {float} and {v} - {v} == 0.0",
    non_negative: "{type}({v}) is {float} and {v} - {v} == 0.0 and {v} >= 0.0",
    positive: "{type}({v}) is {float} and {v} - {v} == 0.0 and {v} > 0.0",
    boolean: "{type}({v}) is {bool}",
    integer: "{type}({v}) is {int}",
    coordinate: (
        f"{{type}}({{v}}) is {{float}} and -{MAX_COORDINATE!r} <= {{v}} <= {MAX_COORDINATE!r}"
    ),
}
