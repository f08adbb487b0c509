"""Pre-solve / post-solve hooks, one-way platforms, conveyor belts (box2d-reference)."""

from __future__ import annotations

import pytest

from kge.components.collider import Collider
from kge.components.platform import OneWayPlatform
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Circle
from kge.components.transform import Transform
from kge.physics.contacts import PostSolve, PreSolve

from .conftest import Sim


def _platform_scene(one_way: bool, y0: float, vy: float) -> tuple[float, float]:
    s = Sim()
    s.ground()
    comps: list[object] = [Transform(0.0, 10.0), Collider(Box(3.0, 0.5))]
    if one_way:
        comps.append(OneWayPlatform())
    s.spawn(*comps)
    ball = s.dynamic(Circle(0.5), 0.0, y0, body=RigidBody(velocity=(0.0, vy)))
    top = y0
    for _ in range(240):
        s.step()
        top = max(top, s.t(ball).y)
    y = s.t(ball).y
    s.close()
    return top, y


def test_one_way_platform_from_below_lands_on_top() -> None:
    top, y = _platform_scene(True, 5.0, 13.0)
    assert top > 12.0
    assert y == pytest.approx(11.005, abs=0.02)


def test_one_way_platform_from_above() -> None:
    _, y = _platform_scene(True, 13.0, 0.0)
    assert y == pytest.approx(11.005, abs=0.02)


def test_plain_platform_blocks_from_below() -> None:
    top, y = _platform_scene(False, 5.0, 13.0)
    assert top < 9.05  # Box2D 8.995
    assert y < 1.0


def test_pre_solve_disable_and_called_once_per_step(sim: Sim) -> None:
    sim.ground()
    hooked = sim.dynamic(Box(0.5, 0.5), 0.0, 0.6, contact_hooks=True)
    plain = sim.dynamic(Box(0.5, 0.5), 3.0, 0.6)
    calls: list[tuple[int, int]] = []

    def hook(c: PreSolve) -> None:
        calls.append((sim.steps, c.collider_b))
        if sim.steps >= 30:
            c.enabled = False

    sim.physics.on_pre_solve(hook)
    sim.step(30)
    assert sim.t(hooked).y == pytest.approx(0.515, abs=0.01)
    assert all(b == hooked for _, b in calls)
    steps = [s for s, _ in calls]
    assert len(steps) == len(set(steps))  # once per step, not per substep
    sim.step(30)
    assert sim.t(hooked).y < -0.5  # falling through the disabled contact
    assert sim.t(plain).y == pytest.approx(0.515, abs=0.01)


def test_conveyor_belt_tangent_speed(sim: Sim) -> None:
    belt = sim.spawn(Transform(0.0, 0.0), Collider(Box(20.0, 0.25), friction=0.8,
                                                    contact_hooks=True))
    box = sim.dynamic(Box(0.5, 0.5), 0.0, 0.765, friction=0.8)

    def conveyor(c: PreSolve) -> None:
        if c.collider_a == belt:
            c.tangent_speed = 2.0

    sim.physics.on_pre_solve(conveyor)
    sim.step(120)
    assert sim.rb(box).velocity[0] == pytest.approx(2.0, abs=0.05)


def test_pre_solve_friction_override(sim: Sim) -> None:
    sim.spawn(Transform(0.0, 0.0), Collider(Box(20.0, 0.25), friction=1.0, contact_hooks=True))
    box = sim.dynamic(Box(0.5, 0.5), 0.0, 0.765, friction=1.0,
                      body=RigidBody(velocity=(3.0, 0.0)))

    def ice(c: PreSolve) -> None:
        assert c.friction == pytest.approx(1.0)
        c.friction = 0.0

    sim.physics.on_pre_solve(ice)
    sim.step(60)
    assert sim.rb(box).velocity[0] == pytest.approx(3.0, abs=0.02)


@pytest.mark.parametrize("shape,density,mass,points", [
    (Box(0.5, 0.5), 1.0, 1.0, 2),
    (Box(0.5, 0.5), 4.0, 4.0, 2),
    (Circle(0.5), 1.0, 0.785398, 1),
])
def test_post_solve_impulses(sim: Sim, shape: object, density: float, mass: float,
                             points: int) -> None:
    sim.ground()
    e = sim.dynamic(shape, 0.0, 0.52, density=density, contact_hooks=True,
                    body=RigidBody(allow_sleep=False))
    got: list[PostSolve] = []
    sim.physics.on_post_solve(got.append)
    sim.step(40)
    got.clear()
    sim.step()
    assert len(got) == 1
    ev = got[0]
    assert ev.collider_b == e and ev.point_count == points
    assert ev.normal == pytest.approx((0.0, 1.0))
    assert ev.normal_impulse == pytest.approx(mass * 10.0 / 60.0, rel=0.03)
    assert abs(ev.tangent_impulse) < 1e-6


def test_sensors_get_no_solve_hooks(sim: Sim) -> None:
    sim.spawn(Transform(0, 0), Collider(Box(2, 2), sensor=True, contact_hooks=True))
    sim.dynamic(Circle(0.5), 0.0, 0.0, contact_hooks=True)
    pre: list[PreSolve] = []
    post: list[PostSolve] = []
    sim.physics.on_pre_solve(pre.append)
    sim.physics.on_post_solve(post.append)
    sim.step(5)
    assert pre == [] and post == []
    assert len(sim.system.sim.recorder.active) == 1


def test_exception_in_a_hook_is_raised_after_the_step(sim: Sim) -> None:
    sim.ground()
    ball = sim.dynamic(Circle(0.5), 0.0, 0.51, contact_hooks=True)

    def bad(c: PreSolve) -> None:
        raise RuntimeError("boom")

    sim.physics.on_pre_solve(bad)
    with pytest.raises(RuntimeError, match="boom"):
        sim.step(3)
    assert not sim.world.is_locked
    sim.physics.remove_hook(bad)
    sim.step(3)
    assert sim.t(ball).y == pytest.approx(0.505, abs=0.01)


def test_locked_world_error_reaches_the_caller(sim: Sim) -> None:
    from kge.errors import WorldLockedError

    sim.ground()
    sim.dynamic(Circle(0.5), 0.0, 0.51)

    def spawner(a: int, b: int) -> bool:
        sim.world.spawn(Transform())
        return True

    sim.physics.contact_filter = spawner
    n = len(sim.world.entities())
    with pytest.raises(WorldLockedError):
        sim.step(2)
    assert len(sim.world.entities()) == n


def test_events_of_a_step_whose_hook_raised_are_delivered_with_the_next(sim: Sim) -> None:
    """A failing pre-solve hook must not lose the begin event recorded in that step."""
    sim.ground()
    sim.dynamic(Circle(0.5), 0.0, 0.52, contact_hooks=True)
    seen: list[object] = []
    sim.world.set_handler("contact_begin", seen.append)
    calls = 0

    def bad_once(c: PreSolve) -> None:
        nonlocal calls
        calls += 1
        if calls == 1:
            raise RuntimeError("boom")

    sim.physics.on_pre_solve(bad_once)
    with pytest.raises(RuntimeError, match="boom"):
        for _ in range(30):
            sim.step()
    assert seen == []  # the failing step's delivery never ran
    sim.step()
    assert len(seen) == 1, "the begin of the failed step is delivered with the next one"
    sim.step(3)
    assert len(seen) == 1
