"""Bodies: ``b2BodyDef`` and ``b2Body`` (a kge entity with Transform and RigidBody).

A ``b2Body`` keeps references to its entity's ``Transform`` and ``RigidBody``
components, which the physics system rewrites after every step; so reading
``body.position`` or ``body.linearVelocity`` costs an attribute read, and
writing one is an ordinary kge component write (a teleport, a velocity change
that wakes the body). Forces, impulses, mass data and coordinate helpers go
through the world's :class:`kge.Physics` resource, which checks them.

The same ``b2Body`` object is returned wherever the body appears (contacts,
fixtures, joints, ``world.bodies``), so ``==`` and hashing by identity behave as
pybox2d's pointer comparisons do, and programs may store attributes on it.
"""

from __future__ import annotations

import itertools
import math
from typing import TYPE_CHECKING, Any

from kge.box2d.constants import b2_dynamicBody, b2_kinematicBody, b2_staticBody
from kge.box2d.errors import MissingError, b2AssertException
from kge.box2d.fixture import b2Fixture, b2FixtureDef, set_keywords
from kge.box2d.massdata import b2MassData
from kge.box2d.shapes import b2ChainShape, b2CircleShape, b2EdgeShape, b2LoopShape, b2PolygonShape
from kge.box2d.transform import b2Transform, make_transform
from kge.box2d.vec import as_xy, b2Vec2
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.transform import Transform
from kge.errors import ComponentTypeError, ValidationError

if TYPE_CHECKING:
    from kge.box2d.contact import b2Contact
    from kge.box2d.joints import b2Joint
    from kge.box2d.world import b2World

_TO_KGE = {b2_staticBody: BodyType.STATIC, b2_kinematicBody: BodyType.KINEMATIC,
           b2_dynamicBody: BodyType.DYNAMIC}
_FROM_KGE = {v: k for k, v in _TO_KGE.items()}


def body_type(value: Any) -> BodyType:
    if isinstance(value, BodyType):
        return value
    if isinstance(value, bool) or not isinstance(value, int) or value not in _TO_KGE:
        raise b2AssertException(
            f"b2Body.type must be b2_staticBody, b2_kinematicBody or b2_dynamicBody, got {value!r}"
        )
    return _TO_KGE[value]


class _View(b2Vec2):
    """A b2Vec2 that stands for one of a body's vectors; in-place arithmetic writes the
    result back once (``body.linearVelocity *= 0.99`` is one velocity write)."""

    __slots__ = ("_owner",)

    def __init__(self, body: b2Body) -> None:
        self._owner = body

    def _put(self, value: tuple[float, float]) -> None:
        raise NotImplementedError

    def __iadd__(self, other: Any) -> b2Vec2:
        ox, oy = other
        self._put((self.x + ox, self.y + oy))
        return self

    def __isub__(self, other: Any) -> b2Vec2:
        ox, oy = other
        self._put((self.x - ox, self.y - oy))
        return self

    def __imul__(self, k: float) -> b2Vec2:
        self._put((self.x * k, self.y * k))
        return self

    def __itruediv__(self, k: float) -> b2Vec2:
        self._put((self.x / k, self.y / k))
        return self

    def Set(self, x: float, y: float) -> None:
        self._put((x, y))


class PositionView(_View):
    """``body.position``: a b2Vec2 whose ``x`` and ``y`` are the body's, now (pybox2d's
    position aliases the body's transform). Arithmetic gives plain vectors."""

    __slots__ = ()

    def _put(self, value: tuple[float, float]) -> None:
        self._owner.position = value

    @property
    def x(self) -> float:
        return self._owner._tf.x

    @x.setter
    def x(self, value: float) -> None:
        self._owner.position = (value, self._owner._tf.y)

    @property
    def y(self) -> float:
        return self._owner._tf.y

    @y.setter
    def y(self, value: float) -> None:
        self._owner.position = (self._owner._tf.x, value)


class VelocityView(_View):
    """``body.linearVelocity``: a b2Vec2 whose ``x`` and ``y`` are the body's velocity, now."""

    __slots__ = ()

    def _put(self, value: tuple[float, float]) -> None:
        self._owner.linearVelocity = value

    @property
    def x(self) -> float:
        return float(self._owner._rb.velocity[0])

    @x.setter
    def x(self, value: float) -> None:
        self._owner.linearVelocity = (value, self._owner._rb.velocity[1])

    @property
    def y(self) -> float:
        return float(self._owner._rb.velocity[1])

    @y.setter
    def y(self, value: float) -> None:
        self._owner.linearVelocity = (self._owner._rb.velocity[0], value)


class b2BodyDef:
    """Everything a body starts with; ``fixtures=`` and ``shapes=`` make its fixtures too."""

    def __init__(self, **kwargs: Any) -> None:
        self.type: Any = b2_staticBody
        self.position: Any = (0.0, 0.0)
        self.angle = 0.0
        self.linearVelocity: Any = (0.0, 0.0)
        self.angularVelocity = 0.0
        self.linearDamping = 0.0
        self.angularDamping = 0.0
        self.allowSleep = True
        self.awake = True
        self.fixedRotation = False
        self.bullet = False
        self.active = True
        self.gravityScale = 1.0
        self.userData: Any = None
        self.fixtures: Any = None
        self.shapes: Any = None
        self.shapeFixture: Any = None
        set_keywords(self, kwargs)

    def components(self) -> tuple[Transform, RigidBody]:
        x, y = as_xy(self.position, "b2BodyDef", "position")
        return (
            Transform(x, y, self.angle),
            RigidBody(
                type=body_type(self.type),
                velocity=as_xy(self.linearVelocity, "b2BodyDef", "linearVelocity"),
                angular_velocity=self.angularVelocity, linear_damping=self.linearDamping,
                angular_damping=self.angularDamping, gravity_scale=self.gravityScale,
                fixed_rotation=self.fixedRotation, bullet=self.bullet,
                allow_sleep=self.allowSleep, awake=self.awake, enabled=self.active,
            ),
        )


class b2JointEdge:
    """One joint of a body, seen from it: ``joint`` and the ``other`` body."""

    def __init__(self, joint: b2Joint, other: b2Body) -> None:
        self.joint, self.other = joint, other


class b2ContactEdge:
    """One touching contact of a body, seen from it: ``contact`` and the ``other`` body."""

    def __init__(self, contact: b2Contact, other: b2Body) -> None:
        self.contact, self.other = contact, other


class b2Body:
    """A rigid body: pose, velocity, mass, its fixtures and joints."""

    def __init__(self, world: b2World, entity: int, tf: Transform, rb: RigidBody,
                 user_data: Any) -> None:
        self._world = world
        self._entity = entity
        self._tf = tf
        self._rb = rb
        self._fixtures: list[b2Fixture] = []
        self._joints: list[b2Joint] = []
        self.userData = user_data
        self._destroyed = False

    if TYPE_CHECKING:  # programs store their own attributes on bodies
        def __getattr__(self, name: str) -> Any: ...
        def __setattr__(self, name: str, value: Any) -> None: ...

    # -- identity --------------------------------------------------------------------------
    @property
    def entity(self) -> int:
        """The kge entity behind this body."""
        return self._entity

    @property
    def world(self) -> b2World:
        return self._world

    def _live(self, op: str) -> None:
        if self._destroyed:
            raise ValidationError(f"b2Body.{op}: the body (entity {self._entity}) was destroyed")

    def __repr__(self) -> str:
        p = self._tf
        return (f"b2Body(entity={self._entity}, type={_FROM_KGE[self._rb.type]}, "
                f"position=({p.x:g}, {p.y:g}), angle={p.angle:g})")

    def _pose(self) -> tuple[float, float, float]:
        """(x, y, angle) now; inside a step (pre-solve) the engine's live pose, which the
        Transform component only receives when the step is over."""
        if not self._world._locked:
            tf = self._tf
            return (tf.x, tf.y, tf.angle)
        physics = self._world._physics
        x, y = physics.world_point(self._entity, (0.0, 0.0))
        ux, uy = physics.world_vector(self._entity, (1.0, 0.0))
        return (x, y, math.atan2(uy, ux))

    # -- pose ---------------------------------------------------------------------------------
    @property
    def position(self) -> b2Vec2:
        """The origin's world position: a vector that stays this body's (pybox2d's alias):
        it reads the current position after later steps, and writing ``x`` or ``y``
        through it moves the body. ``.copy()`` gives a snapshot."""
        return PositionView(self)

    @position.setter
    def position(self, value: Any) -> None:
        self._live("position")
        self._world._unlocked("b2Body.position")
        x, y = as_xy(value, "b2Body", "position")
        self._tf.x, self._tf.y = x, y

    @property
    def angle(self) -> float:
        return self._tf.angle

    @angle.setter
    def angle(self, value: float) -> None:
        self._live("angle")
        self._world._unlocked("b2Body.angle")
        self._tf.angle = value

    @property
    def transform(self) -> b2Transform:
        tf = self._tf
        return make_transform(tf.x, tf.y, tf.angle)

    @transform.setter
    def transform(self, value: Any) -> None:
        """Assign a b2Transform, or ``(position, angle)`` as pybox2d accepts."""
        if isinstance(value, b2Transform):
            pos, angle = value.position, value.angle
        else:
            pos, angle = value
        self._live("transform")
        self._world._unlocked("b2Body.transform")
        x, y = as_xy(pos, "b2Body", "transform")
        self._tf.x, self._tf.y, self._tf.angle = x, y, angle

    def SetTransform(self, position: Any, angle: float) -> None:
        self.transform = (position, angle)

    # -- velocity and flags -----------------------------------------------------------------------
    @property
    def linearVelocity(self) -> b2Vec2:
        """The centre of mass's velocity (m/s), a live vector like :attr:`position`."""
        return VelocityView(self)

    @linearVelocity.setter
    def linearVelocity(self, value: Any) -> None:
        self._live("linearVelocity")
        if self._rb.type is not BodyType.STATIC:
            self._rb.velocity = as_xy(value, "b2Body", "linearVelocity")

    @property
    def angularVelocity(self) -> float:
        return self._rb.angular_velocity

    @angularVelocity.setter
    def angularVelocity(self, value: float) -> None:
        self._live("angularVelocity")
        if self._rb.type is not BodyType.STATIC:
            self._rb.angular_velocity = value

    @property
    def awake(self) -> bool:
        return self._rb.awake and self._rb.type is not BodyType.STATIC

    @awake.setter
    def awake(self, value: bool) -> None:
        self._live("awake")
        if self._rb.type is not BodyType.STATIC:
            self._rb.awake = value

    def _flag(name: str, doc: str) -> property:  # type: ignore[misc]
        def get(self: b2Body) -> Any:
            return getattr(self._rb, name)

        def put(self: b2Body, value: Any) -> None:
            self._live(name)
            setattr(self._rb, name, value)

        return property(get, put, doc=doc)

    active = _flag("enabled", "False takes the body out of the simulation (Box2D SetActive)")
    bullet = _flag("bullet", "Continuous collision against dynamic bodies too")
    fixedRotation = _flag("fixed_rotation", "No rotation: zero inverse inertia")
    sleepingAllowed = _flag("allow_sleep", "May this body fall asleep?")
    linearDamping = _flag("linear_damping", "v *= max(0, 1 - c dt) per step")
    angularDamping = _flag("angular_damping", "w *= max(0, 1 - c dt) per step")
    gravityScale = _flag("gravity_scale", "Multiplier on the world's gravity")
    del _flag

    @property
    def type(self) -> int:
        return _FROM_KGE[self._rb.type]

    @type.setter
    def type(self, value: Any) -> None:
        self._live("type")
        self._world._unlocked("b2Body.type")
        self._rb.type = body_type(value)

    # -- mass ---------------------------------------------------------------------------------
    @property
    def mass(self) -> float:
        if self._rb.type is not BodyType.DYNAMIC:
            return 0.0
        return self._world._physics.mass_data(self._entity).mass

    @mass.setter
    def mass(self, value: float) -> None:
        self._live("mass")
        self._rb.mass = value

    @property
    def inertia(self) -> float:
        """Rotational inertia about the body origin (Box2D's GetInertia)."""
        md = self.massData
        return md.I

    @property
    def massData(self) -> b2MassData:
        if self._rb.type is not BodyType.DYNAMIC:
            return b2MassData()
        md = self._world._physics.mass_data(self._entity)
        cx, cy = md.center
        return b2MassData(md.mass, (cx, cy), md.inertia + md.mass * (cx * cx + cy * cy))

    @massData.setter
    def massData(self, value: b2MassData) -> None:
        self.mass = value.mass

    def ResetMassData(self) -> None:
        self._rb.mass = None
        self._mass_changed()

    def _mass_changed(self) -> None:
        """The fixtures (so the centre of mass) changed: as Box2D's ResetMassData, the
        centre's velocity becomes that of its new point, ``v += w x (c_new - c_old)``
        (kge's physics did that to its body already; the component catches up now, so
        ``linearVelocity`` reads it before the next step, as in pybox2d)."""
        rb = self._rb
        if rb.type is not BodyType.DYNAMIC or not rb.angular_velocity or self._world._locked:
            return
        center = self.worldCenter
        live = self._world._physics.velocity_at_point(self._entity, (center.x, center.y))
        if live != tuple(rb.velocity):
            rb.velocity = live

    @property
    def localCenter(self) -> b2Vec2:
        if self._rb.type is not BodyType.DYNAMIC:
            return b2Vec2(0.0, 0.0)
        return b2Vec2(*self._world._physics.mass_data(self._entity).center)

    @property
    def worldCenter(self) -> b2Vec2:
        return self.GetWorldPoint(self.localCenter)

    # -- forces -------------------------------------------------------------------------------
    def ApplyForce(self, force: Any, point: Any, wake: bool = True) -> None:
        self._live("ApplyForce")
        self._world._physics.apply_force(self._entity, as_xy(force, "ApplyForce", "force"),
                                         as_xy(point, "ApplyForce", "point"), bool(wake))

    def ApplyForceToCenter(self, force: Any, wake: bool = True) -> None:
        self._live("ApplyForceToCenter")
        self._world._physics.apply_force(
            self._entity, as_xy(force, "ApplyForceToCenter", "force"), None, bool(wake))

    def ApplyTorque(self, torque: float, wake: bool = True) -> None:
        self._live("ApplyTorque")
        self._world._physics.apply_torque(self._entity, torque, bool(wake))

    def ApplyLinearImpulse(self, impulse: Any, point: Any, wake: bool = True) -> None:
        self._live("ApplyLinearImpulse")
        self._world._physics.apply_linear_impulse(
            self._entity, as_xy(impulse, "ApplyLinearImpulse", "impulse"),
            as_xy(point, "ApplyLinearImpulse", "point"), bool(wake))

    def ApplyAngularImpulse(self, impulse: float, wake: bool = True) -> None:
        self._live("ApplyAngularImpulse")
        self._world._physics.apply_angular_impulse(self._entity, impulse, bool(wake))

    # -- coordinates ----------------------------------------------------------------------------
    def GetWorldPoint(self, localPoint: Any) -> b2Vec2:
        x, y = as_xy(localPoint, "GetWorldPoint", "localPoint")
        tf = self._tf
        c, s = math.cos(tf.angle), math.sin(tf.angle)
        return b2Vec2(c * x - s * y + tf.x, s * x + c * y + tf.y)

    def GetWorldVector(self, localVector: Any) -> b2Vec2:
        x, y = as_xy(localVector, "GetWorldVector", "localVector")
        a = self._tf.angle
        c, s = math.cos(a), math.sin(a)
        return b2Vec2(c * x - s * y, s * x + c * y)

    def GetLocalPoint(self, worldPoint: Any) -> b2Vec2:
        x, y = as_xy(worldPoint, "GetLocalPoint", "worldPoint")
        tf = self._tf
        c, s = math.cos(tf.angle), math.sin(tf.angle)
        dx, dy = x - tf.x, y - tf.y
        return b2Vec2(c * dx + s * dy, -s * dx + c * dy)

    def GetLocalVector(self, worldVector: Any) -> b2Vec2:
        x, y = as_xy(worldVector, "GetLocalVector", "worldVector")
        a = self._tf.angle
        c, s = math.cos(a), math.sin(a)
        return b2Vec2(c * x + s * y, -s * x + c * y)

    def GetLinearVelocityFromWorldPoint(self, worldPoint: Any) -> b2Vec2:
        px, py = as_xy(worldPoint, "GetLinearVelocityFromWorldPoint", "worldPoint")
        cx, cy = self.worldCenter
        vx, vy = self._rb.velocity
        w = self._rb.angular_velocity
        return b2Vec2(vx - w * (py - cy), vy + w * (px - cx))

    def GetLinearVelocityFromLocalPoint(self, localPoint: Any) -> b2Vec2:
        return self.GetLinearVelocityFromWorldPoint(self.GetWorldPoint(localPoint))

    # -- fixtures -------------------------------------------------------------------------------
    @property
    def fixtures(self) -> list[b2Fixture]:
        """Oldest first, as pybox2d's list."""
        return list(self._fixtures)

    def CreateFixture(self, defn: b2FixtureDef | None = None, **kwargs: Any) -> b2Fixture:
        if defn is None:
            defn = b2FixtureDef(**kwargs)
        elif kwargs:
            raise ComponentTypeError("CreateFixture takes a b2FixtureDef or keywords, not both")
        elif not isinstance(defn, b2FixtureDef):
            raise ComponentTypeError(f"CreateFixture needs a b2FixtureDef, got {defn!r}")
        self._live("CreateFixture")
        return self._world._create_fixture(self, defn)

    def _shaped(self, shape: Any, kwargs: dict[str, Any], keys: tuple[str, ...]) -> b2Fixture:
        for k in keys:
            if k in kwargs:
                setattr(shape, k, kwargs.pop(k))
        return self.CreateFixture(b2FixtureDef(shape=shape, **kwargs))

    def CreatePolygonFixture(self, **kwargs: Any) -> b2Fixture:
        return self._shaped(b2PolygonShape(), kwargs, ("box", "vertices"))

    def CreateCircleFixture(self, **kwargs: Any) -> b2Fixture:
        return self._shaped(b2CircleShape(), kwargs, ("radius", "pos"))

    def CreateEdgeFixture(self, **kwargs: Any) -> b2Fixture:
        return self._shaped(b2EdgeShape(), kwargs, ("vertices",))

    def CreateChainFixture(self, **kwargs: Any) -> b2Fixture:
        """A chain fixture: ``vertices=`` closes it into a loop, ``vertices_chain=`` leaves
        it open (pybox2d's rules)."""
        return self._shaped(b2ChainShape(), kwargs,
                            ("vertices", "vertices_chain", "vertices_loop"))

    def CreateLoopFixture(self, **kwargs: Any) -> b2Fixture:
        return self._shaped(b2LoopShape(), kwargs, ("vertices", "vertices_loop"))

    def CreateEdgeChain(self, edge_list: Any) -> None:
        """One separate edge fixture per pair of consecutive points, as pybox2d makes them
        (not a chain: the edges do not know their neighbours); returns None, as pybox2d."""
        if isinstance(edge_list, (str, bytes)) or not hasattr(edge_list, "__len__"):
            raise MissingError(f"CreateEdgeChain needs a list of points, got {edge_list!r}")
        if len(edge_list) < 2:
            raise ValidationError(f"CreateEdgeChain: edge list length >= 2, got {len(edge_list)}")
        pts = [as_xy(p, "CreateEdgeChain", f"edge_list[{i}]") for i, p in enumerate(edge_list)]
        for a, b in itertools.pairwise(pts):
            self.CreateFixture(b2FixtureDef(shape=b2EdgeShape(vertices=[a, b])))

    def CreateFixturesFromShapes(self, shapes: Any = None, shapeFixture: Any = None) -> None:
        template = shapeFixture if shapeFixture is not None else b2FixtureDef()
        if not isinstance(shapes, (list, tuple)):
            shapes = [shapes]
        for shape in shapes:
            template.shape = shape
            self.CreateFixture(template)

    def DestroyFixture(self, fixture: b2Fixture) -> None:
        self._live("DestroyFixture")
        if not isinstance(fixture, b2Fixture) or fixture.body is not self:
            raise ValidationError(f"DestroyFixture: {fixture!r} is not a fixture of this body")
        self._world._destroy_fixture(fixture)

    # -- joints and contacts --------------------------------------------------------------------
    @property
    def joints(self) -> list[b2JointEdge]:
        """Oldest first, as pybox2d's list."""
        return [b2JointEdge(j, j.bodyB if j.bodyA is self else j.bodyA) for j in self._joints]

    @property
    def contacts(self) -> list[b2ContactEdge]:
        out = []
        for c in self._world._contact_list():
            if c.fixtureA.body is self:
                out.append(b2ContactEdge(c, c.fixtureB.body))
            elif c.fixtureB.body is self:
                out.append(b2ContactEdge(c, c.fixtureA.body))
        return out
