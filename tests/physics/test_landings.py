"""Bodies touch surfaces before they sink into them: landings and fast impacts.

Box2D computes the time of impact of a dynamic body against static and kinematic
bodies (and of a bullet against dynamic ones), so a landing body comes to rest
at the surface instead of sinking in and being pushed back out, and a pre-solve
hook that compares positions sees it there. kge used to sink 8-50 mm on a slow
landing and 0.15 m on a 50 m/s impact. Depths are the overlap of the skinned
outlines after each step (polygons carry a 0.01 m skin, circles none).
"""

from __future__ import annotations

import pytest

from kge.components.collider import Collider
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Circle
from kge.components.transform import Transform
from kge.physics.contacts import PreSolve
from kge.physics.settings import PhysicsSettings

from .conftest import Sim

SLOP = 0.005
TOLERANCE = SLOP + 0.001


def land(speed: float, substeps: int, shape: str, steps: int = 90) -> list[float]:
    """Depths after each step of a body thrown down at ``speed`` from 5 cm above the ground."""
    sim = Sim(PhysicsSettings(substeps=substeps))
    sim.ground()
    skin = 0.02 if shape == "box" else 0.01  # its own and the ground's
    geom = Box(0.5, 0.5) if shape == "box" else Circle(0.5)
    e = sim.dynamic(geom, 0.0, 0.5 + skin + 0.05, body=RigidBody(velocity=(0.0, -speed)))
    depths = []
    for _ in range(steps):
        sim.step()
        depths.append(0.5 + skin - sim.t(e).y)
    sim.close()
    return depths


@pytest.mark.parametrize("substeps", range(1, 9))
@pytest.mark.parametrize("speed", (0.3, 1.0, 3.0, 10.0, 50.0))
@pytest.mark.parametrize("shape", ("box", "circle"))
def test_a_landing_comes_to_rest_at_the_surface_without_sinking_first(
    shape: str, speed: float, substeps: int
) -> None:
    depths = land(speed, substeps, shape)
    rest = depths[-1]
    assert -0.001 <= rest <= TOLERANCE  # at the surface, within the slop
    assert max(depths) <= TOLERANCE
    assert max(depths) <= rest + 0.001  # never deeper than where it rests


def _ball_onto_box(speed: float, bullet: bool, dynamic_box: bool, substeps: int) -> list[float]:
    """A ball of radius 0.5 thrown down at ``speed`` onto a 2 x 1 m box: its depth
    into the box after each step."""
    sim = Sim(PhysicsSettings(substeps=substeps))
    sim.ground()
    if dynamic_box:
        box = sim.dynamic(Box(1.0, 0.5), 0.0, 0.515, density=1.0)
    else:
        box = sim.spawn(Transform(0.0, 0.515), Collider(Box(1.0, 0.5)))
    ball = sim.dynamic(Circle(0.5), 0.0, 4.0,
                       body=RigidBody(velocity=(0.0, -speed), bullet=bullet))
    depths = []
    for _ in range(40):
        sim.step()
        top = sim.t(box).y + 0.5 + 0.01
        depths.append(top + 0.5 - sim.t(ball).y)
    sim.close()
    return depths


@pytest.mark.parametrize("substeps", (1, 4, 8))
@pytest.mark.parametrize("bullet", (False, True))
def test_a_fifty_metre_per_second_impact_stops_at_a_static_surface(
    bullet: bool, substeps: int
) -> None:
    """Box2D: every dynamic body gets a time of impact against static bodies
    (kge stopped the ball up to 0.15 m inside before)."""
    depths = _ball_onto_box(50.0, bullet, False, substeps)
    assert max(depths) <= TOLERANCE
    assert depths[-1] >= -0.001  # and it stays there


@pytest.mark.parametrize("substeps", (1, 4, 8))
def test_a_fifty_metre_per_second_bullet_stops_at_a_dynamic_surface(substeps: int) -> None:
    """Box2D: a bullet gets a time of impact against dynamic bodies too."""
    depths = _ball_onto_box(50.0, True, True, substeps)
    assert max(depths) <= TOLERANCE


@pytest.mark.parametrize("substeps", (1, 4))
@pytest.mark.parametrize(("y0", "vy"), [(12.0, -50.0), (13.0, 0.0), (5.0, 13.0)])
def test_a_pre_solve_hook_comparing_positions_keeps_its_platform(
    y0: float, vy: float, substeps: int
) -> None:
    """The manual's one-sided platform (pybox2d's example): the hook disables the
    contact while the ball is below the platform's top by more than 3 slops. It
    reads the pose the ball had after the last step, so a ball that sank into the
    platform on landing fell through it. Thrown at 50 m/s, dropped, or thrown up
    through it from below, the ball ends on top (Box2D: y = 11.005)."""
    sim = Sim(PhysicsSettings(substeps=substeps))
    sim.ground()
    platform = sim.spawn(Transform(0.0, 10.0), Collider(Box(3.0, 0.5), contact_hooks=True))
    ball = sim.dynamic(Circle(0.5), 0.0, y0, body=RigidBody(velocity=(0.0, vy)))
    top = 10.5

    def one_sided(contact: PreSolve) -> None:
        below = sim.t(ball).y - 0.5 + 3 * SLOP < top
        if platform in (contact.collider_a, contact.collider_b) and below:
            contact.enabled = False

    sim.physics.on_pre_solve(one_sided)
    highest = y0
    for _ in range(180):
        sim.step()
        highest = max(highest, sim.t(ball).y)
    if vy > 0:
        assert highest > 11.0  # it went up through the platform
    assert sim.t(ball).y == pytest.approx(11.005, abs=0.01)
    sim.close()


def test_a_kinematic_platform_rising_into_a_resting_box_carries_it_at_the_slop() -> None:
    """A kinematic body that moves into a dynamic one: the dynamic body is moved
    out to the slop, not left inside for the bias to push out."""
    sim = Sim()
    lift = sim.spawn(Transform(0.0, 0.0),
                     RigidBody(type=BodyType.KINEMATIC, velocity=(0.0, 3.0)),
                     Collider(Box(2.0, 0.25)))
    box = sim.dynamic(Box(0.5, 0.5), 0.0, 0.25 + 0.5 + 0.02 + 0.03)  # 3 cm above it
    for _ in range(30):
        sim.step()
        depth = (sim.t(lift).y + 0.25 + 0.01) - (sim.t(box).y - 0.5 - 0.01)
        assert depth <= TOLERANCE
    sim.close()
