"""Contacts: ``b2Contact`` with its ``manifold`` / ``worldManifold``, and ``b2ContactImpulse``.

``manifold`` and ``worldManifold`` are computed when read, by
:func:`kge.collision.collide` on the two fixtures' shapes at the bodies' current
poses (Box2D's b2Collide functions: the same normal, points and separations).
Between steps that is what Box2D's stored manifold holds; if the shapes have
moved apart since, the geometry kge recorded when the contact began (or at the
last pre-solve) is returned instead. One ``b2Contact``
object lives as long as its two fixtures touch, so a program that keeps it
sees the same object in ``BeginContact``, ``PreSolve`` and ``EndContact``.

Box2D's contact list also holds pairs whose bounding boxes merely overlap
(``touching`` False); kge's holds the touching ones only.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from kge import collision
from kge.box2d.constants import b2_maxManifoldPoints
from kge.box2d.vec import b2Vec2

if TYPE_CHECKING:
    from kge.box2d.fixture import b2Fixture

Vec2 = tuple[float, float]
Poses = tuple[tuple[float, float, float], tuple[float, float, float]]


class b2ManifoldPoint:
    """One contact point: where (in fixture B's body frame) and the solver's impulses."""

    def __init__(self, localPoint: b2Vec2, normalImpulse: float = 0.0,
                 tangentImpulse: float = 0.0) -> None:
        self.localPoint = localPoint
        self.normalImpulse = normalImpulse
        self.tangentImpulse = tangentImpulse
        self.id = 0


class b2Manifold:
    """Contact points in local coordinates (Box2D's b2Manifold, face-A form)."""

    e_circles, e_faceA, e_faceB = 0, 1, 2

    def __init__(self, points: list[b2ManifoldPoint], localNormal: b2Vec2,
                 localPoint: b2Vec2) -> None:
        self.points = points
        self.localNormal = localNormal
        self.localPoint = localPoint
        self.type = self.e_faceA
        #: kge's manifold behind this one (its contact ids), when computed live
        self._kge: collision.Manifold | None = None

    @property
    def pointCount(self) -> int:
        return len(self.points)

    @property
    def type_(self) -> int:
        """pybox2d's name for ``type``."""
        return self.type


class DeferredManifold(b2Manifold):
    """A contact's manifold at a past moment (its poses kept), computed when first read:
    PreSolve's ``oldManifold``, which most listeners never look at."""

    def __init__(self, contact: b2Contact, poses: Poses) -> None:
        object.__setattr__(self, "_source", (contact, poses))

    def __getattr__(self, name: str) -> Any:
        if name == "_source":
            raise AttributeError(name)
        contact, poses = self._source
        done = contact._manifold_at(poses)
        self.__dict__.update(vars(done))
        return getattr(done, name)


class b2WorldManifold:
    """World normal (from A to B), world points and separations.

    ``points`` always has ``b2_maxManifoldPoints`` (2) entries, as pybox2d's: the
    manifold's ``pointCount`` first, then ``(0, 0)``; so do ``separations``.
    """

    def __init__(self, normal: b2Vec2, points: list[Vec2], separations: list[float]) -> None:
        self.normal = normal
        pad = b2_maxManifoldPoints - len(points)
        self.points: tuple[Vec2, ...] = (*((x, y) for x, y in points), *[(0.0, 0.0)] * pad)
        self.separations = [*separations, *[0.0] * pad]


class b2ContactImpulse:
    """Impulses of one contact over the last step, per manifold point (N s)."""

    def __init__(self, normalImpulses: tuple[float, ...], tangentImpulses: tuple[float, ...],
                 count: int) -> None:
        self.normalImpulses = normalImpulses
        self.tangentImpulses = tangentImpulses
        self.count = count


class b2Contact:
    """Two touching fixtures (A before B as Box2D orders them) and their contact data."""

    def __init__(self, fixtureA: b2Fixture, fixtureB: b2Fixture) -> None:
        self._fixtureA = fixtureA
        self._fixtureB = fixtureB
        self.touching = True
        self.enabled = True
        self.tangentSpeed = 0.0
        self._friction: float | None = None
        self._restitution: float | None = None
        self._normal: Vec2 = (0.0, 0.0)
        self._points: tuple[Vec2, ...] = ()
        self._separation = 0.0
        #: the manifold of the last PreSolve, handed to the next one as ``oldManifold``
        self._last_manifold = b2Manifold([], b2Vec2(0, 0), b2Vec2(0, 0))

    fixtureA = property(lambda self: self._fixtureA)
    fixtureB = property(lambda self: self._fixtureB)
    childIndexA = property(lambda self: 0)
    childIndexB = property(lambda self: 0)

    def _set_geometry(self, normal: Vec2, points: tuple[Vec2, ...], separation: float) -> None:
        self._normal, self._points, self._separation = normal, points, separation

    @property
    def friction(self) -> float:
        """Mixed friction, sqrt(fa * fb), unless set for this contact."""
        if self._friction is not None:
            return self._friction
        return float((self._fixtureA.friction * self._fixtureB.friction) ** 0.5)

    @friction.setter
    def friction(self, value: float) -> None:
        self._friction = float(value)

    def ResetFriction(self) -> None:
        self._friction = None

    @property
    def restitution(self) -> float:
        if self._restitution is not None:
            return self._restitution
        return max(self._fixtureA.restitution, self._fixtureB.restitution)

    @restitution.setter
    def restitution(self, value: float) -> None:
        self._restitution = float(value)

    def ResetRestitution(self) -> None:
        self._restitution = None

    def _poses(self) -> Poses:
        return (self._fixtureA.body._pose(), self._fixtureB.body._pose())

    def _collide(self, poses: Poses | None = None) -> collision.Manifold | None:
        """The manifold at ``poses`` (default: now; the deepest over chain children), or
        None if the shapes are apart there."""
        sa, sb = self._fixtureA._col.shape, self._fixtureB._col.shape
        xa, xb = poses or self._poses()
        best: collision.Manifold | None = None
        for ca in range(collision.child_count(sa)):
            for cb in range(collision.child_count(sb)):
                m = collision.collide(sa, xa, sb, xb, child_a=ca, child_b=cb)
                if m and (best is None or min(m.separations) < min(best.separations)):
                    best = m
        return best

    @property
    def worldManifold(self) -> b2WorldManifold:
        m = self._collide()
        if m is not None:
            return b2WorldManifold(b2Vec2(*m.normal), list(m.points), list(m.separations))
        n = self._normal
        return b2WorldManifold(b2Vec2(*n), list(self._points),
                               [self._separation] * len(self._points))

    @property
    def manifold(self) -> b2Manifold:
        return self._manifold_at(None)

    def _manifold_at(self, poses: Poses | None) -> b2Manifold:
        m = self._collide(poses)
        if m is not None:
            out = b2Manifold([b2ManifoldPoint(b2Vec2(*p.local_point)) for p in m.local_points],
                             b2Vec2(*m.local_normal), b2Vec2(*m.local_point))
            out.type = _MANIFOLD_TYPES[m.type]
            out._kge = m
            return out
        body_b = self._fixtureB.body
        body_a = self._fixtureA.body
        pts = [b2ManifoldPoint(body_b.GetLocalPoint(p)) for p in self._points]
        normal = body_a.GetLocalVector(self._normal)
        anchor = body_a.GetLocalPoint(self._points[0]) if self._points else b2Vec2(0, 0)
        return b2Manifold(pts, normal, anchor)

    def _remember_manifold(self) -> b2Manifold:
        """For PreSolve: the manifold of the previous PreSolve (its ``oldManifold``); this
        step's is kept for the next one (the bodies' poses now), computed only if read."""
        old = self._last_manifold
        self._last_manifold = DeferredManifold(self, self._poses())
        return old

    def __repr__(self) -> str:
        return f"b2Contact(fixtureA={self._fixtureA!r}, fixtureB={self._fixtureB!r})"


_MANIFOLD_TYPES = {"circles": b2Manifold.e_circles, "face_a": b2Manifold.e_faceA,
                   "face_b": b2Manifold.e_faceB}


_POINT_STATES = {"add": 1, "persist": 2, "remove": 3}  # b2_addState...


def b2GetPointStates(manifold1: b2Manifold, manifold2: b2Manifold
                     ) -> tuple[tuple[int, int], tuple[int, int]]:
    """Which points of ``manifold1`` persist or go, and which of ``manifold2`` are new
    (``b2_nullState`` pads to two, as pybox2d returns them)."""
    old, new = manifold1._kge, manifold2._kge
    if old is not None and new is not None:
        s1, s2 = collision.point_states(old, new)
        a = [_POINT_STATES[x] for x in s1]
        b = [_POINT_STATES[x] for x in s2]
    else:  # no ids to match: every old point goes, every new one is new
        a = [3] * manifold1.pointCount
        b = [1] * manifold2.pointCount
    a += [0] * (2 - len(a))
    b += [0] * (2 - len(b))
    return (a[0], a[1]), (b[0], b[1])


def impulse_of(normal_impulse: float, tangent_impulse: float, count: int) -> b2ContactImpulse:
    """Split kge's summed impulses evenly over the contact's points."""
    n = max(count, 1)
    return b2ContactImpulse(tuple([normal_impulse / n] * n), tuple([tangent_impulse / n] * n), n)
