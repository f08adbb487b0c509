"""A scripted scene whose full physics event log must be the same in every process.

Used by ``test_event_order.py``: several child processes with different
``PYTHONHASHSEED``s run :func:`event_log` and print it; the logs must be equal
byte for byte. The script makes every kind of event in bulk, in the situations
where Chipmunk's own order follows memory addresses (its arbiter hash set):
many ends produced by one despawn, many bodies separating in one step, sensor
overlaps ending together, a chain touched by one body on two segments, joints
destroyed with their body, and a collider moved to another body.
"""

from __future__ import annotations

import hashlib
import sys

from kge import (
    Box,
    Chain,
    Circle,
    Collider,
    RevoluteJoint,
    RigidBody,
    Transform,
)
from kge.physics.events import PhysicsEvents
from kge.schedule import Stage

from .harness import DT, PhysicsWorld


def _record(pw: PhysicsWorld, log: list[str], step: int) -> None:
    for name, _ in PhysicsEvents.CHANNELS:
        for ev in getattr(pw.events, name):
            log.append(f"{step} {name} {ev!r}")


def event_log(steps: int = 120) -> list[str]:
    """Every event of every step of the script, one line each, in delivery order."""
    pw = PhysicsWorld(name="event-order")
    w = pw.world
    log: list[str] = []
    w.spawn(Transform(0.0, 0.0), Collider(Chain([(-12.0, 0.0), (-4.0, 0.0), (4.0, 0.0),
                                                  (12.0, 0.0)])))
    slab = w.spawn(Transform(0.0, 3.0), RigidBody(), Collider(Box(6.0, 0.25)))
    balls = [
        w.spawn(Transform(-5.5 + 0.5 * i, 3.6), RigidBody(), Collider(Circle(0.24)))
        for i in range(23)
    ]
    sensor = w.spawn(Transform(0.0, 3.6), Collider(Box(7.0, 0.5), sensor=True))
    under = w.spawn(Transform(-4.0, 0.6), RigidBody(), Collider(Box(0.5, 0.5)))
    hinged = [w.spawn(RevoluteJoint(slab, b, anchor=(-5.5 + 0.5 * i, 3.6)))
              for i, b in enumerate(balls[:6])]
    del hinged
    extra = w.spawn(Transform(4.0, 0.6), RigidBody(), Collider(Box(0.5, 0.5)))
    on_chain = w.spawn(Transform(-4.0, 2.0), RigidBody(), Collider(Box(1.0, 0.2)))
    for step in range(steps):
        if step == 40:
            w.despawn(slab)  # every ball and the chain lose their contacts at once
        if step == 70:
            for b in balls[6:]:
                if w.exists(b):
                    pw.physics.apply_linear_impulse(b, (0.0, 3.0))  # all leave together
        if step == 90:
            w.despawn(sensor)
        if step == 100:
            w.get(under, Collider).body = extra  # collider moved onto another body
        w.clear_events()
        w.schedule.run(Stage.FIXED, DT)
        _record(pw, log, step)
    del on_chain
    pw.close()
    return log


def digest(log: list[str]) -> str:
    return hashlib.sha256("\n".join(log).encode()).hexdigest()


if __name__ == "__main__":
    lines = event_log(int(sys.argv[1]) if len(sys.argv) > 1 else 120)
    sys.stdout.write("\n".join(lines) + "\n")
