"""Physics events as data, and the per-step ``PhysicsEvents`` resource.

Callbacks inside the pymunk step only *record* events; they are delivered after
the step (resource lists, esper events named like the lists, and Behaviour
hooks), when the world is unlocked again. Every begin is matched by exactly one
end: when the shapes part, when a collider or body is despawned, disabled, or
refiltered so that the pair no longer collides.

Entities: ``collider_a`` / ``collider_b`` are collider entities; ``body_a`` /
``body_b`` are the body entities (``None`` for a collider on the implicit
static body). The normal points from collider A to collider B, with A chosen
as Box2D does (edge before polygon before circle; otherwise the older
collider). ``child_a`` / ``child_b`` are Box2D's child indices: the segment of a
chain collider (0 for every other shape), so the begins and ends of a body
touching two segments of one chain pair up.

Order: every list is sorted at the end of each step by entity ids, then child
indices (joint events by joint id), so the same script gives the same lists in
every process. Chipmunk reports contacts in the order of its arbiter hash set,
which follows memory addresses; that order never reaches kge's lists.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, ClassVar, TypeVar

T = TypeVar("T")

Vec2 = tuple[float, float]


@dataclass(slots=True, frozen=True)
class ContactBegin:
    collider_a: int
    collider_b: int
    body_a: int | None
    body_b: int | None
    normal: Vec2  #: unit, from collider A to collider B
    points: tuple[Vec2, ...]  #: world points, 1 or 2
    separation: float  #: most negative distance (< 0 = overlap)
    approach_speed: float  #: relative normal speed at first contact (>= 0), m/s
    child_a: int = 0  #: segment of a chain collider A (0 for other shapes)
    child_b: int = 0


@dataclass(slots=True, frozen=True)
class ContactEnd:
    collider_a: int
    collider_b: int
    body_a: int | None
    body_b: int | None
    child_a: int = 0
    child_b: int = 0


@dataclass(slots=True, frozen=True)
class SensorBegin:
    collider_a: int  #: the sensor
    collider_b: int
    body_a: int | None
    body_b: int | None
    child_a: int = 0
    child_b: int = 0


@dataclass(slots=True, frozen=True)
class SensorEnd:
    collider_a: int  #: the sensor
    collider_b: int
    body_a: int | None
    body_b: int | None
    child_a: int = 0
    child_b: int = 0


@dataclass(slots=True, frozen=True)
class Hit:
    """An impact faster than the larger ``hit_threshold`` of the two colliders."""

    collider_a: int
    collider_b: int
    body_a: int | None
    body_b: int | None
    point: Vec2
    normal: Vec2
    approach_speed: float
    child_a: int = 0
    child_b: int = 0


@dataclass(slots=True, frozen=True)
class JointBroken:
    joint: int
    body_a: int
    body_b: int
    reaction_force: Vec2
    reaction_torque: float


@dataclass(slots=True, frozen=True)
class JointDestroyed:
    joint: int
    body_a: int
    body_b: int


ContactEvent = ContactBegin | ContactEnd | SensorBegin | SensorEnd | Hit


def builder(cls: type[T]) -> Callable[..., T]:
    """A function making ``cls`` (a frozen slots dataclass of this module) from all its
    fields in order, without the generated ``__init__``: half its cost, for the
    contact callbacks, which make one event per new and per ended contact.

    >>> make = builder(ContactEnd)
    >>> make(1, 2, None, 3, 0, 0) == ContactEnd(1, 2, None, 3)
    True
    """
    # unrolled, as dataclasses writes its own __init__: a loop over the fields costs
    # what it saves
    names = cls.__slots__  # type: ignore[attr-defined]
    ns: dict[str, Any] = {"new": object.__new__, "cls": cls}
    ns.update((f"s{k}", getattr(cls, name).__set__) for k, name in enumerate(names))
    args = ", ".join(f"v{k}" for k in range(len(names)))
    sets = "; ".join(f"s{k}(o, v{k})" for k in range(len(names)))
    exec(f"def make({args}):\n    o = new(cls); {sets}; return o", ns)
    make: Callable[..., T] = ns["make"]
    return make


@dataclass(slots=True)
class PhysicsEvents:
    """Events of the last fixed step (cleared when the next physics step starts)."""

    contact_begin: list[ContactBegin] = field(default_factory=list)
    contact_end: list[ContactEnd] = field(default_factory=list)
    sensor_begin: list[SensorBegin] = field(default_factory=list)
    sensor_end: list[SensorEnd] = field(default_factory=list)
    hits: list[Hit] = field(default_factory=list)
    joint_broken: list[JointBroken] = field(default_factory=list)
    joint_destroyed: list[JointDestroyed] = field(default_factory=list)

    #: (list name, Behaviour hook or None) in delivery order
    CHANNELS: ClassVar[tuple[tuple[str, str | None], ...]] = (
        ("contact_begin", "on_contact_begin"),
        ("contact_end", "on_contact_end"),
        ("sensor_begin", "on_sensor_begin"),
        ("sensor_end", "on_sensor_end"),
        ("hits", "on_hit"),
        ("joint_broken", None),
        ("joint_destroyed", None),
    )

    def _lists(self) -> tuple[list[Any], ...]:
        # spelled out: this runs twice per fixed step, also in a world at rest
        return (self.contact_begin, self.contact_end, self.sensor_begin, self.sensor_end,
                self.hits, self.joint_broken, self.joint_destroyed)

    def sort(self) -> None:
        """Put every list in its defined order (entity ids, then child indices).

        Sorting is stable, so two events of one pair in one list (an end carried
        from a sync, then a begin and end in the step) keep their order.
        """
        for lst in (self.contact_begin, self.contact_end, self.sensor_begin, self.sensor_end,
                    self.hits):
            if len(lst) > 1:
                lst.sort(key=_contact_key)
        for jl in (self.joint_broken, self.joint_destroyed):
            if len(jl) > 1:
                jl.sort(key=_joint_key)

    def clear(self) -> None:
        for lst in self._lists():
            lst.clear()

    def __len__(self) -> int:
        return sum(map(len, self._lists()))


def _contact_key(ev: ContactEvent) -> tuple[int, int, int, int]:
    return (ev.collider_a, ev.collider_b, ev.child_a, ev.child_b)


def _joint_key(ev: JointBroken | JointDestroyed) -> int:
    return ev.joint
