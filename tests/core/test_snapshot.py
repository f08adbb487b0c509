"""Snapshots: every entity and component comes back, ids and all."""

from dataclasses import dataclass

import pytest

from kge import App, Behaviour, Script, Transform, World
from kge.scenefile import load_game, register_script, save_game
from kge.snapshot import SnapshotError, snapshot


@dataclass(slots=True)
class Health:
    hp: int


@register_script
class Counter(Script):
    def __init__(self) -> None:
        self.ticks = 0

    def on_fixed_update(self, dt: float) -> None:
        self.ticks += 1


def test_roundtrip_keeps_ids_components_and_the_id_counter() -> None:
    w = World()
    a = w.spawn(Transform(1, 2, 0.5), Health(3))
    gone = w.spawn(Health(0))
    b = w.spawn(Transform(-1, 0))
    w.despawn(gone)
    w.flush()
    copy = World.restore(snapshot(w))
    assert copy.entities() == [a, b]
    assert copy.get(a, Transform) == Transform(1, 2, 0.5)
    assert copy.get(a, Health).hp == 3
    assert copy.spawn(Health(1)) == b + 1  # new ids continue after the old ones
    assert not copy.exists(gone)
    w.close()
    copy.close()


def test_tracked_components_are_saved_without_their_binding() -> None:
    from kge.components.tracked import bind

    w = World()
    t = Transform(3, 4)
    e = w.spawn(t)
    bind(t, e, set())
    copy = World.restore(snapshot(w))
    assert copy.get(e, Transform)._binding is None
    assert copy.get(e, Transform).x == 3


def test_app_restore_continues_scripts(tmp_path) -> None:
    def scene(world: World) -> None:
        world.spawn(Transform(), Behaviour(Counter()))

    app = App(scene, headless=True)
    app.step(10)
    path = tmp_path / "save.toml"
    save_game(app.world, path)
    app.step(5)
    app.restore(load_game(path))
    ((_, (beh,)),) = app.world.query(Behaviour)
    assert beh.script.ticks == 10
    app.step(3)
    assert beh.script.ticks == 13
    assert beh.script.world is app.world


def test_garbage_is_a_clear_error() -> None:
    with pytest.raises(SnapshotError, match="not a kge snapshot"):
        World.restore(b"hello")


def test_snapshot_bytes_from_disk_never_reach_pickle(tmp_path) -> None:
    """A pickle that would run code, written to a file as a save: refused before unpickling."""
    import pickle

    ran: list[str] = []

    class Boom:
        def __reduce__(self):
            return (ran.append, ("code ran",))

    evil = pickle.dumps({"format": 1, "entities": Boom()}, protocol=5)
    (tmp_path / "save.kge").write_bytes(evil)
    with pytest.raises(SnapshotError, match="not a kge snapshot taken in this process"):
        App(lambda w: None, headless=True).restore((tmp_path / "save.kge").read_bytes())
    with pytest.raises(SnapshotError, match="taken in this process"):
        World.restore(snapshot(World())[:-1] + b"x")  # a tampered signature
    assert ran == []
    import kge.snapshot

    with pytest.raises(AttributeError, match="save_game"):
        kge.snapshot.save  # noqa: B018  (the pickle-to-disk helpers are gone, with a pointer)


def test_unpicklable_component_is_reported() -> None:
    w = World()
    w.spawn(Health(lambda: 0))  # type: ignore[arg-type]
    with pytest.raises(SnapshotError, match="picklable"):
        snapshot(w)
