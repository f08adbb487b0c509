"""Event lists have one order, defined by entity ids and child indices, in every process.

Chipmunk reports the contacts that end when a shape leaves the space, and the
ones that begin or end in a step, in the order of its arbiter hash set, which
follows memory addresses. ``event_log.py`` makes such events in bulk (one
despawn ending 30 contacts, a sensor's overlaps ending at once, balls leaving
together, joints destroyed with their body, a collider moved to another body);
child processes with different ``PYTHONHASHSEED``s must print the same full log.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from kge import Box, Chain, Collider, RigidBody, Transform

from .event_log import event_log
from .harness import PhysicsWorld

ROOT = Path(__file__).resolve().parents[2]


def _log_in_child(seed: str) -> subprocess.Popen[str]:
    env = {**os.environ, "PYTHONHASHSEED": seed}
    return subprocess.Popen(
        [sys.executable, "-m", "tests.reliability.event_log"], cwd=ROOT, env=env,
        stdout=subprocess.PIPE, text=True,
    )


def test_full_event_logs_are_equal_across_processes() -> None:
    children = [_log_in_child(seed) for seed in ("0", "1", "7", "12345")]
    logs = []
    for child in children:
        out, _ = child.communicate(timeout=300)
        assert child.returncode == 0
        logs.append(out)
    here = "\n".join(event_log()) + "\n"
    assert len(here.splitlines()) > 200  # the script really produces events in bulk
    for seed, log in zip(("0", "1", "7", "12345"), logs, strict=True):
        assert log == here, f"PYTHONHASHSEED={seed} gave another event order"


def test_each_list_is_sorted_by_entity_then_child() -> None:
    lines = event_log()
    by_step: dict[tuple[str, str], list[tuple[int, ...]]] = {}
    for line in lines:
        step, name, rest = line.split(" ", 2)
        fields = dict(
            part.split("=", 1) for part in rest[rest.index("(") + 1:-1].split(", ")
            if "=" in part and part.split("=", 1)[0].isidentifier()
        )
        if name.startswith("joint"):
            key: tuple[int, ...] = (int(fields["joint"]),)
        else:
            key = tuple(int(fields[f]) for f in ("collider_a", "collider_b", "child_a", "child_b"))
        by_step.setdefault((step, name), []).append(key)
    assert any(len(v) > 5 for v in by_step.values())
    for where, keys in by_step.items():
        assert keys == sorted(keys), f"step {where[0]} {where[1]} is not in entity order"


def test_a_box_on_two_chain_segments_gets_two_begins_told_apart_by_child() -> None:
    pw = PhysicsWorld()  # its EventBalance fails on two begins of one (collider, child) pair
    w = pw.world
    chain = w.spawn(Transform(), Collider(Chain([(-4.0, 0.0), (0.0, 0.0), (4.0, 0.0)])))
    box = w.spawn(Transform(0.0, 0.15), RigidBody(), Collider(Box(1.0, 0.2)))
    pw.step()
    got = [(e.collider_a, e.child_a, e.collider_b, e.child_b) for e in pw.events.contact_begin]
    assert got == [(chain, 0, box, 0), (chain, 1, box, 0)]
    w.get(box, Transform).y = 3.0
    pw.step()
    ends = [(e.collider_a, e.child_a, e.collider_b, e.child_b) for e in pw.events.contact_end]
    assert ends == got
    pw.close()
