"""pymunk bodies for kge entities, and the per-body rules pymunk lacks.

A *body record* ties one pymunk Body to its entity. Explicit bodies come from a
:class:`~kge.components.rigidbody.RigidBody`; a collider entity with no
RigidBody gets an *implicit* static body placed by its Transform (Box2D's
ground body, one per collider entity so moving it is a teleport of that body).

Box2D rules implemented here, each kept off the hot path when unused:

* gravity scale and damping (``v *= max(0, 1 - c*dt)`` per fixed step) live in a
  ``velocity_func`` installed only on bodies that need it, guarded so that it
  never touches a kinematic body; it damps through Chipmunk's own damping
  argument, not its velocity setters (each of which restarts the body's sleep
  clock: damped bodies never slept);
* every pymunk call that can abort the process is wrapped: :func:`sleep_island` checks
  that sleeping is enabled, the body is dynamic and in the space (it is never
  called inside a step, because sync-in runs between steps).

Chipmunk keeps a *contact graph* (arbiters and constraints threaded on their
bodies, moved in and out of the space's active arrays when components sleep and
wake). Two of its entry points corrupt that graph when used on a body that is in
the space next to other bodies, and a corrupt graph later frees or dereferences
dangling pointers (segfaults in ``cpSpaceRemoveShape``, ``free(): invalid
pointer`` inside ``cpSpaceStep``); see docs/reliability.md section 2. kge never
calls them in that state:

* ``cpBodySetType`` changes the type in place: it writes the new mass fields
  before waking the body, so a sleeping body made kinematic or static stays in
  its sleeping component (waking it later aborts), and it does not wake bodies
  sleeping on a static body that becomes dynamic, whose parked arbiters are then
  never restored nor released and outlive the shapes they point to.
  :func:`set_body_type` takes the body out of the space (after waking everything
  around it), changes the type and puts it back, as Box2D's ``SetType`` destroys
  the body's contacts and wakes it.
* ``cpBodySleep`` only parks the arbiters and constraints the body owns (it is
  body A of them, or body A is static), so sleeping a body next to an awake one
  leaves half-parked pairs that are restored inconsistently on wake-up. :func:`sleep_island`
  only sleeps a body whose non-static neighbours sleep with it or already sleep in
  one component, which is the state Chipmunk's own sleeping produces.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import pymunk

from kge.components.rigidbody import BodyType, RigidBody
from kge.physics.cp import arbiter_handle, body_handle, constraint_handle, space_handle
from kge.physics.cp import ffi as _ffi
from kge.physics.cp import lib as _lib
from kge.physics.cp.handles import body_shapes, shape_space
from kge.physics.mass import ZERO, MassData
from kge.physics.tiny import flush

DYNAMIC = pymunk.Body.DYNAMIC
KINEMATIC = pymunk.Body.KINEMATIC
STATIC = pymunk.Body.STATIC

PYMUNK_TYPE = {
    BodyType.DYNAMIC: DYNAMIC,
    BodyType.KINEMATIC: KINEMATIC,
    BodyType.STATIC: STATIC,
}


class BodyRecord:
    """One simulated body: its pymunk Body, the collider entities on it and kge's
    per-body state (kept here, not on the pymunk object)."""

    __slots__ = (
        "applied", "awake", "body", "bullet", "colliders", "enabled", "entity", "implicit",
        "in_space", "mass",
    )

    def __init__(self, entity: int, body: pymunk.Body, implicit: bool) -> None:
        self.entity = entity
        self.body = body
        self.implicit = implicit
        #: what kge last saw of the body's sleep; a different RigidBody.awake is a user request
        self.awake = True
        #: RigidBody.bullet as last applied
        self.bullet = False
        self.colliders: set[int] = set()
        self.enabled = True
        self.in_space = False
        self.mass: MassData = ZERO
        #: the RigidBody fields the mass data and continuous collision were last
        #: built from (type, enabled, mass, fixed_rotation, bullet)
        self.applied: tuple[Any, ...] | None = None

    @property
    def event_body(self) -> int | None:
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

    Runs once per spawned body, so it writes through Chipmunk's setters directly:
    pymunk routes every Python-level attribute write through a ``__setattr__`` of its own.
    """
    if kind is BodyType.DYNAMIC:
        body = pymunk.Body(1.0, math.inf)
    else:
        body = pymunk.Body(body_type=PYMUNK_TYPE[kind])
    cp = body_handle(body)
    _lib.cpBodySetPosition(cp, (flush(x), flush(y)))
    _lib.cpBodySetAngle(cp, flush(angle))
    return body


def set_body_type(body: pymunk.Body, body_type: int) -> None:
    """Change a body's type between steps, even while it has joints or sleeping neighbours.

    Out of a space ``cpBodySetType`` only rewrites the mass fields. In a space it
    would also move the body between arrays and spatial indexes in place, which
    leaves the contact graph inconsistent (see the module docstring), so the body
    leaves the space first (:func:`take_out`: its neighbours are woken, its
    contacts end and its constraints come out) and returns with its shapes. The
    caller puts back the constraints that still act (the joint bridge's
    ``refresh_membership``). pymunk's own setter would also refuse a joint between
    two non-dynamic bodies, which Box2D allows (such a joint simply does nothing).
    """
    space = body.space
    if space is None:
        _lib.cpBodySetType(body_handle(body), body_type)
        return
    shapes = take_out(space, body)
    _lib.cpBodySetType(body_handle(body), body_type)
    space.add(body, *shapes)


def _constraint_in(space: pymunk.Space, c: pymunk.Constraint) -> bool:
    """Is ``c`` in ``space`` (O(1); ``space.constraints`` builds a list)?"""
    return bool(_lib.cpConstraintGetSpace(constraint_handle(c)) == space_handle(space))


def neighbours(space: pymunk.Space, body: pymunk.Body) -> list[pymunk.Body]:
    """Non-static bodies touching ``body`` (its arbiters) or jointed to it in ``space``."""
    found: dict[pymunk.Body, None] = {}
    cp = body_handle(body)
    a_p, b_p = _ffi.new("cpBody *[1]"), _ffi.new("cpBody *[1]")
    get_bodies, get_type = _lib.cpArbiterGetBodies, _lib.cpBodyGetType
    get_data, from_handle = _lib.cpBodyGetUserData, _ffi.from_handle

    def visit(arb: pymunk.Arbiter) -> None:
        # what arb.bodies gives, through Chipmunk's getters (pymunk's goes through both
        # shapes and their weak body references): the body's user data is its handle
        get_bodies(arbiter_handle(arb), a_p, b_p)
        a = a_p[0]
        other = b_p[0] if a == cp else a
        if get_type(other) != STATIC:
            found[from_handle(get_data(other))] = None

    body.each_arbiter(visit)
    for c in list(body.constraints):
        if _constraint_in(space, c):
            other = c.b if c.a is body else c.a
            if other.body_type != STATIC:
                found[other] = None
    found.pop(body, None)
    return list(found)


def take_out(space: pymunk.Space, body: pymunk.Body) -> list[pymunk.Shape]:
    """Remove ``body``, its shapes and its constraints from ``space``; returns the shapes.

    Everything around it is woken first: removing a shape only releases the
    arbiters Chipmunk has cached, and a sleeping neighbour's arbiters are parked
    outside the cache until it wakes, so they would outlive the shape.
    """
    wake_neighbours(body)
    shapes = [s for s in body.shapes if s.space is space]
    constraints = [c for c in list(body.constraints) if _constraint_in(space, c)]
    space.remove(*shapes, *constraints)
    space.remove(body)
    return shapes


#: the largest acceleration gravity (scaled) gives a body, m/s^2: a speed gained in one
#: substep beyond any speed cap, and small enough that squares of speeds stay finite
#: (a gravity scale of 1e308 made it inf, and the speed cap's inf * 0 a NaN pose)
MAX_GRAVITY = 1e12


def scaled_gravity(gx: float, gy: float, scale: float) -> tuple[float, float]:
    """``scale * (gx, gy)``, shortened to at most ``MAX_GRAVITY`` (direction kept).

    >>> scaled_gravity(0.0, -10.0, 2.0)
    (0.0, -20.0)
    >>> scaled_gravity(0.0, -1e308, 10.0)
    (0.0, -1000000000000.0)
    """
    n = math.hypot(gx, gy)
    if n == 0.0 or scale == 0.0:
        return 0.0, 0.0
    # compare the lengths in logarithms: n * scale itself may overflow to inf
    if math.log(n) + math.log(abs(scale)) <= math.log(MAX_GRAVITY):
        return gx * scale, gy * scale
    k = math.copysign(MAX_GRAVITY, scale) / n
    return gx * k, gy * k


class Box2DVelocity:
    """A body's velocity_func with gravity scale and Box2D damping (factors per substep).

    Box2D: ``v' = lin * (v + dt * (g + f/m))`` and ``w' = ang * (w + dt * t/I)``.
    Chipmunk's integrator gives ``v' = d * v + dt * (g' + f/m)`` and ``w' = d * w +
    dt * t/I`` for a damping ``d`` and gravity ``g'`` of our choosing: with ``d =
    ang`` and ``g'`` taking up the rest of the linear result, both are Box2D's
    when no torque acts, without a velocity setter (each one restarts the body's
    sleep clock, so damped bodies never slept). With a torque (whose setter woke
    the body anyway) the result is damped after the integration.
    """

    __slots__ = ("ang", "lin", "scale")

    def __init__(self, scale: float, lin: float, ang: float) -> None:
        self.scale, self.lin, self.ang = scale, lin, ang

    def __call__(
        self, body: pymunk.Body, gravity: pymunk.Vec2d, damping: float, dt: float
    ) -> None:
        if body.body_type == DYNAMIC:
            _box2d_velocity(body, gravity, dt, self.scale, self.lin, self.ang)


def _box2d_velocity(
    body: pymunk.Body, gravity: pymunk.Vec2d, dt: float, scale: float, lin: float, ang: float
) -> None:
    gx, gy = scaled_gravity(gravity.x, gravity.y, scale)
    if body.torque == 0.0:
        v, f, inv_mass = body.velocity, body.force, 1.0 / body.mass
        g = (
            (lin - ang) * v.x / dt + lin * gx + (lin - 1.0) * f.x * inv_mass,
            (lin - ang) * v.y / dt + lin * gy + (lin - 1.0) * f.y * inv_mass,
        )
        pymunk.Body.update_velocity(body, g, ang, dt)
        return
    pymunk.Body.update_velocity(body, (gx, gy), 1.0, dt)
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
        if isinstance(body.velocity_func, Box2DVelocity):
            body.velocity_func = pymunk.Body.update_velocity
        return
    lin = max(0.0, 1.0 - rb.linear_damping * dt) ** (1.0 / substeps)
    ang = max(0.0, 1.0 - rb.angular_damping * dt) ** (1.0 / substeps)
    body.velocity_func = Box2DVelocity(rb.gravity_scale, lin, ang)


def can_sleep(space: pymunk.Space, body: pymunk.Body) -> bool:
    """True when ``body.sleep()`` is safe (it aborts the process otherwise)."""
    return (
        math.isfinite(space.sleep_time_threshold)
        and body.body_type == DYNAMIC
        and body.space is space
        and not body.is_sleeping
    )


def sleep_island(
    space: pymunk.Space,
    body: pymunk.Body,
    wants_sleep: Callable[[pymunk.Body], bool],
    looked: set[pymunk.Body] | None = None,
) -> list[pymunk.Body]:
    """Put ``body`` and the awake bodies connected to it to sleep, when that is safe.

    The island is every awake body reachable from ``body`` through contacts and
    joints (static bodies end a path). It sleeps only if every other awake member
    ``wants_sleep``, no member touches or is jointed to a kinematic body, and the
    sleeping bodies it touches form one component (which it joins): then the
    parked arbiters and constraints are exactly those of Chipmunk's own sleeping.
    Otherwise nothing sleeps (Box2D's island solver would wake the body again at
    the next step) and ``[]`` is returned; else the bodies put to sleep. ``looked``,
    when given, collects every body the search looked at (a caller trying many
    bodies of one island need not search it again).
    """
    if not can_sleep(space, body):
        return []
    island = [body]
    seen = {body}
    try:
        return _sleep_island(space, body, wants_sleep, island, seen)
    finally:
        if looked is not None:
            looked.update(seen)


def _sleep_island(
    space: pymunk.Space,
    body: pymunk.Body,
    wants_sleep: Callable[[pymunk.Body], bool],
    island: list[pymunk.Body],
    seen: set[pymunk.Body],
) -> list[pymunk.Body]:
    sleepers: list[pymunk.Body] = []
    for member in island:  # grows while it is walked: a breadth-first search
        for other in neighbours(space, member):
            if other in seen:
                continue
            seen.add(other)
            if other.body_type != DYNAMIC or other.space is not space:
                return []
            if other.is_sleeping:
                sleepers.append(other)
            elif wants_sleep(other) and can_sleep(space, other):
                island.append(other)
            else:
                return []
    if sleepers and not _one_component(space, sleepers):
        return []
    group = sleepers[0] if sleepers else None
    for member in island:
        member.velocity = (0.0, 0.0)
        member.angular_velocity = 0.0
        if group is None:
            member.sleep()
            group = member
        else:
            member.sleep_with_group(group)
    return island


def _one_component(space: pymunk.Space, sleepers: list[pymunk.Body]) -> bool:
    """Do the sleeping ``sleepers`` belong to one sleeping component?

    Chipmunk does not expose a component's root; but kge only ever makes
    components that are connected through contacts and joints, as Chipmunk's
    flood fill does, so connectivity over sleeping bodies decides it.
    """
    want = set(sleepers)
    reached = {sleepers[0]}
    todo = [sleepers[0]]
    while todo and not want <= reached:
        for other in neighbours(space, todo.pop()):
            if other not in reached and other.is_sleeping:
                reached.add(other)
                todo.append(other)
    return want <= reached


def woken_with(
    space: pymunk.Space, body: pymunk.Body, seen_awake: Callable[[pymunk.Body], bool]
) -> list[pymunk.Body]:
    """The bodies Chipmunk woke together with ``body`` that kge still takes for sleepers.

    Waking one body of a sleeping component wakes the whole component (Box2D: the
    next step's island solve wakes every body of the island). kge learns of a wake
    in sync-out from a body's motion, so a woken body that does not move (held by a
    joint, no gravity) would keep reading asleep. The component is every body
    reached from ``body`` through contacts and joints that Chipmunk has awake and
    kge last saw asleep (``seen_awake`` False: kge's own record of the body).
    """
    found: list[pymunk.Body] = []
    seen = {body}
    todo = [body]
    while todo:
        for other in neighbours(space, todo.pop()):
            if other in seen:
                continue
            seen.add(other)
            if other.body_type == DYNAMIC and not other.is_sleeping and not seen_awake(other):
                found.append(other)
                todo.append(other)
    return found


def wake_neighbours(body: pymunk.Body) -> None:
    """Wake ``body`` and every dynamic body touching or jointed to it.

    Called before anything of ``body`` leaves the space or changes: see
    :func:`take_out`.
    """
    space = body.space
    if body.body_type == DYNAMIC:
        if not body.is_sleeping:
            # Nothing around an awake dynamic body sleeps: the step that made a contact
            # or a joint's island woke both sides (cpSpaceProcessComponents), and waking
            # a sleeper wakes its whole island. Walking the arbiters in Python was most
            # of a despawn; Box2D's SetAwake(true) leaves awake bodies' timers alone too.
            return
        body.activate()
    if space is None:
        return
    for other in neighbours(space, body):
        if other.body_type == DYNAMIC:
            other.activate()
    if body.body_type != DYNAMIC:
        wake_sleepers_on(space, body)


def wake_sleepers_on(space: pymunk.Space, body: pymunk.Body) -> None:
    """Wake the sleeping dynamic bodies whose shapes overlap the static or kinematic
    ``body``'s shapes, contact or not.

    A body put to sleep with no contact computed (restored asleep from a snapshot, or
    ``awake=False`` at spawn) has no arbiter with what holds it up, so
    :func:`neighbours` does not find it; Box2D wakes the bodies touching a fixture or
    body that is destroyed, and without this one would hover where its floor was.
    """
    for shape in body_shapes(body):
        if shape_space(shape) is not space:
            continue
        for hit in space.bb_query(shape.bb, pymunk.ShapeFilter()):
            other = hit.body
            if other is not None and other.body_type == DYNAMIC and other.is_sleeping:
                other.activate()


def set_mass(body: pymunk.Body, md: MassData) -> None:
    """Give a dynamic body kge's mass data (Chipmunk's setters directly: once per new body).

    ``md`` comes from :func:`kge.physics.mass.dynamic_mass`: 0 < mass < inf and
    inertia > 0 (inf for no rotation), the values pymunk's setters assert.

    The body's origin stays where it is and its centre of mass moves, as in Box2D's
    ``ResetMassData`` (which also gives the centre the velocity of its new point,
    ``v += ω × Δc``). Chipmunk does the opposite: it keeps the centre's world
    position and its next step redraws the origin around it, so a body spawned at
    rest with an off-centre shape jumped by its centre's offset on its first step.
    """
    cp = body_handle(body)
    cog = _lib.cpBodyGetCenterOfGravity(cp)
    if (
        _lib.cpBodyGetMass(cp) == md.mass
        and _lib.cpBodyGetMoment(cp) == md.inertia
        and (cog.x, cog.y) == (md.center[0], md.center[1])
    ):
        return  # unchanged: Chipmunk's setters would wake the body (and its island) for nothing
    _lib.cpBodySetMass(cp, md.mass)
    _lib.cpBodySetMoment(cp, md.inertia)
    if (cog.x, cog.y) == (md.center[0], md.center[1]):
        return
    origin = _lib.cpBodyGetPosition(cp)  # from the transform: still the old centre's
    old = _lib.cpBodyLocalToWorld(cp, cog)
    _lib.cpBodySetCenterOfGravity(cp, md.center)
    _lib.cpBodySetPosition(cp, origin)  # the centre is placed from the origin again
    w = _lib.cpBodyGetAngularVelocity(cp)
    if w:
        new = _lib.cpBodyLocalToWorld(cp, md.center)
        v = _lib.cpBodyGetVelocity(cp)
        _lib.cpBodySetVelocity(cp, (v.x - w * (new.y - old.y), v.y + w * (new.x - old.x)))
