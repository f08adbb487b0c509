"""pymunk bodies for kge entities, and the per-body rules pymunk lacks.

A *body record* ties one pymunk Body to its entity. Explicit bodies come from a
:class:`~kge.components.rigidbody.RigidBody`; a collider entity with no
RigidBody gets an *implicit* static body placed by its Transform (Box2D's
ground body, one per collider entity so moving it is a teleport of that body).

Box2D rules implemented here, each kept off the hot path when unused:

* gravity scale and damping (``v *= max(0, 1 - c*dt)`` per fixed step) live in a
  ``velocity_func`` installed only on bodies that need it, guarded so that it
  never touches a kinematic body;
* every pymunk call that can abort the process is wrapped: :func:`sleep` checks
  that sleeping is enabled, the body is dynamic and in the space (it is never
  called inside a step, because sync-in runs between steps).
"""

from __future__ import annotations

import math

import pymunk
from pymunk._chipmunk import lib as _lib

from kge.components.rigidbody import BodyType, RigidBody
from kge.physics.mass import ZERO, MassData

DYNAMIC = pymunk.Body.DYNAMIC
KINEMATIC = pymunk.Body.KINEMATIC
STATIC = pymunk.Body.STATIC

PYMUNK_TYPE = {
    BodyType.DYNAMIC: DYNAMIC,
    BodyType.KINEMATIC: KINEMATIC,
    BodyType.STATIC: STATIC,
}


class BodyRecord:
    """One simulated body: its pymunk Body and the collider entities on it."""

    __slots__ = ("body", "colliders", "enabled", "entity", "implicit", "in_space", "mass")

    def __init__(self, entity: int, body: pymunk.Body, implicit: bool) -> None:
        self.entity = entity
        self.body = body
        self.implicit = implicit
        self.colliders: set[int] = set()
        self.enabled = True
        self.in_space = False
        self.mass: MassData = ZERO

    @property
    def kge_body(self) -> int | None:
        """The body entity as events name it (None for the implicit static body)."""
        return None if self.implicit else self.entity


class ColliderRecord:
    """The pymunk shapes built for one collider entity and the body they sit on."""

    __slots__ = ("entity", "geometry", "owner", "shapes")

    def __init__(
        self, entity: int, owner: int, shapes: list[pymunk.Shape], geometry: object
    ) -> None:
        self.entity = entity
        self.owner = owner
        self.shapes = shapes
        self.geometry = geometry  #: the shape value the pymunk shapes were built from


def make_body(kind: BodyType, x: float, y: float, angle: float) -> pymunk.Body:
    """A pymunk body of ``kind`` at the pose (dynamic bodies get mass 1 until sized).

    Runs once per spawned body, so it writes through Chipmunk's setters directly
    and sets kge's attributes in one ``__dict__`` update: pymunk routes every
    Python-level attribute write through a ``__setattr__`` of its own.
    """
    if kind is BodyType.DYNAMIC:
        body = pymunk.Body(1.0, math.inf)
    else:
        body = pymunk.Body(body_type=PYMUNK_TYPE[kind])
    cp = body._body
    _lib.cpBodySetPosition(cp, (x, y))
    _lib.cpBodySetAngle(cp, angle)
    vars(body).update(
        kge_bullet=False,
        # what kge last saw; a different RigidBody.awake is a user request
        kge_awake=True,
        kge_dynamics=None,  # (gravity scale, damping factors) when a velocity_func is set
    )
    return body


def set_body_type(body: pymunk.Body, body_type: int) -> None:
    """Change a body's type between steps, even while it has joints.

    pymunk's setter refuses to make a body non-dynamic while one of its
    constraint objects (in the space or not) links it to another non-dynamic
    body. Box2D allows such joints (they simply do nothing), so kge takes the
    body's constraints out of the space first (the joint bridge keeps joints
    between two non-dynamic bodies out of it) and calls Chipmunk's
    ``cpBodySetType`` directly, which is what the setter does after its check.
    """
    space = body.space
    if space is not None:
        present = space.constraints
        for c in list(body.constraints):
            if c in present:
                space.remove(c)
    _lib.cpBodySetType(body._body, body_type)


def box2d_velocity(body: pymunk.Body, gravity: pymunk.Vec2d, damping: float, dt: float) -> None:
    """velocity_func with gravity scale and Box2D damping (factors precomputed per substep)."""
    if body.body_type != DYNAMIC:
        return
    scale, lin, ang = body.kge_dynamics
    pymunk.Body.update_velocity(body, gravity * scale, 1.0, dt)
    if lin != 1.0:
        body.velocity = body.velocity * lin
    if ang != 1.0:
        body.angular_velocity = body.angular_velocity * ang


def configure_dynamics(body: pymunk.Body, rb: RigidBody, dt: float, substeps: int) -> None:
    """Install (or remove) the custom velocity_func for gravity scale and damping.

    Box2D damps once per step by ``max(0, 1 - c*dt)``; kge integrates ``substeps``
    times per step, so each substep applies that factor's ``substeps``-th root.
    """
    if rb.type is not BodyType.DYNAMIC or (
        rb.gravity_scale == 1.0 and rb.linear_damping == 0.0 and rb.angular_damping == 0.0
    ):
        if getattr(body, "kge_dynamics", None) is not None:
            body.velocity_func = pymunk.Body.update_velocity
            body.kge_dynamics = None
        return
    lin = max(0.0, 1.0 - rb.linear_damping * dt) ** (1.0 / substeps)
    ang = max(0.0, 1.0 - rb.angular_damping * dt) ** (1.0 / substeps)
    body.kge_dynamics = (rb.gravity_scale, lin, ang)
    body.velocity_func = box2d_velocity


def can_sleep(space: pymunk.Space, body: pymunk.Body) -> bool:
    """True when ``body.sleep()`` is safe (it aborts the process otherwise)."""
    return (
        math.isfinite(space.sleep_time_threshold)
        and body.body_type == DYNAMIC
        and body.space is space
        and not body.is_sleeping
    )


def sleep(space: pymunk.Space, body: pymunk.Body) -> bool:
    """Put ``body`` to sleep if that is safe; returns whether it sleeps now."""
    if can_sleep(space, body):
        body.sleep()
        return True
    return body.is_sleeping


def wake_neighbours(body: pymunk.Body) -> None:
    """Wake every dynamic body touching ``body`` (before it leaves the space)."""
    others: list[pymunk.Body] = []

    def visit(arb: pymunk.Arbiter) -> None:
        a, b = arb.bodies
        other = b if a is body else a
        if other.body_type == DYNAMIC:
            others.append(other)

    body.each_arbiter(visit)
    for other in others:
        other.activate()


def set_mass(body: pymunk.Body, md: MassData) -> None:
    """Give a dynamic body kge's mass data (Chipmunk's setters directly: once per new body).

    ``md`` comes from :func:`kge.physics.mass.dynamic_mass`: 0 < mass < inf and
    inertia > 0 (inf for no rotation), the values pymunk's setters assert.
    """
    cp = body._body
    _lib.cpBodySetMass(cp, md.mass)
    _lib.cpBodySetMoment(cp, md.inertia)
    _lib.cpBodySetCenterOfGravity(cp, md.center)
