"""Moving, rotating and one-way platforms: carried without jitter, passed through from below."""

from __future__ import annotations

import math
import statistics

import pytest

from kge import (
    Behaviour,
    BodyType,
    Box,
    Capsule,
    CharacterBody,
    Collider,
    OneWayPlatform,
    RigidBody,
    Transform,
)
from kge.character.contacts import SKIN
from kge.testbed.samples.character import Shuttle
from tests.character.conftest import gap_to, ground


def _in_frame(t: Transform, p: Transform) -> tuple[float, float]:
    c, s = math.cos(-p.angle), math.sin(-p.angle)
    dx, dy = t.x - p.x, t.y - p.y
    return (c * dx - s * dy, s * dx + c * dy)


@pytest.mark.parametrize("velocity", [(2.0, 0.0), (0.0, 1.5), (1.5, 1.0), (0.0, -3.0)])
def test_a_moving_platform_carries_it_without_jitter(app_of, velocity) -> None:
    def scene(world):
        ground(world, y=-20.0)
        world.spawn(Transform(0.0, 0.0), RigidBody(type=BodyType.KINEMATIC),
                    Collider(Box(3.0, 0.2)), Behaviour(Shuttle(velocity, 1.0)))
        world.spawn(Transform(0.5, 0.2 + 0.01 + 0.9 + SKIN), CharacterBody(Capsule(0.3, 0.9)))

    app = app_of(scene)
    world = app.world
    body, t, p = world.get(3, CharacterBody), world.get(3, Transform), world.get(2, Transform)
    app.step(60)  # (spawned resting on it, it falls behind a platform going down at first)
    rel = []
    for _ in range(240):  # two full round trips
        app.step()
        assert body.on_floor and body.floor_collider == 2
        rel.append(_in_frame(t, p))
    xs, ys = zip(*rel, strict=True)
    # the pose on the platform: 0 m^2 variance to rounding
    assert statistics.pvariance(xs) < 1e-24 and statistics.pvariance(ys) < 1e-24
    assert gap_to(world, 3, 2) == pytest.approx(SKIN, abs=1e-3)
    assert body.floor_velocity == pytest.approx(world.get(2, RigidBody).velocity)


def test_a_rotating_platform_carries_it_round_until_too_steep(app_of) -> None:
    def scene(world):
        ground(world, y=-20.0)
        world.spawn(Transform(0.0, 0.0), RigidBody(type=BodyType.KINEMATIC, angular_velocity=0.5),
                    Collider(Box(3.0, 0.2)))
        world.spawn(Transform(1.5, 1.5), CharacterBody(Capsule(0.3, 0.9)))

    app = app_of(scene)
    world = app.world
    body, t, p = world.get(3, CharacterBody), world.get(3, Transform), world.get(2, Transform)
    app.step(40)
    assert body.on_floor
    x0, y0, a0 = t.x, t.y, p.angle
    while body.on_floor:
        # it rides round with the platform: where the platform's rotation takes it (the
        # upright capsule's feet touch the tilting plank a little further along)
        c, s = math.cos(p.angle - a0), math.sin(p.angle - a0)
        assert math.hypot(t.x - (c * x0 - s * y0), t.y - (s * x0 + c * y0)) < 0.25
        app.step()
    assert math.hypot(t.x - x0, t.y - y0) > 0.6  # (left behind, it would not have moved)
    # it was carried until the platform tipped past max_floor_angle, then slid off
    assert p.angle == pytest.approx(math.radians(45.0), abs=0.03)


def test_a_dynamic_seesaw_tips_under_its_weight(app_of) -> None:
    def scene(world):
        ground(world)
        plank = world.spawn(Transform(0.0, 1.0), RigidBody(), Collider(Box(3.0, 0.1), density=2.0))
        from kge import RevoluteJoint

        world.spawn(RevoluteJoint(None, plank, anchor=(0.0, 1.0)))
        world.spawn(Transform(2.5, 3.0), CharacterBody(Capsule(0.3, 0.9), mass=60.0))

    app = app_of(scene)
    app.step(90)
    assert app.world.get(2, Transform).angle < -0.2


def test_jumps_up_through_a_one_way_platform_lands_on_it_and_drops_through(app_of) -> None:
    def scene(world):
        ground(world)
        world.spawn(Transform(0.0, 2.0), Collider(Box(2.0, 0.1)), OneWayPlatform())
        world.spawn(Transform(0.0, 1.0), CharacterBody(Capsule(0.3, 0.9), jump_speed=9.0))

    app = app_of(scene)
    world = app.world
    body, t = world.get(3, CharacterBody), world.get(3, Transform)
    app.step(20)
    assert body.floor_collider == 1
    body.jump = True
    highest = 0.0
    for _ in range(120):
        app.step()
        highest = max(highest, t.y)
    assert highest > 3.5  # it went up through the plank
    assert body.on_floor and body.floor_collider == 2
    assert t.y == pytest.approx(2.1 + 0.01 + 0.9 + SKIN, abs=1e-6)  # top, skin, half height
    body.jump = False
    body.drop_through = True  # one step is enough: it keeps falling until clear
    app.step()
    body.drop_through = False
    app.step(60)
    assert body.on_floor and body.floor_collider == 1


def test_walks_through_a_one_way_platform_from_the_side(app_of) -> None:
    def scene(world):
        ground(world)
        world.spawn(Transform(3.0, 1.0), Collider(Box(1.0, 0.1)), OneWayPlatform())
        world.spawn(Transform(0.0, 1.0), CharacterBody(Capsule(0.3, 0.9)))

    app = app_of(scene)
    body, t = app.world.get(3, CharacterBody), app.world.get(3, Transform)
    for _ in range(120):
        body.velocity = (3.0, body.velocity[1])
        app.step()
    assert t.x > 5.0 and body.on_floor and body.floor_collider == 1


def test_a_rising_one_way_lift_carries_it_up(app_of) -> None:
    def scene(world):
        ground(world)
        world.spawn(Transform(0.0, 0.5), RigidBody(type=BodyType.KINEMATIC, velocity=(0.0, 2.0)),
                    Collider(Box(2.0, 0.1)), OneWayPlatform())
        world.spawn(Transform(0.0, 2.0), CharacterBody(Capsule(0.3, 0.9)))

    app = app_of(scene)
    world = app.world
    body, t, lift = world.get(3, CharacterBody), world.get(3, Transform), world.get(2, Transform)
    app.step(120)
    assert body.on_floor and body.floor_collider == 2
    assert t.y - lift.y == pytest.approx(0.1 + 0.01 + 0.9 + SKIN, abs=1e-6)


def test_a_tweened_platform_carries_it_in_step(app_of) -> None:
    """A platform moved by a tween (its velocity set in the fixed step, before physics)
    carries the character the same step: the character moves after the fixed tweens."""
    from kge import AnimationPlugin, Tweens

    def scene(world):
        ground(world, y=-20.0)
        world.spawn(Transform(0.0, 0.0), RigidBody(type=BodyType.KINEMATIC),
                    Collider(Box(3.0, 0.2)))
        world.spawn(Transform(0.5, 0.2 + 0.9 + SKIN), CharacterBody(Capsule(0.3, 0.9)))

    app = app_of(scene)
    app.add_plugins(AnimationPlugin())
    world = app.world
    body, t, p = world.get(3, CharacterBody), world.get(3, Transform), world.get(2, Transform)
    app.step(10)
    start = _in_frame(t, p)
    world.resource(Tweens).to(2, Transform, "x", 4.0, 1.0, ease="sine_in_out")
    rel = []
    for _ in range(90):  # eased both ways: the platform's speed changes every step
        app.step()
        assert body.on_floor and body.floor_collider == 2
        rel.append(_in_frame(t, p))
    assert p.x == pytest.approx(4.0)
    for x, y in rel:
        assert x == pytest.approx(start[0], abs=1e-9) and y == pytest.approx(start[1], abs=1e-9)
