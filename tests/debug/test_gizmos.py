"""Immediate-mode gizmos: lifetimes per frame, per fixed step and timed; bad input; pixels."""

from __future__ import annotations

import numpy as np
import pytest

from kge import App, Behaviour, Camera, Script, Transform, ValidationError, World
from kge.debug import DebugPlugin, Gizmos
from kge.debug.gizmos import bulk_circles

from ..render.conftest import SIZE, mask, pixels


def test_a_frame_gizmo_lasts_until_the_next_frame() -> None:
    calls: list[int] = []

    class Draw(Script):
        def on_update(self, dt: float) -> None:
            if len(calls) < 2:
                self.world.resource(Gizmos).line((0, 0), (1, 1))
            calls.append(1)

    app = App(lambda w: w.spawn(Transform(), Behaviour(Draw())), headless=True)
    g = app.world.resource(Gizmos)
    app.step(1)
    assert len(g) == 1
    app.step(1)
    assert len(g) == 1  # drawn again this frame
    app.step(1)
    assert len(g) == 0  # not drawn this frame: gone


def test_a_fixed_step_gizmo_lasts_until_the_next_step_not_the_next_frame() -> None:
    class Draw(Script):
        def on_fixed_update(self, dt: float) -> None:
            self.world.resource(Gizmos).circle((0, 0), 1.0, segments=8)

    app = App(lambda w: w.spawn(Transform(), Behaviour(Draw())), headless=True)
    g = app.world.resource(Gizmos)
    app.advance(1 / 60)  # one step
    assert len(g) == 8
    for _ in range(3):  # frames with no fixed step (144 Hz): still shown, not doubled
        app.advance(1 / 600)
        assert len(g) == 8
    app.paused = True
    app.advance(1 / 60)
    assert len(g) == 8  # paused: the last step's shapes stay


def test_a_timed_gizmo_lasts_its_game_time() -> None:
    app = App(lambda w: None, headless=True)
    g = app.world.resource(Gizmos)
    g.arrow((0, 0), (1, 0), duration=0.5)
    g.text((0, 0), "hit", duration=0.5)
    app.step(29)
    assert len(g) == 4  # 3 arrow segments + 1 text
    app.step(2)
    assert len(g) == 0


def test_values_and_colours_come_back_as_arrays() -> None:
    g = Gizmos()
    g.line((0, 0), (1, 2), (255, 0, 0))
    g.lines(np.array([[0, 0, 0, 1], [1, 1, 2, 2]]), (0, 255, 0, 128))
    g.rect((0, 0), (2, 2))
    segs, cols = g.segments()
    assert segs.shape == (7, 4) and cols.shape == (7, 4)
    assert segs[0].tolist() == [0, 0, 1, 2] and cols[0].tolist() == [255, 0, 0, 255]
    assert cols[2].tolist() == [0, 255, 0, 128]
    xs = segs[3:, [0, 2]]
    assert xs.min() == -1 and xs.max() == 1
    assert bulk_circles([(0, 0), (3, 0)], 0.5, 12).shape == (24, 4)


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda g: g.line((0, 0), (float("inf"), 0)), "end must be finite"),
        (lambda g: g.line("ab", (0, 0)), "start must be"),
        (lambda g: g.circle((0, 0), -1.0), "radius must be > 0"),
        (lambda g: g.circle((0, 0), 1.0, segments=2), "segments must be in 3..1024"),
        (lambda g: g.line((0, 0), (1, 1), (300, 0, 0)), "0..255"),
        (lambda g: g.lines(np.zeros((3, 3))), "shape"),
        (lambda g: g.polyline([(0, 0)]), "two or more"),
        (lambda g: g.text((0, 0), "x", duration=0), "duration must be > 0"),
    ],
)
def test_bad_input_is_refused_and_draws_nothing(call, message) -> None:
    g = Gizmos()
    with pytest.raises(ValidationError, match=message):
        call(g)
    assert len(g) == 0


def test_disabled_gizmos_cost_a_return() -> None:
    g = Gizmos()
    g.enabled = False
    g.line((0, 0), (1, 1))
    g.circle((0, 0), float("nan"))  # not even checked
    assert len(g) == 0


def test_a_bare_world_takes_the_plugin() -> None:
    world = World()
    world.add_plugins(DebugPlugin())
    world.resource(Gizmos).line((0, 0), (1, 0))
    from kge.schedule import Stage

    world.schedule.run(Stage.UPDATE, 1 / 60)  # each UPDATE of a bare world is a frame
    assert len(world.resource(Gizmos)) == 0


def test_gizmos_are_drawn_over_the_world_at_their_pixels(make_app) -> None:
    ppm = 20.0

    class Draw(Script):
        def on_update(self, dt: float) -> None:
            g = self.world.resource(Gizmos)
            g.line((-3, 1), (3, 1), (255, 0, 0))
            g.circle((0, -2), 1.5, (0, 255, 0), segments=64)

    app = make_app(lambda w: (w.insert_resource(Camera(pixels_per_meter=ppm)),
                              w.spawn(Transform(), Behaviour(Draw()))))
    app.step(1)
    px = pixels(app)
    red = mask(px, (255, 0, 0))
    ys, xs = np.nonzero(red)
    cx, cy = SIZE[0] / 2, SIZE[1] / 2
    assert abs(ys.mean() - (cy + 1 * ppm)) <= 1.0
    assert abs(xs.min() - (cx - 3 * ppm)) <= 1.0 and abs(xs.max() - (cx + 3 * ppm)) <= 1.0
    green = mask(px, (0, 255, 0))
    ys, xs = np.nonzero(green)
    r = np.hypot(xs + 0.5 - cx, ys + 0.5 - (cy - 2 * ppm))
    assert len(r) > 100 and abs(np.median(r) - 1.5 * ppm) <= 1.0
    app.world.resource(Gizmos).enabled = False
    app.step(1)  # the script draws again, but disabled gizmos record nothing
    px = pixels(app)
    assert not mask(px, (255, 0, 0)).any()


def test_text_gizmos_draw_glyphs_where_asked(make_app) -> None:
    app = make_app(lambda w: None)
    g = app.world.resource(Gizmos)
    g.text((10, 10), "HELLO", (255, 255, 0), size=14, screen=True)
    px = pixels(app)
    yellow = mask(px, (255, 255, 0), tol=90)
    ys, xs = np.nonzero(yellow)
    assert len(xs) > 30 and xs.min() >= 9 and ys.min() >= 9 and xs.max() < 100
    g.clear()
    assert not mask(pixels(app), (255, 255, 0), tol=90).any()
