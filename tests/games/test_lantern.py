"""Lantern Woods, the showcase game: it plays itself for a minute, its parts work, and its
frames show a lit night (8-bit headless frames)."""

from __future__ import annotations

import math
from pathlib import Path

import lantern  # examples/lantern.py
import numpy as np

from kge import App, Behaviour, CharacterBody, Key, Light, MapObject, Sprite, Transform
from kge.testbed.showcase import grab


def fox_of(app: App) -> int:
    world = app.worlds[0]
    return next(e for e, (b,) in world.query(Behaviour) if isinstance(b.script, lantern.Fox))


def game(seed_steps: int = 10) -> App:
    app = lantern.make_app(lantern.level, headless=True)
    app.step(seed_steps)
    return app


def test_it_plays_itself_for_a_minute_from_the_title_menu_and_lights_the_shrine() -> None:
    app = lantern.make_app(headless=True)
    try:
        run = lantern.play(app, seconds=60)
        assert len(run.finished) >= 2, f"the shrine was not lit twice in a minute: {run.last}"
        for p in run.finished:
            assert p.lit and p.jars >= 7 and p.falls <= 2 and p.time < 35
        fox = app.worlds[0].get(fox_of(app), Transform)
        assert math.isfinite(fox.x) and math.isfinite(fox.y)
    finally:
        app.close()


def test_a_jar_counts_glows_out_and_becomes_the_checkpoint() -> None:
    app = game()
    try:
        world, fox = app.world, fox_of(app)
        jar = min((e for e, (m,) in world.query(MapObject) if m.cls == "Jar"),
                  key=lambda e: world.get(e, Transform).x)
        jt = world.get(jar, Transform)
        t = world.get(fox, Transform)
        t.x, t.y = jt.x, jt.y
        app.step(2)
        progress = world.resource(lantern.Progress)
        assert progress.jars == 1 and progress.checkpoint == (jt.x, jt.y + 0.5)
        assert not world.has(jar, Sprite) and not world.has(jar, Light)
        t.x, t.y = 29.5, -5.0  # into a gap: back to the jar
        app.step(2)
        assert progress.falls == 1
        assert abs(t.x - jt.x) < 0.2
    finally:
        app.close()


def jump_height(hold_steps: int) -> float:
    app = game(60)
    try:
        fox = fox_of(app)
        t = app.world.get(fox, Transform)
        y0, top = t.y, t.y
        app.input.press(Key.SPACE)
        for i in range(90):
            if i == hold_steps:
                app.input.release(Key.SPACE)
            app.step()
            top = max(top, t.y)
        return top - y0
    finally:
        app.close()


def test_holding_jump_jumps_higher_than_a_tap() -> None:
    tap, held = jump_height(3), jump_height(60)
    assert held > 5.0 and tap < 0.5 * held


def test_a_gamepad_runs_and_jumps() -> None:
    app = game(60)
    try:
        pad = app.input.connect_gamepad()
        fox = fox_of(app)
        t = app.world.get(fox, Transform)
        x0, y0 = t.x, t.y
        pad.move("leftx", 1.0)
        app.step(30)
        assert t.x > x0 + 1.5 and not app.world.get(fox, Sprite).flip_x
        pad.press("a")
        app.step(20)
        assert t.y > y0 + 2.0
        pad.move("leftx", -1.0)
        app.step(30)
        assert app.world.get(fox, Sprite).flip_x
    finally:
        app.close()


def test_pause_freezes_the_woods() -> None:
    app = game(30)
    try:
        woods = app.world
        app.input.press(Key.P)
        app.step()
        app.input.release(Key.P)
        app.step()
        assert app.world is not woods
        t = woods.get(fox_of(app), Transform)
        before = (t.x, t.y, woods.resource(lantern.Progress).time)
        app.step(60)
        assert (t.x, t.y, woods.resource(lantern.Progress).time) == before
    finally:
        app.close()


def test_the_fox_animates_run_jump_and_fall() -> None:
    app = game(30)
    try:
        from kge import Animator

        anim = app.world.get(fox_of(app), Animator)
        assert anim.current == "idle"
        app.input.press(Key.RIGHT)
        app.step(20)
        assert anim.current == "run"
        app.input.press(Key.SPACE)
        app.step(10)
        assert anim.current == "jump"
        app.input.release(Key.SPACE)
        app.step(40)
        assert anim.current in ("fall", "run")
    finally:
        app.close()


def luminance(img: np.ndarray) -> np.ndarray:
    return np.asarray(img[:, :, :3], float) @ np.array([0.2126, 0.7152, 0.0722])


def test_the_lantern_lights_the_ground_around_the_fox() -> None:
    """An 8-bit frame: ground near the fox is lit by its lantern; with the lantern out, it
    is as dark as the ground far away."""
    app = game(90)
    try:
        world = app.world
        fox = fox_of(app)
        world.get(fox, CharacterBody).velocity = (0.0, 0.0)
        frames = {}
        for lit in (True, False):
            world.get(fox, Light).enabled = lit
            frames[lit] = luminance(grab(app))
        h, w = frames[True].shape
        # the fox sits near the screen's centre-left; compare the ground strip under it
        near = (slice(int(h * 0.80), h), slice(int(w * 0.30), int(w * 0.55)))
        ratio = frames[True][near].mean() / max(frames[False][near].mean(), 1.0)
        assert ratio > 1.4, f"lantern lights the ground only {ratio:.2f}x"
        top = (slice(0, int(h * 0.1)), slice(0, w))  # the sky far above is unlit by it
        assert abs(frames[True][top].mean() - frames[False][top].mean()) < 3.0
    finally:
        app.close()


def test_the_title_frame_shows_the_menu_over_the_night_woods() -> None:
    app = lantern.make_app(headless=True)
    try:
        app.step(30)
        img = grab(app)
        sky = img[: img.shape[0] // 8, :, :3].reshape(-1, 3).mean(axis=0)
        assert np.all(np.abs(sky - np.array(lantern.SKY)) < 40)  # a dark blue night sky
        centre = img[img.shape[0] // 3 : img.shape[0] // 2, img.shape[1] // 3 : 2 * img.shape[1] // 3]
        assert centre[:, :, :3].max() > 200  # the menu's white title text
    finally:
        app.close()


def test_record_gif_writes_an_animation(tmp_path: Path) -> None:
    from PIL import Image, ImageSequence

    out = tmp_path / "lantern.gif"
    lantern.record_gif(out, seconds=1.0, size=(160, 90))
    with Image.open(out) as gif:
        frames = [f.convert("RGB") for f in ImageSequence.Iterator(gif)]
    assert len(frames) >= 9 and frames[0].size == (160, 90)
    assert frames[0].tobytes() != frames[-1].tobytes()  # it moves
