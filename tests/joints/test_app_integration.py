"""Joints end to end: components on entities, stepped by kge.App's physics system."""

from __future__ import annotations

import math

import pytest

import kge
from kge.components.collider import Collider
from kge.components.joints import (
    DistanceJoint,
    GearJoint,
    PrismaticJoint,
    RevoluteJoint,
    WheelJoint,
)
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Circle
from kge.components.transform import Transform
from kge.errors import ValidationError
from kge.physics.events import PhysicsEvents
from tests.joints.conftest import period_of


def make_app(setup: object) -> kge.App:
    return kge.App(setup, headless=True)  # type: ignore[arg-type]


def ground(world: kge.World) -> int:
    return world.spawn(Transform(0.0, -10.0), Collider(Box(50.0, 10.0)))


def test_pendulum_through_the_app() -> None:
    ids: dict[str, int] = {}

    def scene(world: kge.World) -> None:
        th = math.radians(10.0)
        bob = world.spawn(Transform(2 * math.sin(th), 10 - 2 * math.cos(th)), RigidBody(),
                          Collider(Circle(0.1), density=10.0))
        ids["bob"] = bob
        ids["joint"] = world.spawn(RevoluteJoint(None, bob, anchor=(0.0, 10.0)))

    app = make_app(scene)
    swing = []
    for _ in range(600):
        app.step()
        t = app.world.get(ids["bob"], Transform)
        swing.append(math.degrees(math.atan2(t.x, 10 - t.y)))
    assert period_of(swing, app.fixed_dt) == pytest.approx(2.8169, rel=0.01)  # Box2D 2.8169
    j = app.world.get(ids["joint"], RevoluteJoint)
    # the joint angle counts from the pose at build time (the bob started at 10°)
    assert j.reference_angle == 0.0
    assert j.angle == pytest.approx(math.radians(swing[-1] - 10.0), abs=1e-3)


def test_joint_to_a_static_collider_and_reaction_force() -> None:
    ids: dict[str, int] = {}

    def scene(world: kge.World) -> None:
        ceiling = world.spawn(Transform(0.0, 6.0), Collider(Box(2.0, 0.25)))
        box = world.spawn(Transform(0.0, 5.0), RigidBody(), Collider(Box(0.5, 0.5), density=2.0))
        ids["joint"] = world.spawn(RevoluteJoint(ceiling, box, anchor=(0.0, 5.5)))

    app = make_app(scene)
    app.step(60)
    j = app.world.get(ids["joint"], RevoluteJoint)
    assert j.reaction_force[1] == pytest.approx(20.0, rel=0.01)  # Box2D (0, 20.000)


def test_changing_a_motor_field_takes_effect_next_step() -> None:
    ids: dict[str, int] = {}

    def scene(world: kge.World) -> None:
        disc = world.spawn(Transform(0.0, 5.0), RigidBody(), Collider(Circle(1.0)))
        ids["joint"] = world.spawn(RevoluteJoint(None, disc, anchor=(0.0, 5.0),
                                                 enable_motor=True, motor_speed=2.0,
                                                 max_motor_torque=100.0))

    app = make_app(scene)
    app.step(10)
    j = app.world.get(ids["joint"], RevoluteJoint)
    assert j.speed == pytest.approx(2.0, abs=1e-3)
    j.motor_speed = -3.0
    app.step(8)  # 5 rad/s x I (π/2) at 100 N·m takes 4.7 steps
    assert j.speed == pytest.approx(-3.0, abs=1e-3)


def test_breaking_by_force_emits_an_event_and_removes_the_joint() -> None:
    ids: dict[str, int] = {}

    def scene(world: kge.World) -> None:
        box = world.spawn(Transform(0.0, 5.0), RigidBody(), Collider(Box(0.5, 0.5), density=2.0))
        ids["box"] = box
        ids["weak"] = world.spawn(RevoluteJoint(None, box, anchor=(0.0, 5.5), break_force=15.0))

    app = make_app(scene)
    broken = []
    for _ in range(10):
        app.step()
        broken += app.world.resource(PhysicsEvents).joint_broken
    assert [ev.joint for ev in broken] == [ids["weak"]]
    assert broken[0].body_b == ids["box"]
    assert math.hypot(*broken[0].reaction_force) > 15.0
    assert not app.world.exists(ids["weak"])
    y = app.world.get(ids["box"], Transform).y
    app.step(30)
    assert app.world.get(ids["box"], Transform).y < y - 1.0  # falls freely now


def test_despawning_a_body_destroys_its_joints_and_gears_first() -> None:
    ids: dict[str, int] = {}

    def scene(world: kge.World) -> None:
        d1 = world.spawn(Transform(0.0, 0.0), RigidBody(), Collider(Circle(1.0)))
        d2 = world.spawn(Transform(3.0, 0.0), RigidBody(), Collider(Circle(2.0)))
        ids["d1"] = d1
        ids["j1"] = world.spawn(RevoluteJoint(None, d1, enable_motor=True, motor_speed=2.0,
                                              max_motor_torque=1000.0))
        ids["j2"] = world.spawn(RevoluteJoint(None, d2))
        ids["gear"] = world.spawn(GearJoint(ids["j1"], ids["j2"], ratio=2.0))

    def zero_g(world: kge.World) -> None:
        from kge.physics.settings import PhysicsSettings

        world.insert_resource(PhysicsSettings(gravity=(0.0, 0.0)))
        scene(world)

    app = make_app(zero_g)
    app.step(30)
    assert app.world.get(ids["j2"], RevoluteJoint).speed == pytest.approx(-1.0, rel=0.01)
    gear = app.world.get(ids["gear"], GearJoint)
    assert (gear.body_a, gear.body_b) == (ids["d1"], ids["j2"] - 2)
    app.world.despawn(ids["d1"])
    destroyed = []
    for _ in range(2):
        app.step()
        destroyed += app.world.resource(PhysicsEvents).joint_destroyed
    assert {ev.joint for ev in destroyed} == {ids["j1"], ids["gear"]}
    assert not app.world.exists(ids["j1"]) and not app.world.exists(ids["gear"])
    assert app.world.exists(ids["j2"])


def test_car_on_wheel_joints_through_the_app() -> None:
    ids: dict[str, int] = {}

    def scene(world: kge.World) -> None:
        world.spawn(Transform(0.0, -10.0), Collider(Box(50.0, 10.0), friction=1.0))
        chassis = world.spawn(Transform(0.0, 1.0), RigidBody(), Collider(Box(1.5, 0.25)))
        ids["chassis"] = chassis
        for x in (-1.0, 1.0):
            wheel = world.spawn(Transform(x, 0.5), RigidBody(),
                                Collider(Circle(0.5), friction=0.9))
            world.spawn(WheelJoint(chassis, wheel, anchor=(x, 0.5), local_axis_a=(0.0, 1.0),
                                   frequency_hz=4.0, damping_ratio=0.7, enable_motor=True,
                                   motor_speed=-10.0, max_motor_torque=50.0))

    app = make_app(scene)
    app.step(120)
    vx = app.world.get(ids["chassis"], RigidBody).velocity[0]
    assert vx == pytest.approx(5.0, rel=0.10)  # Box2D 4.975 after 2 s (ω·r = 5)


def test_prismatic_between_static_and_kinematic_is_inert() -> None:
    ids: dict[str, int] = {}

    def scene(world: kge.World) -> None:
        a = world.spawn(Transform(0.0, 0.0), RigidBody(type=BodyType.STATIC))
        b = world.spawn(Transform(1.0, 0.0), RigidBody(type=BodyType.KINEMATIC, velocity=(1.0, 0.0)))
        ids["b"] = b
        ids["j"] = world.spawn(PrismaticJoint(a, b, local_axis_a=(0.0, 1.0), enable_motor=True,
                                              motor_speed=1.0, max_motor_force=10.0))

    app = make_app(scene)
    app.step(60)
    assert app.world.get(ids["b"], Transform).x == pytest.approx(2.0, abs=1e-6)
    assert app.world.get(ids["j"], PrismaticJoint).motor_force == 0.0


def test_bad_body_references_are_refused_at_spawn() -> None:
    def scene(world: kge.World) -> None:
        ball = world.spawn(Transform(0.0, 0.0), RigidBody(), Collider(Circle(0.5)))
        before = sorted(world.entities())
        with pytest.raises(ValidationError, match="does not exist"):
            world.spawn(DistanceJoint(ball, 9999))
        with pytest.raises(ValidationError, match="two different bodies"):
            world.spawn(DistanceJoint(ball, ball))
        assert sorted(world.entities()) == before

    make_app(scene)


def test_body_frozen_to_static_and_back_keeps_its_joint_sane() -> None:
    ids: dict[str, int] = {}

    def scene(world: kge.World) -> None:
        bob = world.spawn(Transform(2.0, 10.0), RigidBody(), Collider(Circle(0.1)))
        ids["bob"] = bob
        ids["joint"] = world.spawn(RevoluteJoint(None, bob, anchor=(0.0, 10.0)))

    app = make_app(scene)
    app.step(5)
    body = app.world.get(ids["bob"], RigidBody)
    body.type = BodyType.STATIC  # both ends static: the joint must do nothing
    app.step(5)
    body.type = BodyType.DYNAMIC
    app.step(30)
    t = app.world.get(ids["bob"], Transform)
    assert math.isfinite(t.x) and math.isfinite(t.y)
    assert math.hypot(t.x, t.y - 10.0) == pytest.approx(2.0, abs=0.01)  # still pinned


def test_mouse_joint_drags_through_the_app() -> None:
    from kge.components.joints import MouseJoint

    ids: dict[str, int] = {}

    def scene(world: kge.World) -> None:
        ground(world)
        box = world.spawn(Transform(0.0, 0.5), RigidBody(), Collider(Box(0.5, 0.5)))
        ids["box"] = box
        ids["mouse"] = world.spawn(MouseJoint(None, box, target=(0.0, 0.5), max_force=1000.0))

    app = make_app(scene)
    mouse = app.world.get(ids["mouse"], MouseJoint)
    for i in range(60):
        mouse.target = (0.05 * i, 2.0)
        app.step()
    app.step(30)
    t = app.world.get(ids["box"], Transform)
    assert math.hypot(t.x - 2.95, t.y - 2.0) < 0.05


def test_joint_built_between_non_dynamic_bodies_wakes_up_when_one_turns_dynamic() -> None:
    ids: dict[str, int] = {}

    def scene(world: kge.World) -> None:
        bob = world.spawn(Transform(2.0, 10.0), RigidBody(type=BodyType.KINEMATIC),
                          Collider(Circle(0.1)))
        ids["bob"] = bob
        ids["joint"] = world.spawn(RevoluteJoint(None, bob, anchor=(0.0, 10.0)))

    app = make_app(scene)
    app.step(5)
    app.world.get(ids["bob"], RigidBody).type = BodyType.DYNAMIC
    app.step(40)
    t = app.world.get(ids["bob"], Transform)
    assert t.y < 9.0  # swings down...
    assert math.hypot(t.x, t.y - 10.0) == pytest.approx(2.0, abs=0.01)  # ...on its pivot
    assert app.world.get(ids["joint"], RevoluteJoint).reaction_force[1] > 0


def test_despawning_a_geared_joint_destroys_the_gear_first() -> None:
    from kge.physics.settings import PhysicsSettings

    ids: dict[str, int] = {}

    def scene(world: kge.World) -> None:
        world.insert_resource(PhysicsSettings(gravity=(0.0, 0.0)))
        d1 = world.spawn(Transform(0.0, 0.0), RigidBody(), Collider(Circle(1.0)))
        d2 = world.spawn(Transform(3.0, 0.0), RigidBody(), Collider(Circle(2.0)))
        ids["d2"] = d2
        ids["j1"] = world.spawn(RevoluteJoint(None, d1, enable_motor=True, motor_speed=2.0,
                                              max_motor_torque=1000.0))
        ids["j2"] = world.spawn(RevoluteJoint(None, d2))
        ids["gear"] = world.spawn(GearJoint(ids["j1"], ids["j2"], ratio=2.0))

    app = make_app(scene)
    app.step(30)
    app.world.despawn(ids["j2"])
    destroyed = []
    for _ in range(2):
        app.step()
        destroyed += app.world.resource(PhysicsEvents).joint_destroyed
    assert [ev.joint for ev in destroyed] == [ids["gear"]]
    assert not app.world.exists(ids["gear"])
    w = app.world.get(ids["d2"], RigidBody).angular_velocity
    app.step(30)  # disc 2 now spins freely (no gear, no hinge)
    assert app.world.get(ids["d2"], RigidBody).angular_velocity == pytest.approx(w, abs=1e-6)


def test_changing_a_joint_wakes_its_sleeping_bodies() -> None:
    ids: dict[str, int] = {}

    def scene(world: kge.World) -> None:
        disc = world.spawn(Transform(0.0, 5.0), RigidBody(), Collider(Circle(1.0)))
        ids["disc"] = disc
        ids["joint"] = world.spawn(RevoluteJoint(None, disc, anchor=(0.0, 5.0),
                                                 enable_motor=True, max_motor_torque=100.0))

    app = make_app(scene)
    app.step(120)  # a motor holding speed 0: the disc falls asleep
    assert app.world.get(ids["disc"], RigidBody).awake is False
    j = app.world.get(ids["joint"], RevoluteJoint)
    j.motor_speed = -2.0  # must wake the disc, as Box2D's SetMotorSpeed does
    app.step(10)
    assert j.speed == pytest.approx(-2.0, abs=1e-3)
