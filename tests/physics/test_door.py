"""The door to pymunk's private layer (``kge.physics.cp``) does what pymunk's public API does.

One test (or one parametrised row) per entry point: each C function of the
inventory against its public twin, each handle against the pointer Chipmunk itself
reports, each relation reader against pymunk's property. A pymunk upgrade that
changes a signature, a field or a behaviour kge relies on fails here first.
The bulk paths (``kge.physics.cp.static_bulk``: ``cpSegmentShapeNew``,
``cpSegmentShapeInit``, ``cpShapeFree``, ``cpSpaceAddShape``, ``cpSpaceRemoveShape``)
are pinned against pymunk-built shapes in ``tests/physics/test_static_bulk.py``.
"""

from __future__ import annotations

import gc
import weakref
from collections.abc import Callable
from typing import Any

import pymunk
import pymunk.batch as pb
import pytest

from kge.physics.callback_errors import CallbackErrors
from kge.physics.cp import (
    FUNCTIONS,
    arbiter_handle,
    body_constraints,
    body_handle,
    body_shapes,
    constraint_handle,
    ffi,
    lib,
    shape_body,
    shape_handle,
    shape_hashid,
    shape_space,
    space_handle,
)
from kge.physics.cp.bulk import ArbiterBodies, BodyReader
from kge.physics.cp.capi import signature
from kge.physics.cp.collisions import route_contacts


def _xy(v: Any) -> tuple[float, float]:
    return (float(v.x), float(v.y))


def _moving_body() -> pymunk.Body:
    body = pymunk.Body(2.0, 3.0)
    body.position = (1.5, -2.0)
    body.angle = 0.25
    body.velocity = (3.0, 4.0)
    body.angular_velocity = -1.25
    body.center_of_gravity = (0.1, 0.2)
    return body


# -- the inventory --------------------------------------------------------------


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
def test_each_declared_function_has_its_pinned_signature(name: str) -> None:
    assert signature(name) == FUNCTIONS[name][0]


def test_lib_carries_the_inventory_and_nothing_else() -> None:
    assert set(vars(lib)) == set(FUNCTIONS)
    with pytest.raises(AttributeError):
        lib.cpSpaceStep  # noqa: B018 (real in Chipmunk, not declared: refused)


def test_the_dynamic_constant_is_pymunks() -> None:
    assert lib.CP_BODY_TYPE_DYNAMIC == pymunk.Body.DYNAMIC


# -- handles and relations ------------------------------------------------------


def test_handles_are_the_pointers_chipmunk_reports() -> None:
    space = pymunk.Space()
    a, b = pymunk.Body(1.0, 1.0), pymunk.Body(1.0, 1.0)
    circle = pymunk.Circle(a, 0.5)
    joint = pymunk.PinJoint(a, b)
    space.add(a, b, circle, joint)
    assert lib.cpShapeGetBody(shape_handle(circle)) == body_handle(a)
    assert lib.cpShapeGetSpace(shape_handle(circle)) == space_handle(space)
    assert lib.cpConstraintGetSpace(constraint_handle(joint)) == space_handle(space)
    assert ffi.from_handle(lib.cpBodyGetUserData(body_handle(a))) is a
    assert ffi.from_handle(lib.cpShapeGetUserData(shape_handle(circle))) is circle
    assert body_handle(a) != body_handle(b)


def test_relations_match_pymunks_properties() -> None:
    space = pymunk.Space()
    body, other = pymunk.Body(1.0, 1.0), pymunk.Body(1.0, 1.0)
    shapes = [pymunk.Circle(body, 0.5), pymunk.Segment(body, (0, 0), (1, 0), 0.1),
              pymunk.Poly.create_box(body, (1.0, 1.0))]
    joint = pymunk.PivotJoint(body, other, (0.0, 0.0))
    assert shape_space(shapes[0]) is None
    space.add(body, other, *shapes, joint)
    for s in shapes:
        assert shape_body(s) is s.body is body
        assert shape_space(s) is s.space is space
    assert list(body_shapes(body)) == shapes  # attach order; body.shapes is a set
    assert set(body_shapes(body)) == body.shapes
    assert set(body_constraints(body)) == body.constraints == {joint}
    assert not body_constraints(pymunk.Body(1.0, 1.0))
    space.remove(shapes[1])  # out of the space, still on the body
    assert shape_space(shapes[1]) is None
    assert list(body_shapes(body)) == shapes


def test_hashids_grow_with_each_add_and_are_chipmunks() -> None:
    space = pymunk.Space()
    first, second = pymunk.Circle(space.static_body, 1.0), pymunk.Circle(space.static_body, 1.0)
    space.add(first)
    space.add(second)
    assert shape_hashid(first) < shape_hashid(second)
    assert shape_hashid(second) == lib.cpShapeGetHashID(shape_handle(second))


# -- bodies -------------------------------------------------------------------


BODY_GETTERS: list[tuple[str, Callable[[pymunk.Body], Any], bool]] = [
    ("cpBodyGetPosition", lambda b: b.position, True),
    ("cpBodyGetAngle", lambda b: b.angle, False),
    ("cpBodyGetVelocity", lambda b: b.velocity, True),
    ("cpBodyGetAngularVelocity", lambda b: b.angular_velocity, False),
    ("cpBodyGetCenterOfGravity", lambda b: b.center_of_gravity, True),
    ("cpBodyGetMass", lambda b: b.mass, False),
    ("cpBodyGetMoment", lambda b: b.moment, False),
    ("cpBodyGetType", lambda b: b.body_type, False),
    ("cpBodyIsSleeping", lambda b: b.is_sleeping, False),
]


@pytest.mark.parametrize(("name", "public", "vector"), BODY_GETTERS)
def test_body_getter_matches_public(name: str, public: Callable[..., Any], vector: bool) -> None:
    body = _moving_body()
    got = getattr(lib, name)(body_handle(body))
    if vector:
        assert _xy(got) == tuple(public(body))
    else:
        assert got == public(body)


BODY_SETTERS: list[tuple[str, Any, Callable[[pymunk.Body], Any]]] = [
    ("cpBodySetPosition", (7.0, -8.0), lambda b: tuple(b.position)),
    ("cpBodySetAngle", 1.5, lambda b: b.angle),
    ("cpBodySetVelocity", (-2.0, 0.5), lambda b: tuple(b.velocity)),
    ("cpBodySetAngularVelocity", 3.25, lambda b: b.angular_velocity),
    ("cpBodySetCenterOfGravity", (0.3, -0.4), lambda b: tuple(b.center_of_gravity)),
    ("cpBodySetMass", 5.5, lambda b: b.mass),
    ("cpBodySetMoment", 9.5, lambda b: b.moment),
    ("cpBodySetType", pymunk.Body.KINEMATIC, lambda b: b.body_type),
]


@pytest.mark.parametrize(("name", "value", "public"), BODY_SETTERS)
def test_body_setter_is_seen_by_public(name: str, value: Any, public: Callable[..., Any]) -> None:
    body = _moving_body()
    getattr(lib, name)(body_handle(body), value)
    assert public(body) == value


@pytest.mark.parametrize(
    ("name", "public"),
    [
        ("cpBodyLocalToWorld", lambda b, p: b.local_to_world(p)),
        ("cpBodyWorldToLocal", lambda b, p: b.world_to_local(p)),
        ("cpBodyGetVelocityAtWorldPoint", lambda b, p: b.velocity_at_world_point(p)),
    ],
)
def test_body_point_maps_match_public(name: str, public: Callable[..., Any]) -> None:
    body = _moving_body()
    for p in [(0.0, 0.0), (2.5, -1.0), (-3.0, 4.0)]:
        assert _xy(getattr(lib, name)(body_handle(body), p)) == pytest.approx(
            tuple(public(body, p)), abs=1e-12
        )


def test_update_position_matches_public() -> None:
    ours, theirs = _moving_body(), _moving_body()
    lib.cpBodyUpdatePosition(body_handle(ours), 0.125)
    pymunk.Body.update_position(theirs, 0.125)
    assert (tuple(ours.position), ours.angle) == (tuple(theirs.position), theirs.angle)
    assert tuple(ours.position) != (1.5, -2.0)


# -- shapes -------------------------------------------------------------------


def _shapes() -> tuple[pymunk.Circle, pymunk.Segment, pymunk.Poly]:
    body = _moving_body()
    circle = pymunk.Circle(body, 0.75, (0.25, -0.5))
    segment = pymunk.Segment(body, (-1.0, 0.5), (2.0, 1.5), 0.05)
    poly = pymunk.Poly(body, [(0, 0), (1, 0), (1, 2), (0, 1)], radius=0.01)
    space = pymunk.Space()
    space.add(body, circle, segment, poly)  # bbs are cached when a shape joins a space
    return circle, segment, poly


def test_circle_segment_poly_getters_match_public() -> None:
    circle, segment, poly = _shapes()
    assert _xy(lib.cpCircleShapeGetOffset(shape_handle(circle))) == tuple(circle.offset)
    assert lib.cpCircleShapeGetRadius(shape_handle(circle)) == circle.radius
    assert _xy(lib.cpSegmentShapeGetA(shape_handle(segment))) == tuple(segment.a)
    assert _xy(lib.cpSegmentShapeGetB(shape_handle(segment))) == tuple(segment.b)
    assert lib.cpSegmentShapeGetRadius(shape_handle(segment)) == segment.radius
    verts = poly.get_vertices()
    cp = shape_handle(poly)
    assert lib.cpPolyShapeGetCount(cp) == len(verts)
    assert [_xy(lib.cpPolyShapeGetVert(cp, i)) for i in range(len(verts))] == [
        tuple(v) for v in verts
    ]
    assert lib.cpPolyShapeGetRadius(cp) == poly.radius


def test_shape_getters_match_public() -> None:
    for shape in _shapes():
        cp = shape_handle(shape)
        bb = lib.cpShapeGetBB(cp)
        assert (bb.l, bb.b, bb.r, bb.t) == tuple(shape.bb)
        assert _xy(lib.cpShapeGetCenterOfGravity(cp)) == pytest.approx(
            tuple(shape.center_of_gravity), abs=1e-12
        )
        assert bool(lib.cpShapeGetSensor(cp)) is shape.sensor is False


def test_shape_setters_are_seen_by_public() -> None:
    circle, _, _ = _shapes()
    cp = shape_handle(circle)
    lib.cpShapeSetFriction(cp, 0.625)
    lib.cpShapeSetSensor(cp, True)
    lib.cpShapeSetFilter(cp, pymunk.ShapeFilter(group=3, categories=0b101, mask=0b110))
    assert circle.friction == 0.625
    assert circle.sensor is True
    assert circle.filter == pymunk.ShapeFilter(group=3, categories=0b101, mask=0b110)
    assert lib.cpShapeGetSensor(cp)
    handle = ffi.new_handle(circle)
    lib.cpShapeSetUserData(cp, handle)
    assert ffi.from_handle(lib.cpShapeGetUserData(cp)) is circle


def _drop_on_chain_end(neighbours: Callable[[pymunk.Segment], None]) -> tuple[float, ...]:
    space = pymunk.Space()
    space.gravity = (0.0, -10.0)
    segment = pymunk.Segment(space.static_body, (0, 0), (1, 0), 0.0)
    neighbours(segment)
    body = pymunk.Body(1.0, 1.0)
    body.position, body.angle = (-0.1, 0.4), 0.4
    space.add(segment, body, pymunk.Poly.create_box(body, (0.5, 0.5)))
    for _ in range(60):
        space.step(1 / 60)
    return (*body.position, body.angle)


def test_segment_neighbours_match_public() -> None:
    # (Chipmunk keeps the tangents in an opaque struct: pinned by what a step does)
    ours = _drop_on_chain_end(
        lambda s: lib.cpSegmentShapeSetNeighbors(shape_handle(s), (-1.0, 1.0), (2.0, 0.0))
    )
    theirs = _drop_on_chain_end(lambda s: s.set_neighbors((-1.0, 1.0), (2.0, 0.0)))
    assert ours == theirs


# -- constraints and the space --------------------------------------------------


def test_constraint_functions_match_public() -> None:
    space = pymunk.Space()
    space.gravity = (0.0, -10.0)
    anchor = pymunk.Body(body_type=pymunk.Body.STATIC)
    bob = pymunk.Body(1.0, 1.0)
    bob.position = (0.0, -1.0)
    joint = pymunk.PinJoint(anchor, bob)
    space.add(anchor, bob, joint)
    space.step(1 / 60)
    cp = constraint_handle(joint)
    assert lib.cpConstraintGetImpulse(cp) == joint.impulse != 0.0
    lib.cpConstraintSetMaxForce(cp, 123.0)
    assert joint.max_force == lib.cpConstraintGetMaxForce(cp) == 123.0
    assert lib.cpSpaceContainsConstraint(space_handle(space), cp)
    space.remove(joint)
    assert not lib.cpSpaceContainsConstraint(space_handle(space), cp)
    assert lib.cpConstraintGetSpace(cp) == ffi.NULL


def test_space_getters_match_public() -> None:
    space = pymunk.Space()
    space.gravity = (1.0, -9.5)
    body = pymunk.Body(1.0, 1.0)
    shape = pymunk.Circle(body, 1.0)
    space.add(body, shape)
    space.step(0.03125)
    cs = space_handle(space)
    assert _xy(lib.cpSpaceGetGravity(cs)) == tuple(space.gravity)
    assert lib.cpSpaceGetCurrentTimeStep(cs) == space.current_time_step == 0.03125
    assert lib.cpSpaceContainsShape(cs, shape_handle(shape))
    space.remove(shape)
    assert not lib.cpSpaceContainsShape(cs, shape_handle(shape))


def test_body_reader_matches_pymunk_batch() -> None:
    space = pymunk.Space()
    for i in range(5):
        body = pymunk.Body(1.0, 1.0)
        body.position = (float(i), -float(i))
        body.velocity = (0.5 * i, 2.0)
        space.add(body, pymunk.Circle(body, 0.25))
    fields = pb.BodyFields.BODY_ID | pb.BodyFields.POSITION | pb.BodyFields.VELOCITY
    ids, rows = BodyReader(fields).read(space)
    data = pb.Buffer()
    pb.get_space_bodies(space, fields, data)
    n = len(ids)
    assert n == 5
    assert ids.tolist() == list(memoryview(data.int_buf()).cast("P"))[:n]
    assert rows.ravel().tolist() == list(memoryview(data.float_buf()).cast("d"))[: n * 4]


# -- arbiters -------------------------------------------------------------------


def test_arbiter_functions_match_public() -> None:
    space = pymunk.Space()
    space.gravity = (0.0, -10.0)
    ground = pymunk.Segment(space.static_body, (-5, 0), (5, 0), 0.0)
    ground.friction, ground.surface_velocity = 0.5, (1.0, 0.0)
    body = pymunk.Body(1.0, 1.0)
    body.position = (0.0, 0.45)
    ball = pymunk.Circle(body, 0.5)
    ball.friction = 0.8
    space.add(ground, body, ball)
    seen: list[bool] = []

    def pre_solve(arb: pymunk.Arbiter, _space: pymunk.Space, _data: Any) -> None:
        ca = arbiter_handle(arb)
        a_p, b_p = ffi.new("cpBody **"), ffi.new("cpBody **")
        lib.cpArbiterGetBodies(ca, a_p, b_p)
        assert (ffi.from_handle(lib.cpBodyGetUserData(a_p[0])),
                ffi.from_handle(lib.cpBodyGetUserData(b_p[0]))) == arb.bodies
        sa, sb = ffi.new("cpShape **"), ffi.new("cpShape **")
        lib.cpArbiterGetShapes(ca, sa, sb)
        assert (ffi.from_handle(lib.cpShapeGetUserData(sa[0])),
                ffi.from_handle(lib.cpShapeGetUserData(sb[0]))) == arb.shapes
        cps = lib.cpArbiterGetContactPointSet(ca)
        public = arb.contact_point_set
        assert cps.count == len(public.points) == 1
        assert _xy(cps.normal) == tuple(public.normal)
        assert cps.points[0].distance == public.points[0].distance
        assert lib.cpArbiterGetFriction(ca) == arb.friction
        assert _xy(lib.cpArbiterGetSurfaceVelocity(ca)) == tuple(arb.surface_velocity)
        assert lib.cpArbiterGetProcessCollision(ca) == arb.process_collision == 1
        lib.cpArbiterSetRestitution(ca, 0.25)
        assert arb.restitution == 0.25
        lib.cpArbiterSetProcessCollision(ca, False)
        assert not arb.process_collision
        seen.append(True)

    space.on_collision(pre_solve=pre_solve)
    space.step(1 / 60)
    assert seen == [True]
    assert body.velocity.y < 0.0  # the contact was dropped: the ball falls through


def test_each_arbiter_matches_public() -> None:
    space = pymunk.Space()
    space.gravity = (0.0, -10.0)
    space.add(pymunk.Segment(space.static_body, (-5, 0), (5, 0), 0.0))
    body = pymunk.Body(1.0, 1.0)
    body.position = (0.0, 0.45)
    space.add(body, pymunk.Circle(body, 0.5))
    space.step(1 / 60)
    ours: list[Any] = []

    @ffi.callback("void(cpBody *, cpArbiter *, void *)")
    def collect(_body: Any, arb: Any, _data: Any) -> None:
        ours.append(lib.cpArbiterGetFriction(arb))

    lib.cpBodyEachArbiter(body_handle(body), collect, ffi.NULL)
    theirs: list[float] = []
    body.each_arbiter(lambda arb: theirs.append(arb.friction))
    assert len(ours) == 1
    assert ours == theirs


def test_arbiter_bodies_reader_matches_pymunk_batch() -> None:
    space = pymunk.Space()
    space.gravity = (0.0, -10.0)
    space.add(pymunk.Segment(space.static_body, (-5, 0), (5, 0), 0.0))
    for x in (-2.0, 0.0, 2.0):
        body = pymunk.Body(1.0, 1.0)
        body.position = (x, 0.45)
        space.add(body, pymunk.Circle(body, 0.5))
    space.step(1 / 60)
    ids = ArbiterBodies().read(space).tolist()
    data = pb.Buffer()
    pb.get_space_arbiters(space, pb.ArbiterFields.BODY_A_ID | pb.ArbiterFields.BODY_B_ID, data)
    assert len(ids) == 6  # two bodies per contact
    assert ids == list(memoryview(data.int_buf()).cast("P"))


def test_routed_contacts_get_the_arbiter_pymunk_would_wrap() -> None:
    space = pymunk.Space()
    body = pymunk.Body(1.0, 1.0)
    ball, floor = pymunk.Circle(body, 0.5), pymunk.Circle(space.static_body, 0.5)
    space.add(body, ball, floor)
    seen: list[tuple[str, tuple[pymunk.Shape, ...]]] = []
    errors = CallbackErrors()

    def shapes(arb: Any) -> tuple[pymunk.Shape, ...]:
        sa, sb = ffi.new("cpShape **"), ffi.new("cpShape **")
        lib.cpArbiterGetShapes(arb, sa, sb)
        return (ffi.from_handle(lib.cpShapeGetUserData(sa[0])),
                ffi.from_handle(lib.cpShapeGetUserData(sb[0])))

    def begin(arb: Any) -> None:
        seen.append(("begin", shapes(arb)))
        raise ValueError("kept, not printed")

    route_contacts(space, begin, lambda arb: seen.append(("end", shapes(arb))), errors)
    space.step(0.01)
    space.remove(ball)
    assert [kind for kind, _ in seen] == ["begin", "end"]
    assert {s for _, pair in seen for s in pair} == {ball, floor}
    with pytest.raises(ValueError, match="kept"):
        errors.raise_pending()


def test_a_routed_space_and_its_handler_object_are_collected() -> None:
    class Owner:
        def __init__(self) -> None:
            self.space = pymunk.Space()  # the handler's object holds its space
            route_contacts(self.space, self.begin, self.begin, None)

        def begin(self, arb: Any) -> None:
            pass

    owner = Owner()
    gone = weakref.ref(owner.space)
    del owner
    gc.collect()
    assert gone() is None
