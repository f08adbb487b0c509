"""Despawns leave nothing behind: a body takes the colliders attached to it along.

Box2D's DestroyBody destroys the body's fixtures. In kge a fixture may sit on
another entity (``Collider(body=e)``); despawning ``e`` despawns it too, in the
same flush. Moving a collider to another body by writing ``Collider.body``
removes the implicit static body its entity had.
"""

from __future__ import annotations

from kge import Box, Circle, Collider, RigidBody, Transform

from .harness import PhysicsWorld, check_invariants, check_no_leftovers, space_counts


def test_despawning_a_body_despawns_colliders_attached_from_other_entities() -> None:
    pw = PhysicsWorld()
    w = pw.world
    w.spawn(Transform(0.0, -1.0), Collider(Box(10.0, 1.0)))
    car = w.spawn(Transform(0.0, 1.0), RigidBody(), Collider(Box(1.0, 0.25)))
    wheels = [w.spawn(Transform(), Collider(Circle(0.3, center=(dx, -0.3)), body=car))
              for dx in (-0.8, 0.8)]
    pw.step(30)
    assert pw.events.contact_begin or pw.balance.live_pairs()
    w.despawn(car)
    pw.step()
    assert not any(w.exists(e) for e in wheels)
    assert w.entities() == [1]
    assert space_counts(pw.sim) == {"bodies": 1, "shapes": 1, "constraints": 0}
    check_invariants(pw)
    check_no_leftovers(pw)
    assert not pw.balance.live_pairs()  # every begin of the wheels got its end
    pw.close()


def test_attached_collider_spawned_in_the_same_frame_goes_too() -> None:
    pw = PhysicsWorld()
    w = pw.world
    car = w.spawn(Transform(0.0, 1.0), RigidBody())
    with w.deferred():
        part = w.spawn(Transform(), Collider(Circle(0.3), body=car))
        w.despawn(car)
    assert not w.exists(part)
    pw.step()
    assert w.entities() == []
    check_no_leftovers(pw)
    pw.close()


def test_removing_only_the_rigidbody_keeps_the_attached_collider_waiting() -> None:
    pw = PhysicsWorld()
    w = pw.world
    car = w.spawn(Transform(0.0, 1.0), RigidBody(), Collider(Box(1.0, 0.25)))
    part = w.spawn(Transform(), Collider(Circle(0.3), body=car))
    pw.step()
    w.remove(car, RigidBody)
    pw.step()
    assert w.exists(part)  # a removal is not a despawn
    w.add(car, RigidBody())
    pw.step()
    assert part in pw.sim.bodies[car].colliders
    pw.close()


def test_moving_a_static_collider_onto_a_body_removes_its_implicit_body() -> None:
    pw = PhysicsWorld()
    w = pw.world
    body = w.spawn(Transform(0.0, 5.0), RigidBody(), Collider(Box(0.5, 0.5)))
    fixture = w.spawn(Transform(3.0, 0.0), Collider(Circle(0.5)))
    pw.step()
    assert space_counts(pw.sim)["bodies"] == 2
    w.get(fixture, Collider).body = body
    pw.step()
    assert fixture not in pw.sim.bodies
    assert space_counts(pw.sim) == {"bodies": 1, "shapes": 2, "constraints": 0}
    check_invariants(pw)
    check_no_leftovers(pw)
    w.get(fixture, Collider).body = None  # and back: the implicit body returns
    pw.step()
    assert pw.sim.bodies[fixture].implicit
    assert space_counts(pw.sim) == {"bodies": 2, "shapes": 2, "constraints": 0}
    check_invariants(pw)
    pw.close()
