"""Animation and tween events: per-frame data lists (the :class:`AnimationEvents` resource).

The animation systems run once per frame (UPDATE stage), so their events are
per *frame*, not per fixed step: the lists are cleared when the animation
system starts its pass, and hold what happened in this frame's pass until the
next one. Behaviour hooks receive the same objects:

=========================  =========================  ===============================
event                      list                       hook
=========================  =========================  ===============================
:class:`AnimationEvent`    ``events.frame``           ``on_animation_event(event)``
:class:`AnimationFinished` ``events.finished``        ``on_animation_end(event)``
:class:`TweenFinished`     ``events.tweens``          ``on_tween_end(event)``
=========================  =========================  ===============================
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any


@dataclass(slots=True, frozen=True)
class AnimationEvent:
    """Frame ``frame`` of clip ``clip`` was entered on ``entity``; ``name`` is the clip's label."""

    entity: int
    clip: str
    name: str
    frame: int


@dataclass(slots=True, frozen=True)
class AnimationFinished:
    """A ``once``/``hold`` clip reached its end on ``entity``."""

    entity: int
    clip: str


@dataclass(slots=True, frozen=True)
class TweenFinished:
    """A tween (or sequence / group) started on ``entity`` completed; ``handle`` is its handle.

    ``entity`` is None for a tween of a resource (a Camera resource, say).
    """

    entity: int | None
    handle: Any
    name: str = ""


@dataclass(slots=True, frozen=True)
class TimelineFinished:
    """Timeline ``name`` (one that does not loop) reached its end on ``entity``."""

    entity: int
    name: str


@dataclass(slots=True)
class AnimationEvents:
    """This frame's animation and tween events (see the module docstring)."""

    frame: list[AnimationEvent] = field(default_factory=list)
    finished: list[AnimationFinished] = field(default_factory=list)
    tweens: list[TweenFinished] = field(default_factory=list)

    def clear(self) -> None:
        self.frame.clear()
        self.finished.clear()
        self.tweens.clear()
