"""The classes programs subclass: contact listener and filter, destruction listener, queries.

pybox2d calls them back from C++; kge.box2d calls the overridden methods from
:class:`~kge.box2d.world.b2World`. The bases do nothing, so a subclass only
writes the methods it needs; :func:`overrides` tells whether it did, so that
the expensive per-contact hooks (PreSolve, PostSolve) are only switched on for
listeners that use them.

Callbacks run with the world locked: creating or destroying bodies, fixtures
or joints inside one raises :class:`kge.errors.WorldLockedError`, as Box2D
asserts (pybox2d raises ``b2AssertException``).
"""

from __future__ import annotations

from typing import Any


class b2ContactListener:
    """Told when fixtures start and stop touching, and before/after each solve."""

    def __init__(self, **kwargs: Any) -> None:
        for k, v in kwargs.items():
            setattr(self, k, v)

    def BeginContact(self, contact: Any) -> None:
        """Two fixtures started touching (or a sensor started overlapping)."""

    def EndContact(self, contact: Any) -> None:
        """Two fixtures stopped touching (also when one of them is destroyed)."""

    def PreSolve(self, contact: Any, oldManifold: Any) -> None:
        """Before the solver: set ``contact.enabled = False`` to skip it this step."""

    def PostSolve(self, contact: Any, impulse: Any) -> None:
        """After the solver: ``impulse.normalImpulses`` per manifold point."""


class b2ContactFilter:
    """Decides whether two fixtures may collide (Box2D's default uses their filters)."""

    def __init__(self, **kwargs: Any) -> None:
        for k, v in kwargs.items():
            setattr(self, k, v)

    def ShouldCollide(self, fixtureA: Any, fixtureB: Any) -> bool:
        from kge.box2d.fixture import default_should_collide

        return default_should_collide(fixtureA, fixtureB)


class b2DestructionListener:
    """Told about joints and fixtures destroyed implicitly with their body."""

    def __init__(self, **kwargs: Any) -> None:
        for k, v in kwargs.items():
            setattr(self, k, v)

    def SayGoodbye(self, obj: Any) -> None:
        """``obj`` is a b2Joint or b2Fixture about to go away."""


class b2QueryCallback:
    """``world.QueryAABB(callback, aabb)``: ``ReportFixture(fixture)`` returns True to go on."""

    def __init__(self, **kwargs: Any) -> None:
        for k, v in kwargs.items():
            setattr(self, k, v)

    def ReportFixture(self, fixture: Any) -> bool:
        return True


class b2RayCastCallback:
    """``world.RayCast(callback, p1, p2)``: ``ReportFixture(fixture, point, normal, fraction)``.

    Return the fraction to clip the ray (closest hit), 1 to continue, 0 to stop,
    -1 to ignore this fixture.
    """

    def __init__(self, **kwargs: Any) -> None:
        for k, v in kwargs.items():
            setattr(self, k, v)

    def ReportFixture(self, fixture: Any, point: Any, normal: Any, fraction: float) -> float:
        return 1.0


def overrides(obj: Any, base: type, name: str) -> bool:
    """True when ``obj``'s class replaces ``base.name`` (or ``obj`` is not a ``base`` at all)."""
    return getattr(type(obj), name, None) is not getattr(base, name)
