"""kge.box2d's pybox2d surface: math types, identity, listeners, queries, joints, bad input."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path
from types import ModuleType

import pytest

import kge.box2d as b2
from kge.errors import ComponentTypeError, KgeError, ValidationError, WorldLockedError


def _world_with_box() -> tuple[b2.b2World, b2.b2Body, b2.b2Body]:
    world = b2.b2World(gravity=(0, -10))
    ground = world.CreateStaticBody(shapes=b2.b2EdgeShape(vertices=[(-10, 0), (10, 0)]))
    box = world.CreateDynamicBody(position=(0, 2),
                                  fixtures=b2.b2FixtureDef(shape=b2.b2PolygonShape(box=(0.5, 0.5)),
                                                           density=1.0))
    return world, ground, box


def test_vec2_arithmetic_and_methods() -> None:
    v = b2.b2Vec2(3, 4)
    assert v + (1, 1) == (4, 5) and (1, 1) + v == (4, 5)  # noqa: RUF005
    assert v - b2.b2Vec2(1, 1) == (2, 3) and (5, 5) - v == (2, 1)
    assert v * 2 == (6, 8) and 2 * v == (6, 8) and v / 2 == (1.5, 2) and -v == (-3, -4)
    assert v.dot((1, 0)) == 3 and v.cross((0, 1)) == 3 and v.cross(1.0) == (4, -3)
    assert v.length == 5 and v.lengthSquared == 25 and list(v) == [3, 4] and v[1] == 4
    w = v.copy()
    w += (1, 1)
    w *= 2
    assert w == (8, 10) and v == (3, 4)
    assert w.Normalize() == pytest.approx(12.806248) and w.length == pytest.approx(1.0)
    with pytest.raises(ComponentTypeError):
        b2.b2Vec2("ab")


def test_transform_mat22_aabb() -> None:
    t = b2.b2Transform()
    t.Set((1, 2), b2.b2_pi / 2)
    p = t * (1, 0)
    assert p.x == pytest.approx(1) and p.y == pytest.approx(3)
    m = b2.b2Mat22((2, 0), (0, 4))
    assert m * (1, 1) == (2, 4) and m.inverse * (2, 4) == (1, 1)
    assert m.Solve((2, 4)) == (1, 1)
    box = b2.b2AABB(lowerBound=(0, 0), upperBound=(2, 2))
    assert box.valid and (1, 1) in box and box.center == (1, 1) and box.perimeter == 8


def test_polygon_hull_like_box2d_and_bad_counts() -> None:
    shape = b2.b2PolygonShape(vertices=[(0, 0), (1, 1), (0, 1), (1, 0), (0.5, 0.5)])
    assert shape.vertices == [(1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.0, 0.0)]
    with pytest.raises(ValidationError, match="3..16"):
        b2.b2PolygonShape(vertices=[(0, 0), (1, 0)])
    with pytest.raises(ValidationError, match="3..16"):
        b2.b2PolygonShape(vertices=[(i, i * i) for i in range(17)])
    with pytest.raises(ValidationError, match="collinear"):
        b2.b2PolygonShape(vertices=[(0, 0), (1, 0), (2, 0)])
    with pytest.raises(ValidationError):
        b2.b2EdgeShape(vertices=[(0, 0)])
    with pytest.raises(ValidationError):
        b2.b2CircleShape(radius=-1).to_kge()


def test_bad_fixture_leaves_no_body() -> None:
    world = b2.b2World()
    with pytest.raises(KgeError):
        world.CreateDynamicBody(fixtures=b2.b2FixtureDef(shape=b2.b2CircleShape(radius=-1)))
    assert world.bodies == [] and world.bodyCount == 0


def test_identity_user_attributes_and_type_constants() -> None:
    world, ground, box = _world_with_box()
    box.ground_contact = True  # programs store their own attributes
    fixture = box.fixtures[0]
    assert fixture.body is box and box in world.bodies and {box, ground} == set(world.bodies)
    assert box.type == b2.b2_dynamicBody and ground.type == b2.b2_staticBody
    assert isinstance(fixture.shape, b2.b2PolygonShape)
    assert fixture.shape.vertices == [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)]
    assert box.mass == pytest.approx(1.0)
    assert box.GetWorldPoint((0.5, 0)) == pytest.approx((0.5, 2)) and box.worldCenter == (0, 2)


def test_contact_listener_keeps_objects_and_sees_manifold() -> None:
    seen: list[tuple[str, object]] = []

    class Listener(b2.b2ContactListener):
        def BeginContact(self, contact: b2.b2Contact) -> None:
            seen.append(("begin", contact))
            self.normal = contact.worldManifold.normal

        def PreSolve(self, contact: b2.b2Contact, old: b2.b2Manifold) -> None:
            seen.append(("pre", contact))

        def PostSolve(self, contact: b2.b2Contact, impulse: b2.b2ContactImpulse) -> None:
            seen.append(("post", impulse.normalImpulses[0]))

    listener = Listener()
    world, ground, box = _world_with_box()
    world.contactListener = listener
    for _ in range(90):
        world.Step(1 / 60, 8, 3)
    begins = [c for kind, c in seen if kind == "begin"]
    assert len(begins) == 1
    contact = world.contacts[0]
    assert contact is begins[0] and contact.touching
    assert {contact.fixtureA.body, contact.fixtureB.body} == {box, ground}
    assert any(kind == "pre" and c is contact for kind, c in seen)
    assert listener.normal.y == pytest.approx(1.0, abs=1e-6) or listener.normal.y == pytest.approx(-1.0, abs=1e-6)
    assert contact.manifold.pointCount == 2
    assert any(kind == "post" and isinstance(v, float) and v > 0 for kind, v in seen)
    assert box.contacts[0].contact is contact and box.contacts[0].other is ground


def test_presolve_can_disable_contact() -> None:
    class Ghost(b2.b2ContactListener):
        def PreSolve(self, contact: b2.b2Contact, old: b2.b2Manifold) -> None:
            contact.enabled = False

    world, _, box = _world_with_box()
    world.contactListener = Ghost()
    for _ in range(90):
        world.Step(1 / 60, 8, 3)
    assert box.position.y < -1.0  # fell through the ground


def test_world_is_locked_inside_callbacks() -> None:
    errors: list[Exception] = []

    class Meddler(b2.b2ContactListener):
        def BeginContact(self, contact: b2.b2Contact) -> None:
            try:
                contact.fixtureA.body.world.CreateDynamicBody(position=(5, 5))
            except WorldLockedError as exc:
                errors.append(exc)
            try:
                contact.fixtureA.body.world.DestroyBody(contact.fixtureB.body)
            except WorldLockedError as exc:
                errors.append(exc)

    world, _, _ = _world_with_box()
    world.contactListener = Meddler()
    for _ in range(90):
        world.Step(1 / 60, 8, 3)
    assert len(errors) == 2 and world.bodyCount == 2 and not world.locked


def test_destroy_twice_self_joint_and_bad_step() -> None:
    world, ground, box = _world_with_box()
    with pytest.raises(ValidationError, match="same body"):
        world.CreateRevoluteJoint(bodyA=box, bodyB=box, anchor=(0, 2))
    assert world.jointCount == 0
    world.DestroyBody(box)
    with pytest.raises(ValidationError, match="already destroyed"):
        world.DestroyBody(box)
    with pytest.raises(ValidationError):
        box.ApplyForceToCenter((1, 0), True)
    with pytest.raises(ValidationError):
        world.Step(-1.0, 8, 3)
    with pytest.raises(ValidationError):
        world.Step(1 / 60, -8, 3)
    with pytest.raises(ValidationError):
        box.world.CreateDynamicBody(position=(float("nan"), 0))
    assert world.bodies == [ground]


def test_destruction_listener_and_joint_properties() -> None:
    gone: list[object] = []

    class Goodbye(b2.b2DestructionListener):
        def SayGoodbye(self, obj: object) -> None:
            gone.append(obj)

    world = b2.b2World(gravity=(0, -10))
    world.destructionListener = Goodbye()
    ground = world.CreateStaticBody(position=(0, 10))
    arm = world.CreateDynamicBody(position=(1, 10))
    fixture = arm.CreateCircleFixture(radius=0.2, density=1)
    joint = world.CreateRevoluteJoint(bodyA=ground, bodyB=arm, anchor=(0, 10),
                                      enableMotor=True, maxMotorTorque=1000, motorSpeed=1.0)
    assert isinstance(joint, b2.b2RevoluteJoint) and joint.motorEnabled
    for _ in range(60):
        world.Step(1 / 60, 8, 3)
    assert joint.speed == pytest.approx(1.0, abs=0.05) and joint.angle > 0.5
    joint.motorSpeed = -1.0
    joint.SetLimits(-0.2, 0.2)
    assert joint.limits == (-0.2, 0.2) and joint.motorSpeed == -1.0
    assert arm.joints[0].joint is joint and arm.joints[0].other is ground
    world.DestroyBody(arm)
    assert gone == [joint, fixture] and world.joints == []


def test_raycast_and_query_callbacks() -> None:
    world, _ground, box = _world_with_box()

    class Query(b2.b2QueryCallback):
        def __init__(self) -> None:
            super().__init__()
            self.found: list[b2.b2Fixture] = []

        def ReportFixture(self, fixture: b2.b2Fixture) -> bool:
            self.found.append(fixture)
            return True

    q = Query()
    world.QueryAABB(q, b2.b2AABB(lowerBound=(-1, 1), upperBound=(1, 3)))
    assert q.found == box.fixtures

    class Ray(b2.b2RayCastCallback):
        def ReportFixture(self, fixture: b2.b2Fixture, point: b2.b2Vec2, normal: b2.b2Vec2,
                          fraction: float) -> float:
            self.hit = (fixture, point, normal)
            return fraction

    ray = Ray()
    world.RayCast(ray, (0, 5), (0, -5))
    assert ray.hit[0] is box.fixtures[0] and ray.hit[1].y == pytest.approx(2.5)
    assert box.fixtures[0].TestPoint((0, 2)) and not box.fixtures[0].TestPoint((3, 2))


def test_short_names_and_install(installed: ModuleType) -> None:
    import Box2D
    from Box2D import b2 as short
    from Box2D.b2 import circleShape, staticBody, world

    assert Box2D is b2 and world is b2.b2World and circleShape is b2.b2CircleShape
    assert staticBody == b2.b2_staticBody and short.revoluteJointDef is b2.b2RevoluteJointDef


def test_runner_runs_a_pybox2d_script(tmp_path: Path) -> None:
    script = tmp_path / "drop.py"
    script.write_text(
        "import sys\nfrom Box2D import b2World, b2PolygonShape\n"
        "w = b2World(gravity=(0, -10))\n"
        "w.CreateStaticBody(shapes=b2PolygonShape(box=(5, 1)))\n"
        "b = w.CreateDynamicBody(position=(0, 3))\nb.CreatePolygonFixture(box=(0.5, 0.5), density=1)\n"
        "[w.Step(1/60, 8, 3) for _ in range(120)]\nprint(round(b.position.y, 1), sys.argv[1])\n"
    )
    out = subprocess.run([sys.executable, "-m", "kge.box2d", str(script), "hello"],
                         capture_output=True, text=True, check=True).stdout
    assert out.split() == ["1.5", "hello"]


def test_presolve_tangent_speed_moves_a_box_like_a_conveyor() -> None:
    class Belt(b2.b2ContactListener):
        def PreSolve(self, contact: b2.b2Contact, old: b2.b2Manifold) -> None:
            contact.tangentSpeed = 3.0

    world, _, box = _world_with_box()
    world.contactListener = Belt()
    for _ in range(120):
        world.Step(1 / 60, 8, 3)
    assert abs(box.linearVelocity.x) > 1.0 and abs(box.position.x) > 1.0


def test_contact_filter_decides_and_is_called_with_fixtures() -> None:
    calls: list[tuple[b2.b2Fixture, b2.b2Fixture]] = []

    class NoGround(b2.b2ContactFilter):
        def ShouldCollide(self, fixtureA: b2.b2Fixture, fixtureB: b2.b2Fixture) -> bool:
            calls.append((fixtureA, fixtureB))
            return False

    world, ground, box = _world_with_box()
    world.contactFilter = NoGround()
    for _ in range(90):
        world.Step(1 / 60, 8, 3)
    assert box.position.y < -1.0 and world.contacts == []
    assert calls and {calls[0][0].body, calls[0][1].body} == {box, ground}


def test_sensor_switched_at_runtime_reports_but_does_not_push() -> None:
    begins: list[b2.b2Contact] = []

    class Listener(b2.b2ContactListener):
        def BeginContact(self, contact: b2.b2Contact) -> None:
            begins.append(contact)

    world, ground, box = _world_with_box()
    world.contactListener = Listener()
    ground.fixtures[0].sensor = True  # CarRacing's tiles do this after creation
    for _ in range(90):
        world.Step(1 / 60, 8, 3)
    assert begins and box.position.y < -1.0


def test_editing_a_fixtures_shape_changes_the_collider() -> None:
    world = b2.b2World(gravity=(0, -10))
    world.CreateStaticBody(shapes=b2.b2EdgeShape(vertices=[(-10, 0), (10, 0)]))
    ball = world.CreateDynamicBody(position=(0, 3))
    fixture = ball.CreateCircleFixture(radius=0.5, density=1)
    shape = fixture.shape
    assert isinstance(shape, b2.b2CircleShape)
    mass = ball.mass
    shape.radius = 1.0  # pybox2d programs edit the live shape
    assert ball.mass == pytest.approx(4 * mass)
    for _ in range(120):
        world.Step(1 / 60, 8, 3)
    assert ball.position.y == pytest.approx(1.0, abs=0.03)  # rests on the bigger radius
    with pytest.raises(ValidationError):
        shape.radius = -1.0
    assert shape.radius == 1.0 and ball.mass == pytest.approx(4 * mass)
    free = b2.b2CircleShape(radius=0.2)
    f2 = ball.CreateFixture(b2.b2FixtureDef(shape=free, density=1))
    free.radius = 5.0  # the definition's shape is not the fixture's
    assert f2.shape.radius == pytest.approx(0.2)
