"""A velocity written every step holds at the linear slop, as Box2D's SetLinearVelocity does.

The character walks into a wall by writing ``RigidBody.velocity`` (or applying the
impulse that reaches it) before every step. Box2D solves that velocity against
the contacts before it moves anything and the body stays at the linear slop,
0.005 m of overlap of the skinned outlines; kge used to move first and settled
0.019-0.447 m deep (1-12 m/s), tunnelling with one substep. Depths are the
overlap of the outlines with their skins (0.01 m on polygons, edges and chains),
read from the poses after every step.
"""

from __future__ import annotations

import pytest

from kge.components.collider import Collider
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Chain, Circle, Edge
from kge.components.transform import Transform
from kge.physics.settings import PhysicsSettings

from .conftest import Sim

SLOP = 0.005
TOLERANCE = SLOP + 0.001  # the linear slop plus 1 mm
SKIN = 0.01
FACE = 5.0
SPEEDS = (1.0, 3.0, 6.0, 12.0, 30.0, 60.0)
SUBSTEPS = tuple(range(1, 9))
#: where the skinned face of the wall behind the pressed crate starts (at the slop)
WALL_BEHIND = FACE + 1.0 + 2 * SKIN - SLOP


def _wall(sim: Sim, wall: str) -> int | None:
    """The wall the walker meets at x = FACE; returns the crate entity, if any."""
    if wall == "box":  # 3 m thick
        sim.spawn(Transform(FACE + 1.5, 5.0), Collider(Box(1.5, 5.0)))
    elif wall == "edge":
        sim.spawn(Transform(), Collider(Edge((FACE, 0.0), (FACE, 10.0))))
    elif wall == "chain-ccw":
        sim.spawn(Transform(), Collider(Chain([(FACE, 0.0), (FACE, 10.0)])))
    elif wall == "chain-cw":
        sim.spawn(Transform(), Collider(Chain([(FACE, 10.0), (FACE, 0.0)])))
    else:  # a 1 kg crate resting on the ground: against a static wall, or free
        crate = sim.dynamic(Box(0.5, 0.5), FACE + 0.5 + SKIN, 0.5 + 2 * SKIN - SLOP)
        if wall == "pressed-crate":  # touching the crate at the slop
            sim.spawn(Transform(WALL_BEHIND + 1.5 - SKIN, 5.0), Collider(Box(1.5, 5.0)))
        return crate
    return None


def walk(speed: float, substeps: int, wall: str = "box", mover: str = "box",
         impulse: bool = False, seconds: float = 1.0) -> tuple[list[float], bool]:
    """Depths after every step of a walker driven at ``speed`` into ``wall``, and
    whether its centre ever passed the face it meets. For a pressed crate, each
    depth is the larger of the walker's into the crate and the crate's into the wall."""
    sim = Sim(PhysicsSettings(substeps=substeps))
    sim.ground()
    crate = _wall(sim, wall)
    shape = Box(0.5, 0.5) if mover == "box" else Circle(0.5)
    half = 0.5 + (SKIN if mover == "box" else 0.0)
    rest = 0.5 + (2 * SKIN if mover == "box" else SKIN) - SLOP
    e = sim.dynamic(shape, FACE - half - SKIN - 0.5, rest,
                    body=RigidBody(type=BodyType.DYNAMIC, fixed_rotation=True), friction=0.2)
    depths, past = [], False
    for _ in range(round(seconds * 60) + round(0.5 / speed * 60) + 1):
        rb = sim.rb(e)
        if impulse:
            mass = sim.physics.mass_data(e).mass
            sim.physics.apply_linear_impulse(e, (mass * (speed - rb.velocity[0]), 0.0))
        else:
            rb.velocity = (speed, rb.velocity[1])
        sim.step()
        face = FACE - SKIN if crate is None else sim.t(crate).x - 0.5 - SKIN
        x = sim.t(e).x
        depth = x + half - face
        if wall == "pressed-crate" and crate is not None:
            depth = max(depth, sim.t(crate).x + 0.5 + SKIN - WALL_BEHIND)
        depths.append(depth)
        past = past or x > face + SKIN
    sim.close()
    return depths, past


@pytest.mark.parametrize("substeps", SUBSTEPS)
@pytest.mark.parametrize("speed", SPEEDS)
def test_velocity_written_every_step_holds_at_the_slop(speed: float, substeps: int) -> None:
    """The issue's table: 0.019 / 0.100 / 0.216 / 0.447 m deep at 1 / 3 / 6 / 12 m/s
    (4 substeps) before, and through the wall with one substep."""
    depths, past = walk(speed, substeps)
    assert not past
    assert max(depths) <= TOLERANCE
    assert depths[-1] >= -0.001  # resting against the wall, not bounced off


@pytest.mark.parametrize("substeps", (1, 8))
@pytest.mark.parametrize("speed", (6.0, 60.0))
@pytest.mark.parametrize("mover", ("box", "circle"))
@pytest.mark.parametrize("wall", ("box", "edge", "chain-ccw", "chain-cw"))
def test_every_wall_shape_and_winding(wall: str, mover: str, speed: float,
                                      substeps: int) -> None:
    depths, past = walk(speed, substeps, wall, mover, seconds=0.5)
    assert not past
    assert max(depths) <= TOLERANCE


@pytest.mark.parametrize("substeps", (1, 4))
@pytest.mark.parametrize("speed", (6.0, 60.0))
def test_an_impulse_to_the_same_velocity_holds_too(speed: float, substeps: int) -> None:
    """apply_linear_impulse up to the walking speed every step (0.107 m deep at 6 m/s)."""
    depths, past = walk(speed, substeps, impulse=True, seconds=0.5)
    assert not past
    assert max(depths) <= TOLERANCE


@pytest.mark.parametrize("substeps", SUBSTEPS)
@pytest.mark.parametrize("speed", (6.0, 12.0, 60.0))
@pytest.mark.parametrize("wall", ("pressed-crate", "free-crate"))
def test_dynamic_geometry_holds_at_the_slop(wall: str, speed: float, substeps: int) -> None:
    """A crate pressed against a wall, or pushed along the ground: the walker stays
    out of it within the slop, from the first touch on (Box2D lets non-bullets
    overlap by up to one step's motion at the first touch; a body whose velocity
    was set from outside the solver gets a time of impact against dynamic bodies
    in kge), and the crate stays out of the wall."""
    depths, past = walk(speed, substeps, wall, seconds=0.75)
    assert not past
    assert max(depths) <= TOLERANCE


@pytest.mark.parametrize("speed", (2.0, 6.0))
def test_pressing_into_a_wall_makes_friction_as_in_box2d(speed: float) -> None:
    """Box2D solves the written velocity before moving: the normal impulse that stops
    it allows friction, and a body pushed into a wall (friction 0.2 both sides)
    at 2 or 6 m/s does not slide down it (pybox2d 2.3.10: 0.000 m in 1 s; kge
    before: 0.003 m, one substep). With substeps the push's friction acts in the
    first substep only, and the body slides about 0.06 m/s (docs/physics.md)."""
    sim = Sim(PhysicsSettings(substeps=1))
    sim.spawn(Transform(FACE + 1.5, 5.0), Collider(Box(1.5, 5.0), friction=0.2))
    e = sim.dynamic(Box(0.5, 0.5), FACE - 0.5 - 2 * SKIN + SLOP, 5.0,
                    body=RigidBody(type=BodyType.DYNAMIC, fixed_rotation=True), friction=0.2)
    sim.step()
    y0 = sim.t(e).y
    for _ in range(60):
        sim.rb(e).velocity = (speed, sim.rb(e).velocity[1])
        sim.step()
    assert sim.t(e).y == pytest.approx(y0, abs=0.001)
    sim.close()


def test_a_jump_written_while_standing_starts_at_once() -> None:
    """Velocity away from a contact is kept whole: one step after writing vy = 5 the
    body has risen what Box2D's first step gives (4.833 m/s * dt = 0.0806 m)."""
    sim = Sim()
    sim.ground()
    e = sim.dynamic(Box(0.5, 0.5), 0.0, 0.5 + 2 * SKIN - SLOP)
    sim.step(30)
    y0 = sim.t(e).y
    sim.rb(e).velocity = (0.0, 5.0)
    sim.step()
    assert sim.t(e).y - y0 == pytest.approx(0.0806, abs=0.003)
    assert sim.rb(e).velocity[1] == pytest.approx(5.0 - 10.0 / 60.0, abs=1e-6)
    sim.close()


def test_many_bodies_pushed_at_once_hold_at_the_slop() -> None:
    """A row of 16 walkers pushed by one bulk impulse call every step, each into its own
    wall (more bodies than the contact lists are walked for one by one)."""
    sim = Sim()
    sim.ground()
    walkers = []
    for k in range(16):
        y = 0.515 + 2.0 * k
        sim.spawn(Transform(FACE + 1.5, y), Collider(Box(1.5, 0.45)))  # a wall per row
        if k:
            sim.spawn(Transform(FACE - 3.0, y - 0.515 - 0.25), Collider(Box(8.0, 0.25)))  # a shelf
        walkers.append(sim.dynamic(Box(0.5, 0.5), FACE - 0.5 - 2 * SKIN - 0.3, y,
                                   body=RigidBody(type=BodyType.DYNAMIC, fixed_rotation=True)))
    deepest = 0.0
    for _ in range(60):
        pushes = [(sim.physics.mass_data(e).mass * (12.0 - sim.rb(e).velocity[0]), 0.0)
                  for e in walkers]
        sim.physics.apply_linear_impulses(walkers, pushes)
        sim.step()
        deepest = max(deepest, max(sim.t(e).x + 0.5 + SKIN - (FACE - SKIN) for e in walkers))
    assert deepest <= TOLERANCE
    sim.close()


@pytest.mark.parametrize("substeps", (1, 4))
def test_a_sleeping_crate_is_met_at_the_slop(substeps: int) -> None:
    """The walker's first touch of a crate that fell asleep is settled on the walker's
    side (the sleeper cannot be moved back; Chipmunk wakes it after the contact)."""
    sim = Sim(PhysicsSettings(substeps=substeps))
    sim.ground()
    crate = sim.dynamic(Box(0.5, 0.5), FACE + 0.5 + SKIN, 0.5 + 2 * SKIN - SLOP)
    e = sim.dynamic(Box(0.5, 0.5), FACE - 6.0, 0.5 + 2 * SKIN - SLOP,
                    body=RigidBody(type=BodyType.DYNAMIC, fixed_rotation=True))
    sim.step(40)
    assert not sim.rb(crate).awake
    deepest = 0.0
    for _ in range(30):
        sim.rb(e).velocity = (30.0, sim.rb(e).velocity[1])
        sim.step()
        deepest = max(deepest, sim.t(e).x + 0.5 + SKIN - (sim.t(crate).x - 0.5 - SKIN))
    assert sim.rb(crate).awake
    assert deepest <= TOLERANCE
    sim.close()
