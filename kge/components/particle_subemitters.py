"""``ParticleSubEmitters``: particles that spawn particles on birth, collision and death.

A sub-emitter is another emitter entity (its ``ParticleEmitter`` says how the new
particles look and move; usually ``emitting=False`` so it only sprays when told).
On the parent emitter's entity, ``ParticleSubEmitters(SubEmitter(...), ...)`` names,
for each event kind (:class:`SubEmitEvent`), which emitter fires ``count`` particles
at each event's position, adding ``inherit_velocity`` of the event particle's
velocity to theirs: a firework whose rockets burst into sparks when they die, rain
that splashes where it hits the ground, a comet whose every spark leaves smoke.

Bounded and deterministic: each parent takes at most ``max_events`` events per frame
(later ones are dropped and counted in ``Particles.state(parent).extras``), each
sub-emitter's pool is capped by its ``max_particles``, chains (sparks that spawn
sparks) advance a bounded number of generations per frame, and every random draw
comes from the sub-emitter's own seeded generator, in entity order.

>>> SubEmitter(7, SubEmitEvent.DEATH, count=30).inherit_velocity
0.0
>>> SubEmitter(7, SubEmitEvent.DEATH, count=-1)
Traceback (most recent call last):
...
kge.errors.ValidationError: SubEmitter.count must be in 0..100000, got -1
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from enum import StrEnum
from typing import Any, ClassVar

from kge.components.tracked import Check, Tracked
from kge.errors import ComponentTypeError, ValidationError
from kge.validate import choice, entity_id, in_range, integer

#: the most particles one event may spawn, and the most events a parent takes a frame
MAX_COUNT = 100_000


class SubEmitEvent(StrEnum):
    """When a sub-emitter fires."""

    BIRTH = "birth"  #: each particle the parent emits (a trail of particles)
    COLLISION = "collision"  #: each time a parent particle hits a static collider
    DEATH = "death"  #: each parent particle that dies (of age or on a collider)


def _count(value: Any, owner: str, field: str) -> int:
    n = integer(value, owner, field)
    if not 0 <= n <= MAX_COUNT:
        raise ValidationError(f"{owner}.{field} must be in 0..{MAX_COUNT}, got {n}")
    return n


@dataclass(slots=True, frozen=True)
class SubEmitter:
    """``count`` particles of ``emitter`` at each ``on`` event of the parent's particles."""

    emitter: int
    on: SubEmitEvent = SubEmitEvent.DEATH
    count: int = 10
    inherit_velocity: float = 0.0  #: share of the event particle's velocity, -10..10

    def __post_init__(self) -> None:
        entity_id(self.emitter, "SubEmitter", "emitter")
        object.__setattr__(self, "on", choice(SubEmitEvent)(self.on, "SubEmitter", "on"))
        _count(self.count, "SubEmitter", "count")
        object.__setattr__(self, "inherit_velocity", in_range(
            self.inherit_velocity, -10.0, 10.0, "SubEmitter", "inherit_velocity"))  # fmt: skip


def _subs(value: Any, owner: str, field: str) -> tuple[SubEmitter, ...]:
    if isinstance(value, SubEmitter):
        return (value,)
    if isinstance(value, (str, bytes)) or not isinstance(value, Sequence):
        raise ComponentTypeError(f"{owner}.{field} must be SubEmitter values, got {value!r}")
    for i, sub in enumerate(value):
        if not isinstance(sub, SubEmitter):
            raise ComponentTypeError(f"{owner}.{field}[{i}] must be a SubEmitter, got {sub!r}")
    if len(value) > 16:
        raise ValidationError(f"{owner}.{field} takes at most 16 sub-emitters, got {len(value)}")
    return tuple(value)


def _events(value: Any, owner: str, field: str) -> int:
    return _count(value, owner, field)


@dataclass(slots=True, init=False)
class ParticleSubEmitters(Tracked):
    """The sub-emitters of this entity's emitter. See the module docstring."""

    #: each sub-emitter must be a world-space emitter (checked by the effects plugin)
    _world_fields: ClassVar[frozenset[str]] = frozenset({"emitters"})

    _checks: ClassVar[dict[str, Check]] = {"emitters": _subs, "max_events": _events}

    emitters: tuple[SubEmitter, ...]
    max_events: int = 1000  #: events per frame, at most (the rest are dropped)

    def __init__(self, *subs: SubEmitter, emitters: Sequence[SubEmitter] = (),
                 max_events: int = 1000) -> None:  # fmt: skip
        self.emitters = (*subs, *emitters)
        self.max_events = max_events
        object.__setattr__(self, "_binding", None)  # as Tracked's dataclass __init__ does
