"""One component instance belongs to one entity; one entity holds one joint.

Two entities sharing a component object would make the simulation (which binds
the instance to one entity) and the component disagree, so the second attach is
refused. A joint is an entity: a second joint component on it would never be
built, so it is refused too. Ownership ends with remove / despawn / close.
"""

from __future__ import annotations

import pytest

from kge import Box, Collider, DistanceJoint, Name, RevoluteJoint, RigidBody, Transform
from kge.errors import ComponentTypeError, ValidationError

from .harness import PhysicsWorld


def test_a_shared_instance_is_refused_in_spawn_add_and_deferred_spawn() -> None:
    pw = PhysicsWorld()
    w = pw.world
    t = Transform(1.0, 2.0)
    e = w.spawn(t, RigidBody(), Collider(Box(0.5, 0.5)))
    with pytest.raises(ValidationError, match=f"already is a component of entity {e}"):
        w.spawn(t)
    with w.deferred():
        name = Name("x")
        q = w.spawn(name)
        with pytest.raises(ValidationError, match=f"already is a component of entity {q}"):
            w.spawn(name)  # queued, not applied yet: still owned
    w.add(e, t)  # re-adding to its own entity is allowed (nothing changes)
    pw.step()
    assert w.get(e, Transform) is t
    pw.close()


def test_ownership_ends_with_remove_and_despawn() -> None:
    pw = PhysicsWorld()
    w = pw.world
    rb = RigidBody()
    e = w.spawn(Transform(), rb, Collider(Box(0.5, 0.5)))
    w.remove(e, RigidBody)
    other = w.spawn(Transform(3.0, 0.0), rb, Collider(Box(0.5, 0.5)))  # free again
    pw.step()
    t = w.get(other, Transform)
    w.despawn(other)
    pw.step()
    third = w.spawn(t)
    assert w.get(third, Transform) is t
    pw.close()


def test_an_instance_bound_in_another_world_is_refused() -> None:
    first, second = PhysicsWorld(), PhysicsWorld()
    t = Transform()
    e = first.world.spawn(t, RigidBody())
    with pytest.raises(ValidationError, match=f"entity {e} of another world"):
        second.world.spawn(t)
    first.close()
    second.world.spawn(t)  # the closed world let it go
    second.close()


def test_two_joint_components_on_one_entity_are_refused() -> None:
    pw = PhysicsWorld()
    w = pw.world
    a = w.spawn(Transform(), RigidBody(), Collider(Box(0.5, 0.5)))
    b = w.spawn(Transform(2.0, 0.0), RigidBody(), Collider(Box(0.5, 0.5)))
    with pytest.raises(ComponentTypeError, match="both joints"):
        w.spawn(RevoluteJoint(a, b, anchor=(1.0, 0.0)), DistanceJoint(a, b))
    j = w.spawn(RevoluteJoint(a, b, anchor=(1.0, 0.0)))
    with pytest.raises(ComponentTypeError, match=f"entity {j}: RevoluteJoint and DistanceJoint"):
        w.add(j, DistanceJoint(a, b))
    w.add(j, RevoluteJoint(a, b, anchor=(0.5, 0.0)))  # replacing the joint is fine
    pw.step()
    assert len(pw.sim.joints.handles) == 1
    pw.close()
