"""Every editor edit, driven headless through the model, and its undo and redo."""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import pytest

from kge import (
    App,
    Box,
    Circle,
    Collider,
    Name,
    Polygon,
    RevoluteJoint,
    RigidBody,
    Sprite,
    Transform,
    UINode,
)
from kge.editor import EditorModel
from kge.scenefile import SceneFileError, SceneState

PREFABS = Path(__file__).resolve().parents[2] / "kge" / "testbed" / "prefabs"

LEVEL = """format = 1

[[entity]]
id = "ground"
name = "Ground"
[entity.Transform]
y = -1.0
[entity.Collider]
shape = { type = "Box", half_width = 10.0, half_height = 1.0 }

[[entity]]
id = "crate"
name = "Crate"
[entity.Transform]
x = 1.0
y = 2.0
[entity.RigidBody]
[entity.Collider]
shape = { type = "Box", half_width = 0.5, half_height = 0.5 }

[[entity]]
id = "hinge"
[entity.RevoluteJoint]
body_b = "crate"
anchor = [1.0, 2.5]
"""


@pytest.fixture
def model(tmp_path: Path) -> EditorModel:
    path = tmp_path / "level.scene.toml"
    path.write_text(LEVEL)
    app = App(lambda w: None, headless=True)
    return EditorModel(app.world, path)


def named(m: EditorModel, name: str) -> int:
    return next(e for e in m.entities() if m.name(e) == name)


def undo_redo_round_trip(m: EditorModel, before: str) -> None:
    """Undo gives back exactly the text before the edit; redo the one after."""
    after = m.text()
    assert after != before
    assert m.undo() and m.text() == before
    assert m.redo() and m.text() == after


def test_opening_a_scene_and_the_hierarchy(model: EditorModel) -> None:
    assert [model.name(e) for e in model.entities()] == ["Ground", "Crate", "hinge"]
    assert not model.dirty
    assert [model.name(e) for e, _ in model.hierarchy("cra")] == ["Crate"]


def test_field_edits_and_their_undo(model: EditorModel) -> None:
    crate = named(model, "Crate")
    before = model.text()
    model.set_field(crate, Collider, "density", 3.0)
    assert model.dirty
    undo_redo_round_trip(model, before)
    with pytest.raises(ValueError, match="density"):
        model.set_field(crate, Collider, "density", -1.0)  # refused: nothing changes
    assert model.world.get(crate, Collider).density == 3.0
    before = model.text()
    model.rename(crate, "Big crate")
    undo_redo_round_trip(model, before)


def test_create_delete_duplicate_and_undo(model: EditorModel) -> None:
    before = model.text()
    e = model.create(Transform(3.0, 3.0), RigidBody(), Collider(Circle(0.3)), name="Ball")
    assert model.selection == [e] and model.name(e) == "Ball"
    undo_redo_round_trip(model, before)
    crate = named(model, "Crate")
    before = model.text()
    model.delete([crate])  # the joint naming it goes too
    names = [model.name(x) for x in model.entities()]
    assert "Crate" not in names and "hinge" not in names
    undo_redo_round_trip(model, before)
    model.undo()
    crate = named(model, "Crate")
    hinge = named(model, "hinge")
    before = model.text()
    copies = model.duplicate([crate, hinge])
    assert len(copies) == 2
    joint = model.world.get(copies[1], RevoluteJoint)
    assert joint.body_b == copies[0]  # the copy's joint holds the copy
    assert model.world.get(copies[0], Transform).x == 1.5
    undo_redo_round_trip(model, before)


def test_add_remove_component_and_reparent(model: EditorModel, tmp_path: Path) -> None:
    from PIL import Image

    Image.new("RGBA", (4, 4)).save(tmp_path / "crate.png")
    crate = named(model, "Crate")
    before = model.text()
    model.add_component(crate, Sprite(str(tmp_path / "crate.png"), size=(1.0, 1.0)))
    assert model.world.has(crate, Sprite)
    undo_redo_round_trip(model, before)
    before = model.text()
    model.remove_component(named(model, "Crate"), Sprite)
    undo_redo_round_trip(model, before)
    # reparent: a collider onto the crate's body, kept where it is in the world
    part = model.create(Transform(2.0, 2.0), Collider(Circle(0.2)), name="Bumper")
    crate = named(model, "Crate")
    before = model.text()
    model.reparent(part, crate)
    assert model.world.get(part, Collider).body == crate
    assert model.world_pose(part)[:2] == pytest.approx((2.0, 2.0))
    assert model.parent(part) == crate
    assert [d for e, d in model.hierarchy() if e == part] == [1]
    undo_redo_round_trip(model, before)
    panel = model.create(UINode(), name="Panel")
    button = model.create(UINode(), name="Button")
    model.reparent(button, panel)
    assert model.world.get(button, UINode).parent == panel
    with pytest.raises(SceneFileError, match="only UI nodes and colliders"):
        model.reparent(named(model, "hinge"), panel)


def test_move_rotate_scale_with_snapping(model: EditorModel) -> None:
    crate = named(model, "Crate")
    start = {crate: (1.0, 2.0)}
    before = model.text()
    model.move([crate], (0.3, 0.0), live=True, start=start)  # mid-drag: no undo step yet
    model.move([crate], (0.8, 0.26), start=start)
    t = model.world.get(crate, Transform)
    assert (t.x, t.y) == (2.0, 2.5)  # snapped to the 0.5 m grid
    assert len(model.undo_stack) == 1  # the whole drag is one step
    undo_redo_round_trip(model, before)
    before = model.text()
    model.rotate(crate, math.radians(50))
    assert t.angle == pytest.approx(math.radians(45))
    undo_redo_round_trip(model, before)
    before = model.text()
    model.scale(crate, 2.0)
    shape = model.world.get(crate, Collider).shape
    assert isinstance(shape, Box) and shape.half_width == 1.0
    undo_redo_round_trip(model, before)


def test_shape_and_joint_handles(model: EditorModel) -> None:
    crate = named(model, "Crate")
    model.snap = False
    (corner,) = model.shape_handles(crate)
    assert corner == pytest.approx((1.5, 2.5))
    before = model.text()
    model.drag_shape_handle(crate, 0, (2.0, 3.0))
    shape = model.world.get(crate, Collider).shape
    assert isinstance(shape, Box) and (shape.half_width, shape.half_height) == (1.0, 1.0)
    undo_redo_round_trip(model, before)
    tri = model.create(Transform(), Collider(Polygon([(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)])))
    model.drag_shape_handle(tri, 1, (2.0, 0.0))
    poly = model.world.get(tri, Collider).shape
    assert isinstance(poly, Polygon) and poly.vertices[1] == (2.0, 0.0)
    with pytest.raises(ValueError, match="clockwise|convex"):
        model.drag_shape_handle(tri, 1, (-1.0, 2.0))  # refused: the shape stays valid
    hinge = named(model, "hinge")
    assert model.joint_anchor(hinge) == (1.0, 2.5)
    before = model.text()
    model.drag_joint_anchor(hinge, (1.25, 2.0))
    assert model.world.get(hinge, RevoluteJoint).anchor == (1.25, 2.0)
    undo_redo_round_trip(model, before)


def test_place_prefab_paint_and_pick(model: EditorModel, tmp_path: Path) -> None:
    for name in ("car", "wheel"):
        shutil.copy(PREFABS / f"{name}.prefab.toml", tmp_path / f"{name}.prefab.toml")
    before = model.text()
    ids = model.place_prefab(tmp_path / "car.prefab.toml", (4.1, 3.2))
    assert len(ids) == 5 and model.world.get(ids[0], Transform).position == (4.0, 3.0)
    assert 'prefab = "car.prefab.toml"' in model.text()
    undo_redo_round_trip(model, before)
    brush = named(model, "Crate")
    before = model.text()
    made = model.paint(brush, [(x * 0.5, 5.0) for x in range(6)] + [(0.0, 5.1)])
    assert len(made) == 6  # one per grid cell, repeats skipped
    undo_redo_round_trip(model, before)
    assert model.pick((1.2, 2.3)) == named(model, "Crate")
    assert model.pick((50.0, 50.0)) is None


def test_override_edits_on_prefab_members_are_saved(model: EditorModel, tmp_path: Path) -> None:
    for name in ("car", "wheel"):
        shutil.copy(PREFABS / f"{name}.prefab.toml", tmp_path / f"{name}.prefab.toml")
    model.place_prefab(tmp_path / "car.prefab.toml", (0.0, 5.0))
    inst = next(iter(model.world.resource(SceneState).instances.values()))
    tyre = inst.members["rear/tyre"]
    model.set_field(tyre, Collider, "friction", 0.3)
    model.save()
    text = model.path.read_text() if model.path else ""
    assert "[entity.overrides.\"rear/tyre\".Collider]\nfriction = 0.3" in text
    reopened = EditorModel(App(lambda w: None, headless=True).world, model.path)
    inst2 = next(iter(reopened.world.resource(SceneState).instances.values()))
    assert reopened.world.get(inst2.members["rear/tyre"], Collider).friction == 0.3


def test_save_and_save_as(model: EditorModel, tmp_path: Path) -> None:
    crate = named(model, "Crate")
    model.set_field(crate, Transform, "x", 4.0)
    assert model.dirty
    (tmp_path / "copy").mkdir()
    path = model.save(tmp_path / "copy" / "level2.scene.toml")
    assert not model.dirty and model.path == path
    assert "x = 4.0" in path.read_text()
    assert (tmp_path / "level.scene.toml").read_text() == LEVEL  # the original is untouched
    assert isinstance(model.world.get(crate, Name), Name)


def test_unsaved_after_undo_and_a_new_edit_even_when_the_old_step_is_gone(
    model: EditorModel,
) -> None:
    crate = named(model, "Crate")
    model.set_field(crate, Transform, "x", 4.0)
    model.save()
    for i in range(20):  # the saved step is freed; a new step may get its id
        model.undo()
        assert model.dirty
        model.set_field(crate, Transform, "x", 5.0 + i)
        assert model.dirty  # one step deep again, but not the saved one
        model.undo()
        model.redo()


def test_every_component_can_be_added_from_the_inspector_list(
    model: EditorModel, tmp_path: Path
) -> None:
    """Add (the inspector's list) gives each field without a default a starting value; the
    few that cannot start empty (a map object, a gear of two joints) say what they need."""
    from PIL import Image

    from kge.editor.starters import starter
    from kge.errors import ValidationError
    from kge.scenefile import default_registry
    from kge.scenefile.registry import COMPONENT

    image = tmp_path / "a.png"
    Image.new("RGBA", (4, 4)).save(image)
    added, refused = [], []
    for name in default_registry().names(COMPONENT):
        crate = named(model, "Crate")  # an undo renumbers the scene's entities
        info = default_registry().get(name)
        if info is None or model.world.has(crate, info.cls):
            continue
        before = model.text()
        try:
            comp = starter(info.cls, crate, [str(image)])
        except ValidationError as exc:
            assert name.split(".")[-1] in str(exc)
            refused.append(name)
            continue
        try:
            model.add_component(crate, comp)
        except (SceneFileError, ValueError, TypeError) as exc:
            refused.append(f"{name}: {exc}")
            continue
        added.append(name)
        assert model.world.has(crate, info.cls)
        assert model.undo() and model.text() == before
    assert {"Sprite", "Text", "RevoluteJoint", "draw.Circle", "draw.Rect"} <= set(
        added), refused
    assert len(added) >= 30, (added, refused)
