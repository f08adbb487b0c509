"""The platformer example: its levels are scene files made in the editor; they load, coins
count, the door changes the level, and the files are what the editing session makes."""

from __future__ import annotations

from pathlib import Path

import platformer
import platformer_levels

from kge import App, Behaviour, TileCollider
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


def test_the_level_files_are_what_the_editing_session_writes(tmp_path: Path) -> None:
    for n in (1, 2):
        made = platformer_levels.build(n, tmp_path)
        assert made.read_text() == (platformer.LEVELS / made.name).read_text()
