"""Save, load, save is byte-identical; a loaded scene steps exactly as the world it came from."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import pytest

import kge
from kge import App, Behaviour, Collider, RigidBody, Transform, World
from kge.scenefile import (
    SceneState,
    default_registry,
    dumps,
    load_scene,
    save_scene,
)
from kge.scenefile.registry import COMPONENT
from kge.testbed.samples.stacking import pyramid

from .scenes import Health, Patrol, everything


@pytest.fixture
def folder(tmp_path: Path, game_assets: Path) -> Path:
    (tmp_path / "levels").mkdir()
    return game_assets


def poses(world: World) -> list[tuple[int, float, float, float]]:
    return [(e, t.x, t.y, t.angle) for e, (t, _) in sorted(world.query(Transform, RigidBody))]


def test_every_component_round_trips_byte_for_byte(folder: Path) -> None:
    app = App(lambda w: everything(w, folder), headless=True)
    first = save_scene(app.world, folder / "levels" / "all.scene.toml").read_text()
    loaded = App(str(folder / "levels" / "all.scene.toml"), headless=True)
    second = save_scene(loaded.world, folder / "levels" / "again.scene.toml").read_text()
    assert second == first
    # every component type kge registers is in the file (the scene covers them all)
    reg = default_registry()
    KGE_NAMES = {n for n in reg.names(COMPONENT) if (info := reg.get(n)) is not None
                 and info.cls.__module__.startswith("kge")}
    assert len(KGE_NAMES) > 45
    for name in default_registry().names(COMPONENT):
        if name == "Name":  # written as the entity's name = "..."
            assert 'name = "Hull"' in first
        elif name == "Health" or name in KGE_NAMES:
            assert f"[entity.{name}]" in first or f'[entity."{name}"]' in first, name
    assert "[entity.Behaviour]" in first
    # components equal field by field, entity for entity (ids are 1..N in both)
    for e in app.world.entities():
        a = {type(c): c for c in app.world.components(e)}
        b = {type(c): c for c in loaded.world.components(e)}
        assert a.keys() == b.keys()
        for t, comp in a.items():
            if t is Behaviour:  # data attributes equal (arrays read back as lists)
                for attr in ("speed", "label", "entity"):
                    assert getattr(comp.script, attr) == getattr(b[t].script, attr)
            else:
                assert comp == b[t], t


def test_assets_are_written_relative_to_the_file(folder: Path) -> None:
    app = App(lambda w: everything(w, folder), headless=True)
    text = dumps(app.world, folder / "levels")
    assert 'image = "../art/ship.png"' in text and 'sound = "../sfx/hit.wav"' in text
    assert str(folder) not in text  # no absolute path leaks into the file
    # save-as into another folder keeps every reference working
    (folder / "elsewhere" / "deep").mkdir(parents=True)
    save_scene(app.world, folder / "elsewhere" / "deep" / "copy.scene.toml")
    moved = (folder / "elsewhere" / "deep" / "copy.scene.toml").read_text()
    assert 'image = "../../art/ship.png"' in moved
    App(str(folder / "elsewhere" / "deep" / "copy.scene.toml"), headless=True)


def test_loaded_scene_steps_exactly_as_the_original(folder: Path) -> None:
    """300 steps of bodies, contacts and every joint: identical poses, bit for bit."""
    app = App(lambda w: everything(w, folder), headless=True)
    path = save_scene(app.world, folder / "levels" / "all.scene.toml")
    loaded = App(str(path), headless=True)
    app.step(300)
    loaded.step(300)
    assert poses(loaded.world) == poses(app.world)
    assert len(poses(app.world)) == 6  # five bodies and a character


def test_saved_mid_flight_contact_free_bodies_continue_exactly(tmp_path: Path) -> None:
    """Velocities and poses are components, so a world saved mid-flight continues bit for bit
    (contact impulses, which pymunk cannot export, are the one thing a file lacks)."""

    def throw(world: World) -> None:
        for i in range(10):
            world.spawn(Transform(float(i), 0.0, 0.1 * i),
                        RigidBody(velocity=(1.0, 5.0 + i), angular_velocity=0.3 * i,
                                  linear_damping=0.05 * i),
                        Collider(kge.Box(0.2, 0.1), filter=kge.Filter(group_index=-1)))

    app = App(throw, headless=True)
    app.step(30)
    path = save_scene(app.world, tmp_path / "flight.scene.toml")
    loaded = App(str(path), headless=True)
    app.step(300)
    loaded.step(300)
    assert poses(loaded.world) == poses(app.world)


def test_pyramid_steps_identically_after_a_round_trip(tmp_path: Path) -> None:
    app = App(pyramid, headless=True)
    path = save_scene(app.world, tmp_path / "pyramid.scene.toml")
    loaded = App(str(path), headless=True)
    app.step(300)
    loaded.step(300)
    assert poses(loaded.world) == poses(app.world)
    assert len(poses(app.world)) == 55  # a 10-row pyramid


def test_game_types_and_scripts_load(folder: Path) -> None:
    app = App(lambda w: everything(w, folder), headless=True)
    path = save_scene(app.world, folder / "levels" / "all.scene.toml")
    loaded = App(str(path), headless=True)
    (hull,) = [e for e, (h,) in loaded.world.query(Health) if h.tags == ["boss"]]
    script = loaded.world.get(hull, Behaviour).script
    assert isinstance(script, Patrol) and script.label == "guard"
    assert script.path == [[0.0, 0.0], [3.0, 0.0]]  # plain data: arrays read back as lists
    assert loaded.world.resource(Health).hp == 9
    loaded.step(2)  # the script runs
    assert script.world is loaded.world


def test_references_survive_renumbering(folder: Path) -> None:
    app = App(lambda w: everything(w, folder), headless=True)
    path = save_scene(app.world, folder / "levels" / "all.scene.toml")

    def offset(world: World) -> None:  # entities already there: the file's get other ids
        for _ in range(7):
            world.spawn(Transform())
        load_scene(world, path)

    shifted = App(offset, headless=True)
    cols = {e: c for e, (c,) in shifted.world.query(Collider) if c.body is not None}
    ((part, col),) = cols.items()
    assert col.body is not None
    assert part > 7 and shifted.world.has(col.body, RigidBody) and col.body > 7
    keys = shifted.world.resource(SceneState).keys
    assert keys[col.body] == "hull" and keys[part] == "entity-3"
    shifted.step(10)


def test_saving_a_selection(folder: Path) -> None:
    app = App(lambda w: everything(w, folder), headless=True)
    hull = next(e for e, (n,) in app.world.query(kge.Name) if n.value == "Hull")
    part = next(e for e, (c,) in app.world.query(Collider) if c.body == hull)
    text = dumps(app.world, folder, entities=[hull, part])
    assert text.count("[[entity]]") == 2 and 'body = "hull"' in text
    with pytest.raises(kge.scenefile.SceneFileError, match="not being saved"):
        dumps(app.world, folder, entities=[part])  # its body is left out


def test_defaults_are_not_written_and_unknown_fields_are_named(tmp_path: Path) -> None:
    world = World()
    world.spawn(Transform(1.0), RigidBody())
    text = dumps(world, tmp_path)
    assert "[entity.RigidBody]\n" in text and "gravity_scale" not in text
    field_names = [f.name for f in dataclasses.fields(Collider)]
    assert "density" in field_names
