"""The platformer example: its Tiled levels load, coins count, the door changes the map."""

from __future__ import annotations

import platformer

from kge import App, MapObject, TileCollider
from kge.testbed.samples.tilemaps import levels


def test_the_door_leads_to_the_second_level_with_the_score() -> None:
    app = App(platformer.level, headless=True)
    try:
        first = {m.map for _, (m,) in app.world.query(MapObject)}
        assert first == {str(levels()[0])}
        # the ground of a level is a handful of outlines, not a collider per tile
        outlines = [t for _, (t,) in app.world.query(TileCollider) if t.kind == "outline"]
        assert 1 <= len(outlines) <= 4
        platformer.play(app, levels=1, seconds=30)
        score = app.world.resource(platformer.Score)
        assert score.level == 2 and score.coins >= 1
        assert {m.map for _, (m,) in app.world.query(MapObject)} == {str(levels()[1])}
    finally:
        app.close()
