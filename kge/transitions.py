"""Scene transitions: how ``app.replace_scene(Level2, transition=Fade(0.4))`` looks.

A transition is pure data (its kind, duration, colour, direction); the App keeps
one :class:`ActiveTransition` while it plays, advancing it by each frame's real
time (unscaled, so a paused or slowed game still changes level at the same pace;
``app.step`` advances it by ``fixed_dt``, so headless runs are deterministic), and
the renderer draws it over the frame (``kge/render/transitions.py``):

=============  ==========================================================================
``Fade``       the old scene fades to ``color``; at half time the scene changes; the new
               one fades in
``Crossfade``  a picture of the old scene's last frame fades out over the new scene
``Slide``      that picture slides off the screen towards ``direction``
``Wipe``       that picture is cut away by an edge moving towards ``direction``
=============  ==========================================================================

The picture-based ones change the scene on the first frame of the transition, after
taking a picture of the old scene as the window shows it then (nothing is pictured
before anything was drawn, as in a headless run that never renders). A transition
asked for during a frame (a script's ``on_update``, a button's ``on_click``) starts
its clock with the next frame, so it plays whole wherever it was asked for.
Progress is eased (smoothstep, or your own curve: ``ease=`` any function of progress
0..1, such as ``kge.CubicBezier(0.7, 0, 0.3, 1)`` or ``lambda p: p``), and every
quantity the renderer needs is a property of ``ActiveTransition`` at time t:

>>> active = ActiveTransition(Fade(0.4))
>>> active.advance(0.1); round(active.cover, 3)          # a quarter in: half covered
0.5
>>> active.swap_due, active.advance(0.1), active.swap_due
(False, None, True)
>>> active.swapped = True                                # the App changes the scene here
>>> active.advance(0.2); active.done, active.cover
(True, 0.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, ClassVar

from kge.errors import ComponentTypeError, ValidationError

_DIRECTIONS = ("left", "right", "up", "down")


@dataclass(slots=True, frozen=True)
class Transition:
    """Base of transitions: ``duration`` seconds, ``color`` for fades."""

    duration: float = 0.4
    color: tuple[int, int, int] = (0, 0, 0)
    #: the easing of progress: None (smoothstep) or a function of progress 0..1
    ease: Any = None

    #: does it draw a picture of the old scene (taken on the frame before the change)?
    needs_picture: ClassVar[bool] = False

    def __post_init__(self) -> None:
        d = self.duration
        if isinstance(d, bool) or not isinstance(d, (int, float)) or not 0 < d < math.inf:
            raise ValidationError(
                f"{type(self).__name__}.duration must be a positive number of seconds, got {d!r}"
            )
        if not isinstance(self.color, (tuple, list)):
            raise ComponentTypeError(
                f"{type(self).__name__}.color must be three ints 0..255, got {self.color!r}"
            )
        if len(self.color) != 3 or not all(
            isinstance(c, int) and not isinstance(c, bool) and 0 <= c <= 255 for c in self.color
        ):
            raise ValidationError(
                f"{type(self).__name__}.color must be three ints 0..255, got {self.color!r}"
            )
        if self.ease is not None:
            _check_ease(self.ease, type(self).__name__)

    def curve(self, t: float) -> float:
        """Eased progress at linear progress ``t`` (clamped to 0..1)."""
        t = min(max(t, 0.0), 1.0)
        if self.ease is None:
            return t * t * (3.0 - 2.0 * t)
        return min(max(float(self.ease(t)), 0.0), 1.0)


def _check_ease(fn: Any, owner: str) -> None:
    """A transition's easing must be a function giving finite numbers over 0..1."""
    if not callable(fn):
        raise ValidationError(f"{owner}.ease must be a function of progress, got {fn!r}")
    try:
        values = [float(fn(p)) for p in (0.0, 0.25, 0.5, 0.75, 1.0)]
    except Exception as exc:  # the user's function: reported at the call
        raise ValidationError(f"{owner}.ease failed at progress 0..1 "
                              f"({type(exc).__name__}: {exc})") from None  # fmt: skip
    if not all(math.isfinite(v) for v in values):
        raise ValidationError(f"{owner}.ease gave {values}: not all finite")


@dataclass(slots=True, frozen=True)
class Fade(Transition):
    """Fade out to ``color``, change scene, fade in."""


@dataclass(slots=True, frozen=True)
class Crossfade(Transition):
    """The old scene's last frame fades out over the new scene."""

    needs_picture: ClassVar[bool] = True


@dataclass(slots=True, frozen=True)
class _Directed(Transition):
    direction: str = "left"
    needs_picture: ClassVar[bool] = True

    def __post_init__(self) -> None:
        super(_Directed, self).__post_init__()
        if self.direction not in _DIRECTIONS:
            raise ValidationError(
                f"{type(self).__name__}.direction must be one of {', '.join(_DIRECTIONS)}, "
                f"got {self.direction!r}"
            )


@dataclass(slots=True, frozen=True)
class Slide(_Directed):
    """The old scene's last frame slides away towards ``direction``."""


@dataclass(slots=True, frozen=True)
class Wipe(_Directed):
    """An edge moving towards ``direction`` wipes the old scene's last frame away."""


def smoothstep(t: float) -> float:
    t = min(max(t, 0.0), 1.0)
    return t * t * (3.0 - 2.0 * t)


@dataclass(slots=True)
class ActiveTransition:
    """A transition being played (the App's ``transition`` attribute while it runs)."""

    transition: Transition
    elapsed: float = 0.0
    swapped: bool = False
    #: the renderer's picture of the old scene (a pyglet texture), when it took one
    picture: Any = None
    frames: int = 0
    #: asked for during a frame: its first advance (as that frame ends) is skipped
    fresh: bool = False

    @property
    def kind(self) -> str:
        return type(self.transition).__name__.lower()

    @property
    def t(self) -> float:
        """Linear progress in [0, 1]."""
        return min((self.elapsed + 1e-9) / self.transition.duration, 1.0)  # float sums

    @property
    def eased(self) -> float:
        return self.transition.curve(self.t)

    @property
    def swap_due(self) -> bool:
        """Should the App change the scene now?"""
        if self.swapped:
            return False
        if self.transition.needs_picture:
            return self.frames >= 1  # the first frame of the transition
        return self.t >= 0.5

    @property
    def done(self) -> bool:
        return self.swapped and self.t >= 1.0

    @property
    def cover(self) -> float:
        """Opacity (0..1) of the fade colour over the frame (Fade only; 0 for others)."""
        if not isinstance(self.transition, Fade):
            return 0.0
        return self.transition.curve(1.0 - abs(2.0 * self.t - 1.0))

    @property
    def picture_alpha(self) -> float:
        """Opacity of the old scene's picture (Crossfade), 1 for Slide and Wipe."""
        if isinstance(self.transition, Crossfade):
            return 1.0 - self.eased
        return 1.0 if self.transition.needs_picture else 0.0

    @property
    def shift(self) -> tuple[float, float]:
        """How far (fraction of the window) the picture has moved or been wiped, as (x, y)."""
        tr = self.transition
        if not isinstance(tr, (Slide, Wipe)):
            return (0.0, 0.0)
        e = self.eased
        return {"left": (-e, 0.0), "right": (e, 0.0), "up": (0.0, e), "down": (0.0, -e)}[
            tr.direction
        ]

    def advance(self, dt: float) -> None:
        self.elapsed += max(float(dt), 0.0)
        self.frames += 1
