"""Chipmunk's C functions, as kge calls them: one declared table, one namespace.

pymunk wraps Chipmunk through cffi (``pymunk._chipmunk``: ``lib`` holds the C
functions, ``ffi`` the types). Its public classes cost a Python property and often a
``Vec2d`` per read, so kge's per-step loops call the C getters and setters directly.
This module is the only one that imports that private layer. :data:`FUNCTIONS`
lists every C function and constant kge calls, with the C signature pymunk 7.3
declares and the public pymunk API it stands for; :data:`lib` carries exactly
those names (anything else is an ``AttributeError``), so a call that is not in the
inventory cannot creep in, and ``tests/physics/test_door.py`` checks each
signature against the installed pymunk and each function against its public twin.

>>> import pymunk
>>> body = pymunk.Body(2.0, 3.0)
>>> body.position = (1.0, 2.0)
>>> from kge.physics.cp import body_handle
>>> p = lib.cpBodyGetPosition(body_handle(body))
>>> (p.x, p.y) == tuple(body.position)
True
"""

from __future__ import annotations

from types import SimpleNamespace
from typing import Any

from pymunk._chipmunk import ffi as _ffi
from pymunk._chipmunk import lib as _raw

#: name -> (C signature under pymunk 7.3, the public pymunk API it stands for)
FUNCTIONS: dict[str, tuple[str, str]] = {
    "CP_BODY_TYPE_DYNAMIC": ("0", "pymunk.Body.DYNAMIC"),
    "CP_BODY_TYPE_STATIC": ("2", "pymunk.Body.STATIC"),
    "cpArbiterGetBodies": (
        "void(*)(struct cpArbiter *, struct cpBody * *, struct cpBody * *)",
        "Arbiter.bodies",
    ),
    "cpArbiterGetContactPointSet": (
        "struct cpContactPointSet(*)(struct cpArbiter *)",
        "Arbiter.contact_point_set",
    ),
    "cpArbiterGetFriction": ("double(*)(struct cpArbiter *)", "Arbiter.friction"),
    "cpArbiterGetProcessCollision": (
        "unsigned char(*)(struct cpArbiter *)",
        "Arbiter.process_collision",
    ),
    "cpArbiterGetShapes": (
        "void(*)(struct cpArbiter *, struct cpShape * *, struct cpShape * *)",
        "Arbiter.shapes",
    ),
    "cpArbiterGetSurfaceVelocity": (
        "struct cpVect(*)(struct cpArbiter *)",
        "Arbiter.surface_velocity",
    ),
    "cpArbiterSetProcessCollision": (
        "void(*)(struct cpArbiter *, unsigned char)",
        "Arbiter.process_collision =",
    ),
    "cpArbiterSetRestitution": (
        "void(*)(struct cpArbiter *, double)",
        "Arbiter.restitution =",
    ),
    "cpBodyEachArbiter": (
        "void(*)(struct cpBody *, void(*)(struct cpBody *, struct cpArbiter *, void *), void *)",
        "Body.each_arbiter",
    ),
    "cpBodyGetAngle": ("double(*)(struct cpBody *)", "Body.angle"),
    "cpBodyGetAngularVelocity": ("double(*)(struct cpBody *)", "Body.angular_velocity"),
    "cpBodyGetCenterOfGravity": ("struct cpVect(*)(struct cpBody *)", "Body.center_of_gravity"),
    "cpBodyGetMass": ("double(*)(struct cpBody *)", "Body.mass"),
    "cpBodyGetMoment": ("double(*)(struct cpBody *)", "Body.moment"),
    "cpBodyGetPosition": ("struct cpVect(*)(struct cpBody *)", "Body.position"),
    "cpBodyGetType": ("enum cpBodyType(*)(struct cpBody *)", "Body.body_type"),
    "cpBodyGetUserData": (
        "void *(*)(struct cpBody *)",
        "(the Body's own handle; pymunk reads it in callbacks)",
    ),
    "cpBodyGetVelocity": ("struct cpVect(*)(struct cpBody *)", "Body.velocity"),
    "cpBodyGetVelocityAtWorldPoint": (
        "struct cpVect(*)(struct cpBody *, struct cpVect)",
        "Body.velocity_at_world_point",
    ),
    "cpBodyIsSleeping": ("unsigned char(*)(struct cpBody *)", "Body.is_sleeping"),
    "cpBodyLocalToWorld": (
        "struct cpVect(*)(struct cpBody *, struct cpVect)",
        "Body.local_to_world",
    ),
    "cpBodySetAngle": ("void(*)(struct cpBody *, double)", "Body.angle ="),
    "cpBodySetAngularVelocity": ("void(*)(struct cpBody *, double)", "Body.angular_velocity ="),
    "cpBodySetCenterOfGravity": (
        "void(*)(struct cpBody *, struct cpVect)",
        "Body.center_of_gravity =",
    ),
    "cpBodySetMass": ("void(*)(struct cpBody *, double)", "Body.mass ="),
    "cpBodySetMoment": ("void(*)(struct cpBody *, double)", "Body.moment ="),
    "cpBodySetPosition": ("void(*)(struct cpBody *, struct cpVect)", "Body.position ="),
    "cpBodySetType": ("void(*)(struct cpBody *, enum cpBodyType)", "Body.body_type ="),
    "cpBodySetVelocity": ("void(*)(struct cpBody *, struct cpVect)", "Body.velocity ="),
    "cpBodyUpdatePosition": ("void(*)(struct cpBody *, double)", "Body.update_position"),
    "cpBodyWorldToLocal": (
        "struct cpVect(*)(struct cpBody *, struct cpVect)",
        "Body.world_to_local",
    ),
    "cpCircleShapeGetOffset": ("struct cpVect(*)(struct cpShape *)", "Circle.offset"),
    "cpCircleShapeGetRadius": ("double(*)(struct cpShape *)", "Circle.radius"),
    "cpConstraintGetImpulse": ("double(*)(struct cpConstraint *)", "Constraint.impulse"),
    "cpConstraintGetMaxForce": ("double(*)(struct cpConstraint *)", "Constraint.max_force"),
    "cpConstraintGetSpace": (
        "struct cpSpace *(*)(struct cpConstraint *)",
        "(none: Constraint.a.space / Space.constraints)",
    ),
    "cpConstraintSetMaxForce": (
        "void(*)(struct cpConstraint *, double)",
        "Constraint.max_force =",
    ),
    "cpPolyShapeGetCount": ("int(*)(struct cpShape *)", "len(Poly.get_vertices())"),
    "cpPolyShapeGetRadius": ("double(*)(struct cpShape *)", "Poly.radius"),
    "cpPolyShapeGetVert": ("struct cpVect(*)(struct cpShape *, int)", "Poly.get_vertices()[i]"),
    "cpSegmentShapeGetA": ("struct cpVect(*)(struct cpShape *)", "Segment.a"),
    "cpSegmentShapeGetB": ("struct cpVect(*)(struct cpShape *)", "Segment.b"),
    "cpSegmentShapeGetRadius": ("double(*)(struct cpShape *)", "Segment.radius"),
    "cpSegmentShapeInit": (
        "struct cpSegmentShape *(*)(struct cpSegmentShape *, struct cpBody *, "
        "struct cpVect, struct cpVect, double)",
        "(none: Segment.__init__ on a new shape)",
    ),
    "cpSegmentShapeNew": (
        "struct cpShape *(*)(struct cpBody *, struct cpVect, struct cpVect, double)",
        "Segment(body, a, b, radius)",
    ),
    "cpSegmentShapeSetNeighbors": (
        "void(*)(struct cpShape *, struct cpVect, struct cpVect)",
        "Segment.set_neighbors",
    ),
    "cpShapeFree": ("void(*)(struct cpShape *)", "(none: pymunk's shape finaliser)"),
    "cpShapeGetBB": ("struct cpBB(*)(struct cpShape *)", "Shape.bb"),
    "cpShapeGetBody": ("struct cpBody *(*)(struct cpShape *)", "Shape.body"),
    "cpShapeGetCenterOfGravity": ("struct cpVect(*)(struct cpShape *)", "Shape.center_of_gravity"),
    "cpShapeGetHashID": (
        "uintptr_t(*)(struct cpShape *)",
        "Shape._hashid (pymunk's own private property)",
    ),
    "cpShapeGetSensor": ("unsigned char(*)(struct cpShape *)", "Shape.sensor"),
    "cpShapeGetSpace": ("struct cpSpace *(*)(struct cpShape *)", "Shape.space"),
    "cpShapeGetUserData": (
        "void *(*)(struct cpShape *)",
        "(the Shape's own handle; pymunk reads it in callbacks)",
    ),
    "cpShapeSetFilter": ("void(*)(struct cpShape *, struct cpShapeFilter)", "Shape.filter ="),
    "cpShapeSetFriction": ("void(*)(struct cpShape *, double)", "Shape.friction ="),
    "cpShapeSetSensor": ("void(*)(struct cpShape *, unsigned char)", "Shape.sensor ="),
    "cpShapeSetUserData": ("void(*)(struct cpShape *, void *)", "(none: pymunk's Shape._init)"),
    "cpSpaceAddShape": (
        "struct cpShape *(*)(struct cpSpace *, struct cpShape *)",
        "Space.add(shape)",
    ),
    "cpSpaceContainsConstraint": (
        "unsigned char(*)(struct cpSpace *, struct cpConstraint *)",
        "constraint in Space.constraints",
    ),
    "cpSpaceContainsShape": (
        "unsigned char(*)(struct cpSpace *, struct cpShape *)",
        "shape in Space.shapes",
    ),
    "cpSpaceEachBody": (
        "void(*)(struct cpSpace *, void(*)(struct cpBody *, void *), void *)",
        "pymunk.batch.get_space_bodies",
    ),
    "cpSpaceEachCachedArbiter": (
        "void(*)(struct cpSpace *, void(*)(struct cpArbiter *, void *), void *)",
        "pymunk.batch.get_space_arbiters",
    ),
    "cpSpaceGetCurrentTimeStep": ("double(*)(struct cpSpace *)", "Space.current_time_step"),
    "cpSpaceGetGravity": ("struct cpVect(*)(struct cpSpace *)", "Space.gravity"),
    "cpSpaceRemoveShape": ("void(*)(struct cpSpace *, struct cpShape *)", "Space.remove(shape)"),
}

#: the declared C functions and constants, and nothing else
lib: Any = SimpleNamespace(**{name: getattr(_raw, name) for name in FUNCTIONS})

#: cffi's type system for Chipmunk's structs (``ffi.new("cpBody *[1]")``,
#: ``ffi.buffer``, ``ffi.from_handle``...)
ffi: Any = _ffi

#: the whole C library, for the door's own modules (function addresses for batch
#: iterators); outside :mod:`kge.physics.cp` use :data:`lib`
raw_lib: Any = _raw


def signature(name: str) -> str:
    """The C signature the installed pymunk gives ``name`` (a constant: its value).

    >>> signature("cpBodyGetMass")
    'double(*)(struct cpBody *)'
    """
    obj = getattr(_raw, name)
    return str(obj) if isinstance(obj, int) else str(_ffi.typeof(obj).cname)
