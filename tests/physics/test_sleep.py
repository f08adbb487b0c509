"""Sleep timing and wake rules (box2d-reference: sleep)."""

from __future__ import annotations

import pytest

from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Circle
from kge.physics.settings import PhysicsSettings

from .conftest import Sim


def _asleep_step(sim: Sim, e: int, limit: int = 200) -> int | None:
    for step in range(1, limit):
        sim.step()
        if not sim.rb(e).awake:
            return step
    return None


def test_free_body_sleeps_after_half_a_second(zero_g: Sim) -> None:
    e = zero_g.dynamic(Box(0.5, 0.5))
    step = _asleep_step(zero_g, e)
    assert step is not None and abs(step - 30) <= 5


@pytest.mark.parametrize(("linear", "angular"), [(0.5, 0.0), (0.0, 2.0), (0.5, 2.0)])
def test_a_damped_body_sleeps_after_half_a_second(zero_g: Sim, linear: float, angular: float) -> None:
    """Damping used to restart the body's sleep clock every substep (pybox2d's
    apply_force example: its damped ship never slept)."""
    e = zero_g.dynamic(Box(0.5, 0.5), body=RigidBody(linear_damping=linear, angular_damping=angular))
    step = _asleep_step(zero_g, e)
    assert step is not None and abs(step - 30) <= 5


def test_a_damped_body_slows_down_then_sleeps(sim: Sim) -> None:
    sim.ground()
    e = sim.dynamic(Box(0.5, 0.5), 0.0, 0.515,
                    body=RigidBody(velocity=(2.0, 0.0), linear_damping=2.0), friction=0.0)
    sim.step(60)
    assert 0.5 < sim.t(e).x < 1.0 and sim.rb(e).awake  # damped: 1 m undamped by now
    step = _asleep_step(sim, e, 400)
    assert step is not None
    assert sim.t(e).x < 1.05  # Box2D's 2 m/s under c = 2 coasts 1 m in all


def test_slow_drifter_sleeps_and_freezes(zero_g: Sim) -> None:
    slow = zero_g.dynamic(Box(0.5, 0.5), body=RigidBody(velocity=(0.009, 0.0)))
    fast = zero_g.dynamic(Box(0.5, 0.5), 5.0, body=RigidBody(velocity=(0.011, 0.0)))
    step = _asleep_step(zero_g, slow)
    assert step is not None and abs(step - 30) <= 5
    assert zero_g.rb(slow).velocity == (0.0, 0.0)
    x = zero_g.t(slow).x
    assert x == pytest.approx(0.009 * step / 60, abs=0.002)
    zero_g.step(60)
    assert zero_g.t(slow).x == x
    assert zero_g.rb(fast).awake


def test_ball_dropped_on_sleeping_box_wakes_it(sim: Sim) -> None:
    sim.ground()
    box = sim.dynamic(Box(0.5, 0.5), 0.0, 0.515)
    sim.step(60)
    assert not sim.rb(box).awake
    sim.dynamic(Circle(0.25), 0.0, 3.0)
    woke = begin = None
    for step in range(1, 90):
        sim.step()
        if woke is None and sim.rb(box).awake:
            woke = step
        if begin is None and sim.events.contact_begin:
            begin = step
    assert woke is not None and begin is not None and woke <= begin + 1


def test_awake_is_two_way(sim: Sim) -> None:
    sim.ground()
    e = sim.dynamic(Box(0.5, 0.5), 0.0, 0.515)
    sim.step(60)
    assert not sim.rb(e).awake
    sim.rb(e).awake = True
    sim.step()
    assert sim.rb(e).awake
    step = _asleep_step(sim, e)
    assert step is not None and abs(step - 30) <= 5
    f = sim.dynamic(Box(0.5, 0.5), 5.0, 0.515)
    sim.step()
    sim.rb(f).awake = False
    sim.step()
    assert not sim.rb(f).awake


@pytest.mark.parametrize(("drop", "density"), [(0.0, 1.0), (0.085, 1.0), (0.085, 0.0)])
def test_allow_sleep_false_never_sleeps(sim: Sim, drop: float, density: float) -> None:
    sim.ground()
    e = sim.dynamic(Box(0.5, 0.5), 0.0, 0.515 + drop, body=RigidBody(allow_sleep=False),
                    density=density)
    # (a massless box dropped onto the ground, Box2D's mass of 1 kg with no rotation,
    # used to doze off every 0.5 s: pybox2d's edge_test example)
    assert _asleep_step(sim, e, 120) is None
    sim.rb(e).allow_sleep = True
    assert _asleep_step(sim, e, 60) is not None


def test_a_body_that_may_not_sleep_keeps_its_island_awake(sim: Sim) -> None:
    """Box2D sleeps an island only when every body in it may sleep and has rested."""
    sim.ground()
    low = sim.dynamic(Box(0.5, 0.5), 0.0, 0.6, body=RigidBody(allow_sleep=False), density=0.0)
    high = sim.dynamic(Box(0.5, 0.5), 0.0, 1.7)
    apart = sim.dynamic(Box(0.5, 0.5), 3.0, 0.6)
    assert _asleep_step(sim, high, 150) is None
    assert sim.rb(low).awake and not sim.rb(apart).awake


def test_sleep_disabled_in_settings_never_sleeps_and_awake_false_is_safe() -> None:
    s = Sim(PhysicsSettings(sleep=False))
    s.ground()
    e = s.dynamic(Box(0.5, 0.5), 0.0, 0.515)
    assert _asleep_step(s, e, 120) is None
    s.rb(e).awake = False  # would abort pymunk if passed through: must be refused quietly
    s.step()
    assert s.rb(e).awake
    s.close()


def test_stacked_pair_sleeps_together_and_wakes_together(sim: Sim) -> None:
    sim.ground()
    low = sim.dynamic(Box(0.5, 0.5), 0.0, 0.515)
    high = sim.dynamic(Box(0.5, 0.5), 0.0, 1.53)
    sim.step(90)
    assert not sim.rb(low).awake and not sim.rb(high).awake
    sim.physics.apply_linear_impulse(low, (0.5, 0.0))
    sim.step()
    assert sim.rb(high).awake


def test_despawning_a_neighbour_wakes_the_sleeper(sim: Sim) -> None:
    sim.ground()
    low = sim.dynamic(Box(0.5, 0.5), 0.0, 0.515)
    high = sim.dynamic(Box(0.5, 0.5), 0.0, 1.53)
    sim.step(90)
    assert not sim.rb(high).awake
    sim.world.despawn(low)
    sim.step(30)
    assert sim.t(high).y == pytest.approx(0.515, abs=0.01)
