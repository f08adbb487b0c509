"""Bad input is refused at the call that makes it, naming the field, and changes nothing."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kge import (
    BodyType,
    Box,
    Capsule,
    CharacterBody,
    Circle,
    Collider,
    ComponentTypeError,
    Edge,
    Physics,
    RigidBody,
    Transform,
    ValidationError,
    World,
)
from tests.character.conftest import ground

NAN = math.nan


@pytest.mark.parametrize(("fields", "message"), [
    ({"velocity": (NAN, 0.0)}, "CharacterBody.velocity[0] must be finite"),
    ({"velocity": (0.0, math.inf)}, "CharacterBody.velocity[1] must be finite"),
    ({"velocity": (1e6, 0.0)}, "CharacterBody.velocity must be at most 1000 m/s"),
    ({"max_floor_angle": -0.1}, "max_floor_angle must be in [0, pi/2]"),
    ({"max_floor_angle": math.radians(91)}, "max_floor_angle must be in [0, pi/2]"),
    ({"max_floor_angle": NAN}, "max_floor_angle must be finite"),
    ({"step_height": 1.8}, "step_height (1.8 m) must be less than the shape's height along up"),
    ({"step_height": -0.1}, "step_height must be >= 0"),
    ({"snap_length": 50.0}, "snap_length must be <= 10 m"),
    ({"up": (0.0, 0.0)}, "up must be a non-zero direction"),
    ({"mode": "sideways"}, "mode must be a CharacterMode"),
    ({"jump_speed": 1e9}, "jump_speed must be <= 1000 m/s"),
    ({"jump_cut": 1.5}, "jump_cut must be in [0.0, 1.0]"),
    ({"mass": 0.0}, "mass must be > 0"),
    ({"push_force": -1.0}, "push_force must be >= 0"),
    ({"max_slides": 0}, "max_slides must be in [1, 16]"),
    ({"coyote_time": NAN}, "coyote_time must be finite"),
    ({"gravity_scale": math.inf}, "gravity_scale must be finite"),
])
def test_settings_are_checked_when_made_and_when_written(fields, message) -> None:
    with pytest.raises((ValidationError, ComponentTypeError)) as made:
        CharacterBody(Capsule(0.3, 0.9), **fields)
    assert message in str(made.value)
    world = World()
    body = CharacterBody(Capsule(0.3, 0.9))
    e = world.spawn(Transform(), body)
    before = repr(body)
    for name, value in fields.items():
        with pytest.raises((ValidationError, ComponentTypeError)) as written:
            setattr(body, name, value)
        assert message in str(written.value)
    assert repr(body) == before and world.exists(e)


@pytest.mark.parametrize(("shape", "message"), [
    (Box(100.0, 1.0), "CharacterBody.shape.half_width must be in [0.005, 50.0] m"),
    (Circle(60.0), "CharacterBody.shape.radius must be in [0.005, 50.0] m"),
    (Edge((0, 0), (1, 0)), "must be a Capsule, Box or Circle"),
    ("capsule", "must be a Capsule, Box or Circle"),
])
def test_shapes_are_checked(shape, message) -> None:
    with pytest.raises((ValidationError, ComponentTypeError), match=message.replace(".", r"\.")
                       .replace("[", r"\[")):
        CharacterBody(shape)


@pytest.mark.parametrize(("args", "message"), [
    ((NAN, 1.0), "Capsule.radius must be finite"),
    ((0.3, 1e9), "Capsule.half_height must be in [0.005, 50.0] m"),
    ((0.5, 0.3), "Capsule.half_height must be >= radius"),
    ((-1.0, 1.0), "Capsule.radius must be in"),
])
def test_capsules_are_checked(args, message) -> None:
    with pytest.raises(ValidationError) as err:
        Capsule(*args)
    assert message in str(err.value)


def test_a_new_shape_must_still_fit_the_step() -> None:
    body = CharacterBody(Capsule(0.3, 0.9), step_height=1.0)
    with pytest.raises(ValidationError, match="step_height"):
        body.shape = Box(0.3, 0.3)
    assert body.shape == Capsule(0.3, 0.9)


def _count(world: World) -> int:
    return len(world.entities())


@pytest.mark.parametrize("order", ["body first", "character first"])
def test_a_character_on_a_dynamic_body_is_refused_at_spawn(app_of, order) -> None:
    app = app_of(ground)
    world = app.world
    parts = [RigidBody(), CharacterBody(Capsule(0.3, 0.9)), Transform(0.0, 2.0)]
    if order == "character first":
        parts.reverse()
    n = _count(world)
    with pytest.raises(ValidationError, match="kinematic|KINEMATIC"):
        world.spawn(*parts)
    assert _count(world) == n
    app.step(2)


def test_a_character_added_to_a_dynamic_body_is_refused(app_of) -> None:
    app = app_of(ground)
    world = app.world
    e = world.spawn(Transform(0.0, 2.0), RigidBody(), Collider(Box(0.4, 0.4)))
    with pytest.raises(ValidationError, match="kinematic body"):
        world.add(e, CharacterBody(Box(0.4, 0.4)))
    assert not world.has(e, CharacterBody)
    assert world.get(e, RigidBody).type is BodyType.DYNAMIC


def test_a_characters_body_cannot_become_dynamic(app_of) -> None:
    app = app_of(ground)
    world = app.world
    e = world.spawn(Transform(0.0, 2.0), CharacterBody(Capsule(0.3, 0.9)))
    rb = world.get(e, RigidBody)
    assert rb.type is BodyType.KINEMATIC  # given by the plugin, with a collider
    assert world.get(e, Collider).shape is not None
    with pytest.raises(ValidationError, match=f"entity {e}, RigidBody.type"):
        rb.type = BodyType.DYNAMIC
    assert rb.type is BodyType.KINEMATIC
    with pytest.raises(ValidationError, match="must stay KINEMATIC"):
        world.add(e, RigidBody(type=BodyType.STATIC))
    assert world.get(e, RigidBody) is rb
    app.step(60)
    assert world.get(e, CharacterBody).on_floor


def test_a_character_spawned_with_its_own_kinematic_body_and_collider_keeps_them(app_of) -> None:
    app = app_of(ground)
    world = app.world
    rb = RigidBody(type=BodyType.KINEMATIC)
    col = Collider(Circle(0.2), sensor=True)
    e = world.spawn(CharacterBody(Capsule(0.3, 0.9)), rb, col, Transform(0.0, 2.0))
    assert world.get(e, RigidBody) is rb and world.get(e, Collider) is col
    app.step(60)
    assert world.get(e, CharacterBody).on_floor


def test_set_velocities_checks_every_row_before_changing_any(app_of) -> None:
    def scene(world):
        for k in range(3):
            world.spawn(Transform(float(k), 0.0), RigidBody(type=BodyType.KINEMATIC),
                        Collider(Box(0.2, 0.2)))

    app = app_of(scene)
    physics = app.world.resource(Physics)
    physics.set_velocities([1, 2, 3], np.array([[1.0, 0.0], [0.0, 2.0], [3.0, 3.0]]))
    assert [app.world.get(e, RigidBody).velocity for e in (1, 2, 3)] == [
        (1.0, 0.0), (0.0, 2.0), (3.0, 3.0)]
    for bad, message in (([[0.0, 0.0], [NAN, 0.0], [0.0, 0.0]], r"velocities\[1\] of entity 2"),
                         ([[0.0, 0.0]], "must be 3 \\(x, y\\) pairs"),
                         ("fast", "must be \\(x, y\\) pairs")):
        with pytest.raises(ValidationError, match=message):
            physics.set_velocities([1, 2, 3], bad)
    with pytest.raises(Exception, match="entity 9 does not exist"):
        physics.set_velocities([1, 9], [[0.0, 0.0], [0.0, 0.0]])
    assert [app.world.get(e, RigidBody).velocity for e in (1, 2, 3)] == [
        (1.0, 0.0), (0.0, 2.0), (3.0, 3.0)]
    app.step(60)
    assert app.world.get(3, Transform).x == pytest.approx(2.0 + 3.0)
    physics.set_velocities([3], [[1000.0, 0.0]])  # capped at 2 m per step, as any body
    assert app.world.get(3, RigidBody).velocity == pytest.approx((120.0, 0.0))
