"""Tween specs: what to animate, to what value, how long and with which easing.

A :class:`Tween` names a component type and one of its numeric, vector or colour
fields (``Transform.x``, ``Sprite.opacity``, ``Camera.center``, ``Sprite.tint``),
the value to reach, a duration in seconds and an easing (``linear``, or
``quad``/``cubic``/``quart``/``quint``/``sine``/``expo``/``circ``/``back``/
``elastic``/``bounce`` with ``_in``, ``_out`` or ``_in_out``; or your own curve:
a function of progress, :class:`kge.animation.easing.CubicBezier` as in CSS, or
:class:`kge.animation.easing.EaseCurve` through points). ``relative=True`` makes
``to`` an offset from the value the tween starts from (a move *by*). ``delay`` waits
first; ``repeat`` plays it again that many times (-1: forever), ``yoyo`` plays
every other repetition backwards. ``start`` fixes the starting value; without
it the field's value when the tween begins is used.

:class:`TweenSequence` runs steps one after another, :class:`Parallel` together,
:class:`Delay` is a pause inside a sequence and :class:`Call` calls a function there.
Specs are plain immutable data; ``world.resource(kge.Tweens).start(entity, spec)`` runs one (see
:mod:`kge.systems.animation`) and returns a handle a coroutine can ``yield``.

>>> from kge.components.transform import Transform
>>> pop = TweenSequence(Tween(Transform, "y", 1.0, 0.2, ease="back_out"), Delay(0.1),
...                     Tween(Transform, "y", 0.0, 0.3, ease="bounce_out"))
>>> round(pop.total, 3)
0.6
>>> Tween(Transform, "x", 1.0, 0.0)
Traceback (most recent call last):
...
kge.errors.ValidationError: Tween(Transform.x).duration must be > 0, got 0.0
>>> Tween(Transform, "x", 1.0, 1.0, ease="wobble_in")
Traceback (most recent call last):
...
kge.errors.ValidationError: Tween(Transform.x).ease: unknown easing 'wobble_in'; choose one of: ...
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from kge.deprecation import moved
from kge.errors import ComponentTypeError, ValidationError
from kge.validate import boolean, integer, non_negative, positive

#: easing names (the curves live in kge.animation.easing, which checks names at start)
FAMILIES = ("quad", "cubic", "quart", "quint", "sine", "expo", "circ", "back", "elastic", "bounce")
EASING_NAMES: tuple[str, ...] = (
    "linear",
    *(f"{f}_{kind}" for f in FAMILIES for kind in ("in", "out", "in_out")),
)


def _check_ease(name: Any, owner: str) -> Any:
    if callable(name):
        return check_curve(name, owner)
    if name not in EASING_NAMES:
        raise ValidationError(
            f"{owner}.ease: unknown easing {name!r}; choose one of: {', '.join(EASING_NAMES)} "
            "(or a function of progress)"
        )
    return str(name)


def check_curve(fn: Any, owner: str) -> Any:
    """A custom easing must give a finite number for every progress in [0, 1]."""
    probe = (0.0, 0.25, 0.5, 0.75, 1.0)
    try:
        values = [float(fn(p)) for p in probe]
    except Exception as exc:  # the user's function: any error is reported at the call
        raise ValidationError(
            f"{owner}.ease: the easing function {fn!r} failed at progress 0..1 "
            f"({type(exc).__name__}: {exc})"
        ) from None
    if not all(math.isfinite(v) for v in values):
        raise ValidationError(
            f"{owner}.ease: the easing function {fn!r} gave {values} at progress "
            f"{list(probe)}: not all finite"
        )
    return fn


@dataclass(slots=True, frozen=True)
class Tween:
    """Animate ``component.field`` to ``to`` over ``duration`` seconds. See the module docstring."""

    component: type
    field: str
    to: Any
    duration: float
    ease: Any = "linear"  #: a name, or a function of progress (see the module docstring)
    delay: float = 0.0
    repeat: int = 0
    yoyo: bool = False
    start: Any = None
    name: str = ""
    relative: bool = False  #: ``to`` is added to the start value (move by, not to)

    def __post_init__(self) -> None:
        if not isinstance(self.component, type):
            raise ComponentTypeError(
                f"Tween.component must be a component class (Transform, Sprite...), "
                f"got {self.component!r}"
            )
        if not isinstance(self.field, str) or not self.field:
            raise ComponentTypeError(f"Tween.field must be a field name, got {self.field!r}")
        owner = self.label
        positive(self.duration, owner, "duration")
        non_negative(self.delay, owner, "delay")
        rep = integer(self.repeat, owner, "repeat")
        if rep < -1:
            raise ValidationError(f"{owner}.repeat must be >= 0, or -1 for forever, got {rep}")
        boolean(self.yoyo, owner, "yoyo")
        boolean(self.relative, owner, "relative")
        _check_ease(self.ease, owner)

    @property
    def label(self) -> str:
        return f"Tween({self.component.__name__}.{self.field})"

    @property
    def total(self) -> float:
        """Seconds from start to end, delay and repeats included (inf when forever)."""
        if self.repeat < 0:
            return math.inf
        return float(self.delay) + float(self.duration) * (self.repeat + 1)


@dataclass(slots=True, frozen=True)
class Delay:
    """A pause of ``seconds`` inside a :class:`TweenSequence`."""

    seconds: float

    def __post_init__(self) -> None:
        non_negative(self.seconds, "Delay", "seconds")

    @property
    def total(self) -> float:
        return float(self.seconds)


class Call:
    """Call ``fn(*args)`` at this point of a :class:`TweenSequence` (it takes no time).

    In a repeating sequence it is called on every pass.
    """

    __slots__ = ("args", "fn")

    def __init__(self, fn: Any, *args: Any) -> None:
        if not callable(fn):
            raise ValidationError(f"Call needs a function, got {fn!r}")
        self.fn = fn
        self.args = args

    @property
    def total(self) -> float:
        return 0.0

    def __repr__(self) -> str:
        return f"Call({getattr(self.fn, '__name__', self.fn)!s})"


def _steps(steps: tuple[Any, ...], owner: str) -> None:
    if not steps:
        raise ValidationError(f"{owner} needs at least one step")
    for i, s in enumerate(steps):
        if not isinstance(s, (Tween, Delay, Call, TweenSequence, Parallel)):
            raise ComponentTypeError(
                f"{owner} step {i} must be a Tween, Delay, Call, TweenSequence or Parallel, "
                f"got {s!r}"
            )


class TweenSequence:
    """Steps one after another; ``repeat`` runs the whole sequence again (-1: forever).

    (``Sequence`` before kge 2.0.0a2: that name shadowed ``typing.Sequence``.)
    """

    __slots__ = ("name", "repeat", "steps")

    def __init__(self, *steps: Any, repeat: int = 0, name: str = "") -> None:
        _steps(steps, "TweenSequence")
        rep = integer(repeat, "TweenSequence", "repeat")
        if rep < -1:
            raise ValidationError(
                f"TweenSequence.repeat must be >= 0, or -1 for forever, got {rep}"
            )
        self.steps: tuple[Any, ...] = steps
        self.repeat = rep
        self.name = name

    @property
    def once(self) -> float:
        """One pass through the steps, in seconds."""
        return math.fsum(s.total for s in self.steps)

    @property
    def total(self) -> float:
        if self.repeat < 0:
            return math.inf
        return self.once * (self.repeat + 1)

    def __repr__(self) -> str:
        return f"TweenSequence({', '.join(map(repr, self.steps))}, repeat={self.repeat})"


class Parallel:
    """Steps that start together; it ends when the longest ends."""

    __slots__ = ("name", "steps")

    def __init__(self, *steps: Any, name: str = "") -> None:
        _steps(steps, "Parallel")
        self.steps: tuple[Any, ...] = steps
        self.name = name

    @property
    def total(self) -> float:
        return max(s.total for s in self.steps)

    def __repr__(self) -> str:
        return f"Parallel({', '.join(map(repr, self.steps))})"


#: ``Sequence``, the old name of :class:`TweenSequence`, for one release
__getattr__ = moved(__name__, {"Sequence": (lambda: TweenSequence, "TweenSequence")})
