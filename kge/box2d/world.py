"""``b2World``: pybox2d's world, running on a kge :class:`~kge.world.World`.

Underneath each ``b2World`` is a kge World with the physics system attached:
bodies are entities with ``Transform`` + ``RigidBody``, fixtures are entities
with a ``Collider`` naming their body, joints are joint-component entities.
``Step`` runs one kge physics step, so every Box2D rule kge implements
(friction and restitution mixing, filtering, sleeping after 0.5 s at rest,
speed limits, CCD) applies unchanged.

Iterations: Box2D solves velocities ``velocityIterations`` times per step and
then corrects positions ``positionIterations`` times. pymunk (Chipmunk) has one
iterative solver that fixes overlap through bias velocities, and kge splits each
step into ``PhysicsSettings.substeps`` (4) pymunk steps. ``Step(dt, v, p)`` sets
pymunk's iterations per substep to ``v`` (so Box2D's 8 gives 4 x 8 = 32 solver
passes per step, close to kge's tuned default of 4 x 10), and uses
``p`` only as a switch: 0 position iterations turns off overlap correction in
Box2D, which pymunk cannot do, so it is accepted and ignored.

Listeners: kge records contact begin/end events while it steps and
``Step`` hands them to ``contactListener.BeginContact`` / ``EndContact`` when the
step's solve is over, in each pair's own order; ``PreSolve`` / ``PostSolve`` run
inside the step (through kge's per-contact hooks, switched on only when the
listener overrides them, because a Python call per contact per step is the
most expensive thing a physics scene can do). The world is locked during all
of them: creating or destroying anything raises
:class:`~kge.errors.WorldLockedError`.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable
from typing import Any

from kge.box2d.body import b2Body, b2BodyDef
from kge.box2d.broadphase import b2ContactManager
from kge.box2d.callbacks import (
    b2ContactFilter,
    b2ContactListener,
    b2DestructionListener,
    b2QueryCallback,
    b2RayCastCallback,
    overrides,
)
from kge.box2d.constants import b2_dynamicBody, b2_kinematicBody, b2_staticBody
from kge.box2d.contact import b2Contact, impulse_of
from kge.box2d.errors import KeywordError, LockedError, MissingError
from kge.box2d.fixture import b2Fixture, b2FixtureDef
from kge.box2d.joints import JOINT_CLASSES, b2GearJoint, b2GearJointDef, b2Joint, b2JointDef
from kge.box2d.joints import b2DistanceJointDef as _Distance
from kge.box2d.joints import b2FrictionJointDef as _Friction
from kge.box2d.joints import b2MotorJointDef as _Motor
from kge.box2d.joints import b2MouseJointDef as _Mouse
from kge.box2d.joints import b2PrismaticJointDef as _Prismatic
from kge.box2d.joints import b2PulleyJointDef as _Pulley
from kge.box2d.joints import b2RevoluteJointDef as _Revolute
from kge.box2d.joints import b2RopeJointDef as _Rope
from kge.box2d.joints import b2WeldJointDef as _Weld
from kge.box2d.joints import b2WheelJointDef as _Wheel
from kge.box2d.transform import b2AABB
from kge.box2d.vec import as_xy, b2Vec2
from kge.errors import ComponentTypeError, ValidationError
from kge.physics.contacts import PostSolve, PreSolve
from kge.physics.events import PhysicsEvents
from kge.physics.resource import Physics
from kge.physics.settings import PhysicsSettings
from kge.systems.physics import PhysicsSystem
from kge.validate import finite
from kge.world import World

Pair = tuple[int, int]

#: fewest pymunk substeps per step (kge's default: they stand in for Box2D's
#: position iterations, which pymunk lacks)
MIN_SUBSTEPS = 4
#: most pymunk substeps per step
MAX_SUBSTEPS = 8
#: solver passes per substep that a Box2D-like load needs before a substep is added
PASSES_PER_SUBSTEP = 23
#: fewest solver passes per substep
MIN_ITERATIONS = 8


def solver_counts(velocity_iterations: int) -> tuple[int, int]:
    """(pymunk substeps, iterations per substep) for Box2D's velocity iteration count.

    Box2D makes ``velocity_iterations`` solver passes per step; kge makes
    ``substeps x iterations``. Up to 4 x 8 the passes are kge's (few iterations
    stack badly in pymunk, which has no position pass); above, the passes are
    Box2D's, split into up to 8 substeps of about 23 (8 -> 4 x 8, 60 -> 4 x 15,
    180 -> 8 x 23: Gymnasium's 6*30 runs 184 passes).
    """
    v = max(1, velocity_iterations)
    substeps = max(MIN_SUBSTEPS, min(MAX_SUBSTEPS, -(-v // PASSES_PER_SUBSTEP)))
    return substeps, max(MIN_ITERATIONS, -(-v // substeps))


class b2World:
    """The physics world: bodies, joints, contacts, listeners, Step and queries."""

    def __init__(self, gravity: Any = (0.0, -10.0), doSleep: bool = True, **kwargs: Any) -> None:
        self._kworld = World()
        self._settings = self._kworld.insert_resource(
            PhysicsSettings(gravity=as_xy(gravity, "b2World", "gravity"), sleep=bool(doSleep),
                            iterated_hinges=True)
        )
        self._system = PhysicsSystem()
        self._kworld.add_system(self._system)
        self._physics: Physics = self._kworld.resource(Physics)
        self._events: PhysicsEvents = self._system.events  # the step's record
        self._bodies: dict[int, b2Body] = {}
        self._fixtures: dict[int, b2Fixture] = {}
        self._joints: dict[int, b2Joint] = {}
        self._contacts: dict[Pair, b2Contact] = {}
        #: contacts a pre-solve saw before their begin was delivered (same object later)
        self._pending: dict[Pair, b2Contact] = {}
        self._locked = False
        self._hooks = False  # colliders hooked for pre/post-solve
        self._hooked: set[str] = set()  # which of PreSolve, PostSolve kge calls back
        self._contactListener: b2ContactListener | None = None
        self._contactFilter: b2ContactFilter | None = None
        self.destructionListener: b2DestructionListener | None = None
        self.autoClearForces = True
        self.warmStarting = True
        self.continuousPhysics = True
        self.subStepping = False
        self.renderer: Any = None
        self._steps = 0  # Steps taken (the broad phase view updates once per step)
        self._fixture_changes = 0  # fixtures created or destroyed so far
        self._contact_manager: b2ContactManager | None = None
        for name, value in kwargs.items():
            if not hasattr(type(self), name) and name not in self.__dict__:
                raise KeywordError(f"b2World has no property {name!r}")
            setattr(self, name, value)

    # -- world settings --------------------------------------------------------------------
    @property
    def kge_world(self) -> World:
        """The kge World underneath (for mixing kge components with pybox2d code)."""
        return self._kworld

    @property
    def gravity(self) -> b2Vec2:
        return b2Vec2(*self._settings.gravity)

    @gravity.setter
    def gravity(self, value: Any) -> None:
        self._settings.gravity = as_xy(value, "b2World", "gravity")

    @property
    def allowSleeping(self) -> bool:
        return self._settings.sleep

    @allowSleeping.setter
    def allowSleeping(self, value: bool) -> None:
        self._settings.sleep = bool(value)

    doSleep = allowSleeping

    @property
    def locked(self) -> bool:
        return self._locked

    def _unlocked(self, op: str) -> None:
        if self._locked:
            raise LockedError(
                f"{op}: the world is locked (called from inside Step or a callback)")

    # -- listeners -----------------------------------------------------------------------------
    @property
    def contactListener(self) -> b2ContactListener | None:
        return self._contactListener

    @contactListener.setter
    def contactListener(self, listener: b2ContactListener | None) -> None:
        if listener is not None and not isinstance(listener, b2ContactListener):
            raise ComponentTypeError(
                f"b2World.contactListener must be a b2ContactListener or None, got {listener!r}")
        self._contactListener = listener
        self._sync_hooks(listener)

    def _sync_hooks(self, listener: b2ContactListener | None) -> None:
        """Hook kge's per-contact pre/post-solve for what ``listener`` overrides, and only
        that: a Python call per contact per step is what costs most (PreSolve and PostSolve
        separately; colliders are hooked while either is)."""
        wanted = {name for name in ("PreSolve", "PostSolve")
                  if listener is not None and overrides(listener, b2ContactListener, name)}
        hooks: dict[str, tuple[Callable[[Any], None], Callable[[Any], Any]]] = {
            "PreSolve": (self._pre_solve, self._physics.on_pre_solve),
            "PostSolve": (self._post_solve, self._physics.on_post_solve)}
        for name, (fn, register) in hooks.items():
            if name in wanted and name not in self._hooked:
                register(fn)
            elif name not in wanted and name in self._hooked:
                self._physics.remove_hook(fn)
        self._hooked = wanted
        if bool(wanted) != self._hooks:
            self._hooks = bool(wanted)
            for f in self._fixtures.values():
                f._col.contact_hooks = self._hooks

    @property
    def contactFilter(self) -> b2ContactFilter | None:
        return self._contactFilter

    @contactFilter.setter
    def contactFilter(self, flt: b2ContactFilter | None) -> None:
        if flt is not None and not isinstance(flt, b2ContactFilter):
            raise ComponentTypeError(
                f"b2World.contactFilter must be a b2ContactFilter or None, got {flt!r}")
        self._contactFilter = flt
        self._physics.contact_filter = None if flt is None else self._should_collide

    def _should_collide(self, ca: int, cb: int) -> bool:
        flt, fa, fb = self._contactFilter, self._fixtures.get(ca), self._fixtures.get(cb)
        if flt is None or fa is None or fb is None:
            return True
        locked, self._locked = self._locked, True
        try:
            return bool(flt.ShouldCollide(fa, fb))
        finally:
            self._locked = locked

    # -- bodies --------------------------------------------------------------------------------
    @property
    def bodies(self) -> list[b2Body]:
        """Oldest first, as pybox2d's list."""
        return list(self._bodies.values())

    @property
    def bodyCount(self) -> int:
        return len(self._bodies)

    def CreateBody(self, defn: b2BodyDef | None = None, **kwargs: Any) -> b2Body:
        self._unlocked("CreateBody")
        if defn is None:
            defn = b2BodyDef(**kwargs)
        elif kwargs or not isinstance(defn, b2BodyDef):
            raise ComponentTypeError("CreateBody takes a b2BodyDef or keywords, not both")
        tf, rb = defn.components()  # checked before anything is created
        entity = self._kworld.spawn(tf, rb)
        body = b2Body(self, entity, tf, rb, defn.userData)
        self._bodies[entity] = body
        try:
            if defn.fixtures is not None:
                fixtures = defn.fixtures
                for fd in fixtures if isinstance(fixtures, (list, tuple)) else [fixtures]:
                    body.CreateFixture(fd)
            if defn.shapes is not None:
                body.CreateFixturesFromShapes(defn.shapes, defn.shapeFixture)
        except Exception:
            self.DestroyBody(body)  # bad fixtures leave no half-built body behind
            raise
        return body

    def _typed(self, kind: int, defn: b2BodyDef | None, kwargs: dict[str, Any]) -> b2Body:
        if defn is None:
            defn = b2BodyDef(**kwargs)
        elif kwargs:
            raise ComponentTypeError("give a b2BodyDef or keywords, not both")
        defn.type = kind
        return self.CreateBody(defn)

    def CreateDynamicBody(self, defn: b2BodyDef | None = None, **kwargs: Any) -> b2Body:
        return self._typed(b2_dynamicBody, defn, kwargs)

    def CreateStaticBody(self, defn: b2BodyDef | None = None, **kwargs: Any) -> b2Body:
        return self._typed(b2_staticBody, defn, kwargs)

    def CreateKinematicBody(self, defn: b2BodyDef | None = None, **kwargs: Any) -> b2Body:
        return self._typed(b2_kinematicBody, defn, kwargs)

    def DestroyBody(self, body: b2Body) -> None:
        self._unlocked("DestroyBody")
        if not isinstance(body, b2Body) or body._world is not self:
            raise ValidationError(f"DestroyBody: {body!r} is not a body of this world")
        if body._destroyed:
            raise ValidationError(f"DestroyBody: body (entity {body.entity}) was already destroyed")
        goodbye = self.destructionListener
        for joint in list(body._joints)[::-1]:
            if goodbye is not None and not joint._destroyed:
                goodbye.SayGoodbye(joint)
            if not joint._destroyed:
                self._destroy_joint(joint)
        for fixture in list(body._fixtures)[::-1]:
            if goodbye is not None:
                goodbye.SayGoodbye(fixture)
            self._destroy_fixture(fixture)
        body._destroyed = True
        del self._bodies[body.entity]
        self._kworld.despawn(body.entity)
        self._kworld.flush()

    # -- fixtures ------------------------------------------------------------------------------
    def _create_fixture(self, body: b2Body, defn: b2FixtureDef) -> b2Fixture:
        self._unlocked("CreateFixture")
        col, shape = defn.to_collider(body.entity)
        if self._hooks:
            col.contact_hooks = True
        entity = self._kworld.spawn(col)
        fixture = b2Fixture(body, entity, col, shape, defn.userData, defn.density)
        self._fixtures[entity] = fixture
        body._fixtures.append(fixture)
        self._fixture_changes += 1
        body._mass_changed()
        return fixture

    def _destroy_fixture(self, fixture: b2Fixture) -> None:
        self._unlocked("DestroyFixture")
        if fixture._destroyed:
            raise ValidationError(
                f"DestroyFixture: fixture (entity {fixture.entity}) was already destroyed")
        listener = self._contactListener
        for key, contact in list(self._contacts.items()):
            if fixture.entity in key:
                del self._contacts[key]
                if listener is not None:
                    self._call(listener.EndContact, contact)
        fixture._destroyed = True
        self._fixture_changes += 1
        fixture.body._fixtures.remove(fixture)
        del self._fixtures[fixture.entity]
        self._kworld.despawn(fixture.entity)
        self._kworld.flush()
        if not fixture.body._destroyed:
            fixture.body._mass_changed()

    # -- joints --------------------------------------------------------------------------------
    @property
    def joints(self) -> list[b2Joint]:
        """Oldest first, as pybox2d's list."""
        return list(self._joints.values())

    @property
    def jointCount(self) -> int:
        return len(self._joints)

    def CreateJoint(self, defn: b2JointDef | None = None, **kwargs: Any) -> b2Joint:
        """A joint from a definition, or from keywords with ``type=`` naming the joint
        (its class or its definition's class), as pybox2d accepts."""
        self._unlocked("CreateJoint")
        if defn is None:
            kind = kwargs.pop("type", None)
            if isinstance(kind, type) and issubclass(kind, b2Joint):
                kind = kind.DEF
            if not (isinstance(kind, type) and kind in JOINT_CLASSES):
                raise MissingError(
                    "CreateJoint needs a joint definition, or type=<joint or definition class> "
                    f"and keywords; got type={kind!r}")
            defn = kind(**kwargs)
        elif kwargs:
            raise ComponentTypeError("CreateJoint takes a definition or keywords, not both")
        if not isinstance(defn, b2JointDef) or type(defn) not in JOINT_CLASSES:
            raise ComponentTypeError(f"CreateJoint needs a b2*JointDef, got {defn!r}")
        for name in ("bodyA", "bodyB"):
            b = getattr(defn, name)
            if isinstance(b, b2Body) and (b._destroyed or b._world is not self):
                raise ValidationError(f"CreateJoint: {name} is not a live body of this world")
        comp = defn.component(self)  # checked before anything is created
        entity = self._kworld.spawn(comp)
        cls = JOINT_CLASSES[type(defn)]
        if isinstance(defn, b2GearJointDef):
            j1, j2 = defn.joint1, defn.joint2
            assert j1 is not None and j2 is not None
            joint: b2Joint = b2GearJoint(self, entity, comp, j1.bodyB, j2.bodyB, defn.userData,
                                         joint1=j1, joint2=j2)
        else:
            a, b = defn._bodies()
            joint = cls(self, entity, comp, a, b, defn.userData)
        self._joints[entity] = joint
        joint.bodyA._joints.append(joint)
        joint.bodyB._joints.append(joint)
        return joint

    def _create(self, cls: type[b2JointDef], kwargs: dict[str, Any]) -> b2Joint:
        kind = kwargs.pop("type", cls.TYPE)
        if kind not in (cls.TYPE, cls, JOINT_CLASSES[cls]):
            raise ComponentTypeError(
                f"Create{cls.__name__[2:-3]}: type={kind!r} names another joint")
        return self.CreateJoint(cls(**kwargs))

    def CreateRevoluteJoint(self, **kw: Any) -> b2Joint:
        return self._create(_Revolute, kw)

    def CreatePrismaticJoint(self, **kw: Any) -> b2Joint:
        return self._create(_Prismatic, kw)

    def CreateDistanceJoint(self, **kw: Any) -> b2Joint:
        return self._create(_Distance, kw)

    def CreateRopeJoint(self, **kw: Any) -> b2Joint:
        return self._create(_Rope, kw)

    def CreateWeldJoint(self, **kw: Any) -> b2Joint:
        return self._create(_Weld, kw)

    def CreateWheelJoint(self, **kw: Any) -> b2Joint:
        return self._create(_Wheel, kw)

    def CreateFrictionJoint(self, **kw: Any) -> b2Joint:
        return self._create(_Friction, kw)

    def CreateMotorJoint(self, **kw: Any) -> b2Joint:
        return self._create(_Motor, kw)

    def CreateMouseJoint(self, **kw: Any) -> b2Joint:
        return self._create(_Mouse, kw)

    def CreatePulleyJoint(self, **kw: Any) -> b2Joint:
        return self._create(_Pulley, kw)

    def CreateGearJoint(self, **kw: Any) -> b2Joint:
        return self._create(b2GearJointDef, kw)

    def DestroyJoint(self, joint: b2Joint) -> None:
        self._unlocked("DestroyJoint")
        if not isinstance(joint, b2Joint) or joint._world is not self:
            raise ValidationError(f"DestroyJoint: {joint!r} is not a joint of this world")
        if joint._destroyed:
            raise ValidationError(
                f"DestroyJoint: joint (entity {joint.entity}) was already destroyed")
        self._destroy_joint(joint)

    def _destroy_joint(self, joint: b2Joint) -> None:
        # a gear on this joint goes first (Box2D leaves it dangling; kge removes it)
        for other in list(self._joints.values()):
            if isinstance(other, b2GearJoint) and joint in (other.joint1, other.joint2):
                if self.destructionListener is not None:
                    self.destructionListener.SayGoodbye(other)
                self._destroy_joint(other)
        joint._destroyed = True
        del self._joints[joint.entity]
        for body in (joint.bodyA, joint.bodyB):
            if joint in body._joints:
                body._joints.remove(joint)
        self._kworld.despawn(joint.entity)
        self._kworld.flush()

    # -- contacts ------------------------------------------------------------------------------
    def _contact_list(self) -> list[b2Contact]:
        return list(self._contacts.values())

    @property
    def contacts(self) -> list[b2Contact]:
        return self._contact_list()

    @property
    def contactCount(self) -> int:
        return len(self._contacts)

    @property
    def proxyCount(self) -> int:
        return sum(f.shape.childCount for f in self._fixtures.values())

    # -- stepping ------------------------------------------------------------------------------
    def Step(self, timeStep: float, velocityIterations: int, positionIterations: int) -> None:
        """Advance by ``timeStep`` seconds (see the module notes for the iteration counts)."""
        self._unlocked("Step")
        dt = finite(timeStep, "b2World.Step", "timeStep")
        if dt < 0.0:
            raise ValidationError(f"b2World.Step: timeStep must be >= 0, got {dt!r}")
        for name, n in (("velocityIterations", velocityIterations),
                        ("positionIterations", positionIterations)):
            if isinstance(n, bool) or not isinstance(n, int) or n < 0:
                raise ValidationError(f"b2World.Step: {name} must be an int >= 0, got {n!r}")
        if dt == 0.0:
            return
        substeps, iterations = solver_counts(velocityIterations)
        st = self._settings
        if st.iterations != iterations or st.substeps != substeps:
            st.iterations = iterations
            st.substeps = substeps
        self._system.sim.joints.position_iterations = max(1, positionIterations)
        self._locked = True
        try:
            self._system.process(dt)
        finally:
            self._locked = False
            self._steps += 1
        self._deliver()

    def _deliver(self) -> None:
        """Update the contact table from the step's events and call the listener."""
        ev = self._events
        if not (ev.contact_begin or ev.contact_end or ev.sensor_begin or ev.sensor_end):
            return
        # per pair, its begins and ends in alternation starting from the state before
        counts: dict[Pair, list[Any]] = {}
        e: Any
        for e in (*ev.contact_begin, *ev.sensor_begin):
            key = (e.collider_a, e.collider_b) if e.collider_a < e.collider_b else (
                e.collider_b, e.collider_a)
            counts.setdefault(key, [0, 0, e])[0] += 1
        for e in (*ev.contact_end, *ev.sensor_end):
            key = (e.collider_a, e.collider_b) if e.collider_a < e.collider_b else (
                e.collider_b, e.collider_a)
            counts.setdefault(key, [0, 0, None])[1] += 1
        listener = self._contactListener
        fixtures, contacts = self._fixtures, self._contacts
        self._locked = True
        try:
            for key, (nb, ne, begin) in counts.items():
                touching = key in contacts
                for _ in range(nb + ne):
                    if touching:
                        contact = contacts.pop(key, None)
                        touching = False
                        if contact is not None and listener is not None:
                            contact.touching = False
                            listener.EndContact(contact)
                    else:
                        fa = fixtures.get(begin.collider_a) if begin is not None else None
                        fb = fixtures.get(begin.collider_b) if begin is not None else None
                        touching = True
                        if fa is None or fb is None:
                            continue  # destroyed since
                        contact = self._pending.pop(key, None) or b2Contact(fa, fb)
                        if hasattr(begin, "normal"):
                            contact._set_geometry(begin.normal, begin.points, begin.separation)
                        contacts[key] = contact
                        if listener is not None:
                            listener.BeginContact(contact)
        finally:
            self._locked = False
            self._pending.clear()

    def _contact_for(self, ca: int, cb: int) -> b2Contact | None:
        key = (ca, cb) if ca < cb else (cb, ca)
        contact = self._contacts.get(key)
        if contact is None:
            fa, fb = self._fixtures.get(ca), self._fixtures.get(cb)
            if fa is None or fb is None:
                return None
            # begun in this very step: the table gets this same object after the step
            contact = self._pending.get(key)
            if contact is None:
                contact = self._pending[key] = b2Contact(fa, fb)
        return contact

    def _pre_solve(self, pre: PreSolve) -> None:
        listener = self._contactListener
        if listener is None:
            return
        contact = self._contact_for(pre.collider_a, pre.collider_b)
        if contact is None:
            return
        contact._set_geometry(pre.normal, pre.points, pre.separation)
        contact.enabled = True
        listener.PreSolve(contact, contact._remember_manifold())
        pre.enabled = bool(contact.enabled)
        pre.tangent_speed = float(contact.tangentSpeed)
        if contact._friction is not None:
            pre.friction = contact._friction
        if contact._restitution is not None:
            pre.restitution = contact._restitution

    def _post_solve(self, post: PostSolve) -> None:
        listener = self._contactListener
        if listener is None:
            return
        contact = self._contact_for(post.collider_a, post.collider_b)
        if contact is None:
            return
        listener.PostSolve(contact, impulse_of(post.normal_impulse, post.tangent_impulse,
                                               post.point_count))

    def _call(self, fn: Any, *args: Any) -> None:
        locked, self._locked = self._locked, True
        try:
            fn(*args)
        finally:
            self._locked = locked

    def ClearForces(self) -> None:
        """kge clears applied forces after every step (Box2D's autoClearForces): nothing left."""

    # -- queries -------------------------------------------------------------------------------
    def RayCast(self, callback: b2RayCastCallback, point1: Any, point2: Any) -> None:
        """Report fixtures along ``point1 -> point2`` to ``callback.ReportFixture``."""
        if not callable(getattr(callback, "ReportFixture", None)):
            raise ComponentTypeError(f"RayCast needs a b2RayCastCallback, got {callback!r}")
        p1 = as_xy(point1, "RayCast", "point1")
        p2 = as_xy(point2, "RayCast", "point2")
        fixtures = self._fixtures

        def report(hit: Any) -> float:
            f = fixtures.get(hit.collider)
            if f is None:
                return -1.0
            r = callback.ReportFixture(f, b2Vec2(*hit.point), b2Vec2(*hit.normal), hit.fraction)
            return float(r)

        self._physics.raycast(p1, p2, report)

    def QueryAABB(self, callback: b2QueryCallback, aabb: b2AABB) -> None:
        """Report fixtures whose bounding boxes overlap ``aabb``; stop when it returns False."""
        if not callable(getattr(callback, "ReportFixture", None)):
            raise ComponentTypeError(f"QueryAABB needs a b2QueryCallback, got {callback!r}")
        if not isinstance(aabb, b2AABB):
            raise ComponentTypeError(f"QueryAABB needs a b2AABB, got {aabb!r}")
        fixtures = self._fixtures

        def report(hit: Any) -> bool:
            f = fixtures.get(hit.collider)
            return True if f is None else bool(callback.ReportFixture(f))

        self._physics.query_aabb(aabb.lowerBound.tuple, aabb.upperBound.tuple, report)

    # -- broad phase -----------------------------------------------------------------------------
    @property
    def contactManager(self) -> b2ContactManager:
        """The broad phase and contacts as pybox2d shows them (see kge.box2d.broadphase)."""
        if self._contact_manager is None:
            self._contact_manager = b2ContactManager(self)
        return self._contact_manager

    def GetTreeHeight(self) -> int:
        return self.contactManager.broadPhase.treeHeight

    def GetTreeBalance(self) -> int:
        return self.contactManager.broadPhase.treeBalance

    def GetTreeQuality(self) -> float:
        return self.contactManager.broadPhase.treeQuality

    def GetAllowSleeping(self) -> bool:
        return self.allowSleeping

    def SetAllowSleeping(self, flag: bool) -> None:
        self.allowSleeping = flag

    # -- misc ----------------------------------------------------------------------------------
    def DrawDebugData(self) -> None:
        """Draw the world through ``world.renderer`` (a :class:`~kge.box2d.draw.b2Draw`),
        as Box2D's b2World::DrawDebugData does; nothing without a renderer."""
        renderer = self.renderer
        if renderer is None:
            return
        from kge.box2d.draw import b2Draw, draw_debug_data

        if not isinstance(renderer, b2Draw):
            raise ComponentTypeError(f"b2World.renderer must be a b2Draw, got {renderer!r}")
        draw_debug_data(self, renderer)

    def __repr__(self) -> str:
        return (f"b2World(gravity={self.gravity!r}, bodies={len(self._bodies)}, "
                f"joints={len(self._joints)}, contacts={len(self._contacts)})")

    def __del__(self) -> None:
        with contextlib.suppress(Exception):
            self._kworld.close()
