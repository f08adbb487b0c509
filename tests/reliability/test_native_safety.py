"""Nothing reachable from kge's API may corrupt Chipmunk's contact graph.

Chipmunk threads arbiters (contacts) and constraints on their bodies and parks them
outside the space's active arrays while a component sleeps. Three of its entry
points, used on a body in the space next to other bodies, left that graph with
dangling or doubly pushed entries, which crashed the interpreter steps later
(segfaults in ``cpSpaceRemoveShape``, ``free(): invalid pointer`` or a Chipmunk
abort inside ``cpSpaceStep``); benchmarks/results/reliability.md has the story:

* a type change of a static body under sleeping bodies, or of a sleeping body
  (``cpBodySetType`` in place);
* ``RigidBody.awake = False`` on a body touching or jointed to an awake body
  (``cpBodySleep``);
* disabling, detaching or despawning around such bodies.

A regression is a native crash, which would kill pytest, so each scenario runs in a
child process; the parent reports its exit status and output. Inside the child,
:func:`contact_graph_problems` reads the graph through Chipmunk's C API after every
step, so a corrupt graph fails the scenario the step it appears, before it crashes.
"""

from __future__ import annotations

import os
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

from kge.components.collider import Collider
from kge.components.joints import RevoluteJoint
from kge.components.rigidbody import BodyType, RigidBody
from kge.components.shapes import Box, Circle
from kge.components.transform import Transform

from .harness import (
    PhysicsWorld,
    check_invariants,
    check_no_leftovers,
    contact_graph_problems,
)

ROOT = Path(__file__).resolve().parents[2]
HERE = Path(__file__).resolve().parent

# -- scenario helpers ---------------------------------------------------------------------
def _step(pw: PhysicsWorld, n: int = 1) -> None:
    """Step and check everything after each step (ECS mirror and the contact graph)."""
    import gc

    for _ in range(n):
        pw.step()
        gc.collect()  # free what kge dropped, so a dangling pointer dangles now
        check_invariants(pw)
        problems = contact_graph_problems(pw.sim.space)
        assert not problems, problems


def _box(pw: PhysicsWorld, x: float, y: float, kind: BodyType = BodyType.DYNAMIC,
         hw: float = 0.45, hh: float = 0.45) -> int:
    return pw.world.spawn(Transform(x, y), RigidBody(type=kind), Collider(Box(hw, hh)))


def _rb(pw: PhysicsWorld, e: int) -> RigidBody:
    return pw.world.get(e, RigidBody)


def _stack(pw: PhysicsWorld, base: BodyType, n: int = 3) -> tuple[int, list[int]]:
    """A platform of type ``base`` on the ground and ``n`` boxes on it, all at rest."""
    pw.world.spawn(Transform(0.0, -1.0), Collider(Box(10.0, 1.0)))
    platform = _box(pw, 0.0, 0.5, base, 2.0, 0.5)
    boxes = [_box(pw, 0.0, 1.45 + 0.9 * k) for k in range(n)]
    return platform, boxes


def _until_asleep(pw: PhysicsWorld, bodies: list[int], limit: int = 120) -> None:
    for _ in range(limit):
        _step(pw)
        if not any(_rb(pw, e).awake for e in bodies):
            return
    raise AssertionError(f"bodies {bodies} did not fall asleep")


def _empty_the_world(pw: PhysicsWorld) -> None:
    """Despawn everything; the space must empty and no internal map keep anything."""
    _step(pw)
    check_no_leftovers(pw)
    for e in pw.world.entities():
        pw.world.despawn(e)
    _step(pw, 2)
    space = pw.sim.space
    assert not space.bodies and not space.shapes and not space.constraints
    check_no_leftovers(pw)
    assert not pw.balance.live_pairs(), "begin events without an end"
    pw.close()


# -- scenarios (run in a child process) ---------------------------------------------------
def type_change_under_a_sleeping_stack() -> None:
    """cpBodySetType did not wake bodies sleeping on a static body made dynamic or kinematic."""
    for new in (BodyType.DYNAMIC, BodyType.KINEMATIC):
        pw = PhysicsWorld()
        platform, boxes = _stack(pw, BodyType.STATIC)
        _until_asleep(pw, boxes)
        _rb(pw, platform).type = new
        _step(pw)
        assert all(_rb(pw, e).awake for e in boxes), "the stack must wake (Box2D SetType)"
        _step(pw, 5)
        pw.world.despawn(boxes[-1])
        _step(pw)
        _rb(pw, platform).enabled = False
        _step(pw, 3)
        _rb(pw, platform).enabled = True
        _rb(pw, platform).type = BodyType.STATIC
        _step(pw, 3)
        _empty_the_world(pw)


def type_change_of_a_sleeping_body() -> None:
    """cpBodySetType made a sleeping body non-dynamic before waking it: it stayed in its
    sleeping component, and waking the component later aborted (or used freed memory)."""
    for new in (BodyType.KINEMATIC, BodyType.STATIC):
        for which in (0, 1, 2):
            pw = PhysicsWorld()
            _, boxes = _stack(pw, BodyType.STATIC)
            _until_asleep(pw, boxes)
            _rb(pw, boxes[which]).type = new
            _step(pw, 3)
            _rb(pw, boxes[which]).type = BodyType.DYNAMIC
            _step(pw, 3)
            _empty_the_world(pw)


def manual_sleep_next_to_an_awake_body() -> None:
    """cpBodySleep on a body touching an awake one left half-parked arbiters."""
    pw = PhysicsWorld()
    pw.world.spawn(Transform(0.0, -1.0), Collider(Box(10.0, 1.0)))
    a = _box(pw, 0.0, 0.5)
    b = _box(pw, 0.0, 1.45)
    _step(pw, 10)
    assert _rb(pw, a).awake and _rb(pw, b).awake
    _rb(pw, a).awake = False  # b rests on it, awake
    _step(pw)
    assert _rb(pw, a).awake, "a body touching an awake body stays awake (Box2D islands)"
    _rb(pw, b).awake = False
    _step(pw, 2)
    # both asked at once: the island (a, b) sleeps at once
    _rb(pw, a).awake = False
    _rb(pw, b).awake = False
    _step(pw)
    assert not _rb(pw, a).awake and not _rb(pw, b).awake
    assert _rb(pw, a).velocity == (0.0, 0.0)
    pw.physics.apply_linear_impulse(b, (0.0, 0.1))
    _step(pw)
    assert _rb(pw, a).awake and _rb(pw, b).awake, "one island: both wake"
    _until_asleep(pw, [a, b])
    c = _box(pw, 3.0, 0.5)
    _step(pw, 2)
    _rb(pw, c).awake = False  # only the ground touches it: sleeps at once
    _step(pw)
    assert not _rb(pw, c).awake
    pw.world.despawn(a)
    _step(pw, 3)
    _empty_the_world(pw)


def manual_sleep_of_jointed_bodies() -> None:
    """cpBodySleep on a body jointed to an awake body, then type changes and wake-ups."""
    pw = PhysicsWorld()
    pw.world.spawn(Transform(0.0, -1.0), Collider(Box(10.0, 1.0)))
    a = _box(pw, 0.0, 2.0)
    b = _box(pw, 1.0, 2.0)
    c = _box(pw, -3.0, 2.0)
    pw.world.spawn(RevoluteJoint(a, b, anchor=(0.5, 2.0)))
    pw.world.spawn(RevoluteJoint(c, None, anchor=(-3.0, 3.0)))
    _step(pw, 3)
    _rb(pw, a).awake = False  # jointed to awake b
    _rb(pw, c).awake = False  # jointed to the ground only: sleeps at once
    _step(pw)
    assert _rb(pw, a).awake and not _rb(pw, c).awake
    _rb(pw, b).type = BodyType.STATIC
    _step(pw, 2)
    _rb(pw, a).awake = False  # now its only neighbour is static
    _step(pw)
    assert not _rb(pw, a).awake
    _rb(pw, b).type = BodyType.DYNAMIC  # wakes a through the joint
    _rb(pw, c).type = BodyType.KINEMATIC
    _step(pw, 3)
    assert _rb(pw, a).awake
    _rb(pw, c).type = BodyType.DYNAMIC
    _rb(pw, b).awake = False
    _step(pw, 3)
    _rb(pw, a).enabled = False
    _step(pw, 2)
    _empty_the_world(pw)


def manual_sleep_next_to_a_kinematic_body() -> None:
    """A body carried by a kinematic platform cannot sleep (Chipmunk and Box2D agree)."""
    pw = PhysicsWorld()
    platform = _box(pw, 0.0, 0.5, BodyType.KINEMATIC, 2.0, 0.5)
    _rb(pw, platform).velocity = (0.5, 0.0)
    box = _box(pw, 0.0, 1.45)
    ball = pw.world.spawn(Transform(0.0, 3.0), RigidBody(), Collider(Circle(0.3)))
    _step(pw, 20)
    _rb(pw, box).awake = False
    _rb(pw, ball).awake = False
    _step(pw)
    assert _rb(pw, box).awake
    _rb(pw, platform).type = BodyType.STATIC
    _step(pw, 3)
    _empty_the_world(pw)


def enable_detach_and_despawn_around_sleepers() -> None:
    """Disable, re-enable, remove and reshape colliders of sleeping bodies and their support."""
    pw = PhysicsWorld()
    platform, boxes = _stack(pw, BodyType.STATIC, 4)
    _until_asleep(pw, boxes)
    _rb(pw, boxes[1]).enabled = False
    _step(pw, 2)
    _rb(pw, boxes[1]).enabled = True
    _until_asleep(pw, [boxes[0]])
    pw.world.remove(boxes[3], Collider)
    _step(pw)
    pw.world.get(platform, Collider).shape = Box(3.0, 0.5)
    _step(pw, 2)
    _until_asleep(pw, boxes[:3])
    _rb(pw, platform).enabled = False
    _step(pw, 2)
    _rb(pw, platform).enabled = True
    _rb(pw, boxes[0]).awake = False
    _step(pw, 2)
    pw.world.remove(platform, RigidBody)
    _step(pw, 2)
    _empty_the_world(pw)


def fixed_crash_sequence() -> None:
    """Replay the sequence the random-operation fuzz shrank to (a sleeping box made kinematic)."""
    from tests.reliability import fuzz

    replay(HERE / "fixed_crash_sequence.txt", fuzz.PhysicsMachine)


def replay(path: Path, machine: Callable[[], object]) -> None:
    """Run the ``state.<rule>(...)`` lines of a saved hypothesis sequence."""
    from kge.components.filter import Filter
    from kge.components.shapes import Polygon

    names = {
        "BodyType": BodyType, "Box": Box, "Circle": Circle, "Polygon": Polygon,
        "Filter": Filter, "RigidBody": RigidBody, "Collider": Collider,
        "state": machine(),
    }
    for line in path.read_text().splitlines():
        if line.startswith("state."):
            eval(line, names)  # the sequence file is part of the test suite


SCENARIOS: dict[str, Callable[[], None]] = {
    f.__name__: f
    for f in (
        type_change_under_a_sleeping_stack,
        type_change_of_a_sleeping_body,
        manual_sleep_next_to_an_awake_body,
        manual_sleep_of_jointed_bodies,
        manual_sleep_next_to_a_kinematic_body,
        enable_detach_and_despawn_around_sleepers,
        fixed_crash_sequence,
    )
}


def _in_child(name: str) -> None:
    """Run one scenario in a fresh interpreter; a crash there fails only this test."""
    env = dict(os.environ, PYTHONFAULTHANDLER="1", PYTHONPATH=str(ROOT))
    code = (
        "import sys\n"
        "from tests.reliability.test_native_safety import SCENARIOS\n"
        "SCENARIOS[sys.argv[1]]()\n"
        "print('scenario done')\n"
    )
    p = subprocess.run(
        [sys.executable, "-c", code, name], cwd=ROOT, env=env, capture_output=True, text=True,
        timeout=120,
    )
    assert p.returncode == 0 and "scenario done" in p.stdout, (
        f"{name}: child exited with {p.returncode}\n{p.stderr[-4000:]}"
    )


@pytest.mark.parametrize("scenario", list(SCENARIOS))
def test_scenario_runs_clean_in_a_child_process(scenario: str) -> None:
    _in_child(scenario)
