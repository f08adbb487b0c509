"""``world.contactManager`` and its ``broadPhase``: pybox2d's view of Box2D's broad phase.

kge's contacts come from Chipmunk's own spatial index, which is not Box2D's tree
and cannot be read. So that programs can still show Box2D's statistics (the
tiles example prints the tree's height; ``world.GetTreeHeight()``...),
:class:`b2BroadPhase` keeps a Box2D dynamic AABB tree
(:class:`kge.collision.DynamicTree`, Box2D's algorithm) of every fixture child's
box, brought up to date when it is read: a proxy moves when its body moved, and
is re-inserted only when its box left its fat box, as in Box2D. Nothing is
computed for programs that never ask.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from kge.box2d.transform import b2AABB
from kge.collision import DynamicTree

if TYPE_CHECKING:
    from kge.box2d.fixture import b2Fixture
    from kge.box2d.world import b2World

Key = tuple[int, int]  # (fixture entity, child index)
Pose = tuple[float, float, float]


class b2BroadPhase:
    """A dynamic tree of the fixtures' boxes (fat by 0.1 m), read as Box2D's broad phase."""

    e_nullProxy = -1

    def __init__(self, world: b2World) -> None:
        self._world = world
        self._tree = DynamicTree()
        self._proxies: dict[Key, int] = {}
        self._poses: dict[int, Pose] = {}  # body entity -> pose at the last update
        #: (world steps, fixture changes) at the last update
        self._synced_at: tuple[int, int] = (-1, -1)

    def _update(self) -> DynamicTree:
        world = self._world
        if self._synced_at == (world._steps, world._fixture_changes):
            return self._tree
        reshaped = self._synced_at[1:] != (world._fixture_changes,)
        tree, proxies, poses = self._tree, self._proxies, self._poses
        for body in world._bodies.values():
            tf = body._tf
            pose = (tf.x, tf.y, tf.angle)
            old = poses.get(body.entity)
            if old == pose and not reshaped:
                continue  # at rest since the last update (static ground, sleepers)
            poses[body.entity] = pose
            shift = (0.0, 0.0) if old is None else (pose[0] - old[0], pose[1] - old[1])
            for fixture in body._fixtures:
                for child in range(fixture.shape.childCount):
                    key = (fixture.entity, child)
                    proxy = proxies.get(key)
                    if proxy is None:
                        proxies[key] = tree.insert(_box(fixture, child), fixture)
                    elif old != pose:
                        tree.move(proxy, _box(fixture, child), shift)
        if reshaped:
            live = {(f.entity, c) for f in world._fixtures.values()
                    for c in range(f.shape.childCount)}
            for key in [k for k in proxies if k not in live]:
                tree.remove(proxies.pop(key))
            for entity in [e for e in poses if e not in world._bodies]:
                del poses[entity]
        self._synced_at = (world._steps, world._fixture_changes)
        return tree

    @property
    def proxyCount(self) -> int:
        return len(self._update())

    @property
    def treeHeight(self) -> int:
        return self._update().height

    @property
    def treeBalance(self) -> int:
        return self._update().max_balance

    @property
    def treeQuality(self) -> float:
        return self._update().area_ratio

    def GetFatAABB(self, proxyId: int) -> b2AABB:
        box = self._update().fat_aabb(proxyId)
        return b2AABB(box.lower, box.upper)

    def GetUserData(self, proxyId: int) -> Any:
        return self._update().user_data(proxyId)

    def TestOverlap(self, proxyIdA: int, proxyIdB: int) -> bool:
        tree = self._update()
        a, b = tree.fat_aabb(proxyIdA), tree.fat_aabb(proxyIdB)
        return not (b.lower[0] > a.upper[0] or b.lower[1] > a.upper[1]
                    or a.lower[0] > b.upper[0] or a.lower[1] > b.upper[1])


def _box(fixture: b2Fixture, child: int) -> tuple[tuple[float, float], tuple[float, float]]:
    aabb = fixture.GetAABB(child)
    lo, hi = aabb.lowerBound, aabb.upperBound
    return ((lo.x, lo.y), (hi.x, hi.y))


class b2ContactManager:
    """The world's contact manager as pybox2d shows it: its broad phase and contacts.

    kge finds and updates contacts inside ``Step``: ``FindNewContacts`` and
    ``Collide`` have nothing left to do.
    """

    def __init__(self, world: b2World) -> None:
        self._world = world
        self.broadPhase = b2BroadPhase(world)

    @property
    def contactCount(self) -> int:
        return self._world.contactCount

    @property
    def contactList(self) -> Any:
        contacts = self._world.contacts
        return contacts[0] if contacts else None

    @property
    def contactListener(self) -> Any:
        return self._world.contactListener

    @property
    def contactFilter(self) -> Any:
        return self._world.contactFilter

    def FindNewContacts(self) -> None:
        """Nothing to do: kge finds new contacts in ``Step``."""

    def Collide(self) -> None:
        """Nothing to do: kge updates contacts in ``Step``."""
