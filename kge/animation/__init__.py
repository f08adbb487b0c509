"""Animation state and maths with no GL: clips in numpy, tweens, easings, GIF timing, shake.

The systems and plugin that run them live in :mod:`kge.systems.animation`; the
atlas and bulk texture-coordinate writer in :mod:`kge.render.animation`.
"""

from kge.animation.clips import ClipState, ClipTable, CrossFade
from kge.animation.easing import EASINGS, CubicBezier, EaseCurve, ease
from kge.animation.events import (
    AnimationEvent,
    AnimationEvents,
    AnimationFinished,
    TimelineFinished,
    TweenFinished,
)
from kge.animation.gif import gif_clip
from kge.animation.tweens import TweenHandle, Tweens, TweenTable

__all__ = [
    "EASINGS",
    "AnimationEvent",
    "AnimationEvents",
    "AnimationFinished",
    "ClipState",
    "ClipTable",
    "CrossFade",
    "CubicBezier",
    "EaseCurve",
    "TimelineFinished",
    "TweenFinished",
    "TweenHandle",
    "TweenTable",
    "Tweens",
    "ease",
    "gif_clip",
]
