"""Every public name of :mod:`kge.box2d` (the package and ``Box2D.b2`` read them here)."""

from __future__ import annotations

import math
import random
import sys
from typing import Any

from kge.box2d.body import b2Body, b2BodyDef, b2ContactEdge, b2JointEdge
from kge.box2d.broadphase import b2BroadPhase, b2ContactManager
from kge.box2d.callbacks import (
    b2ContactFilter,
    b2ContactListener,
    b2DestructionListener,
    b2QueryCallback,
    b2RayCastCallback,
)
from kge.box2d.constants import *  # noqa: F403
from kge.box2d.constants import b2_pi
from kge.box2d.contact import (
    b2Contact,
    b2ContactImpulse,
    b2GetPointStates,
    b2Manifold,
    b2ManifoldPoint,
    b2WorldManifold,
)
from kge.box2d.distance import (
    b2Distance,
    b2DistanceInput,
    b2DistanceOutput,
    b2DistanceProxy,
    b2DistanceResult,
    b2TimeOfImpact,
    b2TOIInput,
    b2TOIOutput,
)
from kge.box2d.draw import b2Color, b2Draw, b2DrawExtended
from kge.box2d.errors import b2AssertException
from kge.box2d.fixture import b2Filter, b2Fixture, b2FixtureDef
from kge.box2d.joints import (
    b2DistanceJoint,
    b2DistanceJointDef,
    b2FrictionJoint,
    b2FrictionJointDef,
    b2GearJoint,
    b2GearJointDef,
    b2Joint,
    b2JointDef,
    b2MotorJoint,
    b2MotorJointDef,
    b2MouseJoint,
    b2MouseJointDef,
    b2PrismaticJoint,
    b2PrismaticJointDef,
    b2PulleyJoint,
    b2PulleyJointDef,
    b2RevoluteJoint,
    b2RevoluteJointDef,
    b2RopeJoint,
    b2RopeJointDef,
    b2WeldJoint,
    b2WeldJointDef,
    b2WheelJoint,
    b2WheelJointDef,
)
from kge.box2d.massdata import b2MassData
from kge.box2d.matrix import b2Mat22, b2Mat33
from kge.box2d.products import b2Mul, b2Mul22, b2MulT
from kge.box2d.rays import b2RayCastInput, b2RayCastOutput
from kge.box2d.shapes import (
    b2ChainShape,
    b2CircleShape,
    b2EdgeShape,
    b2LoopShape,
    b2PolygonShape,
    b2Shape,
)
from kge.box2d.transform import b2AABB, b2Rot, b2Sweep, b2Transform
from kge.box2d.vec import b2Vec2, b2Vec3
from kge.box2d.world import b2World

b2Globals = sys.modules[__name__]  # pybox2d's module of globals


def b2Random(lo: float = -1.0, hi: float = 1.0) -> float:
    """A uniform random number in [lo, hi] (Box2D's testbed helper)."""
    return random.uniform(lo, hi)


def b2Clamp(a: Any, low: Any, high: Any) -> Any:
    if isinstance(a, (int, float)):
        return max(low, min(a, high))
    return b2Vec2(max(low[0], min(a[0], high[0])), max(low[1], min(a[1], high[1])))


def b2Cross(a: Any, b: Any) -> Any:
    """vector x vector -> scalar; vector x scalar and scalar x vector -> vector."""
    if isinstance(a, (int, float)):
        bx, by = b
        return b2Vec2(-a * by, a * bx)
    return b2Vec2(a).cross(b)


def b2Dot(a: Any, b: Any) -> float:
    return b2Vec2(a).dot(b)


def b2DistanceSquared(a: Any, b: Any) -> float:
    return (b2Vec2(a) - b).lengthSquared


def b2Distance_points(a: Any, b: Any) -> float:
    return math.sqrt(b2DistanceSquared(a, b))



__version__ = "2.3.10"
