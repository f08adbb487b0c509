"""A restored world's maps: drawn as before the restore (pixels), tile edits and colliders
kept, editable there, and handles game code kept either rebound or refused clearly."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from kge import App, Behaviour, Box, Collider, RigidBody, Script, Transform
from kge.components.camera import Camera
from kge.components.drawables import Rect
from kge.render.setup import frame_pixels
from kge.tilemap import TileMap, TilemapError, load_map
from kge.tilemap.runtime import maps_in

from .maps import ANIM_A, ANIM_B, COIN, COLORS, DECOR, GROUND, MARK, ONE_WAY, write_level
from .test_drawing import SIZE, at


def level(tmp_path: Path) -> Path:
    g = np.zeros((8, 10), np.int64)
    g[7, :] = GROUND  # solid floor: y in [0, 1)
    g[2, 3] = ONE_WAY  # x in [3, 4), y in [5, 6)
    return write_level(tmp_path, g)


def scene(path: Path) -> Any:
    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(5.0, 4.0), pixels_per_meter=20))
        load_map(world, path)
        world.spawn(  # kept awake: a restored sleeper has no contacts to be woken through
            Transform(7.5, 3.0), RigidBody(allow_sleep=False), Collider(Box(0.25, 0.25)),
            Rect(0.5, 0.5, color=(250, 250, 250, 255)),
        )

    return setup


def restored(app: App) -> TileMap:
    app.restore(app.world.snapshot())
    (tmap,) = maps_in(app.world).maps
    return tmap


def test_a_restored_map_draws_as_before_with_its_edits(tmp_path: Path, apps: list[App]) -> None:
    app = App(scene(level(tmp_path)), headless=True, size=SIZE, background=(0, 0, 0))
    apps.append(app)
    (old,) = maps_in(app.world).maps
    app.render()
    old.set_tile("Ground", 6, 2, COIN)  # an edit made before the snapshot
    app.render()
    before = frame_pixels(app).copy()
    assert at(before, 6.5, 5.5) == COLORS[3] and at(before, 3.5, 5.5) == COLORS[1]
    tmap = restored(app)
    assert tmap is not old and tmap.world is app.world
    app.render()
    after = frame_pixels(app)
    assert np.array_equal(after, before)  # every pixel: tiles, the edit, the box
    tmap.set_tile("Ground", 1, 2, ONE_WAY)  # edits after the restore draw too
    app.render()
    assert at(frame_pixels(app), 1.5, 5.5) == COLORS[1]


def test_a_restored_maps_colliders_and_edits_act_in_the_new_world(
    tmp_path: Path, apps: list[App]
) -> None:
    app = App(scene(level(tmp_path)), headless=True, size=SIZE)
    apps.append(app)
    app.step(90)
    ((box, _),) = app.world.query(RigidBody)
    assert app.world.get(box, Transform).y == pytest.approx(1.25, abs=0.02)  # on the floor
    tmap = restored(app)
    app.step(30)
    assert app.world.get(box, Transform).y == pytest.approx(1.25, abs=0.02)  # still on it
    for col in (6, 7, 8):  # dig the floor away under the box, through the restored map
        tmap.clear_tile("Ground", col, 7)
    app.step(30)
    assert app.world.get(box, Transform).y < 0.5  # it falls through the hole


class Digger(Script):
    """Keeps the map in an attribute, as game scripts do."""

    def __init__(self, tmap: TileMap) -> None:
        self.tmap = tmap


def test_a_map_kept_in_a_component_is_the_restored_one(tmp_path: Path, apps: list[App]) -> None:
    path = level(tmp_path)

    def setup(world: Any) -> None:
        world.spawn(Behaviour(Digger(load_map(world, path))))

    app = App(setup, headless=True, size=SIZE)
    apps.append(app)
    app.step(1)
    tmap = restored(app)
    ((_, (behaviour,)),) = app.world.query(Behaviour)
    digger = behaviour.script
    assert digger.tmap is tmap and tmap.world is app.world
    digger.tmap.clear_tile("Ground", 0, 7)
    assert tmap.tile("Ground", 0, 7) == 0


def test_a_handle_of_the_closed_world_says_where_the_restored_map_is(
    tmp_path: Path, apps: list[App]
) -> None:
    app = App(scene(level(tmp_path)), headless=True, size=SIZE)
    apps.append(app)
    (old,) = maps_in(app.world).maps
    tmap = restored(app)
    with pytest.raises(TilemapError, match="world is closed.*find"):
        old.set_tile("Ground", 0, 0, GROUND)
    assert old.tile("Ground", 0, 0) == 0 and tmap.tile("Ground", 0, 0) == 0
    assert maps_in(app.world).find("level.tmx") is tmap
    assert maps_in(app.world).find(tmap.path) is tmap
    with pytest.raises(TilemapError, match="no loaded map 'other.tmx'.*'level.tmx'"):
        maps_in(app.world).find("other.tmx")


def test_an_unloaded_map_is_not_restored(tmp_path: Path, apps: list[App]) -> None:
    app = App(scene(level(tmp_path)), headless=True, size=SIZE)
    apps.append(app)
    (old,) = maps_in(app.world).maps
    old.unload()
    app.restore(app.world.snapshot())
    assert maps_in(app.world).maps == []


def test_animated_tiles_go_on_from_where_they_were(tmp_path: Path, apps: list[App]) -> None:
    """Twin runs, one restored in between, show the same frame at the same time (the
    clip is 0.1 s + 0.1 s; a clock restarted at the restore shows the other frame)."""
    g = np.zeros((8, 10), np.int64)
    g[2, 3] = ANIM_A
    path = write_level(tmp_path, g)

    def frames(restore: bool) -> list[int]:
        app = App(scene(path), headless=True, size=SIZE, background=(0, 0, 0))
        apps.append(app)
        shown = []
        for k in range(4):
            if restore and k == 1:
                restored(app)
            app.step(7)  # 7/60 s
            app.render()
            shown.append(int(maps_in(app.world).find(path).shown[ANIM_A]))
            assert at(frame_pixels(app), 3.5, 5.5) == COLORS[shown[-1] - 1]
        return shown

    plain = frames(False)
    assert plain == [ANIM_B, ANIM_A, ANIM_B, ANIM_A]  # t = 0.117, 0.233, 0.35, 0.467
    assert frames(True) == plain


def test_a_save_file_keeps_the_maps_load_options_and_its_edits(
    tmp_path: Path, apps: list[App]
) -> None:
    """A map loaded in code with options and edited: the save names the options and the
    edited cells, and the loaded save draws and collides as the saved world did."""
    from kge import load_game, save_game
    from kge.tilemap.model import FLIP_H

    g = np.zeros((8, 10), np.int64)
    g[7, :] = DECOR  # a floor of a tile that is solid only through solid_layers
    path = write_level(tmp_path, g)

    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(5.0, 4.0), pixels_per_meter=20))
        load_map(world, path, solid_layers=["Ground"], friction=0.1)

    app = App(setup, headless=True, size=SIZE, background=(0, 0, 0))
    apps.append(app)
    (tmap,) = maps_in(app.world).maps
    tmap.clear_tile("Ground", 4, 7)  # a hole in the floor: two outlines
    tmap.set_tile("Ground", 2, 2, MARK, flip_x=True)  # a mirrored tile in the air
    app.render()
    before = frame_pixels(app).copy()
    colliders = len(tmap.collider_entities)
    assert colliders == 3
    save_game(app.world, tmp_path / "save.toml")
    text = (tmp_path / "save.toml").read_text()
    assert 'solid_layers = ["Ground"]' in text and "friction = 0.1" in text
    app.restore(load_game(tmp_path / "save.toml"))
    (loaded,) = maps_in(app.world).maps
    assert loaded.tile("Ground", 4, 7) == 0 and loaded.tile("Ground", 2, 2) == MARK
    assert loaded.layer("Ground").flags[2, 2] == FLIP_H
    assert len(loaded.collider_entities) == colliders
    assert loaded.edits() == tmap.edits()  # saved again, the same cells
    app.render()
    assert np.array_equal(frame_pixels(app), before)


def test_a_bad_edit_in_a_save_is_refused_naming_the_field(tmp_path: Path) -> None:
    from kge import load_game
    from kge.scenefile import SceneFileError

    write_level(tmp_path, np.zeros((8, 10), np.int64))
    for edit, why in ((
        '["Ground", 99, 0, 1]', "col must be an int in"), ('["Ground", 0, 0]', "must be \\[layer"),
        ('["Sky", 0, 0, 1]', "Sky"),
    ):  # fmt: skip
        (tmp_path / "save.toml").write_text(
            'format = 1\nkind = "save"\nname = "s"\nnext_id = 1\n\n[[tilemap]]\n'
            f'source = "level.tmx"\nedits = [{edit}]\n'
        )
        app = App(lambda world: None, headless=True)
        try:
            with pytest.raises(SceneFileError, match=f"edits.*{why}"):
                app.restore(load_game(tmp_path / "save.toml"))
            assert maps_in(app.world).maps == []  # the running scene is left as it was
        finally:
            app.close()
