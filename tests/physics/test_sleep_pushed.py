"""Forces and impulses follow Box2D's sleep rule: they wake a sleeping body, and leave
an awake body's clock to its velocity.

Box2D 2.3's ``ApplyForce``, ``ApplyLinearImpulse``, ``ApplyTorque`` and
``ApplyAngularImpulse`` with ``wake=True`` call ``SetAwake(true)`` only on a body that
sleeps (its time at rest starts again from zero); an awake body sleeps once its
island has been below the tolerances for 0.5 s, pushed or not. Measured with pybox2d
2.3.10 (a box half 0.5, no gravity, 8/3 iterations, one push before every step): a
push that leaves it at rest (a zero impulse, a force of 0 N) or barely moves it lets
it fall asleep in step 30; with ``wake=True`` the next push wakes it for another 30
steps (asleep after steps 30, 60, 90...); with ``wake=False`` it stays asleep. Alone
or hinged to a second box. kge's Chipmunk restarts its own timer at every force or
velocity write, so such a body never slept (a top-down car's tyres, pushed sideways
by their friction impulses every step).
"""

from __future__ import annotations

from collections.abc import Callable

import pytest

from kge.components import joints
from kge.components.shapes import Box
from kge.physics.resource import Physics

from .conftest import Sim

PUSHES: dict[str, Callable[[Physics, int, int, bool], None]] = {
    "zero impulse": lambda p, e, k, wake: p.apply_linear_impulse(e, (0.0, 0.0), wake=wake),
    # +-1 mm/s, alternating: moving, below Box2D's 0.01 m/s
    "small impulses": lambda p, e, k, wake: p.apply_linear_impulse(
        e, (0.001 * (-1) ** k, 0.0), wake=wake),
    "zero force": lambda p, e, k, wake: p.apply_force(e, (0.0, 0.0), (0.3, 0.0), wake=wake),
    "zero torque": lambda p, e, k, wake: p.apply_torque(e, 0.0, wake=wake),
    "zero angular impulse": lambda p, e, k, wake: p.apply_angular_impulse(e, 0.0, wake=wake),
    "bulk impulses": lambda p, e, k, wake: p.apply_linear_impulses([e], [(0.0, 0.0)], wake=wake),
}


def _asleep_after(sim: Sim, pushed: int, bodies: list[int], push: Callable[..., None],
                  wake: bool, steps: int) -> list[int]:
    """The steps (1-based) after which every body of ``bodies`` read asleep."""
    out = []
    for k in range(steps):
        push(sim.physics, pushed, k, wake)
        sim.step()
        if not any(sim.rb(e).awake for e in bodies):
            out.append(k + 1)
    return out


@pytest.mark.parametrize("hinged", [False, True], ids=["alone", "hinged"])
@pytest.mark.parametrize("how", sorted(PUSHES))
def test_a_body_pushed_every_step_sleeps_as_in_box2d(zero_g: Sim, how: str, hinged: bool) -> None:
    a = zero_g.dynamic(Box(0.5, 0.5))
    bodies = [a]
    if hinged:
        b = zero_g.dynamic(Box(0.5, 0.5), 2.0)
        zero_g.spawn(joints.RevoluteJoint(a, b, anchor=(1.0, 0.0)))
        bodies.append(b)
    # pybox2d 2.3.10: asleep after step 30, woken by the next push, asleep after 60, 90
    assert _asleep_after(zero_g, a, bodies, PUSHES[how], True, 100) == [30, 60, 90]


@pytest.mark.parametrize("how", sorted(PUSHES))
def test_a_push_without_wake_leaves_a_sleeper_asleep(zero_g: Sim, how: str) -> None:
    a = zero_g.dynamic(Box(0.5, 0.5))
    assert _asleep_after(zero_g, a, [a], PUSHES[how], False, 100) == list(range(30, 101))


def test_a_pushed_island_wakes_whole_and_its_still_bodies_read_awake(zero_g: Sim) -> None:
    """Waking one body wakes its island (Box2D's next island solve does): the hinged
    box, which does not move, reads awake too, and its clock starts from zero."""
    a = zero_g.dynamic(Box(0.5, 0.5))
    b = zero_g.dynamic(Box(0.5, 0.5), 2.0)
    zero_g.spawn(joints.RevoluteJoint(a, b, anchor=(1.0, 0.0)))
    zero_g.step(30)
    assert not zero_g.rb(a).awake and not zero_g.rb(b).awake
    zero_g.physics.apply_linear_impulse(a, (0.0, 0.0))
    zero_g.step()
    assert zero_g.rb(a).awake and zero_g.rb(b).awake
    zero_g.step(28)
    assert zero_g.rb(b).awake  # 29 steps at rest since it woke
    zero_g.step()
    assert not zero_g.rb(a).awake and not zero_g.rb(b).awake


def test_a_pushed_body_that_moves_stays_awake(zero_g: Sim) -> None:
    a = zero_g.dynamic(Box(0.5, 0.5))
    for _ in range(100):
        zero_g.physics.apply_force(a, (1.0, 0.0))
        zero_g.step()
        assert zero_g.rb(a).awake
