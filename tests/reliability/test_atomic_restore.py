"""Restores are atomic and validated, and keep what the scene registered in code.

A failed ``App.restore`` leaves the running scene exactly as it was; restored
data passes the checks ``spawn`` runs (a NaN inside a snapshot is refused, not
turned into a NaN pose); physics hooks, the contact filter, handlers, world hooks,
the scene's own resources and systems are still in force after a restore.
"""

from __future__ import annotations

import math
import pickle
import warnings
from dataclasses import dataclass
from typing import Any

import pytest

from kge import App, Box, Collider, RigidBody, System, Transform, World
from kge.components.tracked import raw_set
from kge.physics.contacts import PreSolve
from kge.physics.resource import Physics
from kge.scene_carry import RestoreWarning
from kge.schedule import Stage
from kge.snapshot import SnapshotError, seal

from .harness import state_dump


def boxes(world: World) -> None:
    world.spawn(Transform(0.0, -1.0), Collider(Box(10.0, 1.0)))
    for i in range(3):
        world.spawn(Transform(0.0, 0.5 + i), RigidBody(),
                    Collider(Box(0.5, 0.5), contact_hooks=True))


def _bad_snapshots(app: App) -> dict[str, bytes]:
    """Snapshots of ``app``'s world with one thing wrong in each (made through pickle)."""
    good = pickle.loads(app.world.snapshot())
    out: dict[str, bytes] = {"garbage": b"\x80\x05garbage", "truncated": app.world.snapshot()[:-9]}

    def variant(name: str, edit: Any) -> None:
        data = pickle.loads(pickle.dumps(good))
        edit(data)
        out[name] = seal(data)  # signed like a real snapshot: the checks behind the seal run

    def nan_x(d: dict[str, Any]) -> None:
        raw_set(next(c for c in d["entities"][2] if isinstance(c, Transform)), "x", math.nan)

    def inf_velocity(d: dict[str, Any]) -> None:
        raw_set(next(c for c in d["entities"][3] if isinstance(c, RigidBody)), "velocity",
                (math.inf, 0.0))

    def missing_body(d: dict[str, Any]) -> None:
        raw_set(next(c for c in d["entities"][2] if isinstance(c, Collider)), "body", 999)

    def shared(d: dict[str, Any]) -> None:
        d["entities"][3] = [*d["entities"][3][:1], *d["entities"][2][1:]]

    def bad_id(d: dict[str, Any]) -> None:
        d["entities"]["x"] = d["entities"].pop(4)

    for name, edit in (("NaN position", nan_x), ("infinite velocity", inf_velocity),
                       ("collider on a missing body", missing_body),
                       ("one instance on two entities", shared), ("entity id", bad_id)):
        variant(name, edit)
    return out


def test_a_failed_restore_leaves_the_running_scene_exactly_as_it_was() -> None:
    app = App(boxes, headless=True)
    app.step(20)
    for name, data in _bad_snapshots(app).items():
        world = app.world
        before = state_dump(world)
        with pytest.raises(SnapshotError):
            app.restore(data)
        assert app.world is world and not world.closed, name
        assert state_dump(world) == before, name
        app.step()  # still running
        check_invariants_app(app)


def check_invariants_app(app: App) -> None:
    for e, (t,) in app.world.query(Transform):
        assert math.isfinite(t.x) and math.isfinite(t.y), e


def test_restored_data_is_validated_like_spawned_data() -> None:
    app = App(boxes, headless=True)
    app.step(5)
    bad = _bad_snapshots(app)
    with pytest.raises(SnapshotError, match=r"snapshot entity 2, Transform: Transform\.x must be"):
        World.restore(bad["NaN position"])
    with pytest.raises(SnapshotError, match=r"snapshot entity 3, RigidBody: .*velocity\[0\]"):
        World.restore(bad["infinite velocity"])
    with pytest.raises(SnapshotError, match="share one"):
        World.restore(bad["one instance on two entities"])
    with pytest.raises(SnapshotError, match=r"snapshot entity 2: .*body entity 999 does not exist"):
        app.restore(bad["collider on a missing body"])


@dataclass
class Score:
    points: int = 0


class Counter(System):
    stage = Stage.FIXED

    def __init__(self) -> None:
        self.runs = 0

    def process(self, dt: float) -> None:
        self.runs += 1


def test_what_the_scene_registered_in_code_stays_in_force() -> None:
    calls: dict[str, int] = {"pre": 0, "post": 0, "filter": 0, "handler": 0, "added": 0}

    def scene(world: World) -> None:
        boxes(world)
        physics = world.resource(Physics)

        def pre(contact: PreSolve) -> None:
            calls["pre"] += 1
            assert world.exists(contact.collider_a)  # the closure sees the live world

        physics.on_pre_solve(pre)
        physics.on_post_solve(lambda c: calls.__setitem__("post", calls["post"] + 1))

        def never_ground_top(a: int, b: int) -> bool:
            calls["filter"] += 1
            return physics.settings.gravity[1] < 0  # captured Physics: the new one after

        physics.contact_filter = never_ground_top
        world.set_handler("contact_begin", lambda ev: calls.__setitem__(
            "handler", calls["handler"] + 1))
        world.on_add(Score, lambda e, s: calls.__setitem__("added", calls["added"] + 1))
        world.insert_resource(Score(7))
        world.add_system(Counter())

    app = App(scene, headless=True)
    app.step(3)
    data = app.world.snapshot()
    app.step(10)
    old = app.world
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # nothing here is tied to the old world
        app.restore(data)
    assert app.world is not old and old.closed
    for key in calls:
        calls[key] = 0
    app.world.get(4, Transform).y = 3.0  # lift the top box: new contacts after the restore
    app.step(60)
    assert calls["pre"] > 0 and calls["post"] > 0 and calls["filter"] > 0
    assert calls["handler"] > 0
    app.world.spawn(Score())
    assert calls["added"] == 1
    assert app.world.resource(Score).points == 7
    counter = app.world.get_system(Counter)
    assert counter is not None and counter.runs >= 60  # the scene's system still runs


class Tied:
    def __init__(self, world: World) -> None:
        self.world = world

    def hook(self, contact: PreSolve) -> None:
        self.world.exists(1)


def test_a_hook_bound_to_the_old_world_is_reported_loudly() -> None:
    def scene(world: World) -> None:
        boxes(world)
        world.resource(Physics).on_pre_solve(Tied(world).hook)

    app = App(scene, headless=True)
    app.step()
    with pytest.warns(RestoreWarning, match="Tied.hook"):
        app.restore(app.world.snapshot())
    app.step()
    check_invariants_app(app)


def test_restoring_a_world_directly_keeps_ids_and_checks_references() -> None:
    w = World()
    w.spawn(Transform())
    copy = World.restore(w.snapshot())
    assert copy.entities() == [1]
