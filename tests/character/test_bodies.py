"""Characters among bodies: pushing dynamic bodies, being pushed, sensors, ray casts,
each other, and determinism."""

from __future__ import annotations

import math
import warnings

import pytest

from kge import (
    Behaviour,
    BodyType,
    Box,
    Capsule,
    CharacterBody,
    Circle,
    Collider,
    Physics,
    RigidBody,
    Script,
    SensorBegin,
    Transform,
)
from tests.character.conftest import ground


def _crate_scene(world, density=1.0, push_force=500.0):
    ground(world)
    world.spawn(Transform(2.0, 0.51), RigidBody(), Collider(Box(0.5, 0.5), density=density,
                                                            friction=0.6))
    world.spawn(Transform(0.0, 1.0), CharacterBody(Capsule(0.3, 0.9), push_force=push_force))


def _walk(app, body, vx, steps):
    for _ in range(steps):
        body.velocity = (vx, body.velocity[1])
        app.step()


def test_it_pushes_a_crate_at_its_own_speed(app_of) -> None:
    app = app_of(_crate_scene)
    world = app.world
    body, t, crate = world.get(3, CharacterBody), world.get(3, Transform), world.get(2, Transform)
    app.step(20)
    _walk(app, body, 2.0, 120)
    assert t.x == pytest.approx(4.0, abs=0.15)  # hardly slowed
    assert crate.x - t.x == pytest.approx(0.5 + 0.3 + 0.015, abs=0.05)  # in front, touching
    assert world.get(2, RigidBody).velocity[0] == pytest.approx(2.0, abs=0.2)


@pytest.mark.parametrize(("push_force", "density", "moves"),
                         [(0.0, 1.0, False), (500.0, 1.0, True), (50.0, 100.0, False),
                          (math.inf, 100.0, True)])
def test_push_force_limits_what_it_can_push(app_of, push_force, density, moves) -> None:
    """A 1 kg crate needs 6 N against friction; a 100 kg one 600 N."""
    app = app_of(_crate_scene, density=density, push_force=push_force)
    body, crate = app.world.get(3, CharacterBody), app.world.get(2, Transform)
    app.step(20)
    _walk(app, body, 2.0, 120)
    assert (crate.x > 3.0) is moves
    if not moves:
        assert body.on_wall and crate.x == pytest.approx(2.0, abs=0.02)


@pytest.mark.parametrize(("density", "mass", "pushed"),
                         [(1.0, 80.0, False), (500.0, 80.0, True), (500.0, math.inf, False)])
def test_a_heavy_body_rolling_into_it_pushes_it(app_of, density, mass, pushed) -> None:
    def scene(world):
        world.spawn(Transform(0.0, -0.5), Collider(Box(50.0, 0.5), friction=0.0))
        world.spawn(Transform(-3.0, 1.01), RigidBody(velocity=(6.0, 0.0)),
                    Collider(Box(1.0, 1.0), density=density, friction=0.0))
        world.spawn(Transform(0.0, 1.0), CharacterBody(Capsule(0.3, 0.9), mass=mass))

    app = app_of(scene)
    t = app.world.get(3, Transform)
    app.step(60)
    assert (t.x > 1.0) is pushed


def test_a_crate_dropped_on_it_rests_on_its_head(app_of) -> None:
    def scene(world):
        ground(world)
        world.spawn(Transform(0.0, 1.0), CharacterBody(Capsule(0.3, 0.9)))
        world.spawn(Transform(0.0, 4.0), RigidBody(), Collider(Box(0.4, 0.4)))

    app = app_of(scene)
    app.step(120)
    crate = app.world.get(3, Transform)
    head = app.world.get(2, Transform).y + 0.9
    assert crate.y == pytest.approx(head + 0.4, abs=0.03)


class _Counter(Script):
    def __init__(self) -> None:
        self.begins: list[int] = []
        self.ends: list[int] = []

    def on_sensor_begin(self, event) -> None:
        self.begins.append(event.collider_a)

    def on_sensor_end(self, event) -> None:
        self.ends.append(event.collider_a)


@pytest.mark.parametrize("kind", ["static", "kinematic", "dynamic"])
def test_it_enters_and_leaves_sensors_once_each(app_of, kind) -> None:
    def scene(world):
        ground(world)
        for k in range(3):
            parts = [Transform(2.0 + 2.0 * k, 1.0), Collider(Circle(0.3), sensor=True)]
            if kind != "static":
                body = BodyType.KINEMATIC if kind == "kinematic" else BodyType.DYNAMIC
                parts.append(RigidBody(type=body, gravity_scale=0.0))
            world.spawn(*parts)
        world.spawn(Transform(0.0, 1.0), CharacterBody(Capsule(0.3, 0.9)), Behaviour(_Counter()))

    app = app_of(scene)
    world = app.world
    body = world.get(5, CharacterBody)
    script = world.get(5, Behaviour).script
    seen = []
    for _ in range(150):
        body.velocity = (3.0, body.velocity[1])
        app.step()
        seen += [(e.collider_a, e.collider_b) for e in world.events(SensorBegin)]
    assert script.begins == [2, 3, 4] and script.ends == [2, 3, 4]
    assert seen == [(2, 5), (3, 5), (4, 5)]


def test_ray_casts_see_it(app_of) -> None:
    def scene(world):
        ground(world)
        world.spawn(Transform(0.0, 1.0), CharacterBody(Capsule(0.3, 0.9)))

    app = app_of(scene)
    app.step(10)
    hit = app.world.resource(Physics).raycast((-5.0, 1.0), (5.0, 1.0))
    assert hit is not None and hit.body == 2
    assert app.world.get(2, RigidBody).type is BodyType.KINEMATIC


def test_two_characters_walking_into_each_other_do_not_pass(app_of) -> None:
    def scene(world):
        ground(world)
        world.spawn(Transform(-2.0, 1.0), CharacterBody(Capsule(0.3, 0.9)))
        world.spawn(Transform(2.0, 1.0), CharacterBody(Capsule(0.3, 0.9)))

    app = app_of(scene)
    a, b = app.world.get(2, CharacterBody), app.world.get(3, CharacterBody)
    ta, tb = app.world.get(2, Transform), app.world.get(3, Transform)
    for _ in range(120):
        a.velocity = (3.0, a.velocity[1])
        b.velocity = (-3.0, b.velocity[1])
        app.step()
        assert tb.x - ta.x > 0.6 - 0.06  # never more than one step's move into each other
    assert tb.x - ta.x == pytest.approx(0.6, abs=0.06)


def _run(steps: int) -> list[tuple[float, float]]:
    from tests.character.conftest import make_app

    def scene(world):
        ground(world)
        world.spawn(Transform(3.0, 0.2, 0.3), Collider(Box(1.0, 0.2)))
        world.spawn(Transform(4.0, 2.0), RigidBody(), Collider(Box(0.3, 0.3)))
        for k in range(6):
            world.spawn(Transform(-2.0 + 0.9 * k, 1.0 + 0.5 * k),
                        CharacterBody(Capsule(0.3, 0.9), jump_speed=6.0, step_height=0.3))

    app = make_app(scene)
    bodies = [b for _, (b,) in app.world.query(CharacterBody)]
    out = []
    for i in range(steps):
        for k, b in enumerate(bodies):
            b.velocity = (3.0 * math.sin(0.05 * i + k), b.velocity[1])
            b.jump = (i + 7 * k) % 40 < 10
        app.step()
    out = [(t.x, t.y) for _, (t, _b) in app.world.query(Transform, CharacterBody)]
    app.close()
    return out


def test_the_same_inputs_give_the_same_poses_bit_for_bit() -> None:
    assert _run(240) == _run(240)


def test_a_world_without_characters_tracks_nothing(app_of) -> None:
    """The character system starts following colliders with the first character."""
    from kge.systems.character import CharacterSystem

    def scene(world):
        ground(world)
        world.spawn(Transform(0.0, 2.0), RigidBody(), Collider(Box(0.5, 0.5)))

    app = app_of(scene)
    app.step(10)
    system = app.world.get_system(CharacterSystem)
    assert system is not None and system._obstacles is None
    binding = app.world.get(2, RigidBody)._binding
    assert binding is not None and len(binding.sets) == 1  # physics' own, nothing more
    app.world.spawn(Transform(3.0, 2.0), CharacterBody(Capsule(0.3, 0.9)))
    app.step(60)
    assert system._obstacles is not None
    assert app.world.get(3, CharacterBody).on_floor


def test_moving_a_static_wall_is_seen(app_of) -> None:
    def scene(world):
        ground(world)
        world.spawn(Transform(3.0, 2.0), Collider(Box(0.5, 2.0)))
        world.spawn(Transform(0.0, 1.0), CharacterBody(Capsule(0.3, 0.9)))

    app = app_of(scene)
    body, t = app.world.get(3, CharacterBody), app.world.get(3, Transform)
    for _ in range(60):
        body.velocity = (3.0, body.velocity[1])
        app.step()
    assert t.x == pytest.approx(2.5 - 0.3 - 0.015, abs=1e-3)
    app.world.get(2, Transform).x = 6.0  # the wall teleported away
    for _ in range(60):
        body.velocity = (3.0, body.velocity[1])
        app.step()
    assert t.x == pytest.approx(5.5 - 0.3 - 0.015, abs=1e-3)


class _HoldJump(_Counter):
    """Holds jump from step 10 to step ``release`` (a variable jump), runs right."""

    def __init__(self, release: int) -> None:
        super().__init__()
        self.release = release
        self.steps = 0

    def on_fixed_update(self, dt: float) -> None:
        body = self.get(CharacterBody)
        self.steps += 1
        body.jump = 10 <= self.steps < self.release
        body.velocity = (2.0, body.velocity[1])


def _jumper(world) -> None:
    ground(world)
    world.spawn(Transform(3.0, 3.0), Collider(Box(0.5, 3.0), sensor=True))
    world.spawn(Transform(0.0, 1.0), CharacterBody(Capsule(0.3, 0.9), jump_speed=8.0),
                Behaviour(_HoldJump(30)))


def _restored_run(before: int, after: int) -> tuple[list[tuple[float, float]], list[int]]:
    from kge import App
    from tests.character.conftest import PLUGINS

    app = App(_jumper, headless=True, plugins=[p() for p in PLUGINS])
    poses = []
    for k in range(before + after):
        if k == before:
            app.restore(app.world.snapshot())
        with warnings.catch_warnings():  # (nothing of the old world is carried over)
            warnings.simplefilter("error")
            app.step()
        t = app.world.get(3, Transform)
        poses.append((t.x, t.y))
    script = app.world.get(3, Behaviour).script
    app.close()
    return poses, script.begins


@pytest.mark.parametrize("before", [20, 25, 90])
def test_a_restored_world_goes_on_as_the_same_run(before) -> None:
    """Snapshots carry the characters' jump and ground state and the sensors they are
    in: restored mid-jump with the button held (20, 25: the release still cuts the
    jump), or walking through a sensor (90: it is not entered again)."""
    plain = _restored_run(200, 0)
    assert _restored_run(before, 200 - before) == plain
    assert plain[1] == [2]
