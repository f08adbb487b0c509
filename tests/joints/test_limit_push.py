"""``PhysicsSettings.hinge_limit_push``: how an iterated hinge's limit treats overshoot.

With a push (kge's default, 0.1 rad/s) pymunk speeds an overshooting hinge back
towards its range; with 0 the limit only stops it, as Box2D's velocity solver
does, and the position pass removes what overshoots b2_angularSlop. A motor that
presses a leg onto its stop is the case that tells them apart: a push lifts the
load the leg carries, every step, and LunarLander's landed hull never came to rest.
"""

from __future__ import annotations

import math

import pytest

from kge.app import App
from kge.components import Transform
from kge.components.collider import Collider
from kge.components.joints import RevoluteJoint
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box
from kge.errors import KgeError
from kge.physics.settings import PhysicsSettings
from kge.world import World


def _pressed_hinge(push: float, overshoot: float) -> tuple[float, float]:
    """A rod hinged to the ground, ``overshoot`` rad past its lower limit (0), its motor
    pressing it further on (no gravity); returns the hinge's speed and angle after one
    step."""

    def setup(world: World) -> None:
        world.insert_resource(PhysicsSettings(gravity=(0.0, 0.0), iterated_hinges=True,
                                              hinge_limit_push=push))
        angle = -overshoot
        rod = world.spawn(Transform(math.cos(angle), math.sin(angle), angle), RigidBody(),
                          Collider(Box(2.0, 0.1), density=1.0))
        ground = world.spawn(Transform(0.0, 0.0), RigidBody(BodyType.STATIC))
        world.spawn(RevoluteJoint(ground, rod, anchor=(0.0, 0.0), reference_angle=0.0,
                                  enable_limit=True, lower_angle=0.0, upper_angle=1.0, enable_motor=True,
                                  motor_speed=-1.0, max_motor_torque=50.0))

    app = App(setup, headless=True)
    app.step(1)
    (_, (joint,)), = app.world.query(RevoluteJoint)
    app.close()
    return joint.speed, joint.angle


@pytest.mark.parametrize("overshoot", [0.005, 0.02, 0.1])
def test_no_push_only_stops_the_hinge_at_its_limit(overshoot: float) -> None:
    speed, angle = _pressed_hinge(0.0, overshoot)
    assert abs(speed) < 1e-6  # stopped against the motor, not sped back
    if overshoot < math.radians(2.0):  # within b2_angularSlop: nothing moves it
        assert angle == pytest.approx(-overshoot, abs=1e-9)
    else:  # the position pass turns it back (one pass: the pivot's share takes some)
        assert -overshoot + 0.02 < angle < 0.0


def test_a_push_speeds_the_hinge_back_at_most_at_its_cap() -> None:
    assert _pressed_hinge(0.1, 0.02)[0] == pytest.approx(0.1)  # capped
    assert _pressed_hinge(0.05, 0.02)[0] == pytest.approx(0.05)
    # pymunk's bias over the substep, below the cap
    assert 0.01 < _pressed_hinge(0.1, 0.005)[0] < 0.05


@pytest.mark.parametrize("bad", [-0.1, math.nan, math.inf, 1e4, "fast"])
def test_bad_push_is_refused(bad: object) -> None:
    with pytest.raises(KgeError, match="hinge_limit_push"):
        PhysicsSettings(hinge_limit_push=bad)  # type: ignore[arg-type]
    settings = PhysicsSettings()
    with pytest.raises(KgeError, match="hinge_limit_push"):
        settings.hinge_limit_push = bad  # type: ignore[assignment]
    assert settings.hinge_limit_push == 0.1
