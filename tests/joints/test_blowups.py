"""Joints never fling bodies or make NaN, whatever pose or settings they start from.

Found by the long fuzz run: a wheel or prismatic joint created between bodies
metres apart flung a light body 10^7-10^8 m within three steps (a weld made to
it afterwards gave NaN). Each case below blew up on the old code; the cause of
each is in the docstring of the part that now prevents it.
"""

from __future__ import annotations

import math

from kge.components.collider import Collider
from kge.components.joints import DistanceJoint, RevoluteJoint, WeldJoint, WheelJoint
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Circle, Polygon
from kge.components.transform import Transform
from tests.reliability.harness import PhysicsWorld, check_invariants

TRIANGLE = Polygon([(0.0, 0.0), (0.6, 0.0), (0.0, 0.4)])


def world_with_ground() -> PhysicsWorld:
    pw = PhysicsWorld()
    pw.world.spawn(Transform(0.0, -1.0), Collider(Box(10.0, 1.0)))
    return pw


def run(pw: PhysicsWorld, steps: int) -> tuple[float, float]:
    """Step with the invariants (no NaN anywhere); the largest |position| and |speed| seen."""
    far = fast = 0.0
    try:
        for _ in range(steps):
            pw.step()
            check_invariants(pw)
            for rec in pw.sim.bodies.values():
                far = max(far, abs(rec.body.position))
                fast = max(fast, abs(rec.body.velocity))
    finally:
        pw.close()
    return far, fast


def test_a_wheel_axis_metres_from_a_light_body_holds_against_a_contact() -> None:
    """pymunk's GrooveJoint projects a 2-D point impulse onto the groove normal, which
    leaks the sliding velocity into it when the line runs far from the body's centre
    (kge/physics/joints/line.py). Old code: 8e6 m."""
    pw = world_with_ground()
    body = pw.world.spawn(Transform(4.96, 0.0), RigidBody(), Collider(TRIANGLE, density=3.8))
    pw.world.spawn(WheelJoint(body, None, anchor=(0.0, 1.0), local_axis_a=(0.0, 1.0)))
    pw.step(3)
    pw.world.spawn(Transform(5.6, 0.0), RigidBody(), Collider(Circle(0.7), density=4.0))
    far, _ = run(pw, 30)
    assert far < 10.0


def test_two_hinges_that_disagree_stay_put() -> None:
    """Two hinges to the ground at anchors that cannot both hold: pymunk's warm start
    fed their opposing impulses until they stopped cancelling (ForgetImpulse in
    kge/physics/joints/base.py). Old code: 9e10 m at step 105."""
    pw = world_with_ground()
    body = pw.world.spawn(Transform(-1.5, 0.4, 0.33), RigidBody(), Collider(TRIANGLE))
    pw.world.spawn(RevoluteJoint(body, None))  # the body's origin on the world's
    pw.world.spawn(RevoluteJoint(None, body, local_anchor_a=(2.395, -0.115),
                                 local_anchor_b=(1.989, -2.302)))
    far, fast = run(pw, 150)
    assert far < 5.0 and fast < 1.0


def test_a_soft_weld_and_a_hinge_that_disagree_stay_put() -> None:
    pw = world_with_ground()
    body = pw.world.spawn(Transform(-1.5, 0.4, 0.33), RigidBody(), Collider(TRIANGLE))
    pw.world.spawn(WeldJoint(body, None, reference_angle=0.95, frequency_hz=30.0,
                             damping_ratio=0.7))
    pw.world.spawn(RevoluteJoint(None, body, local_anchor_a=(2.395, -0.115),
                                 local_anchor_b=(1.989, -2.302)))
    far, _ = run(pw, 100)
    assert far < 5.0


def test_a_stiff_spring_to_the_ground_stays_finite() -> None:
    """pymunk's springs are explicit: past ω·h = 2 they diverge (MAX_SPRING_OMEGA_H in
    kge/physics/joints/base.py). Old code: NaN within 100 steps at 100 Hz."""
    pw = world_with_ground()
    ball = pw.world.spawn(Transform(1.5, 5.0), RigidBody(), Collider(Circle(0.3), density=0.01))
    pw.world.spawn(DistanceJoint(None, ball, anchor_a=(1.5, 8.0), frequency_hz=100.0))
    far, _ = run(pw, 120)
    assert far < 10.0


def test_a_limit_set_far_from_the_angle_pushes_back_gently() -> None:
    """Past its bound a limit pushes back with a velocity that the bodies keep; Box2D
    clamps the correction to 8° (kge/physics/joints/rows.py: correction). Old code:
    the whole chain spun at the speed cap."""
    pw = world_with_ground()
    links = [
        pw.world.spawn(Transform(k, 5.0), RigidBody(), Collider(Box(0.5, 0.1), density=0.1))
        for k in range(6)
    ]
    hinges = [
        pw.world.spawn(RevoluteJoint(None if k == 0 else links[k - 1], links[k],
                                     anchor=(k - 0.5, 5.0), enable_limit=True,
                                     lower_angle=-0.2, upper_angle=0.2))
        for k in range(6)
    ]
    pw.step(10)
    for h in hinges:
        pw.world.get(h, RevoluteJoint).set_limits(3.0, 3.1)
    spin = 0.0
    for _ in range(120):
        pw.step()
        check_invariants(pw)
        spin = max(spin, *(abs(pw.sim.bodies[e].body.angular_velocity) for e in links))
    pw.close()
    assert spin < 0.5 * math.pi * 60  # well below the speed cap (π/2 per step)
