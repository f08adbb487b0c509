"""What a frame of UI work touches (counts, never timings): an unchanged HUD is neither
laid out nor synced again; a changed value syncs its widget alone; hover syncs two."""

from __future__ import annotations

from typing import Any

from kge import App, Button, Label, ProgressBar, UINode, World
from kge.render.ui import drawer_for
from kge.ui.state import UIState

from .conftest import pixels


def hud(world: World, buttons: int = 200) -> None:
    world.spawn(UINode(anchor="top_left", offset=(10, -10)), Label("Score 0"))
    world.spawn(UINode(anchor="top_right", offset=(-10, -10), width=120, height=12),
                ProgressBar(1.0))  # fmt: skip
    grid = world.spawn(UINode(anchor="bottom", width="90%", layout="grid", columns=20))
    for i in range(buttons):
        world.spawn(UINode(parent=grid, height=14), Button(f"B{i}"))


def _frame(app: App) -> tuple[int, int]:
    """One frame (step + draw); (layouts made, entities synced) during it."""
    drawer = drawer_for(app.world)
    version, syncs = app.world.resource(UIState).layout.version, drawer.syncs
    app.step()
    pixels(app)
    return app.world.resource(UIState).layout.version - version, drawer.syncs - syncs


def test_an_unchanged_hud_is_not_laid_out_or_synced_again(make_app: Any) -> None:
    app = make_app(hud, size=(800, 600))
    _frame(app)
    _frame(app)
    for _ in range(5):
        assert _frame(app) == (0, 0)


def test_a_changed_value_syncs_its_widget_alone_and_needs_no_layout(make_app: Any) -> None:
    app = make_app(hud, size=(800, 600))
    _frame(app)
    bar = next(b for _, (b,) in app.world.query(ProgressBar))
    bar.value = 0.5  # a fixed-size bar: no box moves
    assert _frame(app) == (0, 1)
    score = next(lbl for _, (lbl,) in app.world.query(Label))
    score.text = "Score 1"  # same width (digits are as wide as each other): no layout
    assert _frame(app) == (0, 1)
    score.text = "Score 1000"  # wider: laid out again, but only the label moved
    assert _frame(app) == (1, 1)


def test_hover_syncs_the_two_buttons_whose_look_changed(make_app: Any) -> None:
    app = make_app(hud, size=(800, 600))
    _frame(app)
    lay = app.world.resource(UIState).layout
    buttons = [e for e, _ in app.world.query(Button)]
    app.input.move_mouse(*lay.boxes[buttons[3]].center)
    assert _frame(app) == (0, 1)
    app.input.move_mouse(*lay.boxes[buttons[40]].center)
    assert _frame(app) == (0, 2)


def test_a_resize_lays_out_once_and_syncs_what_moved(make_app: Any) -> None:
    app = make_app(hud, size=(800, 600))
    _frame(app)
    app.size = (900, 600)
    layouts, syncs = _frame(app)
    assert layouts == 1 and syncs > 200  # everything moved
    assert _frame(app) == (0, 0)
