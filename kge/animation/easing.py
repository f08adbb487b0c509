"""Easing curves (Robert Penner's set), vectorised over numpy arrays.

An easing maps progress ``p`` in [0, 1] to a curve value with ``f(0) = 0`` and
``f(1) = 1``; ``back`` and ``elastic`` overshoot in between. Every family comes
as ``<name>_in``, ``<name>_out`` and ``<name>_in_out``; ``out(p) = 1 - in(1 - p)``
and ``in_out`` runs ``in`` over the first half and ``out`` over the second, so
each family is written once, as its ``in`` curve.

Tweens evaluate thousands of progress values per frame, grouped by easing, so
the functions take arrays (a float works too) and never loop in Python.

Your own curves work wherever a name does: :class:`CubicBezier` (CSS's
``cubic-bezier(x1, y1, x2, y2)``, what animation tools export), :class:`EaseCurve`
(straight pieces through points, a curve drawn in an editor), or any function of
progress (called with an array when it takes one, else once per value).

>>> round(float(CubicBezier(0.25, 0.1, 0.25, 1.0)(0.5)), 4)    # CSS "ease"
0.8024
>>> EaseCurve([(0, 0), (0.5, 0.8), (1, 1)])(0.25)
0.4

>>> round(float(ease("quad_in", 0.5)), 6), round(float(ease("quad_out", 0.5)), 6)
(0.25, 0.75)
>>> ease("wobble", 0.5)
Traceback (most recent call last):
...
kge.errors.ValidationError: unknown easing 'wobble'; choose one of: linear, quad_in, ...
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from kge.components.tween import EASING_NAMES, check_curve
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


@dataclass(slots=True, frozen=True)
class CubicBezier:
    """CSS's ``cubic-bezier(x1, y1, x2, y2)``: the curve from (0, 0) to (1, 1) with
    control points (x1, y1) and (x2, y2); x1 and x2 in [0, 1], y may overshoot."""

    x1: float
    y1: float
    x2: float
    y2: float

    def __post_init__(self) -> None:
        for name in ("x1", "y1", "x2", "y2"):
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v):
                raise ValidationError(f"CubicBezier.{name} must be a finite number, got {v!r}")
        if not (0.0 <= self.x1 <= 1.0 and 0.0 <= self.x2 <= 1.0):
            raise ValidationError(
                f"CubicBezier: x1 and x2 must be in [0, 1] (time runs forward), got "
                f"{self.x1!r}, {self.x2!r}"
            )

    def __call__(self, p: Any) -> Any:
        x = np.clip(np.asarray(p, dtype=float), 0.0, 1.0)
        t = _bezier_solve(x, self.x1, self.x2)
        out = _bezier(t, self.y1, self.y2)
        return float(out) if np.ndim(out) == 0 else out


def _bezier(t: np.ndarray, a: float, b: float) -> np.ndarray:
    """One coordinate of the curve with control values a, b at parameter t."""
    u = 1.0 - t
    return 3 * u * u * t * a + 3 * u * t * t * b + t**3


def _bezier_solve(x: np.ndarray, x1: float, x2: float) -> np.ndarray:
    """The parameter t where the curve's x is ``x`` (x is monotonic: bisection, exact
    to 1e-9 in 32 halvings, all values at once)."""
    lo, hi = np.zeros_like(x), np.ones_like(x)
    for _ in range(32):
        mid = (lo + hi) / 2
        below = _bezier(mid, x1, x2) < x
        lo = np.where(below, mid, lo)
        hi = np.where(below, hi, mid)
    return (lo + hi) / 2


class EaseCurve:
    """An easing through points ``(progress, value)``, straight between them (a curve
    resource drawn in an editor). Progress must start at 0, end at 1 and increase."""

    __slots__ = ("_xs", "_ys", "points")

    def __init__(self, points: Sequence[tuple[float, float]]) -> None:
        try:
            arr = np.asarray(points, dtype=float)
        except (TypeError, ValueError):
            raise ValidationError(
                f"EaseCurve needs (progress, value) pairs, got {points!r}"
            ) from None
        if arr.ndim != 2 or arr.shape[1] != 2 or len(arr) < 2:
            raise ValidationError(
                f"EaseCurve needs two or more (progress, value) pairs, got {points!r}"
            )
        if not np.isfinite(arr).all():
            raise ValidationError("EaseCurve: every point must be finite")
        xs = arr[:, 0]
        if xs[0] != 0.0 or xs[-1] != 1.0 or np.any(np.diff(xs) <= 0):
            raise ValidationError(
                f"EaseCurve: progress must run from 0 to 1, increasing; got {xs.tolist()}"
            )
        self.points = tuple((float(a), float(b)) for a, b in arr)
        self._xs, self._ys = xs, arr[:, 1]

    def __call__(self, p: Any) -> Any:
        out = np.interp(np.asarray(p, dtype=float), self._xs, self._ys)
        return float(out) if np.ndim(out) == 0 else out

    def __eq__(self, other: object) -> bool:
        return isinstance(other, EaseCurve) and other.points == self.points

    def __hash__(self) -> int:
        return hash(self.points)

    def __repr__(self) -> str:
        return f"EaseCurve({list(self.points)!r})"


#: custom curves started so far: the curve (or its id, if unhashable) -> code
_CUSTOM: dict[Any, int] = {}


def _vectorised(fn: Callable[..., Any]) -> Curve:
    """``fn`` as an array curve: called with the array when it answers one, else per value."""
    probe = np.array([0.0, 0.3, 0.7, 1.0])
    try:
        out = np.asarray(fn(probe), dtype=float)
        if out.shape == probe.shape and np.allclose(out, [float(fn(v)) for v in probe.tolist()]):
            return lambda p: np.asarray(fn(p), dtype=float)
    except Exception:  # a scalar-only function: called once per value below
        pass

    def per_value(p: np.ndarray) -> np.ndarray:
        return np.array([float(fn(v)) for v in np.asarray(p, dtype=float).ravel().tolist()]
                        ).reshape(np.shape(p))  # fmt: skip

    return per_value


def custom_code(fn: Callable[..., Any], owner: str = "Tween") -> int:
    """The code of a custom easing (registered on first use, checked then)."""
    try:
        key: Any = fn
        hash(key)
    except TypeError:
        key = ("id", id(fn))
    code = _CUSTOM.get(key)
    if code is None:
        check_curve(fn, owner)
        code = _CUSTOM[key] = len(CURVES)
        CURVES.append(_vectorised(fn))
        NAMES.append(repr(fn))
    return code


def easing_code(name: Any, owner: str = "", field: str = "ease") -> int:
    """The code of easing ``name`` (or of a custom curve); an unknown name is a
    ValidationError listing the set."""
    if callable(name):
        return custom_code(name, owner or "Tween")
    code = CODES.get(name) if isinstance(name, str) else None
    if code is None:
        label = f"{owner}.{field}: " if owner else ""
        raise ValidationError(
            f"{label}unknown easing {name!r}; choose one of: {', '.join(EASING_NAMES)}"
        )
    return code


def ease(name: str | Callable[..., Any], p: Any) -> np.ndarray:
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
