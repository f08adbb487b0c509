"""RevoluteJoint: pendulum, limits, motor, reaction (box2d-reference.md joint table)."""

from __future__ import annotations

import math

import pytest

from kge.components.joints import RevoluteJoint
from kge.physics.joints.revolute import Revolute
from tests.joints.conftest import Sim, period_of, turning_points


def pendulum(start_deg: float, seconds: float) -> list[float]:
    """Pivot (0, 10); bob r=0.1 d=10 at L=2; returns the swing angle in degrees."""
    sim = Sim()
    th = math.radians(start_deg)
    bob = sim.add_body((2 * math.sin(th), 10 - 2 * math.cos(th)), circle=0.1, density=10.0)
    sim.add_joint(RevoluteJoint(None, bob, anchor=(0.0, 10.0)))
    out = []
    for _ in range(int(seconds * 60)):
        sim.step()
        p = sim.pos(bob)
        out.append(math.degrees(math.atan2(p.x, 10 - p.y)))
    return out


def test_small_swing_period_and_amplitude() -> None:
    swing = pendulum(10.0, 10.0)
    assert period_of(swing, 1 / 60) == pytest.approx(2.8169, rel=0.01)  # Box2D 2.8169
    peaks = turning_points(swing)
    assert peaks[-1] > 10.0 * 0.98  # loses < 2 % in 10 s (Box2D 9.949 after 3.5 cycles)


def test_large_swing_never_gains_energy() -> None:
    swing = pendulum(90.0, 12.0)
    peaks = turning_points(swing)
    assert len(peaks) >= 3
    assert all(b <= a + 1e-6 for a, b in zip([90.0, *peaks], peaks, strict=False))
    first = period_of(swing[:390], 1 / 60)  # between the first two upward crossings
    assert first == pytest.approx(3.319, rel=0.05)  # analytic 3.319; Box2D 3.191


def test_limit_holds_a_dropped_rod_within_two_degrees(sim: Sim) -> None:
    bob = sim.add_body((2.0, 10.0), circle=0.1, density=10.0)
    j = RevoluteJoint(None, bob, anchor=(0.0, 10.0), enable_limit=True,
                      lower_angle=-math.pi / 4, upper_angle=math.pi / 4)
    sim.add_joint(j)
    lowest = 0.0
    for _ in range(180):
        sim.step()
        lowest = min(lowest, j.angle)
    assert math.degrees(j.angle) == pytest.approx(-45.0, abs=2.0)  # Box2D rests at -46.08
    assert math.degrees(lowest) > -45.0 - 2.5  # transient overshoot (Box2D -47.1)
    m = sim.bodies[bob].mass
    assert abs(j.reaction_torque) == pytest.approx(m * 10 * 2 * math.cos(j.angle), rel=0.02)


def test_motor_into_upper_limit(sim: Sim) -> None:
    sim.space.gravity = (0.0, 0.0)
    bob = sim.add_body((2.0, 10.0), circle=0.1, density=10.0)
    j = RevoluteJoint(None, bob, anchor=(0.0, 10.0), enable_limit=True, lower_angle=-0.5,
                      upper_angle=0.5, enable_motor=True, motor_speed=3.0, max_motor_torque=100.0)
    sim.add_joint(j)
    highest = 0.0
    for _ in range(120):
        sim.step()
        highest = max(highest, j.angle)
    assert highest <= 0.5 + math.radians(2.0)  # Box2D 0.5286
    assert j.angle == pytest.approx(0.5, abs=0.01)


def spin_disc(torque: float) -> tuple[Sim, RevoluteJoint, int]:
    sim = Sim(gravity=(0.0, 0.0))
    disc = sim.add_body((0.0, 0.0), circle=1.0)  # I = π/2
    j = RevoluteJoint(None, disc, anchor=(0.0, 0.0), enable_motor=True, motor_speed=2.0,
                      max_motor_torque=torque)
    sim.add_joint(j)
    return sim, j, disc


def test_strong_motor_reaches_speed_at_once() -> None:
    sim, j, _disc = spin_disc(100.0)
    sim.step(2)
    assert j.speed == pytest.approx(2.0, abs=1e-3)  # Box2D 2.0 from step 2
    sim.step(30)
    assert j.speed == pytest.approx(2.0, abs=1e-3)


def test_weak_motor_ramps_at_torque_over_inertia() -> None:
    sim, j, _disc = spin_disc(1.0)
    step = 0
    while j.speed < 2.0 - 1e-6 and step < 400:
        sim.step()
        step += 1
        if step == 100:
            assert j.motor_torque == pytest.approx(1.0, rel=1e-3)
            assert j.speed == pytest.approx(100 / 60 / (math.pi / 2), rel=1e-3)  # τ·t/I
    assert step == pytest.approx(189, abs=2)  # Box2D step 189 (2I/τ = 3.14 s)


def test_motor_as_brake_holds_or_slips(sim: Sim) -> None:
    # bob of 0.5 kg on a 2 m arm, horizontal: gravity torque m·g·L = 10 N·m
    bob = sim.add_body((2.0, 10.0), circle=0.1, density=0.5 / (math.pi * 0.01))
    j = RevoluteJoint(None, bob, anchor=(0.0, 10.0), enable_motor=True, motor_speed=0.0,
                      max_motor_torque=20.0)
    sim.add_joint(j)
    sim.step(30)
    assert abs(j.angle) < 0.01
    assert j.motor_torque == pytest.approx(10.0, rel=0.01)  # Box2D 10.0
    j.max_motor_torque = 5.0  # too weak: the arm slips down
    sim.step(30)
    assert j.angle < -0.1


def test_motor_speed_changed_every_step_tracks_a_servo(sim: Sim) -> None:
    sim.space.gravity = (0.0, 0.0)
    bob = sim.add_body((2.0, 10.0), circle=0.1, density=10.0)
    j = RevoluteJoint(None, bob, anchor=(0.0, 10.0), enable_motor=True, max_motor_torque=50.0)
    e = sim.add_joint(j)
    for _ in range(180):
        j.motor_speed = 4.0 * (1.0 - j.angle)  # gain loop towards 1 rad
        sim.handles[e].apply(j)
        sim.step()
    assert j.angle == pytest.approx(1.0, abs=0.01)


def test_reaction_force_of_a_hanging_box_is_its_weight(sim: Sim) -> None:
    box = sim.add_body((0.0, 5.0), box=(0.5, 0.5), density=2.0)  # m = 2
    j = RevoluteJoint(None, box, anchor=(0.0, 5.5))
    sim.add_joint(j)
    sim.step(60)
    fx, fy = j.reaction_force
    assert fy == pytest.approx(20.0, rel=0.01)  # Box2D (0, 20.000)
    assert abs(fx) < 0.2
    assert abs(j.reaction_torque) < 1e-6


def test_limit_and_motor_switched_on_later(sim: Sim) -> None:
    sim.space.gravity = (0.0, 0.0)
    disc = sim.add_body((0.0, 0.0), circle=1.0)
    j = RevoluteJoint(None, disc)
    e = sim.add_joint(j)
    sim.step(10)
    assert j.speed == 0.0
    j.enable_motor, j.motor_speed, j.max_motor_torque = True, 3.0, 1000.0
    j.enable_limit, j.upper_angle = True, 0.5
    sim.handles[e].apply(j)
    sim.step(60)
    assert j.angle == pytest.approx(0.5, abs=0.01)
    assert j.motor_torque == pytest.approx(1000.0, rel=1e-3)  # pushing into the limit
    assert j.reaction_torque == pytest.approx(-1000.0, rel=1e-3)  # the limit pushes back
    j.enable_limit = False
    sim.handles[e].apply(j)
    sim.step(10)
    assert j.speed == pytest.approx(3.0, abs=1e-3)


def test_moving_the_world_anchor_later_re_resolves_it(sim: Sim) -> None:
    sim.space.gravity = (0.0, 0.0)
    bar = sim.add_body((1.0, 0.0), box=(1.0, 0.1))
    j = RevoluteJoint(None, bar, anchor=(0.0, 0.0))
    e = sim.add_joint(j)
    assert j.anchor is None and j.local_anchor_b == pytest.approx((-1.0, 0.0))
    j.anchor = (1.0, 0.0)  # pin it at its centre instead
    sim.handles[e].apply(j)
    assert j.local_anchor_b == pytest.approx((0.0, 0.0))
    assert j.local_anchor_a == pytest.approx((1.0, 0.0))


def test_taut_plank_bridge_loses_energy_and_stays_joined(sim: Sim) -> None:
    """Box2D testbed's Bridge: 30 planks pinned end to end, exactly spanning the gap.
    pymunk's velocity bias alone makes this gain kilojoules and jitter at 10 m/s."""
    planks = []
    prev: int | None = None
    for i in range(30):
        plank = sim.add_body((-14.5 + i, 5.0), box=(0.5, 0.125), density=20.0)
        sim.add_joint(RevoluteJoint(prev, plank, anchor=(-15.0 + i, 5.0)))
        planks.append(plank)
        prev = plank
    sim.add_joint(RevoluteJoint(prev, None, anchor=(15.0, 5.0)))

    def energy() -> float:
        total = 0.0
        for p in planks:
            b = sim.bodies[p]
            total += 0.5 * b.mass * b.velocity.length**2 + 0.5 * b.moment * b.angular_velocity**2
            total += b.mass * 10.0 * b.position.y
        return total

    start = energy()
    for _ in range(6):
        sim.step(100)
        assert energy() < start + 1.0
    gaps = []
    for h in sim.handles.values():
        assert isinstance(h, Revolute) and h.pivot is not None
        gaps.append(
            abs(h.a.local_to_world(h.pivot.anchor_a) - h.b.local_to_world(h.pivot.anchor_b))
        )
    assert max(gaps) < 0.01
