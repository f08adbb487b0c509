"""pybox2d behaviours kge.box2d keeps for unmodified programs (issue: pybox2d's own tests
and testbed): live vectors, list order, exception types, points, ghost vertices, math."""

from __future__ import annotations

import math

import numpy as np
import pytest

import kge.box2d as b2
from kge.box2d.errors import KeywordError
from kge.components.shapes import Edge
from kge.errors import KgeError, ValidationError, WorldLockedError


def _falling_box() -> tuple[b2.b2World, b2.b2Body]:
    world = b2.b2World(gravity=(0, -10))
    world.CreateStaticBody(shapes=b2.b2EdgeShape(vertices=[(-10, 0), (10, 0)]))
    body = world.CreateDynamicBody(position=(0, 4))
    body.CreatePolygonFixture(box=(0.5, 0.5), density=1)
    return world, body


def test_position_and_velocity_are_live_vectors_of_the_body() -> None:
    world, body = _falling_box()
    pos, vel, snap = body.position, body.linearVelocity, body.position.copy()
    for _ in range(10):
        world.Step(1 / 60, 8, 3)
    assert pos.y < 4.0 and pos == body.position and snap == (0, 4)  # reads the body now
    assert vel.y < -1.0 and vel == body.linearVelocity
    pos.x = 3.0  # writes through: the body moves
    assert body.position.x == 3.0
    vel.x = 2.0
    assert body.linearVelocity.x == 2.0
    assert type(pos + b2.b2Vec2(1, 0)) is b2.b2Vec2  # arithmetic gives plain vectors
    body.position += (1, 0)
    assert body.position.x == 4.0


def test_lists_are_oldest_first() -> None:
    world = b2.b2World()
    a, b, c = (world.CreateDynamicBody(userData=n) for n in "abc")
    a.CreateCircleFixture(radius=1, userData=1)
    a.CreateCircleFixture(radius=2, userData=2)
    j1 = world.CreateDistanceJoint(bodyA=a, bodyB=b)
    j2 = world.CreateDistanceJoint(bodyA=c, bodyB=a)
    assert [x.userData for x in world.bodies] == ["a", "b", "c"]
    assert [f.userData for f in a.fixtures] == [1, 2]
    assert world.joints == [j1, j2]
    assert [e.joint for e in a.joints] == [j1, j2] and [e.other for e in a.joints] == [b, c]


def test_errors_are_what_pybox2d_raises_and_kge_errors() -> None:
    world, body = _falling_box()
    cases: list[tuple[type[BaseException], object]] = [
        (AssertionError, lambda: b2.b2PolygonShape(vertices=[(0, 0), (1, 0), (2, 0)])),
        (AssertionError, lambda: b2.b2PolygonShape(vertices=[(0, 0), (1, 0)])),
        (AssertionError, lambda: world.CreateRevoluteJoint(bodyA=body, bodyB=body)),
        (AssertionError, lambda: body.CreateLoopFixture(vertices=[(0, 0), (1, 0)])),
        (ValueError, lambda: b2.b2PolygonShape(vertices=(2, 1))),
        (ValueError, lambda: b2.b2PolygonShape(vertices=[(0, 1, 5), (1, 1)])),
        (ValueError, lambda: body.CreateFixture()),
        (ValueError, lambda: world.CreateJoint(b2.b2RevoluteJointDef())),
        (ValueError, lambda: body.CreateEdgeChain([])),
        (ValueError, lambda: b2.b2EdgeShape(vertices=[(0, 0)])),
        (AttributeError, lambda: b2.b2BodyDef(foo=1)),
        (AttributeError, lambda: b2.b2FixtureDef(foo=1)),
    ]
    for kind, call in cases:
        with pytest.raises(kind) as caught:
            call()  # type: ignore[operator]
        assert isinstance(caught.value, KgeError), caught.value
    assert issubclass(KeywordError, AttributeError)

    class Spawner(b2.b2ContactListener):
        error: BaseException | None = None

        def BeginContact(self, contact: b2.b2Contact) -> None:
            try:
                world.CreateDynamicBody()
            except AssertionError as e:  # Box2D's IsLocked() assertion
                self.error = e

    world.contactListener = listener = Spawner()
    for _ in range(120):
        world.Step(1 / 60, 8, 3)
    assert isinstance(listener.error, WorldLockedError)
    assert world.bodyCount == 2


def test_joint_limits_and_pybox2d_names() -> None:
    world, body = _falling_box()
    other = world.CreateDynamicBody(position=(2, 4))
    other.CreateCircleFixture(radius=0.5, density=1)
    rev = world.CreateRevoluteJoint(bodyA=body, bodyB=other, anchor=(1, 4), enableLimit=True,
                                    lowerAngle=-0.5, upperAngle=0.5)
    rev.upperLimit = 2.0
    rev.lowerLimit = -1.0
    assert rev.limits == (-1.0, 2.0) and rev.GetReferenceAngle() == 0.0
    with pytest.raises(AssertionError):
        rev.lowerLimit = 3.0  # above the upper limit: Box2D asserts
    assert rev.limits == (-1.0, 2.0)
    dist = world.CreateJoint(type=b2.b2DistanceJoint, bodyA=body, bodyB=other,
                             anchorA=(0, 4), anchorB=(2, 4), frequencyHz=4.0)
    assert isinstance(dist, b2.b2DistanceJoint) and dist.frequency == 4.0
    assert dist.length == pytest.approx(2.0)
    again = world.CreateDistanceJoint(**b2.b2DistanceJointDef(
        bodyA=body, bodyB=other, anchorA=(0, 4), anchorB=(2, 4)).to_kwargs())
    assert again.length == pytest.approx(2.0) and again.anchorB == (2, 4)
    weld = b2.b2WeldJointDef()
    other.angle = 0.25
    weld.Initialize(body, other, (1, 4))  # the weld's own Initialize (was bound to revolute's)
    assert weld.referenceAngle == pytest.approx(0.25)
    assert world.CreateJoint(weld).GetReferenceAngle() == pytest.approx(0.25)


def test_world_manifold_points_are_two_as_pybox2d() -> None:
    world = b2.b2World(gravity=(0, -10))
    world.CreateStaticBody(shapes=b2.b2PolygonShape(box=(5, 1)))
    ball = world.CreateDynamicBody(position=(0, 1.6))
    ball.CreateCircleFixture(radius=0.5, density=1)
    for _ in range(30):
        world.Step(1 / 60, 8, 3)
    contact = world.contacts[0]
    wm = contact.worldManifold
    assert contact.manifold.pointCount == 1 and len(wm.points) == 2
    assert wm.points[1] == (0.0, 0.0) and wm.points[0][1] == pytest.approx(1.0, abs=0.02)


def test_zero_radius_circle_is_a_massless_point() -> None:
    world = b2.b2World(gravity=(0, -10))
    world.CreateStaticBody(shapes=b2.b2PolygonShape(box=(5, 1)))
    dot = world.CreateDynamicBody(position=(0, 2))
    fixture = dot.CreateCircleFixture(radius=0, density=5)
    assert fixture.shape.radius == 0.0 and fixture.density == 5.0
    assert dot.mass == 1.0  # Box2D: a body without mass gets 1 kg
    for _ in range(120):
        world.Step(1 / 60, 8, 3)
    assert dot.position.y == pytest.approx(1.01, abs=0.01)  # on the box's skin
    with pytest.raises(ValidationError):
        dot.CreateCircleFixture(radius=-1)


def test_edge_shapes_take_ghost_vertices() -> None:
    edge = b2.b2EdgeShape(vertices=[None, (0, 0), (1, 0), (2, 1)])
    assert edge.vertices == [(0.0, 0.0), (1.0, 0.0)] and edge.vertexCount == 3
    assert not edge.hasVertex0 and edge.hasVertex3 and edge.vertex3 == (2, 1)
    shape = edge.to_kge()
    assert isinstance(shape, Edge)
    assert shape.vertex0 is None and shape.vertex3 == (2.0, 1.0)
    edge = b2.b2EdgeShape(vertices=[(-1, 0), (0, 0), (1, 0)])
    assert edge.hasVertex0 and not edge.hasVertex3
    chain = b2.b2ChainShape(vertices=[(0, 0), (1, 0), (2, 1)])
    middle = chain.getChildEdge(1)
    assert middle.vertices == [(1.0, 0.0), (2.0, 1.0)] and middle.vertex0 == (0, 0)


def test_vec3_and_matrices_as_box2d() -> None:
    rng = np.random.default_rng(3)
    a = rng.normal(size=(3, 3))
    m = b2.b2Mat33(*(tuple(col) for col in a.T))
    rhs = rng.normal(size=3)
    assert tuple(m.Solve33(tuple(rhs))) == pytest.approx(tuple(np.linalg.solve(a, rhs)))
    assert tuple(m * tuple(rhs)) == pytest.approx(tuple(a @ rhs))
    sym = a @ a.T
    inv = b2.b2Mat33()
    b2.b2Mat33(*(tuple(c) for c in sym.T)).GetSymInverse33(inv)
    got = np.array([tuple(inv.col1), tuple(inv.col2), tuple(inv.col3)]).T
    assert np.allclose(got, np.linalg.inv(sym))
    m2 = b2.b2Mat22(1, 2, 3, 4)
    assert (m2 * m2).col1 == (7, 15) and tuple(m2.Solve((1, 1))) == pytest.approx((-1, 1))
    xf = b2.b2Transform()
    xf.Set((1, 2), math.pi / 2)
    p = b2.b2Mul(xf, (1, 0))
    assert tuple(p) == pytest.approx((1, 3)) and tuple(b2.b2MulT(xf, p)) == pytest.approx((1, 0))
    both = b2.b2Mul(xf, xf)
    assert tuple(both.position) == pytest.approx((-1, 3)) and both.angle == pytest.approx(math.pi)
    assert b2.b2Mul(b2.b2Rot(0.3), b2.b2Rot(0.2)).angle == pytest.approx(0.5)
    v = b2.b2Vec3(1, 2, 3)
    v += (1, 1, 1)
    assert v == (2, 3, 4) and v.cross((0, 0, 1)) == (3, -2, 0)
    c = b2.b2Color(0.2, 0.4, 0.6)
    c *= 2
    assert c == pytest.approx((0.4, 0.8, 1.2)) and b2.b2Color(1, 0.5, 0).bytes == [255, 127, 0]


def test_destroying_a_fixture_moves_the_centre_s_velocity_as_reset_mass_data() -> None:
    """Box2D's ResetMassData keeps every point's velocity: the centre's becomes that of
    its new place, v += w x dc (pybox2d 2.3.10: (0.531754, 3.9645) here), at once."""
    world = b2.b2World(gravity=(0, 0))
    halves = (b2.b2PolygonShape(box=(0.5, 0.5, (-0.5, 0), 0)),
              b2.b2PolygonShape(box=(0.5, 0.5, (0.5, 0), 0)))
    body = world.CreateDynamicBody(shapes=halves, shapeFixture=b2.b2FixtureDef(density=1))
    body.angularVelocity = -8.0
    world.Step(1 / 60, 8, 3)
    body.DestroyFixture(body.fixtures[1])
    assert tuple(body.linearVelocity) == pytest.approx((0.531754, 3.9645), abs=1e-4)
    body.CreatePolygonFixture(box=(0.5, 0.5, (0.5, 0), 0), density=1)
    assert tuple(body.linearVelocity) == pytest.approx((0.0, 0.0), abs=1e-9)


def test_install_sets_a_real_pybox2d_aside_and_uninstall_brings_it_back() -> None:
    import sys
    from types import ModuleType

    import kge.box2d

    saved = {k: sys.modules.get(k) for k in ("Box2D", "Box2D.b2", "Box2D.Box2D")}
    real = ModuleType("Box2D")  # stands for pybox2d, imported before kge.box2d.install()
    sys.modules["Box2D"] = real
    try:
        kge.box2d.install()
        import Box2D

        assert Box2D is kge.box2d
        kge.box2d.uninstall()
        import Box2D as again

        assert again is real
    finally:
        for k, v in saved.items():
            if v is None:
                sys.modules.pop(k, None)
            else:
                sys.modules[k] = v
