"""Sync-out keeps every component equal to its pymunk body, whichever shortcut it takes.

Sync-out writes only what changed since the last step, and takes shorter paths
when every body moved, when only some did, and when no velocity changed (a
crowd drifting without gravity writes Transforms only). Each step here checks
the invariant those shortcuts must keep: every Transform and RigidBody holds
its body's pose and velocity, through drifting, collisions, sleeping, user
writes and a body added mid-way.
"""

from __future__ import annotations

import math

from kge.components.collider import Collider
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Circle
from kge.components.transform import Transform
from kge.physics.settings import PhysicsSettings

from .conftest import Sim


def _check(sim: Sim) -> None:
    bodies = sim.system.sim.bodies
    for e, rec in bodies.items():
        if rec.implicit:
            continue
        t, rb = sim.t(e), sim.rb(e)
        b = rec.body
        assert (t.x, t.y) == (b.position.x, b.position.y), f"entity {e} Transform"
        assert t.angle == b.angle, f"entity {e} angle"
        if not b.is_sleeping:
            assert rb.velocity == (b.velocity.x, b.velocity.y), f"entity {e} velocity"
            assert rb.angular_velocity == b.angular_velocity, f"entity {e} spin"


def test_components_follow_bodies_through_every_sync_out_path() -> None:
    sim = Sim(PhysicsSettings(gravity=(0.0, 0.0)))
    try:
        # a drifting crowd: positions change, velocities do not (Transforms only)
        drifters = [
            sim.dynamic(Circle(0.2), x=float(i), y=0.0, density=1.0,
                        body=RigidBody(velocity=(0.5, 0.25 * (i % 3)), angular_velocity=0.1))
            for i in range(12)
        ]
        # a wall some of them reach: their velocities change on impact (both halves)
        sim.spawn(Transform(13.0, 0.0), Collider(Box(0.5, 10.0), restitution=1.0))
        resting = sim.dynamic(Box(0.5, 0.5), x=-5.0, y=-5.0, density=1.0)  # never moves
        for step in range(240):
            sim.step()
            _check(sim)
            if step == 30:  # a user write between steps
                sim.rb(drifters[0]).velocity = (3.0, -1.0)
            if step == 60:  # a user write that physics keeps as it is (no gravity)
                sim.rb(drifters[1]).velocity = (0.5, 0.0)
            if step == 90:  # a body arriving mid-way
                drifters.append(sim.dynamic(Circle(0.3), x=0.0, y=3.0, density=1.0,
                                            body=RigidBody(velocity=(1.0, 0.0))))
        assert sim.t(drifters[2]).x > 2.0 + 1.5  # they did drift
        assert sim.rb(resting).velocity == (0.0, 0.0)
        assert any(sim.rb(d).velocity[0] < 0.0 for d in drifters)  # and some bounced
        assert all(math.isfinite(sim.t(d).x) for d in drifters)
    finally:
        sim.close()


def test_components_follow_bodies_while_a_pile_falls_asleep() -> None:
    sim = Sim()
    try:
        sim.ground()
        boxes = [sim.dynamic(Box(0.5, 0.5), x=0.0, y=0.6 + 1.05 * i, density=1.0)
                 for i in range(5)]
        for _ in range(200):
            sim.step()
            _check(sim)
        assert all(not sim.rb(b).awake for b in boxes)  # asleep: some steps wrote nothing
        sim.rb(boxes[-1]).velocity = (0.0, 2.0)  # wake the top one
        for _ in range(30):
            sim.step()
            _check(sim)
    finally:
        sim.close()

