"""Long play: the CCD index holds the bodies tracked now, not the ones despawned since
its last query (a game whose bodies all go away never queries it again)."""

from __future__ import annotations

from kge import Box, Circle, Collider, RigidBody, Transform
from tests.reliability.harness import PhysicsWorld


def test_despawning_every_body_leaves_no_index_behind() -> None:
    pw = PhysicsWorld()
    world = pw.world
    world.spawn(Transform(0.0, -1.0), Collider(Box(20.0, 0.5)))
    balls = [world.spawn(Transform(0.3 * i - 7.0, 1.0), RigidBody(), Collider(Circle(0.1)))
             for i in range(50)]
    pw.step(3)
    ccd = pw.sim.ccd
    assert ccd is not None and ccd._index is not None  # queried while the balls fall
    for e in balls:
        world.despawn(e)
    pw.step(3)
    assert not ccd._tracked
    assert ccd._index is None and not ccd._index_changes
    ball = world.spawn(Transform(0.0, 3.0), RigidBody(velocity=(0.0, -400.0)),
                       Collider(Circle(0.1)))
    pw.step(30)  # a new fast body is indexed again: it does not tunnel through the floor
    assert world.get(ball, Transform).y > -1.0
    pw.close()
