"""``kge.box2d``: pybox2d 2.3's Python API on kge's physics.

Programs written for pybox2d (``import Box2D``) run on kge: ``b2World``,
bodies, fixtures, shapes, all joints, contacts and listeners, queries and the
math types keep pybox2d's names and behaviour, while the simulation is a kge
World stepped by kge's physics system (pymunk with Box2D's rules). It needs no
SWIG and no C++ compiler.

``install()`` makes ``import Box2D`` (and ``Box2D.b2``) resolve to this package,
so unmodified programs, Gymnasium's Box2D environments among them, use it::

    import kge.box2d
    kge.box2d.install()
    import gymnasium as gym
    env = gym.make("LunarLander-v3")

or run a script with ``python -m kge.box2d script.py``.

This is a top floor: it may import anything in kge (except testbed and gym);
nothing in kge imports it.
"""

from __future__ import annotations

import math
import random
import sys
from types import ModuleType
from typing import Any

from kge.box2d.body import b2Body, b2BodyDef, b2ContactEdge, b2JointEdge, b2MassData
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
    b2Manifold,
    b2ManifoldPoint,
    b2WorldManifold,
)
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
from kge.box2d.shapes import (
    b2ChainShape,
    b2CircleShape,
    b2EdgeShape,
    b2LoopShape,
    b2PolygonShape,
    b2Shape,
)
from kge.box2d.transform import b2AABB, b2Mat22, b2Rot, b2Sweep, b2Transform
from kge.box2d.vec import b2Vec2
from kge.box2d.world import b2World
from kge.errors import KgeError


class b2AssertException(KgeError, AssertionError):
    """pybox2d's exception for a failed Box2D assertion (kge raises its own errors)."""


b2Globals = sys.modules[__name__]


class b2Color:
    """An RGB colour with components in 0..1 (``bytes`` gives 0..255)."""

    def __init__(self, r: float = 0.0, g: float = 0.0, b: float = 0.0) -> None:
        self.r, self.g, self.b = float(r), float(g), float(b)

    @property
    def bytes(self) -> tuple[int, int, int]:
        return (int(self.r * 255), int(self.g * 255), int(self.b * 255))

    def __iter__(self) -> Any:
        return iter((self.r, self.g, self.b))

    def __repr__(self) -> str:
        return f"b2Color({self.r:g},{self.g:g},{self.b:g})"


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


def install() -> None:
    """Make ``import Box2D`` and ``Box2D.b2`` resolve to ``kge.box2d`` in this interpreter."""
    from kge.box2d import b2 as short

    me = sys.modules[__name__]
    sys.modules["Box2D"] = me
    sys.modules["Box2D.Box2D"] = me
    sys.modules["Box2D.b2"] = short


def uninstall() -> None:
    """Undo :func:`install` (modules imported since keep what they imported)."""
    for name in ("Box2D", "Box2D.Box2D", "Box2D.b2"):
        mod = sys.modules.get(name)
        if isinstance(mod, ModuleType) and mod.__name__.startswith("kge.box2d"):
            del sys.modules[name]


__version__ = "2.3.10"
_ = b2_pi
