"""``PhysicsSettings``: world-wide simulation parameters, tuned for metres.

pymunk's defaults assume pixels (``collision_slop`` 0.1 is 20x Box2D's linear
slop) and its plain 10-iteration solver lets a 15-box stack drift half a metre.
kge's defaults reproduce Box2D 2.3's feel at 8/3 iterations: each fixed step is
split into ``substeps`` pymunk steps (4 x 1/240 s holds a 10-row pyramid and a
20-box stack), polygons carry Box2D's 0.01 m skin, and bodies sleep after
0.5 s below 0.01 m/s.

Insert your own before or during scene setup to change them; the physics system
reads them at every step, so gravity can change at run time.

>>> PhysicsSettings().gravity
(0.0, -10.0)
>>> PhysicsSettings(substeps=0)
Traceback (most recent call last):
...
kge.errors.ValidationError: PhysicsSettings.substeps must be >= 1, got 0
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from kge.errors import ValidationError
from kge.snapshot import keep_resource
from kge.validate import Vec2, at_most, boolean, integer, non_negative, positive, vec2


@keep_resource  # simulation state: snapshots carry it
@dataclass(slots=True)
class PhysicsSettings:
    """Global physics parameters (read by the physics system every step)."""

    gravity: Vec2 = (0.0, -10.0)
    #: pymunk steps per fixed step (stacking quality; cost grows linearly)
    substeps: int = 4
    #: solver iterations per substep
    iterations: int = 10
    #: Box2D's b2_linearSlop: allowed overlap that the solver leaves alone
    collision_slop: float = 0.005
    #: Box2D's b2_polygonRadius: skin on polygons and edges
    polygon_radius: float = 0.01
    sleep: bool = True
    #: b2_timeToSleep
    time_to_sleep: float = 0.5
    #: b2_linearSleepTolerance (pymunk's idle speed)
    sleep_speed: float = 0.01
    #: b2_velocityThreshold: no bounce at or below this approach speed
    velocity_threshold: float = 1.0
    #: b2_maxTranslation per fixed step
    max_translation: float = 2.0
    #: b2_maxRotation per fixed step
    max_rotation: float = 0.5 * math.pi
    #: solve revolute motors and limits inside pymunk's iterations, with the
    #: contacts, as Box2D does (its motor and limit rows are angular-only, like
    #: pymunk's SimpleMotor and RotaryLimitJoint; limit overshoot is removed by the
    #: position pass, not by velocity). Holds a load (landing legs) with many
    #: iterations; kge's default, once per substep on the pivot-folded hinge, brakes
    #: a heavy pendulum better at few iterations. kge.box2d turns it on. Prismatic
    #: limits are then solved in pymunk's iterations too (a pymunk SlideJoint along
    #: the axis), and left b2_linearSlop past their bound by the position pass.
    iterated_hinges: bool = False
    #: iterated hinges: the most speed, rad/s, a limit adds to push an overshooting
    #: hinge back (pymunk's bias). 0 is Box2D's rule: the limit only stops the hinge,
    #: and the position pass removes what overshoots b2_angularSlop, velocities
    #: untouched. A push lifts whatever a motor presses onto its stop: a hull landed
    #: on two motorised legs hopped on its legs for ever with 0.1 and comes to rest with 0 (at
    #: 8 x 8 solver passes; with 0.1 it needed 8 x 40). But a push also holds a joint
    #: the iterations leave short of converged: a motorised two-legged walker walks 6 of
    #: 10 seeds past 30 m with 0.1, and with 0 only 3, while 5 fall within 14 m; so 0.1
    #: stays the default. Read when a joint is built or changed.
    hinge_limit_push: float = 0.1
    #: broad phase: None keeps Chipmunk's bounding-box tree; a cell size in metres
    #: (about a typical shape's size) switches to its spatial hash, faster for many
    #: similar shapes (rain-5000 0.82x, dense-pile-6000 0.92x the tree's step time,
    #: docs/benchmarks.md) and slower for mixed sizes (pyramid-40 1.11x). Deterministic
    #: either way, but the two give different (equally valid) results. Choose it
    #: before the first step: Chipmunk cannot go back to its tree.
    spatial_hash: float | None = None
    #: solver threads (pymunk's threaded space, 1 or 2; not on Windows). 2 solves
    #: large scenes faster (rain-5000 about 0.6x the serial step) but is NOT
    #: deterministic: the same scene run twice ends in different poses. Choose it
    #: before the first step.
    threads: int = 1

    def __setattr__(self, name: str, value: Any) -> None:
        # every assignment is checked, not only the constructor's: a NaN gravity set
        # between steps would otherwise turn every pose into NaN at the next step
        check = _CHECKS.get(name)
        if check is not None:
            value = check(value, "PhysicsSettings", name)
        object.__setattr__(self, name, value)


def _at_least_one(value: Any, owner: str, name: str) -> int:
    v = integer(value, owner, name)
    if v < 1:
        raise ValidationError(f"{owner}.{name} must be >= 1, got {v!r}")
    if v > 1000:  # 10**19 substeps is a step that never ends
        raise ValidationError(f"{owner}.{name} must be <= 1000, got {v!r}")
    return v


def _bounded(limit: float, unit: str, check: Callable[[Any, str, str], float]) -> Any:
    """``check``, then no more than ``limit``: skins and slops beyond a metre, or per-step
    caps beyond a kilometre, are no game's settings and overflow squares downstream."""

    def checked(value: Any, owner: str, name: str) -> float:
        return at_most(check(value, owner, name), limit, owner, name, unit)

    return checked


def _optional_cell(value: Any, owner: str, name: str) -> float | None:
    if value is None:
        return None
    return at_most(positive(value, owner, name), 1e3, owner, name, "m")


def _thread_count(value: Any, owner: str, name: str) -> int:
    v = integer(value, owner, name)
    if v not in (1, 2):
        raise ValidationError(f"{owner}.{name} must be 1 or 2 (pymunk's solver threads), got {v!r}")
    return v


_CHECKS: dict[str, Callable[[Any, str, str], Any]] = {
    "gravity": vec2,
    "substeps": _at_least_one,
    "iterations": _at_least_one,
    "collision_slop": _bounded(1.0, "m", non_negative),
    "polygon_radius": _bounded(1.0, "m", non_negative),
    "sleep": boolean,
    "time_to_sleep": positive,
    "sleep_speed": non_negative,
    "velocity_threshold": non_negative,
    "max_translation": _bounded(1e3, "m", positive),
    "max_rotation": _bounded(1e3, "rad", positive),
    "iterated_hinges": boolean,
    "hinge_limit_push": _bounded(1e3, "rad/s", non_negative),
    "spatial_hash": _optional_cell,
    "threads": _thread_count,
}
