"""A gear whose two bodies are one is refused or inert; joint body writes rebuild the joint.

Found by the long fuzz run: a ``GearJoint`` whose two joints both move the same
body (two hinges between the same pair) reached pymunk's bare ``assert a is not
b`` at the next step. Box2D asserts ``bodyA != bodyB`` for every joint, a gear's
bodies being its joints' body B. ``world.spawn`` refuses such a gear; when a
later write of a joint's bodies makes them one, the gear stays inert (no
constraint) for as long as they are.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from kge.components.collider import Collider
from kge.components.joints import GearJoint, RevoluteJoint
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Circle
from kge.components.tracked import raw_set
from kge.components.transform import Transform
from kge.errors import ValidationError
from kge.physics.joints.gear import Gear
from tests.reliability.harness import PhysicsWorld, check_invariants


@pytest.fixture
def pw() -> Iterator[PhysicsWorld]:
    pw = PhysicsWorld()
    yield pw
    pw.close()


def disc(pw: PhysicsWorld, x: float) -> int:
    return pw.world.spawn(Transform(x, 0.0), RigidBody(), Collider(Circle(0.5)))


def step(pw: PhysicsWorld, n: int = 3) -> None:
    for _ in range(n):
        pw.step()
        check_invariants(pw)


def gear_handle(pw: PhysicsWorld, gear: int) -> Gear:
    handle = pw.sim.joints.handles[gear]
    assert isinstance(handle, Gear)
    return handle


def test_a_gear_of_two_hinges_between_the_same_bodies_is_refused(pw: PhysicsWorld) -> None:
    a, b = disc(pw, 0.0), disc(pw, 2.0)
    j1 = pw.world.spawn(RevoluteJoint(a, b, anchor=(1.0, 0.0)))
    j2 = pw.world.spawn(RevoluteJoint(a, b, anchor=(1.0, 0.5)))
    step(pw)
    count = len(pw.world.entities())
    with pytest.raises(ValidationError, match=rf"joints {j1} and {j2} both move entity {b}"):
        pw.world.spawn(GearJoint(j1, j2, ratio=2.0))
    assert len(pw.world.entities()) == count
    step(pw)


def test_a_gear_goes_inert_while_a_joint_write_makes_its_bodies_one(pw: PhysicsWorld) -> None:
    a, b = disc(pw, 0.0), disc(pw, 3.0)
    j1 = pw.world.spawn(RevoluteJoint(None, a, anchor=(0.0, 0.0)))
    j2 = pw.world.spawn(RevoluteJoint(None, b, anchor=(3.0, 0.0)))
    gear = pw.world.spawn(GearJoint(j1, j2, ratio=2.0))
    step(pw)
    assert gear_handle(pw, gear).constraints
    pw.world.get(j2, RevoluteJoint).body_b = a  # both joints now turn disc a
    step(pw)
    assert not gear_handle(pw, gear).constraints
    assert pw.world.get(gear, GearJoint).body_b == a
    pw.world.get(j2, RevoluteJoint).body_b = b
    pw.world.get(j1, RevoluteJoint).motor_speed = 2.0
    pw.world.get(j1, RevoluteJoint).max_motor_torque = 100.0
    pw.world.get(j1, RevoluteJoint).enable_motor = True
    step(pw, 30)
    assert gear_handle(pw, gear).constraints
    assert pw.world.get(j2, RevoluteJoint).speed == pytest.approx(-1.0, rel=0.02)


def test_a_joint_body_write_moves_the_joint(pw: PhysicsWorld) -> None:
    b, c = disc(pw, 2.0), disc(pw, 4.0)
    hinge = pw.world.spawn(RevoluteJoint(None, b, anchor=(2.0, 1.0)))
    step(pw)
    pw.world.get(hinge, RevoluteJoint).body_b = c
    step(pw, 60)
    # b falls freely now; c hangs from the hinge's ground point (its anchor 1 m above it)
    assert pw.world.get(b, Transform).y < -4.0
    tc = pw.world.get(c, Transform)
    assert (tc.x - 2.0) ** 2 + (tc.y - 1.0) ** 2 == pytest.approx(1.0, abs=0.05)


def test_a_joint_written_onto_one_body_twice_is_refused_and_the_guard_holds(
    pw: PhysicsWorld,
) -> None:
    a, b = disc(pw, 0.0), disc(pw, 2.0)
    hinge = pw.world.spawn(RevoluteJoint(a, b, anchor=(1.0, 0.0)))
    step(pw)
    joint = pw.world.get(hinge, RevoluteJoint)
    with pytest.raises(ValidationError, match=r"entity 3, RevoluteJoint: body_a and body_b"):
        joint.body_a = b  # a joint of b to itself: refused at the write (issue 15)
    assert joint.body_a == a
    # the bridge's guard still keeps such a joint inert if one gets through (raw write)
    raw_set(joint, "body_a", b)
    pw.sim.joints.dirty.add(hinge)
    step(pw)
    assert not pw.sim.joints.handles[hinge].constraints
    pw.world.get(b, RigidBody).type = BodyType.STATIC
    joint.body_a = a
    step(pw)
    assert pw.sim.joints.handles[hinge].constraints


def test_a_gear_built_on_one_body_twice_is_inert() -> None:
    """The handle itself never reaches pymunk's assertion (whatever the world let through)."""
    from tests.joints.conftest import Sim

    sim = Sim()
    a = sim.add_body((0.0, 0.0), circle=0.5)
    b = sim.add_body((2.0, 0.0), circle=0.5)
    e1 = sim.add_joint(RevoluteJoint(a, b, anchor=(1.0, 0.0)))
    e2 = sim.add_joint(RevoluteJoint(a, b, anchor=(1.0, 0.5)))
    gear = sim.add_joint(GearJoint(e1, e2, ratio=-1.0))
    sim.step(10)
    assert not sim.handles[gear].constraints
