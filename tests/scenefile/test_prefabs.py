"""Prefabs: templates in their own files, placed many times, overridden per instance."""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import pytest

from kge import App, Collider, Name, Physics, RevoluteJoint, RigidBody, Transform, WheelJoint, World
from kge.scenefile import (
    SceneFileError,
    SceneState,
    instantiate,
    load_scene,
    save_scene,
)

PREFABS = Path(__file__).resolve().parents[2] / "kge" / "testbed" / "prefabs"


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    for name in ("car", "wheel", "ragdoll"):
        shutil.copy(PREFABS / f"{name}.prefab.toml", tmp_path / f"{name}.prefab.toml")
    return tmp_path


GARAGE = """format = 1

[[entity]]
id = "ground"
[entity.Transform]
[entity.Collider]
shape = { type = "Box", half_width = 50.0, half_height = 0.5 }

[[entity]]
id = "red"
prefab = "car.prefab.toml"
at = [0.0, 2.0]

[[entity]]
id = "blue"
prefab = "car.prefab.toml"
at = [10.0, 2.0, 0.5]

[entity.overrides.rear_axle.WheelJoint]
motor_speed = -40.0

[entity.overrides."front/tyre".Collider]
friction = 0.1

[entity.overrides.chassis]
name = "blue chassis"

[[entity]]
id = "green"
prefab = "car.prefab.toml"
at = [20.0, 2.0]
"""


def members(world: World, instance: str) -> dict[str, int]:
    return world.resource(SceneState).instances[instance].members


def test_instances_get_their_own_entities_and_overrides(folder: Path) -> None:
    (folder / "garage.scene.toml").write_text(GARAGE)
    app = App(str(folder / "garage.scene.toml"), headless=True)
    w = app.world
    assert len(w.entities()) == 1 + 3 * 5  # ground + (chassis, 2 tyres, 2 axles) per car
    red, blue = members(w, "red"), members(w, "blue")
    assert set(red) == {"chassis", "rear/tyre", "front/tyre", "rear_axle", "front_axle"}
    # references stay inside each instance
    assert w.get(blue["rear_axle"], WheelJoint).body_b == blue["rear/tyre"]
    assert w.get(red["rear_axle"], WheelJoint).body_a == red["chassis"]
    # overrides reach only the instance that wrote them (nested members included)
    assert w.get(blue["rear_axle"], WheelJoint).motor_speed == -40.0
    assert w.get(red["rear_axle"], WheelJoint).motor_speed == -20.0
    assert w.get(blue["front/tyre"], Collider).friction == 0.1
    assert w.get(red["front/tyre"], Collider).friction == 0.9
    assert w.get(blue["chassis"], Name).value == "blue chassis"
    # the root lands exactly at `at`; the rest keeps its place around it (turned by 0.5)
    t = w.get(blue["chassis"], Transform)
    assert (t.x, t.y, t.angle) == (10.0, 2.0, 0.5)
    tyre = w.get(blue["rear/tyre"], Transform)
    local = (-1.0, 0.35 - 1.0)
    expect = (10.0 + math.cos(0.5) * local[0] - math.sin(0.5) * local[1],
              2.0 + math.sin(0.5) * local[0] + math.cos(0.5) * local[1])
    assert math.dist((tyre.x, tyre.y), expect) < 1e-12
    app.step(1)  # the anchors were moved with the car: no joint opens
    physics = w.resource(Physics)
    for e in (blue["rear_axle"], blue["front_axle"]):
        j = w.get(e, WheelJoint)
        assert j.body_a is not None and j.body_b is not None
        gap = math.dist(physics.world_point(j.body_a, j.local_anchor_a),
                        physics.world_point(j.body_b, j.local_anchor_b))
        assert gap < 0.005  # the springs give a little in one step; a missed anchor is metres off


def test_instances_save_back_as_instances_byte_for_byte(folder: Path) -> None:
    (folder / "garage.scene.toml").write_text(GARAGE)
    app = App(str(folder / "garage.scene.toml"), headless=True)
    first = save_scene(app.world, folder / "out.scene.toml").read_text()
    assert first.count('prefab = "car.prefab.toml"') == 3 and "WheelJoint]\nmotor_speed = -40.0" in first
    again = App(str(folder / "out.scene.toml"), headless=True)
    assert save_scene(again.world, folder / "out2.scene.toml").read_text() == first
    # moving an instance's root moves the instance
    w = again.world
    w.get(members(w, "green")["chassis"], Transform).x = 30.0
    moved = save_scene(w, folder / "out3.scene.toml").read_text()
    assert "at = [30.0, 2.0, 0.0]" in moved


def test_changing_the_prefab_changes_every_instance_not_overridden(folder: Path) -> None:
    (folder / "garage.scene.toml").write_text(GARAGE)
    wheel = folder / "wheel.prefab.toml"
    wheel.write_text(wheel.read_text().replace("friction = 0.9", "friction = 0.7\ndensity = 3.0"))
    w = App(str(folder / "garage.scene.toml"), headless=True).world
    for car in ("red", "green"):
        assert w.get(members(w, car)["front/tyre"], Collider).friction == 0.7
    assert w.get(members(w, "blue")["front/tyre"], Collider).friction == 0.1  # overridden
    assert w.get(members(w, "blue")["front/tyre"], Collider).density == 3.0  # not overridden


def test_instantiate_at_run_time_many_times(folder: Path) -> None:
    def scene(world: World) -> None:
        world.spawn(Transform(), Collider(__import__("kge").Box(40.0, 0.5)))
        for i in range(12):
            instantiate(world, folder / "ragdoll.prefab.toml", at=(-30.0 + 5.0 * i, 4.0, 0.3 * i))

    app = App(scene, headless=True)
    w = app.world
    assert len(w.query(RevoluteJoint)) == 12 * 9
    keys = set(w.resource(SceneState).instances)
    assert len(keys) == 12 and "ragdoll" in keys and "ragdoll-12" in keys
    app.step(120)
    physics = w.resource(Physics)
    for _, (rj,) in w.query(RevoluteJoint):
        assert rj.body_a is not None and rj.body_b is not None
        gap = math.dist(physics.world_point(rj.body_a, rj.local_anchor_a),
                        physics.world_point(rj.body_b, rj.local_anchor_b))
        assert gap < 0.05


def test_an_instance_can_be_instantiated_from_code_with_overrides(folder: Path) -> None:
    world = App(lambda w: None, headless=True).world
    ids = instantiate(world, folder / "car.prefab.toml", at=(3.0, 4.0), key="mine",
                      overrides={"rear_axle": {"WheelJoint": {"motor_speed": -5.0}},
                                 "rear/tyre": {"Collider": {"restitution": 0.5}}})
    assert len(ids) == 5
    m = members(world, "mine")
    assert world.get(m["rear_axle"], WheelJoint).motor_speed == -5.0
    assert world.get(m["rear/tyre"], Collider).restitution == 0.5
    assert world.get(m["chassis"], Transform).position == (3.0, 4.0)
    with pytest.raises(SceneFileError, match="no member"):
        instantiate(world, folder / "car.prefab.toml", overrides={"boot": {"Name": {}}})
    assert len(world.entities()) == 5  # the refused one added nothing


def test_prefab_cycles_and_kinds_are_refused(folder: Path) -> None:
    (folder / "a.prefab.toml").write_text(
        'format = 1\nkind = "prefab"\n[[entity]]\nid = "x"\n[entity.Transform]\n'
        '[[entity]]\nid = "b"\nprefab = "b.prefab.toml"\n')
    (folder / "b.prefab.toml").write_text(
        'format = 1\nkind = "prefab"\n[[entity]]\nid = "a"\nprefab = "a.prefab.toml"\n')
    (folder / "s.scene.toml").write_text('format = 1\n[[entity]]\nid = "i"\n'
                                         'prefab = "a.prefab.toml"\n')
    world = World()
    with pytest.raises(SceneFileError, match=r"prefab cycle: .*a.prefab.toml"):
        load_scene(world, folder / "s.scene.toml")
    with pytest.raises(SceneFileError, match="not a scene"):
        load_scene(world, folder / "car.prefab.toml")
    assert world.entities() == []


def test_instance_members_get_rigid_bodies_of_their_own(folder: Path) -> None:
    (folder / "garage.scene.toml").write_text(GARAGE)
    w = App(str(folder / "garage.scene.toml"), headless=True).world
    bodies = {e for e, _ in w.query(RigidBody)}
    assert len(bodies) == 9
