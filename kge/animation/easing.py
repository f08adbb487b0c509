"""Easing curves (Robert Penner's set), vectorised over numpy arrays.

An easing maps progress ``p`` in [0, 1] to a curve value with ``f(0) = 0`` and
``f(1) = 1``; ``back`` and ``elastic`` overshoot in between. Every family comes
as ``<name>_in``, ``<name>_out`` and ``<name>_in_out``; ``out(p) = 1 - in(1 - p)``
and ``in_out`` runs ``in`` over the first half and ``out`` over the second, so
each family is written once, as its ``in`` curve.

Tweens evaluate thousands of progress values per frame, grouped by easing, so
the functions take arrays (a float works too) and never loop in Python.

>>> round(float(ease("quad_in", 0.5)), 6), round(float(ease("quad_out", 0.5)), 6)
(0.25, 0.75)
>>> ease("wobble", 0.5)
Traceback (most recent call last):
...
kge.errors.ValidationError: unknown easing 'wobble'; choose one of: linear, quad_in, ...
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from kge.components.tween import EASING_NAMES
from kge.errors import ValidationError

Curve = Callable[[np.ndarray], np.ndarray]

_C1 = 1.70158  # back overshoot ("10 %")
_C2 = _C1 * 1.525
_C3 = _C1 + 1.0


def _bounce_out(p: np.ndarray) -> np.ndarray:
    n1, d1 = 7.5625, 2.75
    return np.where(
        p < 1 / d1,
        n1 * p * p,
        np.where(
            p < 2 / d1,
            n1 * (p - 1.5 / d1) ** 2 + 0.75,
            np.where(p < 2.5 / d1, n1 * (p - 2.25 / d1) ** 2 + 0.9375,
                     n1 * (p - 2.625 / d1) ** 2 + 0.984375),
        ),
    )


def _elastic_in(p: np.ndarray) -> np.ndarray:
    c4 = 2 * np.pi / 3
    with np.errstate(over="ignore", under="ignore"):
        v = -(2.0 ** (10 * p - 10)) * np.sin((p * 10 - 10.75) * c4)
    return np.where(p <= 0, 0.0, np.where(p >= 1, 1.0, v))


def _expo_in(p: np.ndarray) -> np.ndarray:
    with np.errstate(under="ignore"):
        return np.where(p <= 0, 0.0, 2.0 ** (10 * p - 10))


_IN: dict[str, Curve] = {
    "quad": lambda p: p * p,
    "cubic": lambda p: p**3,
    "quart": lambda p: p**4,
    "quint": lambda p: p**5,
    "sine": lambda p: 1 - np.cos(p * np.pi / 2),
    "expo": _expo_in,
    "circ": lambda p: 1 - np.sqrt(np.maximum(0.0, 1 - p * p)),
    "back": lambda p: _C3 * p**3 - _C1 * p * p,
    "elastic": _elastic_in,
    "bounce": lambda p: 1 - _bounce_out(1 - p),
}


def _out(f: Curve) -> Curve:
    return lambda p: 1 - f(1 - p)


def _in_out(f: Curve) -> Curve:
    def curve(p: np.ndarray) -> np.ndarray:
        first = p < 0.5  # in over the first half, out (mirrored in) over the second
        half = f(np.where(first, 2 * p, 2 - 2 * p)) / 2
        return np.where(first, half, 1 - half)

    return curve


def _linear(p: np.ndarray) -> np.ndarray:
    return p


EASINGS: dict[str, Curve] = {"linear": _linear}
for _name, _f in _IN.items():
    EASINGS[f"{_name}_in"] = _f
    EASINGS[f"{_name}_out"] = _out(_f)
    EASINGS[f"{_name}_in_out"] = _in_out(_f)

assert tuple(EASINGS) == EASING_NAMES, "kge.components.tween.EASING_NAMES is out of date"

#: easing name -> small integer code (tween tables store codes, not names)
CODES: dict[str, int] = {name: i for i, name in enumerate(EASINGS)}
CURVES: list[Curve] = list(EASINGS.values())
NAMES: list[str] = list(EASINGS)


def easing_code(name: Any, owner: str = "", field: str = "ease") -> int:
    """The code of easing ``name``; an unknown name is a ValidationError listing the set."""
    code = CODES.get(name) if isinstance(name, str) else None
    if code is None:
        label = f"{owner}.{field}: " if owner else ""
        raise ValidationError(
            f"{label}unknown easing {name!r}; choose one of: {', '.join(NAMES)}"
        )
    return code


def ease(name: str, p: Any) -> np.ndarray:
    """``name``'s curve at progress ``p`` (clipped to [0, 1])."""
    curve = CURVES[easing_code(name)]
    return np.asarray(curve(np.clip(np.asarray(p, dtype=float), 0.0, 1.0)), dtype=float)


def apply(codes: np.ndarray, p: np.ndarray) -> np.ndarray:
    """Evaluate each row's easing (``codes[i]``) at ``p[i]``: one numpy call per easing used."""
    out = np.empty_like(p)
    if not len(codes):
        return out
    lo, hi = int(codes.min()), int(codes.max())
    if lo == hi:  # one easing for all (the usual case): no grouping
        out[:] = CURVES[lo](p)
        return out
    used = np.unique(codes)
    for code in used:
        mask = codes == code
        out[mask] = CURVES[int(code)](p[mask])
    return out
