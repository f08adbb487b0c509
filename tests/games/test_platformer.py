"""The platformer example: its levels are scene files made in the editor; they load, coins
count, the door changes the level, and the files are what the editing session makes."""

from __future__ import annotations

from pathlib import Path

import platformer
import platformer_levels

from kge import (
    App,
    Behaviour,
    Button,
    Dialog,
    Key,
    ScrollView,
    Slider,
    TileCollider,
    Transform,
    UINode,
    UISettings,
)
from kge.scenefile import SceneState


def test_the_door_leads_to_the_second_level_with_the_score() -> None:
    app = App(platformer.level, headless=True)
    try:
        source = app.world.resource(SceneState).source
        assert source is not None and source.name == "level1.scene.toml"
        (player,) = platformer.named(app.world, "player")
        assert isinstance(app.world.get(player, Behaviour).script, platformer.Player)
        # the ground of a level is a handful of outlines, not a collider per tile
        outlines = [t for _, (t,) in app.world.query(TileCollider) if t.kind == "outline"]
        assert 1 <= len(outlines) <= 4
        platformer.play(app, levels=1, seconds=30)
        score = app.world.resource(platformer.Score)
        assert score.level == 2 and score.coins >= 1
        source = app.world.resource(SceneState).source
        assert source is not None and source.name == "level2.scene.toml"
    finally:
        app.close()


def _open_settings() -> App:
    from kge.testing import click, press

    app = App(platformer.level, headless=True, size=(platformer.WIDTH, platformer.HEIGHT))
    app.step(5)
    press(app, Key.P)  # the pause menu, over the frozen level
    click(app, "Settings")
    app.step()
    return app


def test_the_settings_menu_has_tabs_of_volumes_rebindable_controls_and_ui_size() -> None:
    from kge.testing import box_of, click, press

    app = _open_settings()
    try:
        world = app.world
        assert world.name == "settings" and find_text(app, "Music volume")
        click(app, "Controls")
        view = next(e for e, _ in world.query(ScrollView))
        rows = [e for e, (b,) in world.query(Button) if b.text.startswith(("left:", "jump:"))]
        assert all(world.get(e, UINode).parent == view for e in rows)
        click(app, "jump: SPACE / UP / W")
        press(app, Key.J)
        assert app.actions.bindings("jump")[0] == "key:J"
        assert find_text(app, "jump: J")
        click(app, "Reset controls")
        assert world.query(Dialog)  # asks first
        click(app, "Reset")
        app.step()
        assert app.actions.bindings("jump")[0] == "key:SPACE" and not world.query(Dialog)
        click(app, "Display")
        size = min(e for e, _ in world.query(Slider) if world.get(e, Slider).min == 0.75)
        b = box_of(app, size)
        app.input.click(at=(b.right - 1, b.center[1]))
        app.step()
        assert world.resource(UISettings).scale == 1.5
        click(app, "Back")
        app.step()
        assert app.world.resource(UISettings).scale == 1.5  # every scene of the App
    finally:
        app.close()


def test_a_rebound_jump_jumps_in_the_level() -> None:
    from kge.testing import click, press

    app = _open_settings()
    try:
        click(app, "Controls")
        click(app, "jump: SPACE / UP / W")
        press(app, Key.J)
        press(app, Key.ESCAPE)  # leaves the settings
        press(app, Key.ESCAPE)  # and the pause
        assert app.world.name == "level"
        app.step(60)  # landed
        (player,) = platformer.named(app.world, "player")
        y = app.world.get(player, Transform).y
        app.input.press(Key.J)
        app.step(10)
        assert app.world.get(player, Transform).y > y + 0.5
    finally:
        app.close()


def find_text(app: App, text: str) -> bool:
    from kge.testing import UITargetError, find

    try:
        find(app, text)
    except UITargetError:
        return False
    return True


def test_the_level_files_are_what_the_editing_session_writes(tmp_path: Path) -> None:
    for n in (1, 2):
        made = platformer_levels.build(n, tmp_path)
        assert made.read_text() == (platformer.LEVELS / made.name).read_text()
