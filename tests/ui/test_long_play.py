"""Long play: the UI's per-entity tables (state kept between frames, the drawer's clip
groups) hold the nodes that are alive, not every node that ever was."""

from __future__ import annotations

from typing import Any

from kge import App, Panel, ScrollView, TextInput, UINode, World
from kge.render.ui import drawer_for
from kge.ui.state import UIState

from .conftest import pixels


def _panel(world: World) -> None:
    world.spawn(UINode(width=300, height=300, layout="column"), Panel())


def _churn(app: App, frames: int, draw: bool) -> list[int]:
    world = app.world
    panel = next(e for e in world.entities() if world.has(e, Panel))
    alive: list[int] = []
    for k in range(frames):
        view = world.spawn(UINode(parent=panel, width=200, height=40), ScrollView())
        alive.append(view)
        alive.append(world.spawn(UINode(parent=view, height=20), TextInput(f"field {k}")))
        while len(alive) > 8:
            world.despawn(alive.pop(0))
        app.step()
        if draw:
            pixels(app)
    return alive


def test_state_of_despawned_nodes_is_dropped() -> None:
    app = App(_panel, headless=True)
    state = app.world.resource(UIState)
    for e in _churn(app, 200, draw=False):
        if app.world.has(e, TextInput):
            state.text_scroll[e] = 1.0  # what drawing a field does
    assert len(state.versions) <= 8 + 2
    for e in list(state.versions):
        if app.world.has(e, TextInput):
            app.world.despawn(e)
    app.step(2)  # the despawn lands in the first frame, the next layout sees it
    assert not state.text_scroll
    assert all(app.world.exists(e) for e in state.versions)


def test_the_drawer_keeps_clip_groups_of_live_nodes_only(make_app: Any) -> None:
    app = make_app(_panel, size=(400, 400))
    alive = _churn(app, 120, draw=True)
    drawer = drawer_for(app.world)
    state = app.world.resource(UIState)
    assert {k[1] for k in drawer.clips} <= set(alive)
    assert len(drawer.groups) <= 4 * len(alive) + 8
    assert len(state.text_scroll) <= len(alive)
    for e in alive:
        app.world.despawn(e)
    app.step()
    pixels(app)
    assert not drawer.clips and not state.text_scroll
