"""``kge.physics.drain``: joints restarted from zero impulse, outside pymunk's step.

``Physics.reset_joints`` (and a jolted joint) drains the warm start in the first
substep of the next step: ``max_force`` 0 around that substep, put back after it.
"""

from __future__ import annotations

import math
from typing import Any

from kge.app import App
from kge.components import Transform
from kge.components.collider import Collider
from kge.components.joints import RevoluteJoint
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box
from kge.physics.resource import Physics
from kge.physics.settings import PhysicsSettings
from kge.systems.physics import PhysicsSystem
from kge.world import World


def _pendulum_on_a_floor(world: World) -> None:
    """Two boxes lying on a floor, hinged where they meet: they fall asleep."""
    world.insert_resource(PhysicsSettings(substeps=2))
    world.spawn(Transform(0.0, -0.1), Collider(Box(4.0, 0.2)))
    left = world.spawn(Transform(-0.5, 0.2), RigidBody(), Collider(Box(0.4, 0.2), density=1.0))
    right = world.spawn(Transform(0.5, 0.2), RigidBody(), Collider(Box(0.4, 0.2), density=1.0))
    world.spawn(RevoluteJoint(left, right, anchor=(0.0, 0.2)))


def _sim(app: App) -> Any:
    system = app.world.get_system(PhysicsSystem)
    assert system is not None
    return system.sim


def test_the_drain_spans_the_first_substep_only_and_needs_no_callback() -> None:
    app = App(_pendulum_on_a_floor, headless=True)
    app.step(5)
    sim = _sim(app)
    (j_e, _), = app.world.query(RevoluteJoint)
    pivot = sim.joints.handles[j_e].parts[0]
    physics = app.world.resource(Physics)
    seen: list[float] = []
    step = sim.space.step

    def spy(h: float) -> None:  # max_force as each substep begins
        seen.append(pivot.max_force)
        step(h)

    sim.space.step = spy
    physics.reset_joints([j_e])
    assert pivot.pre_solve is None  # nothing runs inside pymunk's step
    app.step(2)
    assert seen == [0.0, math.inf, math.inf, math.inf]
    assert not sim.joints.drain.waiting
    app.close()


def test_a_sleeping_joint_waits_for_its_bodies_to_wake() -> None:
    app = App(_pendulum_on_a_floor, headless=True)
    app.step(120)
    sim = _sim(app)
    (j_e, (joint,)), = app.world.query(RevoluteJoint)
    bob = sim.bodies[joint.body_b].body
    assert bob.is_sleeping
    app.world.resource(Physics).reset_joints([j_e])
    app.step(3)
    assert bob.is_sleeping  # not woken by the reset: it waits, as pymunk's warm start
    assert sim.joints.drain.waiting
    bob.activate()
    app.step(1)
    assert not sim.joints.drain.waiting


def test_a_destroyed_joint_leaves_the_drain() -> None:
    app = App(_pendulum_on_a_floor, headless=True)
    app.step(120)
    sim = _sim(app)
    (j_e, _), = app.world.query(RevoluteJoint)
    app.world.resource(Physics).reset_joints([j_e])
    assert sim.joints.drain.waiting
    app.world.despawn(j_e)
    app.step(1)
    assert not sim.joints.drain.waiting
