"""One event model (kge/events.py): ``world.emit`` / ``world.events``; every reader sees
every event once per fixed step (fixed-step code) or per frame (frame code), whatever the
number of steps in a frame; nobody consumes; the old per-subsystem resources still work,
deprecated."""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import pytest

from kge import (
    AnimationEvents,
    App,
    Box,
    Circle,
    Collider,
    ContactBegin,
    ParticleBurst,
    ParticleEmitter,
    Particles,
    PhysicsEvents,
    RigidBody,
    Stage,
    System,
    SystemSet,
    Transform,
    UIEvents,
    World,
)


@dataclass(frozen=True)
class Tick:
    n: int


class Emitter(System):
    """Emits Tick(1), Tick(2)... one per run, in its stage and set."""

    def __init__(self, stage: Stage, in_set: SystemSet) -> None:
        self.stage = stage  # type: ignore[misc]
        self.in_set = in_set
        self.count = 0

    def process(self, dt: float) -> None:
        self.count += 1
        self.world.emit(Tick(self.count))


class Reader(System):
    """Records every Tick it can read, each run."""

    def __init__(self, stage: Stage, in_set: SystemSet) -> None:
        self.stage = stage  # type: ignore[misc]
        self.in_set = in_set
        self.seen: list[int] = []

    def process(self, dt: float) -> None:
        self.seen += [t.n for t in self.world.events(Tick)]


def _app(emitter_stage: Stage, emitter_set: SystemSet) -> tuple[App, Emitter, list[Reader]]:
    app = App(lambda world: None, headless=True)
    emitter = app.world.add_system(Emitter(emitter_stage, emitter_set))
    readers = [
        app.world.add_system(Reader(stage, in_set))
        for stage, in_set in (
            (Stage.INPUT, SystemSet.FIRST),
            (Stage.FIXED, SystemSet.FIRST),
            (Stage.FIXED, SystemSet.GAME),
            (Stage.UPDATE, SystemSet.FIRST),
            (Stage.UPDATE, SystemSet.GAME),
            (Stage.LATE, SystemSet.GAME),
        )
    ]
    return app, emitter, readers


def _frames(app: App, steps: list[int]) -> None:
    """Frames with the given numbers of fixed steps (0 to 3), through the accumulator."""
    dt = app.fixed_dt
    for n in steps:
        app.timestep.accumulator = 0.25 * dt
        app.advance(n * dt)


@pytest.mark.parametrize(
    ("stage", "in_set"),
    [(Stage.FIXED, SystemSet.SCRIPTS), (Stage.UPDATE, SystemSet.SCRIPTS),
     (Stage.INPUT, SystemSet.UI), (Stage.LATE, SystemSet.CAMERA)],
)
def test_every_reader_sees_every_event_once_whatever_the_steps_per_frame(
    stage: Stage, in_set: SystemSet
) -> None:
    app, emitter, readers = _app(stage, in_set)
    _frames(app, [1, 0, 3, 2, 0, 0, 1, 3, 1])
    emitted = list(range(1, emitter.count + 1))
    assert emitter.count >= 9
    for reader in readers:
        # in order, never twice; a reader running before the emitter may still owe the
        # last few (it sees them at its next run)
        assert reader.seen == emitted[: len(reader.seen)], (reader.stage, reader.in_set)
        assert len(reader.seen) >= len(emitted) - 3, (reader.stage, reader.in_set)
    _frames(app, [1, 1])  # two more frames: now everyone has caught up with the first ones
    for reader in readers:
        assert reader.seen[: len(emitted)] == emitted


def test_a_second_reader_of_particle_bursts_still_sees_them() -> None:
    """ParticleSystem used to clear the shared list (take_events), so a game system
    reading ParticleBurst after it saw nothing."""
    seen: list[ParticleBurst] = []

    class BurstCounter(System):
        stage = Stage.UPDATE
        after = (SystemSet.EFFECTS,)

        def process(self, dt: float) -> None:
            seen.extend(self.world.events(ParticleBurst))

    app = App(lambda world: None, headless=True)
    world = app.world
    emitter = world.spawn(Transform(), ParticleEmitter(rate=0.0, seed=1))
    world.add_system(BurstCounter())
    world.emit(ParticleBurst(emitter, 12))
    app.step(1)
    assert [b.count for b in seen] == [12]
    assert world.resource(Particles).count(emitter) == 12
    app.step(3)
    assert len(seen) == 1  # once, not again on later frames


def test_reading_returns_a_copy_nobody_can_consume() -> None:
    world = World()
    world.emit(Tick(1))
    first = world.events(Tick)
    first.clear()
    assert world.events(Tick) == [Tick(1)]
    world.clear_events()
    assert world.events(Tick) == []


def test_code_between_frames_reads_the_last_frame() -> None:
    app = App(lambda world: None, headless=True)
    emitter = app.world.add_system(Emitter(Stage.FIXED, SystemSet.SCRIPTS))
    app.step(1)
    assert app.world.events(Tick) == [Tick(1)]
    app.step(1)
    assert app.world.events(Tick) == [Tick(2)]
    app.world.emit(Tick(99))  # between frames: seen now, and by the next frame's readers
    assert app.world.events(Tick) == [Tick(2), Tick(99)]
    assert emitter.count == 2


def test_old_events_are_dropped() -> None:
    app = App(lambda world: None, headless=True)
    app.world.add_system(Emitter(Stage.FIXED, SystemSet.SCRIPTS))
    app.world.add_system(Emitter(Stage.UPDATE, SystemSet.SCRIPTS))
    _frames(app, [1, 3, 0, 2] * 50)
    assert len(app.world.eventlog) <= 8  # about two frames' worth, not 400


def _drop(world: World) -> None:
    world.spawn(Transform(0, -1), Collider(Box(5, 1)))
    world.spawn(Transform(0, 1), RigidBody(), Collider(Circle(0.5)))


def test_contacts_reach_world_events_and_the_deprecated_resource() -> None:
    app = App(_drop, headless=True)
    begins: list[ContactBegin] = []
    for _ in range(120):
        app.step(1)
        now = app.world.events(ContactBegin)
        with pytest.warns(DeprecationWarning, match="the PhysicsEvents resource: read world.events"):
            old = app.world.resource(PhysicsEvents).contact_begin
        assert now == old
        begins += now
    assert len(begins) == 1 and begins[0].body_b == 2


def test_the_deprecated_resources_and_handler_names_warn_but_work() -> None:
    app = App(_drop, headless=True)
    handled: list[ContactBegin] = []
    with pytest.warns(DeprecationWarning, match=r"set_handler\('contact_begin'"):
        app.world.set_handler("contact_begin", handled.append)
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)
        app.world.set_handler("my_own_event", print)  # only the physics names are deprecated
    app.step(60)
    assert len(handled) == 1
    for resource in (AnimationEvents, UIEvents):
        with pytest.warns(DeprecationWarning, match=f"{resource.__name__} resource"):
            app.world.resource(resource)


@dataclass(frozen=True)
class Tock:
    n: int


def test_several_types_are_read_together_in_emission_order() -> None:
    world = World()
    for event in (Tick(1), Tock(2), Tick(3), Tock(4), Tock(5)):
        world.emit(event)
    assert world.events(Tick, Tock) == [Tick(1), Tock(2), Tick(3), Tock(4), Tock(5)]
    assert world.events(Tock, Tick, Tock) == world.events(Tick, Tock)
    assert world.events(Tock) == [Tock(2), Tock(4), Tock(5)]
