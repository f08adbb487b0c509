"""Overlay scenes (frozen or running below) and transitions (timing and pixels)."""

from __future__ import annotations

from typing import Any

import pytest

from kge import App, Behaviour, Input, Key, Script, Transform, World
from kge.components.camera import Camera
from kge.components.color import RGBA
from kge.components.drawables import Rect
from kge.errors import ValidationError
from kge.transitions import Crossfade, Fade, Slide, Wipe

from .conftest import bbox, mask, pixels

RED: RGBA = (255, 0, 0, 255)
BLUE: RGBA = (0, 0, 255, 255)


class Ticker(Script):
    def __init__(self) -> None:
        self.fixed = 0
        self.keys = 0

    def on_fixed_update(self, dt: float) -> None:
        self.fixed += 1
        self.keys += self.world.resource(Input).pressed(Key.SPACE)


def game(world: World, ticker: Ticker) -> None:
    world.insert_resource(Camera(pixels_per_meter=20))  # 200 px window: red at x 40..80
    world.spawn(Transform(-2, 0), Rect(2.0, 2.0, color=RED), Behaviour(ticker))


def pause(world: World) -> None:
    world.insert_resource(Camera(pixels_per_meter=20))  # blue at x 120..160
    world.spawn(Transform(2, 0), Rect(2.0, 2.0, color=BLUE))


def test_overlay_freezes_the_scene_below_and_pop_returns_to_it_intact() -> None:
    t = Ticker()
    app = App(game, headless=True, ticker=t)
    app.step(5)
    below = app.world
    app.push_scene(pause, overlay=True)
    assert app.visible_worlds() == [below, app.world]
    app.step(10)
    assert t.fixed == 5  # frozen
    app.pop_scene()
    assert app.world is below and app.visible_worlds() == [below]
    app.step(1)
    assert t.fixed == 6


def test_overlay_can_keep_the_scene_below_running_without_its_input() -> None:
    t = Ticker()
    app = App(game, headless=True, ticker=t)
    app.push_scene(pause, overlay=True, run_below=True)
    app.input.press(Key.SPACE)
    app.step(4)
    assert t.fixed == 4 and t.keys == 0


def test_a_running_scene_below_gets_no_clicks_or_key_hooks() -> None:
    from kge import Button, UINode

    got: list[object] = []

    class Hooks(Script):
        def on_key_down(self, key: int) -> None:
            got.append(key)

        def on_click(self, event: object) -> None:
            got.append(event)

    def below(world: World) -> None:
        world.spawn(UINode(width=400, height=300), Button("under"), Behaviour(Hooks()))

    app = App(below, headless=True, size=(400, 300))
    app.push_scene(pause, overlay=True, run_below=True)
    app.input.click(at=(200, 150))
    app.input.press(Key.A)
    app.step(3)
    assert got == []


def test_a_plain_push_hides_the_scene_below() -> None:
    app = App(game, headless=True, ticker=Ticker())
    app.push_scene(pause)
    assert app.visible_worlds() == [app.world]
    with pytest.raises(ValueError, match="overlay=True"):
        app.push_scene(pause, run_below=True)


def test_overlay_draws_both_scenes(make_app: Any) -> None:
    app = make_app(game, ticker=Ticker())
    app.push_scene(pause, overlay=True)
    px = pixels(app)
    assert mask(px, RED[:3]).sum() > 500 and mask(px, BLUE[:3]).sum() > 500
    app.pop_scene()
    app.push_scene(pause)  # not an overlay: only the top scene shows
    px = pixels(app)
    assert mask(px, RED[:3]).sum() == 0 and mask(px, BLUE[:3]).sum() > 500


def test_fade_alpha_at_time_t_and_the_change_at_half_time() -> None:
    app = App(game, headless=True, ticker=Ticker(), fixed_dt=0.05)
    first = app.world
    app.replace_scene(pause, transition=Fade(0.4))
    covers = []
    for _ in range(8):
        app.advance(0.05)
        covers.append(round(app.transition.cover, 3) if app.transition else None)
        if app.transition and app.transition.elapsed < 0.2 - 1e-9:
            assert app.world is first
    assert app.world is not first and app.transition is None
    # eased triangle: up to 1 at t = 0.5, back to 0 at t = 1
    assert covers[:4] == [0.156, 0.5, 0.844, 1.0]
    assert covers[4:7] == [0.844, 0.5, 0.156]


def test_picture_transitions_change_scene_on_the_next_frame() -> None:
    app = App(game, headless=True, ticker=Ticker())
    first = app.world
    app.replace_scene(pause, transition=Crossfade(0.5))
    assert app.world is first
    app.advance(0.1)
    assert app.world is not first
    tr = app.transition
    assert tr is not None and tr.picture_alpha == pytest.approx(1 - 0.104, abs=1e-3)


def test_bad_transitions_are_refused() -> None:
    with pytest.raises(ValidationError, match="duration"):
        Fade(-1)
    with pytest.raises(ValidationError, match="direction"):
        Slide(0.3, direction="sideways")
    with pytest.raises(ValidationError, match="color"):
        Fade(0.3, color=(300, 0, 0))
    app = App(game, headless=True, ticker=Ticker())
    with pytest.raises(TypeError, match="Transition"):
        app.replace_scene(pause, transition=0.4)  # type: ignore[arg-type]
    assert app.transition is None


def test_fade_pixels_darken_then_show_the_new_scene(make_app: Any) -> None:
    app = make_app(game, ticker=Ticker(), fixed_dt=0.05)
    base = mask(pixels(app), RED[:3]).sum()
    app.replace_scene(pause, transition=Fade(0.4, color=(0, 0, 0)))
    app.advance(0.05)  # cover 0.156: red dims a little
    px = pixels(app)
    red_px = px[mask(px, (215, 0, 0), tol=20)]
    assert len(red_px) > base * 0.9
    app.advance(0.15)  # t = 0.5, fully covered
    px = pixels(app)
    assert px[..., :3].max() <= 2
    for _ in range(6):
        app.advance(0.05)
    px = pixels(app)
    assert mask(px, BLUE[:3]).sum() > 500 and mask(px, RED[:3]).sum() == 0


def _half_way(make_app: Any, kind: Any, dt: float) -> Any:
    app = make_app(game, ticker=Ticker())
    assert bbox(mask(pixels(app), RED[:3]))[:2] == (40, 79)
    app.replace_scene(pause, transition=kind)
    pixels(app)  # the last frame of the old scene: its picture is taken
    app.advance(dt)
    return app, pixels(app)


def test_crossfade_blends_the_old_picture_over_the_new_scene(make_app: Any) -> None:
    app, px = _half_way(make_app, Crossfade(0.4), 0.2)
    assert app.transition.picture_alpha == pytest.approx(0.5)
    # half of the old picture (red on black) over the new scene (blue on black)
    assert mask(px, (128, 0, 0), tol=12).sum() > 500
    assert mask(px, (0, 0, 128), tol=12).sum() > 500
    assert mask(px, RED[:3]).sum() == 0 and mask(px, BLUE[:3]).sum() == 0


def test_slide_moves_the_old_picture_away(make_app: Any) -> None:
    app, px = _half_way(make_app, Slide(0.4, direction="left"), 0.1)
    moved = round(app.transition.shift[0] * 200)  # eased: -31 px at t = 0.25
    assert moved == -31
    x0, x1, _, _ = bbox(mask(px, RED[:3]))
    assert abs(x0 - (40 + moved)) <= 1 and abs(x1 - (79 + moved)) <= 1
    assert mask(px, BLUE[:3]).sum() == 0  # blue (x 120..160) is still under the picture


def test_wipe_cuts_the_old_picture_away(make_app: Any) -> None:
    app, px = _half_way(make_app, Wipe(0.4, direction="left"), 0.2)
    assert app.transition.shift == pytest.approx((-0.5, 0.0))
    # left half: the old picture (red in place); right half: the new scene (blue)
    assert bbox(mask(px, RED[:3]))[:2] == (40, 79)
    assert bbox(mask(px, BLUE[:3]))[:2] == (120, 159)
    app.advance(0.3)
    px = pixels(app)
    assert app.transition is None and mask(px, RED[:3]).sum() == 0
