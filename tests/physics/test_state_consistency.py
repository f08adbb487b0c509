"""State that stays consistent: extreme inputs, event delivery, re-parenting, poses.

Defects of state rather than of input, found by probes: extreme but finite values
that turned poses into NaN after one step, begins delivered for entities already
despawned in the same delivery, an implicit static body left behind by a collider
moved onto a body while every collider was being rebuilt, and a Transform pose
written with the wrong shape.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from kge import App, Behaviour, Script, World
from kge.components.collider import Collider
from kge.components.joints import PrismaticJoint, RevoluteJoint, WheelJoint
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Circle
from kge.components.transform import Transform
from kge.errors import ComponentTypeError, ValidationError
from kge.physics.resource import Physics
from kge.physics.settings import PhysicsSettings

from .conftest import Sim


def _finite(sim: Sim, bodies: list[int]) -> bool:
    for e in bodies:
        t, rb = sim.t(e), sim.rb(e)
        values = (t.x, t.y, t.angle, *rb.velocity, rb.angular_velocity)
        if not all(math.isfinite(v) for v in values):
            return False
    return True


@pytest.mark.parametrize(("gravity", "scale"), [
    (-10.0, 1e308), (-10.0, -1e308), (-1e308, 10.0), (1e308, -1e308), (-10.0, 5e307),
])
def test_an_extreme_gravity_scale_leaves_poses_finite(gravity: float, scale: float) -> None:
    """gravity * scale beyond float64 was inf, and the speed cap's inf * 0 a NaN pose."""
    sim = Sim(PhysicsSettings(gravity=(0.0, gravity)))
    sim.ground()
    e = sim.dynamic(Box(0.5, 0.5), 0.0, 2.0, body=RigidBody(gravity_scale=scale))
    sim.step(5)
    assert _finite(sim, [e])
    assert abs(sim.rb(e).velocity[1]) <= 120.0 + 1e-9  # held by the speed cap
    sim.close()


@pytest.mark.parametrize("joint", ["prismatic", "wheel", "revolute"])
@pytest.mark.parametrize(("speed", "force"), [(1e308, 1e308), (-1e308, 1e308), (1e308, 1e300), (5.0, 1e308), (-5.0, 1e308)])
def test_extreme_motor_speeds_and_forces_leave_poses_finite(
    joint: str, speed: float, force: float
) -> None:
    sim = Sim()
    sim.ground()
    a = sim.dynamic(Box(1.0, 0.25), 0.0, 3.0)
    b = sim.dynamic(Circle(0.3), 0.0, 2.0)
    if joint == "prismatic":
        sim.spawn(PrismaticJoint(a, b, anchor=(0.0, 2.0), enable_motor=True,
                                 motor_speed=speed, max_motor_force=force))
    elif joint == "wheel":
        sim.spawn(WheelJoint(a, b, anchor=(0.0, 2.0), local_axis_a=(0.0, 1.0),
                             enable_motor=True, motor_speed=speed, max_motor_torque=force))
    else:
        sim.spawn(RevoluteJoint(a, b, anchor=(0.0, 2.0), enable_motor=True,
                                motor_speed=speed, max_motor_torque=force))
    for _ in range(10):
        sim.step()
        assert _finite(sim, [a, b])
    sim.close()


class _Sweeper(Script):
    """At its first contact, despawns every ball (the other balls' begins of this
    same step are still waiting to be delivered)."""

    def __init__(self) -> None:
        super().__init__()
        self.balls: list[int] = []
        self.seen: list[tuple[int, int]] = []

    def on_contact_begin(self, event: object) -> None:
        self.seen.append((event.collider_a, event.collider_b))  # type: ignore[attr-defined]
        for e in self.balls:
            if self.world.exists(e):
                self.world.despawn(e)


@pytest.mark.filterwarnings("ignore:world.set_handler:DeprecationWarning")
def test_a_begin_naming_an_entity_despawned_earlier_in_the_delivery_is_not_delivered() -> None:
    """Neither to the (deprecated) esper handlers nor to the Behaviour hooks."""
    begins: list[tuple[int, int]] = []
    ends: list[tuple[int, int]] = []
    ids: dict[str, list[int]] = {}
    scripts: list[_Sweeper] = []

    def level(world: World) -> None:
        world.spawn(Transform(0.0, -10.0), Collider(Box(50.0, 10.0)))
        sweeper = _Sweeper()
        scripts.append(sweeper)
        world.spawn(Transform(0.0, 0.6), RigidBody(), Collider(Box(3.0, 0.1)), Behaviour(sweeper))
        balls = [world.spawn(Transform(-1.0 + i, 1.5), RigidBody(velocity=(0.0, -5.0)),
                             Collider(Circle(0.2))) for i in range(3)]
        sweeper.balls = balls
        ids["balls"] = balls

        def on_begin(ev: object) -> None:
            begins.append((ev.collider_a, ev.collider_b))  # type: ignore[attr-defined]

        def on_end(ev: object) -> None:
            ends.append((ev.collider_a, ev.collider_b))  # type: ignore[attr-defined]

        world.set_handler("contact_begin", on_begin)
        world.set_handler("contact_end", on_end)

    app = App(level, headless=True)
    app.step(30)
    first, *others = ids["balls"]
    # the three balls touch the plank (entity 2) in one step: the first begin is
    # delivered, its hook despawns all three, the other two begins are not
    assert (2, first) in begins
    assert not any(ball in pair for pair in begins for ball in others)
    # the hook that despawned them did not get their begins either
    assert (2, first) in scripts[0].seen
    assert not any(ball in pair for pair in scripts[0].seen for ball in others)
    # every end a handler sees follows a begin it saw
    assert sorted(ends) == sorted(p for p in begins if p in ends) and (2, first) in ends
    app.close()


class _SensorSweeper(Script):
    """A sensor zone (or a plank reporting hits) that, at its first begin, despawns
    every ball; it records every sensor begin, sensor end and hit it is given."""

    def __init__(self) -> None:
        super().__init__()
        self.balls: list[int] = []
        self.seen: list[tuple[str, int]] = []

    def _record(self, kind: str, event: object) -> None:
        self.seen.append((kind, event.collider_b))  # type: ignore[attr-defined]
        if kind != "end":
            for e in self.balls:
                if self.world.exists(e):
                    self.world.despawn(e)

    def on_sensor_begin(self, event: object) -> None:
        self._record("begin", event)

    def on_sensor_end(self, event: object) -> None:
        self._record("end", event)

    def on_hit(self, event: object) -> None:
        self._record("hit", event)


@pytest.mark.parametrize("kind", ["sensor", "hit"])
def test_sensor_begins_and_hits_naming_a_despawned_entity_are_not_delivered(kind: str) -> None:
    """Three balls enter a sensor (or hit a plank) in one step: the hook of the first
    despawns all three; the other two begins (hits) never reach a hook, nor the sensor
    ends their despawn brings, while ``world.events`` keeps the step's whole record."""
    from kge.physics.events import Hit, SensorBegin

    ids: dict[str, list[int]] = {}
    scripts: list[_SensorSweeper] = []
    recorded: list[int] = []

    def level(world: World) -> None:
        sweeper = _SensorSweeper()
        scripts.append(sweeper)
        zone = (Collider(Box(3.0, 0.1), sensor=True) if kind == "sensor"
                else Collider(Box(3.0, 0.1), hit_threshold=1.0))
        world.spawn(Transform(0.0, 0.6), zone, Behaviour(sweeper))
        sweeper.balls = ids["balls"] = [
            world.spawn(Transform(-1.0 + i, 1.5), RigidBody(velocity=(0.0, -5.0)),
                        Collider(Circle(0.2))) for i in range(3)
        ]

    app = App(level, headless=True)
    for _ in range(30):
        app.step()
        if kind == "sensor":
            recorded += [ev.collider_b for ev in app.world.events(SensorBegin)]
        else:
            recorded += [ev.collider_b for ev in app.world.events(Hit)]
    first, *others = ids["balls"]
    seen = scripts[0].seen
    begin = "begin" if kind == "sensor" else "hit"
    assert (begin, first) in seen
    assert not any(ball in others for _, ball in seen), seen
    if kind == "sensor":
        assert seen.count(("end", first)) == 1  # the despawn brings the first ball's end
    assert sorted(recorded) == sorted(ids["balls"])  # the record keeps all three
    app.close()


@pytest.mark.parametrize("back", [False, True])
def test_a_static_collider_moved_onto_a_body_while_the_skin_changes_leaves_no_static_body(
    back: bool,
) -> None:
    """Every collider is rebuilt when ``polygon_radius`` changes; a collider moved onto
    a body in the same frame kept its old implicit static body in the space (and,
    moved back to ``body=None``, must get one again)."""
    sim = Sim()
    sim.ground()
    body = sim.dynamic(Box(0.5, 0.5), 0.0, 5.0)
    c = sim.spawn(Transform(3.0, 3.0), Collider(Box(0.2, 0.2)))
    sim.step()
    simulation = sim.world.resource(Physics)._sim
    static_bodies = len(simulation.space.bodies)
    sim.world.get(c, Collider).body = body
    sim.world.resource(PhysicsSettings).polygon_radius = 0.02
    sim.step()
    assert c not in simulation.bodies
    assert len(simulation.space.bodies) == static_bodies - 1
    assert simulation.colliders[c].owner == body
    if back:
        sim.world.get(c, Collider).body = None
        sim.world.resource(PhysicsSettings).polygon_radius = 0.01
        sim.step()
        assert simulation.bodies[c].implicit
        assert len(simulation.space.bodies) == static_bodies
        assert simulation.colliders[c].owner == c
    sim.close()


@pytest.mark.parametrize(("value", "exc", "text"), [
    ((1.0, 2.0, 3.0), ValidationError, "Transform.position must be an (x, y) pair"),
    (5, ComponentTypeError, "Transform.position must be an (x, y) pair"),
    ("ab", ComponentTypeError, "Transform.position must be an (x, y) pair"),
    ((1.0, math.nan), ValidationError, "Transform.position[1] must be finite"),
    ((np.bool_(True), 1.0), ComponentTypeError, "Transform.position[0] must be a number"),
])
def test_a_bad_position_is_refused_and_the_pose_kept(value: object, exc: type[Exception],
                                                     text: str) -> None:
    t = Transform(7.0, 8.0, 0.5)
    with pytest.raises(exc, match=text.replace("(", r"\(").replace(")", r"\)").replace(
            "[", r"\[").replace("]", r"\]")):
        t.position = value  # type: ignore[assignment]
    assert (t.x, t.y, t.angle) == (7.0, 8.0, 0.5)


@pytest.mark.parametrize("value", [np.bool_(True), np.bool_(False), 1 + 2j,
                                   np.complex128(1.0 + 0.0j), complex(2.0, 0.0)])
def test_numpy_bools_and_complex_numbers_are_not_coordinates(value: object) -> None:
    with pytest.raises(ComponentTypeError, match=r"Transform\.x must be a number"):
        Transform(value)  # type: ignore[arg-type]
    t = Transform()
    with pytest.raises(ComponentTypeError, match=r"Transform\.angle must be a number"):
        t.angle = value  # type: ignore[assignment]
    assert t.angle == 0.0


def test_numpy_real_scalars_are_still_numbers() -> None:
    t = Transform(np.float32(1.5), np.int64(2), np.float64(0.25))  # type: ignore[arg-type]
    assert (t.x, t.y, t.angle) == (1.5, 2.0, 0.25)
    assert all(type(v) is float for v in (t.x, t.y, t.angle))
