"""Joints: every pybox2d joint definition and joint, as kge joint-component entities.

One table per joint type names each pybox2d field with its kge component field
(``maxMotorTorque`` -> ``max_motor_torque``); the definition classes accept those
names as keywords and attributes, and the joint classes expose them as live
properties that read and write the joint's component, so ``joint.motorSpeed = 3``
is an ordinary (checked) component write. Read-only live state (``angle``,
``speed``, ``translation``, ``motorTorque``...) is what the physics system writes
into the component after every step.

Definitions take Box2D's defaults, not kge's: a revolute, prismatic or weld
definition's ``referenceAngle`` is 0, except that, as in pybox2d, one built with
``bodyA=`` and ``bodyB=`` keywords (and no ``referenceAngle=``) takes the angle
between the bodies *now* (Gymnasium's walker and lander legs rely on it: their
hinge limits are relative to the build angle); local anchors are given in body frames, and
``anchor`` / ``axis`` / ``anchorA`` / ``anchorB`` / ``groundAnchorA`` keywords run
``Initialize`` with the definition's bodies.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any, ClassVar

from kge.box2d import constants as c
from kge.box2d.errors import KeywordError, MissingError, b2AssertException
from kge.box2d.vec import as_xy, b2Vec2
from kge.components import joints as kj
from kge.errors import ComponentTypeError, ValidationError

if TYPE_CHECKING:
    from kge.box2d.body import b2Body
    from kge.box2d.world import b2World


def _vec(v: Any) -> tuple[float, float]:
    return as_xy(v, "b2JointDef", "vector")


def _same(v: Any) -> Any:
    return v


Field = tuple[str, Any, Callable[[Any], Any]]  # kge field, Box2D default, converter

_ANCHORS: dict[str, Field] = {
    "localAnchorA": ("local_anchor_a", (0.0, 0.0), _vec),
    "localAnchorB": ("local_anchor_b", (0.0, 0.0), _vec),
}
_BASE: dict[str, Field] = {"collideConnected": ("collide_connected", False, bool)}


class b2JointDef:
    """Base definition: ``bodyA``, ``bodyB``, ``collideConnected``, ``userData``."""

    if TYPE_CHECKING:  # the per-type fields are set from FIELDS
        def __getattr__(self, name: str) -> Any: ...

    FIELDS: ClassVar[dict[str, Field]] = dict(_BASE)
    COMPONENT: ClassVar[type[kj.Joint]]
    TYPE: ClassVar[int] = c.e_unknownJoint
    #: keywords that run Initialize once the bodies are known
    INIT_KEYS: ClassVar[tuple[str, ...]] = ()
    #: pybox2d's constructor rule: given both bodies and no referenceAngle keyword,
    #: referenceAngle = bodyB.angle - bodyA.angle (revolute, prismatic, weld)
    REFERENCE_FROM_BODIES: ClassVar[bool] = False

    def __init__(self, **kwargs: Any) -> None:
        self.bodyA: b2Body | None = None
        self.bodyB: b2Body | None = None
        self.userData: Any = None
        for name, (_, default, _conv) in self.FIELDS.items():
            value = b2Vec2(*default) if isinstance(default, tuple) else default
            object.__setattr__(self, name, value)
        kwargs.pop("type", None)  # to_kwargs() passes it back; the class says the type
        init = {k: kwargs.pop(k) for k in self.INIT_KEYS if k in kwargs}
        for name, value in kwargs.items():
            if name not in self.FIELDS and name not in ("bodyA", "bodyB", "userData"):
                raise KeywordError(f"{type(self).__name__} has no property {name!r}")
            setattr(self, name, value)
        if init:
            self._initialize(**init)
        if (self.REFERENCE_FROM_BODIES and self.bodyA is not None and self.bodyB is not None
                and "referenceAngle" not in kwargs and "referenceAngle" in self.FIELDS):
            a, b = self._bodies()
            setattr(self, "referenceAngle", b.angle - a.angle)  # noqa: B010 - a FIELDS name

    @property
    def type(self) -> int:
        """The joint type number (``e_revoluteJoint``...)."""
        return self.TYPE

    def to_kwargs(self) -> dict[str, Any]:
        """The definition as keywords for ``world.Create*Joint(**kwargs)`` (pybox2d's)."""
        out: dict[str, Any] = {"bodyA": self.bodyA, "bodyB": self.bodyB,
                               "userData": self.userData, "type": self.TYPE}
        for name in self.FIELDS:
            v = getattr(self, name)
            out[name] = v.copy() if isinstance(v, b2Vec2) else v
        return out

    def ClearUserData(self) -> None:
        self.userData = None

    def __setattr__(self, name: str, value: Any) -> None:
        spec = self.FIELDS.get(name)
        if spec is not None:
            value = spec[2](value)
            if isinstance(value, tuple):
                value = b2Vec2(*value)
        object.__setattr__(self, name, value)

    def _initialize(self, **init: Any) -> None:
        raise ComponentTypeError(f"{type(self).__name__} takes no {sorted(init)}")

    def _bodies(self) -> tuple[b2Body, b2Body]:
        from kge.box2d.body import b2Body

        a, b = self.bodyA, self.bodyB
        for name, body in (("bodyA", a), ("bodyB", b)):
            if not isinstance(body, b2Body):
                raise MissingError(
                    f"{type(self).__name__}: bodyA and bodyB must be set; {name} is {body!r}")
        assert a is not None and b is not None
        return a, b

    def component(self, world: b2World) -> kj.Joint:
        """The kge joint component this definition describes (kge checks the values)."""
        a, b = self._bodies()
        if a is b:
            raise b2AssertException(
                f"{type(self).__name__}: bodyA and bodyB are the same body (entity {a.entity}); "
                "a joint needs two different bodies"
            )
        kw: dict[str, Any] = {}
        for name, (field, _, _conv) in self.FIELDS.items():
            v = getattr(self, name)
            kw[field] = tuple(v) if isinstance(v, b2Vec2) else v
        make: Any = self.COMPONENT
        joint: kj.Joint = make(a.entity, b.entity, **kw)
        return joint


class _AnchorDef(b2JointDef):
    """Defs initialised from one world anchor (revolute, weld, friction)."""

    INIT_KEYS: ClassVar[tuple[str, ...]] = ("anchor",)

    def _initialize(self, anchor: Any = None, **_: Any) -> None:
        self.Initialize(self.bodyA, self.bodyB, anchor)

    def Initialize(self, bodyA: Any, bodyB: Any, anchor: Any) -> None:
        """Both bodies and the world ``anchor`` (and, when the joint has one, the
        reference angle: the angle between the bodies now)."""
        self.bodyA, self.bodyB = bodyA, bodyB
        a, b = self._bodies()
        self.localAnchorA = a.GetLocalPoint(anchor)
        self.localAnchorB = b.GetLocalPoint(anchor)
        if "referenceAngle" in self.FIELDS:
            self.referenceAngle = b.angle - a.angle

    @property
    def anchor(self) -> b2Vec2:
        """The world anchor (from ``bodyA``); setting it sets both local anchors."""
        a, _ = self._bodies()
        return a.GetWorldPoint(self.localAnchorA)

    @anchor.setter
    def anchor(self, value: Any) -> None:
        a, b = self._bodies()
        self.localAnchorA = a.GetLocalPoint(value)
        self.localAnchorB = b.GetLocalPoint(value)


class b2RevoluteJointDef(_AnchorDef):
    REFERENCE_FROM_BODIES = True
    FIELDS: ClassVar[dict[str, Field]] = {**_BASE, **_ANCHORS,
              "referenceAngle": ("reference_angle", 0.0, float),
              "enableLimit": ("enable_limit", False, bool),
              "lowerAngle": ("lower_angle", 0.0, float),
              "upperAngle": ("upper_angle", 0.0, float),
              "enableMotor": ("enable_motor", False, bool),
              "motorSpeed": ("motor_speed", 0.0, float),
              "maxMotorTorque": ("max_motor_torque", 0.0, float)}
    COMPONENT = kj.RevoluteJoint
    TYPE = c.e_revoluteJoint


class b2WeldJointDef(_AnchorDef):
    REFERENCE_FROM_BODIES = True
    FIELDS: ClassVar[dict[str, Field]] = {**_BASE, **_ANCHORS,
              "referenceAngle": ("reference_angle", 0.0, float),
              "frequencyHz": ("frequency_hz", 0.0, float),
              "dampingRatio": ("damping_ratio", 0.0, float)}
    COMPONENT = kj.WeldJoint
    TYPE = c.e_weldJoint


class b2FrictionJointDef(_AnchorDef):
    FIELDS: ClassVar[dict[str, Field]] = {**_BASE, **_ANCHORS,
              "maxForce": ("max_force", 0.0, float),
              "maxTorque": ("max_torque", 0.0, float)}
    COMPONENT = kj.FrictionJoint
    TYPE = c.e_frictionJoint


class _AnchorAxisDef(_AnchorDef):
    """Defs initialised from one world anchor and one world axis (prismatic, wheel)."""

    INIT_KEYS = ("anchor", "axis")

    def _initialize(self, anchor: Any = None, axis: Any = (1.0, 0.0), **_: Any) -> None:
        self.Initialize(self.bodyA, self.bodyB, anchor, axis)

    def Initialize(self, bodyA: Any, bodyB: Any, anchor: Any,  # type: ignore[override]
                   axis: Any) -> None:
        """Both bodies, the world ``anchor`` and the world ``axis`` of translation."""
        super().Initialize(bodyA, bodyB, anchor)
        self.axis = axis

    @property
    def axis(self) -> b2Vec2:
        """The world axis (from ``bodyA``); setting it sets ``localAxisA``."""
        a, _ = self._bodies()
        return a.GetWorldVector(self.localAxisA)

    @axis.setter
    def axis(self, value: Any) -> None:
        a, _ = self._bodies()
        self.localAxisA = a.GetLocalVector(value)


class b2PrismaticJointDef(_AnchorAxisDef):
    REFERENCE_FROM_BODIES = True
    FIELDS: ClassVar[dict[str, Field]] = {**_BASE, **_ANCHORS,
              "localAxisA": ("local_axis_a", (1.0, 0.0), _vec),
              "referenceAngle": ("reference_angle", 0.0, float),
              "enableLimit": ("enable_limit", False, bool),
              "lowerTranslation": ("lower_translation", 0.0, float),
              "upperTranslation": ("upper_translation", 0.0, float),
              "enableMotor": ("enable_motor", False, bool),
              "motorSpeed": ("motor_speed", 0.0, float),
              "maxMotorForce": ("max_motor_force", 0.0, float)}
    COMPONENT = kj.PrismaticJoint
    TYPE = c.e_prismaticJoint


class b2WheelJointDef(_AnchorAxisDef):
    FIELDS: ClassVar[dict[str, Field]] = {**_BASE, **_ANCHORS,
              "localAxisA": ("local_axis_a", (1.0, 0.0), _vec),
              "enableMotor": ("enable_motor", False, bool),
              "motorSpeed": ("motor_speed", 0.0, float),
              "maxMotorTorque": ("max_motor_torque", 0.0, float),
              "frequencyHz": ("frequency_hz", 2.0, float),
              "dampingRatio": ("damping_ratio", 0.7, float)}
    COMPONENT = kj.WheelJoint
    TYPE = c.e_wheelJoint


class _TwoAnchorDef(b2JointDef):
    """Defs with an anchor on each body (distance, rope, pulley): ``anchorA`` and
    ``anchorB`` read and write them as world points."""

    INIT_KEYS = ("anchorA", "anchorB")

    @property
    def anchorA(self) -> b2Vec2:
        a, _ = self._bodies()
        return a.GetWorldPoint(self.localAnchorA)

    @anchorA.setter
    def anchorA(self, value: Any) -> None:
        a, _ = self._bodies()
        self.localAnchorA = a.GetLocalPoint(value)

    @property
    def anchorB(self) -> b2Vec2:
        _, b = self._bodies()
        return b.GetWorldPoint(self.localAnchorB)

    @anchorB.setter
    def anchorB(self, value: Any) -> None:
        _, b = self._bodies()
        self.localAnchorB = b.GetLocalPoint(value)


class b2DistanceJointDef(_TwoAnchorDef):
    FIELDS: ClassVar[dict[str, Field]] = {**_BASE, **_ANCHORS,
              "length": ("length", 1.0, float),
              "frequencyHz": ("frequency_hz", 0.0, float),
              "dampingRatio": ("damping_ratio", 0.0, float)}
    COMPONENT = kj.DistanceJoint
    TYPE = c.e_distanceJoint

    def _initialize(self, anchorA: Any = None, anchorB: Any = None, **_: Any) -> None:
        self.Initialize(self.bodyA, self.bodyB, anchorA, anchorB)

    def Initialize(self, bodyA: Any, bodyB: Any, anchorA: Any, anchorB: Any) -> None:
        self.bodyA, self.bodyB = bodyA, bodyB
        a, b = self._bodies()
        pa, pb = b2Vec2(anchorA), b2Vec2(anchorB)
        self.localAnchorA = a.GetLocalPoint(pa)
        self.localAnchorB = b.GetLocalPoint(pb)
        self.length = (pb - pa).length


class b2RopeJointDef(_TwoAnchorDef):
    FIELDS: ClassVar[dict[str, Field]] = {**_BASE,
              "localAnchorA": ("local_anchor_a", (-1.0, 0.0), _vec),
              "localAnchorB": ("local_anchor_b", (1.0, 0.0), _vec),
              "maxLength": ("max_length", 0.0, float)}
    COMPONENT = kj.RopeJoint
    TYPE = c.e_ropeJoint

    def _initialize(self, anchorA: Any = None, anchorB: Any = None, **_: Any) -> None:
        if anchorA is not None:
            self.anchorA = anchorA
        if anchorB is not None:
            self.anchorB = anchorB


class b2PulleyJointDef(_TwoAnchorDef):
    FIELDS: ClassVar[dict[str, Field]] = {**_BASE, **_ANCHORS,
              "groundAnchorA": ("ground_anchor_a", (-1.0, 1.0), _vec),
              "groundAnchorB": ("ground_anchor_b", (1.0, 1.0), _vec),
              "ratio": ("ratio", 1.0, float),
              "collideConnected": ("collide_connected", True, bool)}
    COMPONENT = kj.PulleyJoint
    TYPE = c.e_pulleyJoint

    def _initialize(self, anchorA: Any = None, anchorB: Any = None, **_: Any) -> None:
        self.anchorA, self.anchorB = anchorA, anchorB

    def Initialize(self, bodyA: Any, bodyB: Any, groundAnchorA: Any, groundAnchorB: Any,
                   anchorA: Any, anchorB: Any, ratio: float) -> None:
        self.bodyA, self.bodyB = bodyA, bodyB
        self.groundAnchorA, self.groundAnchorB = groundAnchorA, groundAnchorB
        self.ratio = ratio
        self._initialize(anchorA, anchorB)

    @property
    def lengthA(self) -> float:
        a, _ = self._bodies()
        return (a.GetWorldPoint(self.localAnchorA) - self.groundAnchorA).length

    @property
    def lengthB(self) -> float:
        _, b = self._bodies()
        return (b.GetWorldPoint(self.localAnchorB) - self.groundAnchorB).length


class b2MouseJointDef(b2JointDef):
    FIELDS: ClassVar[dict[str, Field]] = {**_BASE,
              "target": ("target", (0.0, 0.0), _vec),
              "maxForce": ("max_force", 0.0, float),
              "frequencyHz": ("frequency_hz", 5.0, float),
              "dampingRatio": ("damping_ratio", 0.7, float)}
    COMPONENT = kj.MouseJoint
    TYPE = c.e_mouseJoint


class b2MotorJointDef(b2JointDef):
    FIELDS: ClassVar[dict[str, Field]] = {**_BASE,
              "linearOffset": ("linear_offset", (0.0, 0.0), _vec),
              "angularOffset": ("angular_offset", 0.0, float),
              "maxForce": ("max_force", 1.0, float),
              "maxTorque": ("max_torque", 1.0, float),
              "correctionFactor": ("correction_factor", 0.3, float)}
    COMPONENT = kj.MotorJoint
    TYPE = c.e_motorJoint

    def Initialize(self, bodyA: Any, bodyB: Any) -> None:
        self.bodyA, self.bodyB = bodyA, bodyB
        a, b = self._bodies()
        self.linearOffset = a.GetLocalPoint(b.position)
        self.angularOffset = b.angle - a.angle


class b2GearJointDef(b2JointDef):
    FIELDS: ClassVar[dict[str, Field]] = {**_BASE, "ratio": ("ratio", 1.0, float)}
    COMPONENT = kj.GearJoint
    TYPE = c.e_gearJoint

    def __init__(self, **kwargs: Any) -> None:
        self.joint1: b2Joint | None = None
        self.joint2: b2Joint | None = None
        for k in ("joint1", "joint2"):
            if k in kwargs:
                setattr(self, k, kwargs.pop(k))
        super().__init__(**kwargs)

    def to_kwargs(self) -> dict[str, Any]:
        return {**super().to_kwargs(), "joint1": self.joint1, "joint2": self.joint2}

    def component(self, world: b2World) -> kj.Joint:
        j1, j2 = self.joint1, self.joint2
        for name, j in (("joint1", j1), ("joint2", j2)):
            if not isinstance(j, (b2RevoluteJoint, b2PrismaticJoint)):
                raise ComponentTypeError(
                    f"b2GearJointDef.{name} must be a revolute or prismatic joint, got {j!r}")
        assert j1 is not None and j2 is not None
        return kj.GearJoint(j1.entity, j2.entity, ratio=self.ratio,
                            collide_connected=self.collideConnected)


# -- joints ---------------------------------------------------------------------------------------

def _live_field(field: str, conv: Callable[[Any], Any]) -> property:
    def get(self: b2Joint) -> Any:
        v = getattr(self._comp, field)
        return b2Vec2(*v) if isinstance(v, tuple) else v

    def put(self: b2Joint, value: Any) -> None:
        self._check_live()
        self._set(field, conv(value))

    return property(get, put)


def _read(field: str) -> property:
    def get(self: b2Joint) -> Any:
        v = getattr(self._comp, field)
        return b2Vec2(*v) if isinstance(v, tuple) else v

    return property(get)


def _alias(name: str) -> property:
    """Another name for the property ``name`` (pybox2d's joint names differ from its defs')."""
    return property(lambda self: getattr(self, name), lambda self, v: setattr(self, name, v))


class b2Joint:
    """A joint between two bodies (a kge joint entity); properties are live component fields."""

    DEF: ClassVar[type[b2JointDef]] = b2JointDef

    def __init__(self, world: b2World, entity: int, comp: kj.Joint, bodyA: b2Body,
                 bodyB: b2Body, user_data: Any) -> None:
        self._world = world
        self._entity = entity
        self._comp: Any = comp
        self._bodyA = bodyA
        self._bodyB = bodyB
        self.userData = user_data
        self._destroyed = False

    if TYPE_CHECKING:  # the per-type properties are made by __init_subclass__
        def __getattr__(self, name: str) -> Any: ...
        def __setattr__(self, name: str, value: Any) -> None: ...

    def __init_subclass__(cls, **kw: Any) -> None:
        super().__init_subclass__(**kw)
        for name, (field, _, conv) in cls.DEF.FIELDS.items():
            if name not in cls.__dict__:
                setattr(cls, name, _live_field(field, conv))

    def _check_live(self) -> None:
        if self._destroyed:
            raise ValidationError(f"{type(self).__name__} (entity {self._entity}) was destroyed")

    def _set(self, field: str, value: Any) -> None:
        """Write a component field; a value Box2D would assert on raises b2AssertException."""
        try:
            setattr(self._comp, field, value)
        except ValidationError as e:
            raise b2AssertException(str(e)) from None

    @property
    def entity(self) -> int:
        return self._entity

    bodyA = property(lambda self: self._bodyA)
    bodyB = property(lambda self: self._bodyB)
    type = property(lambda self: self.DEF.TYPE)
    collideConnected = property(lambda self: bool(self._comp.collide_connected))

    def getAsType(self) -> b2Joint:
        """This joint as its own type (pybox2d's downcast: kge's joints already are)."""
        return self

    def ClearUserData(self) -> None:
        self.userData = None

    @property
    def active(self) -> bool:
        return bool(self._bodyA.active and self._bodyB.active)

    def GetLocalAnchorA(self) -> b2Vec2:
        return b2Vec2(*getattr(self._comp, "local_anchor_a", (0.0, 0.0)))

    def GetLocalAnchorB(self) -> b2Vec2:
        return b2Vec2(*(getattr(self._comp, "local_anchor_b", None) or (0.0, 0.0)))

    @property
    def anchorA(self) -> b2Vec2:
        return self._bodyA.GetWorldPoint(self.GetLocalAnchorA())

    @property
    def anchorB(self) -> b2Vec2:
        return self._bodyB.GetWorldPoint(self.GetLocalAnchorB())

    def GetReactionForce(self, inv_dt: float = 0.0) -> b2Vec2:
        """The force on bodyB at the anchor over the last step (N)."""
        return b2Vec2(*self._comp.reaction_force)

    def GetReactionTorque(self, inv_dt: float = 0.0) -> float:
        return float(self._comp.reaction_torque)

    def ShiftOrigin(self, newOrigin: Any) -> None:
        """Nothing to do: kge joints keep no world-space state to shift."""

    def Dump(self) -> None:
        print(repr(self))

    def __repr__(self) -> str:
        return f"{type(self).__name__}(entity={self._entity})"


class _Motor:
    """``motorEnabled`` and ``EnableMotor`` (revolute, prismatic, wheel)."""

    _comp: Any

    motorEnabled = property(lambda self: self._comp.enable_motor,
                            lambda self, v: setattr(self._comp, "enable_motor", bool(v)))

    def EnableMotor(self, flag: bool) -> None:
        self.motorEnabled = flag


class _Limits(_Motor):
    """pybox2d's limit names shared by revolute and prismatic joints: ``limits``,
    ``lowerLimit``, ``upperLimit`` (each settable), ``limitEnabled``, ``SetLimits``."""

    _LIMIT: ClassVar[tuple[str, str]]

    limitEnabled = property(lambda self: self._comp.enable_limit,
                            lambda self, v: setattr(self._comp, "enable_limit", bool(v)))

    def EnableLimit(self, flag: bool) -> None:
        self.limitEnabled = flag

    def SetLimits(self, lower: float, upper: float) -> None:
        """Both limits at once; ``lower > upper`` is Box2D's assertion (b2AssertException)."""
        try:
            self._comp.set_limits(lower, upper)
        except ValidationError as e:
            raise b2AssertException(str(e)) from None

    @property
    def limits(self) -> tuple[float, float]:
        lo, hi = self._LIMIT
        return (getattr(self._comp, lo), getattr(self._comp, hi))

    @limits.setter
    def limits(self, value: Any) -> None:
        self.SetLimits(*value)

    @property
    def lowerLimit(self) -> float:
        return float(self.limits[0])

    @lowerLimit.setter
    def lowerLimit(self, value: float) -> None:
        self.SetLimits(value, self.limits[1])

    @property
    def upperLimit(self) -> float:
        return float(self.limits[1])

    @upperLimit.setter
    def upperLimit(self, value: float) -> None:
        self.SetLimits(self.limits[0], value)


class b2RevoluteJoint(_Limits, b2Joint):
    DEF = b2RevoluteJointDef
    _LIMIT = ("lower_angle", "upper_angle")
    angle = _read("angle")
    speed = _read("speed")
    motorTorque = _read("motor_torque")

    def GetMotorTorque(self, inv_dt: float = 0.0) -> float:
        return float(self._comp.motor_torque)

    def GetMaxMotorTorque(self) -> float:
        return float(self._comp.max_motor_torque)

    def GetReferenceAngle(self) -> float:
        return float(self._comp.reference_angle or 0.0)


class b2PrismaticJoint(_Limits, b2Joint):
    DEF = b2PrismaticJointDef
    _LIMIT = ("lower_translation", "upper_translation")
    translation = _read("translation")
    speed = _read("speed")
    motorForce = _read("motor_force")

    def GetMotorForce(self, inv_dt: float = 0.0) -> float:
        return float(self._comp.motor_force)

    def GetLocalAxisA(self) -> b2Vec2:
        return b2Vec2(*self._comp.local_axis_a)

    def GetReferenceAngle(self) -> float:
        return float(self._comp.reference_angle or 0.0)


class b2WheelJoint(_Motor, b2Joint):
    DEF = b2WheelJointDef
    translation = _read("translation")
    speed = _read("speed")
    motorTorque = _read("motor_torque")
    springFrequencyHz = _alias("frequencyHz")
    springDampingRatio = _alias("dampingRatio")

    def GetMotorTorque(self, inv_dt: float = 0.0) -> float:
        return float(self._comp.motor_torque)

    def GetLocalAxisA(self) -> b2Vec2:
        return b2Vec2(*self._comp.local_axis_a)


class b2DistanceJoint(b2Joint):
    DEF = b2DistanceJointDef
    frequency = _alias("frequencyHz")


class b2RopeJoint(b2Joint):
    DEF = b2RopeJointDef

    def SetMaxLength(self, length: float) -> None:
        self.maxLength = length

    @property
    def limitState(self) -> int:
        """``e_atUpperLimit`` (2) when the rope is taut, else ``e_inactiveLimit`` (0)."""
        d = (self.anchorB - self.anchorA).length
        return 2 if d >= self._comp.max_length - c.b2_linearSlop else 0


class b2WeldJoint(b2Joint):
    DEF = b2WeldJointDef

    def GetReferenceAngle(self) -> float:
        return float(self._comp.reference_angle or 0.0)

    def GetFrequency(self) -> float:
        return float(self.frequencyHz)

    def SetFrequency(self, hz: float) -> None:
        self.frequencyHz = hz

    def GetDampingRatio(self) -> float:
        return float(self.dampingRatio)

    def SetDampingRatio(self, ratio: float) -> None:
        self.dampingRatio = ratio


class b2FrictionJoint(b2Joint):
    DEF = b2FrictionJointDef


class b2MotorJoint(b2Joint):
    DEF = b2MotorJointDef


class b2MouseJoint(b2Joint):
    DEF = b2MouseJointDef
    frequency = _alias("frequencyHz")

    @property
    def anchorA(self) -> b2Vec2:
        return b2Vec2(*self._comp.target)

    @property
    def anchorB(self) -> b2Vec2:
        md = self._comp.local_anchor_b
        if md is None:
            return b2Vec2(*(self._comp.grab_point or self._comp.target))
        return self._bodyB.GetWorldPoint(md)


class b2PulleyJoint(b2Joint):
    DEF = b2PulleyJointDef
    length1 = _read("length_a")
    length2 = _read("length_b")
    lengthA = length1
    lengthB = length2

    def GetCurrentLengthA(self) -> float:
        return (self.anchorA - self.groundAnchorA).length

    def GetCurrentLengthB(self) -> float:
        return (self.anchorB - self.groundAnchorB).length


class b2GearJoint(b2Joint):
    DEF = b2GearJointDef

    def __init__(self, *args: Any, joint1: b2Joint, joint2: b2Joint) -> None:
        super().__init__(*args)
        self.joint1, self.joint2 = joint1, joint2

    def GetJoint1(self) -> b2Joint:
        return self.joint1

    def GetJoint2(self) -> b2Joint:
        return self.joint2


JOINT_CLASSES: dict[type[b2JointDef], type[b2Joint]] = {
    cls.DEF: cls for cls in (
        b2RevoluteJoint, b2PrismaticJoint, b2WheelJoint, b2DistanceJoint, b2RopeJoint,
        b2WeldJoint, b2FrictionJoint, b2MotorJoint, b2MouseJoint, b2PulleyJoint, b2GearJoint)
}
