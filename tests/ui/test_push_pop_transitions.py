"""Transitions on push and pop: a menu that fades in over the game and out again, with
the stack changing at the transition's half way and the scene below intact."""

from __future__ import annotations

from typing import Any

import pytest

from kge import App, SceneStackError
from kge.transitions import Fade

from .conftest import mask, pixels
from .test_scenes import BLUE, RED, Ticker, game, pause


def test_push_and_pop_change_the_stack_when_the_fade_is_due() -> None:
    t = Ticker()
    app = App(game, headless=True, ticker=t, fixed_dt=0.05)
    below = app.world
    app.push_scene(pause, overlay=True, transition=Fade(0.4))
    app.advance(0.05)
    assert app.world is below and app.transition is not None  # fading out the game
    app.advance(0.15)  # t = 0.5: the menu is pushed
    menu = app.world
    assert menu is not below and app.worlds == [below, menu]
    for _ in range(4):
        app.advance(0.05)
    assert app.transition is None
    app.pop_scene(transition=Fade(0.4))
    app.advance(0.1)
    assert app.world is menu  # still covered, not popped yet
    app.advance(0.1)
    assert app.world is below and menu.closed and app.worlds == [below]
    fixed = t.fixed
    app.advance(0.05)
    assert t.fixed == fixed + 1  # the game runs again, its state intact


def test_a_pending_pop_counts_so_the_last_scene_cannot_be_popped() -> None:
    app = App(game, headless=True, ticker=Ticker(), fixed_dt=0.05)
    app.push_scene(pause, transition=Fade(0.2))
    with pytest.raises(SceneStackError):
        app.pop_scene()  # the push is not made yet: nothing to pop
    for _ in range(6):
        app.advance(0.05)
    assert len(app.worlds) == 2
    app.pop_scene(transition=Fade(0.2))
    with pytest.raises(SceneStackError):
        app.pop_scene()  # the pending pop leaves one scene
    with pytest.raises(TypeError, match="Transition"):
        app.push_scene(pause, transition=0.3)  # type: ignore[arg-type]
    for _ in range(10):
        app.advance(0.05)
    assert len(app.worlds) == 1


def test_a_pushed_menu_fades_in_over_the_game(make_app: Any) -> None:
    app = make_app(game, ticker=Ticker(), fixed_dt=0.05)
    app.push_scene(pause, overlay=True, transition=Fade(0.4, color=(0, 0, 0)))
    app.advance(0.2)  # fully covered: black
    assert pixels(app)[..., :3].max() <= 2
    for _ in range(5):
        app.advance(0.05)
    px = pixels(app)
    assert mask(px, RED[:3]).sum() > 500 and mask(px, BLUE[:3]).sum() > 500  # menu over game
