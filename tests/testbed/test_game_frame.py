"""The game-frame sample holds what the bench times, and its unchanged HUD costs no UI work
(counted: layouts made and widgets re-synced, never timed)."""

from __future__ import annotations

from typing import Any

from kge import App, Transform
from kge.components.animation import Animator
from kge.components.lights import Light
from kge.components.particles import ParticleEmitter
from kge.components.rigidbody import RigidBody
from kge.components.sprite import Sprite
from kge.components.ui import Label, UINode
from kge.particles import Particles
from kge.render.ui import drawer_for
from kge.testbed import get_sample
from kge.testbed.samples.game_frame import COLS, ROWS, level_grid
from kge.tilemap.runtime import TileMaps
from kge.ui.state import UIState
from tests.render.conftest import make_app, pixels

__all__ = ["make_app"]  # the pooled headless window fixture


def _app(make_app: Any) -> App:
    app: App = make_app(get_sample("game-frame").setup)
    app.step(2)
    pixels(app)
    return app


def test_the_scene_is_the_one_the_issue_names(make_app: Any) -> None:
    app = _app(make_app)
    world = app.world
    assert level_grid().shape == (ROWS, COLS) == (50, 200)
    maps = world.resource(TileMaps)
    assert len(maps.maps) == 1 and (maps.maps[0].data.cols, maps.maps[0].data.rows) == (200, 50)
    assert len(world.query(RigidBody, Sprite)) == 300
    assert len(world.query(Animator, Sprite)) == 30
    assert len(world.query(Light)) == 4
    assert len(world.query(UINode)) == 10
    particles = world.resource(Particles)
    live = sum(particles.state(e).pool.count for e, _ in world.query(ParticleEmitter))
    assert 2600 <= live <= 2900, live  # prewarmed: at its steady count from the first frame


def _frame(app: App) -> tuple[int, int]:
    drawer = drawer_for(app.world)
    version, syncs = app.world.resource(UIState).layout.version, drawer.syncs
    app.step()
    pixels(app)
    return app.world.resource(UIState).layout.version - version, drawer.syncs - syncs


def test_an_unchanged_hud_is_not_laid_out_or_synced_while_the_game_runs(make_app: Any) -> None:
    app = _app(make_app)
    _frame(app)
    moved = {e: t.y for e, (t, _) in app.world.query(Transform, RigidBody)}
    for _ in range(5):
        assert _frame(app) == (0, 0)
    after = {e: t.y for e, (t, _) in app.world.query(Transform, RigidBody)}
    assert after != moved  # the world below the HUD did change
    score = next(lbl for _, (lbl,) in app.world.query(Label) if lbl.text.startswith("score"))
    score.text = "score 1300"  # one value changes: that widget alone is re-synced
    assert _frame(app)[1] == 1
    assert _frame(app) == (0, 0)
