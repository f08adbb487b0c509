"""An exception raised inside a pymunk callback reaches the caller of the step.

pymunk runs kge code from C in the middle of a step (contact handlers, the
joints' own solvers in ``pre_solve``, continuous collision's ``position_func``
and post-step callbacks); cffi would print such an exception through
``sys.unraisablehook`` and carry on. Each test makes one of those callbacks
fail and checks that the step raises it, that nothing went to the unraisable
hook, and that the world steps on normally once the fault is gone.
"""

from __future__ import annotations

import sys
from collections.abc import Iterator
from typing import Any

import pymunk
import pytest

from kge.components.collider import Collider
from kge.components.joints import MouseJoint
from kge.components.rigidbody import RigidBody
from kge.components.shapes import Box, Circle
from kge.components.transform import Transform
from kge.physics.ccd import ContinuousCollision, sweep
from kge.physics.contacts import ContactRecorder
from kge.physics.joints.base import Composite
from kge.physics.simulation import Simulation
from tests.physics.conftest import Sim


class Boom(RuntimeError):
    pass


@pytest.fixture
def unraisable(monkeypatch: pytest.MonkeyPatch) -> Iterator[list[Any]]:
    """Everything that reached ``sys.unraisablehook`` during the test."""
    seen: list[Any] = []
    monkeypatch.setattr(sys, "unraisablehook", seen.append)
    yield seen


def _simulation(sim: Sim) -> Simulation:
    return sim.physics._sim


def test_a_failing_joint_solver_raises_from_the_step(unraisable: list[Any]) -> None:
    sim = Sim()
    box = sim.dynamic(Box(0.5, 0.5), 0.0, 2.0)
    joint = sim.spawn(
        MouseJoint(None, box, target=(0.0, 3.0), grab_point=(0.0, 2.0), max_force=1000.0)
    )
    sim.step()  # builds the joint
    handle = _simulation(sim).joints.handles[joint]
    assert isinstance(handle, Composite)  # the handles' base, which runs the solvers
    solve = handle._pre[0]
    calls = 0

    def failing(h: float) -> None:
        nonlocal calls
        calls += 1
        raise Boom("joint solver")

    handle._pre[0] = failing
    with pytest.raises(Boom, match="joint solver"):
        sim.step()
    assert calls == 4  # every substep ran (and failed); the step finished first
    assert unraisable == []
    handle._pre[0] = solve
    y = sim.t(box).y
    sim.step(30)
    assert sim.t(box).y > y + 0.5  # the joint pulls the box up again
    sim.close()


def test_a_failing_sweep_raises_from_the_step(
    unraisable: list[Any], monkeypatch: pytest.MonkeyPatch
) -> None:
    sim = Sim()
    sim.ground()
    ball = sim.dynamic(Circle(0.05), 0.0, 5.0, body=RigidBody(velocity=(0.0, -100.0), bullet=True))

    def failing(self: Any, body: pymunk.Body, dt: float) -> None:
        raise Boom("sweep")

    monkeypatch.setattr(sweep.Tracked, "_move", failing)
    with pytest.raises(Boom, match="sweep"):
        for _ in range(5):  # armed once the ball is fast and near the ground
            sim.step()
    assert unraisable == []
    monkeypatch.undo()
    sim.step(60)
    assert -0.1 < sim.t(ball).y < 0.2  # landed on the ground, did not tunnel
    sim.close()


def test_a_failing_contact_handler_raises_from_the_step(
    unraisable: list[Any], monkeypatch: pytest.MonkeyPatch
) -> None:
    def failing(self: Any, arb: Any) -> None:  # kge's begin gets Chipmunk's arbiter
        raise Boom("begin")

    monkeypatch.setattr(ContactRecorder, "_begin", failing)  # before the handlers are bound
    sim = Sim()
    sim.ground()
    sim.spawn(Transform(0.0, 0.5), RigidBody(), Collider(Circle(0.5)))
    with pytest.raises(Boom, match="begin"):
        sim.step()
    assert unraisable == []
    sim.step()  # the error was raised once, not again
    sim.close()


def test_standalone_ccd_raises_from_after_step(
    unraisable: list[Any], monkeypatch: pytest.MonkeyPatch
) -> None:
    space = pymunk.Space()
    wall = pymunk.Poly(space.static_body, [(5, -2), (5.1, -2), (5.1, 2), (5, 2)])
    ball = pymunk.Body()
    shot = pymunk.Circle(ball, 0.05)
    shot.density = 1.0
    space.add(wall, ball, shot)
    ball.velocity = (500.0, 0.0)
    ccd = ContinuousCollision(space)
    ccd.track(ball)

    def failing(self: Any, body: pymunk.Body, dt: float) -> None:
        raise Boom("standalone")

    monkeypatch.setattr(sweep.Tracked, "_move", failing)
    with pytest.raises(Boom, match="standalone"):
        for _ in range(5):
            ccd.before_step(1 / 60)
            space.step(1 / 60)
            ccd.after_step(1 / 60)
    assert unraisable == []
