"""Tweens beyond the built-in curves: custom easings, relative moves, calls inside a
sequence, tweening a function, and pause / resume / speed per tween."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kge import Call, Delay, Sprite, Transform, Tween, TweenSequence, ValidationError, World
from kge.animation.easing import CubicBezier, EaseCurve, ease
from kge.animation.tweens import Tweens
from kge.render.images import solid


def _world() -> tuple[World, int, Tweens]:
    w = World()
    e = w.spawn(Transform(3.0, 0.0))
    return w, e, Tweens(w)


def _x(w: World, e: int) -> float:
    return w.get(e, Transform).x


# -- custom easing ------------------------------------------------------------------------------
def test_a_function_a_bezier_and_a_curve_ease_a_tween() -> None:
    w, e, tweens = _world()
    tweens.start(e, Tween(Transform, "x", 13.0, 1.0, ease=lambda p: p**0.5))
    tweens.advance(0.25, fixed=False)
    assert _x(w, e) == pytest.approx(3.0 + 10.0 * 0.5)
    css_ease = CubicBezier(0.25, 0.1, 0.25, 1.0)
    f = w.spawn(Transform())
    tweens.start(f, Tween(Transform, "x", 1.0, 1.0, ease=css_ease))
    tweens.advance(0.5, fixed=False)
    assert _x(w, f) == pytest.approx(0.8024033877399112, abs=1e-6)  # CSS "ease" at 50 %
    assert _x(w, e) == pytest.approx(3.0 + 10.0 * math.sqrt(0.75))  # both curves, one pass
    g = w.spawn(Transform())
    tweens.start(g, Tween(Transform, "x", 10.0, 1.0, ease=EaseCurve([(0, 0), (0.5, 1.0),
                                                                     (1, 0.5)])))  # fmt: skip
    tweens.advance(0.5, fixed=False)
    assert _x(w, g) == pytest.approx(10.0)
    tweens.advance(0.5, fixed=False)
    assert _x(w, g) == pytest.approx(5.0)  # a curve need not end at 1


def test_a_scalar_only_function_is_called_per_value() -> None:
    def smooth(p: float) -> float:
        return math.sin(p * math.pi / 2)  # math.sin refuses arrays

    assert ease(smooth, np.array([0.0, 1 / 3, 1.0])).tolist() == pytest.approx([0.0, 0.5, 1.0])
    w, e, tweens = _world()
    tweens.start(e, Tween(Transform, "x", 5.0, 1.0, ease=smooth))
    tweens.advance(1 / 3, fixed=False)
    assert _x(w, e) == pytest.approx(4.0)


def test_the_bezier_matches_its_definition() -> None:
    b = CubicBezier(0.42, 0.0, 0.58, 1.0)
    t = np.linspace(0, 1, 11)
    u = 1 - t
    xs = 3 * u * u * t * 0.42 + 3 * u * t * t * 0.58 + t**3
    ys = 3 * u * t * t + t**3
    assert np.allclose(b(xs), ys, atol=1e-8)


@pytest.mark.parametrize(
    ("make", "message"),
    [
        (lambda: Tween(Transform, "x", 1.0, 1.0, ease=lambda p: 1 / (p - 0.5)),
         "failed at progress"),
        (lambda: Tween(Transform, "x", 1.0, 1.0, ease=lambda p: float("nan")), "not all finite"),
        (lambda: CubicBezier(1.5, 0, 0.5, 1), "x1 and x2 must be in"),
        (lambda: CubicBezier(0.5, float("inf"), 0.5, 1), "y1 must be a finite"),
        (lambda: EaseCurve([(0, 0), (0.6, 1), (0.5, 1), (1, 1)]), "increasing"),
        (lambda: EaseCurve([(0.1, 0), (1, 1)]), "from 0 to 1"),
        (lambda: EaseCurve([(0, 0)]), "two or more"),
    ],
)  # fmt: skip
def test_bad_curves_are_refused_at_the_call(make, message) -> None:
    with pytest.raises(ValidationError, match=message):
        make()


# -- relative ------------------------------------------------------------------------------------
def test_relative_moves_add_to_where_they_start() -> None:
    w, e, tweens = _world()
    tweens.start(e, TweenSequence(Tween(Transform, "x", 2.0, 0.5, relative=True),
                                  Tween(Transform, "x", 2.0, 0.5, relative=True)))  # fmt: skip
    tweens.advance(0.25, fixed=False)
    assert _x(w, e) == pytest.approx(4.0)
    tweens.advance(0.5, fixed=False)
    assert _x(w, e) == pytest.approx(6.0)  # the second step starts from 5
    tweens.advance(0.25, fixed=False)
    assert _x(w, e) == pytest.approx(7.0)
    f = w.spawn(Transform(), Sprite(solid(1, 1, (255, 255, 255))))
    tweens.by(f, Sprite, "tint", (-100, -50, 0), 1.0)
    tweens.start(f, Tween(Transform, "y", 1.0, 1.0, start=4.0, relative=True))
    tweens.advance(1.0, fixed=False)
    assert w.get(f, Sprite).tint == (155, 205, 255)
    assert w.get(f, Transform).y == pytest.approx(5.0)


# -- calls ---------------------------------------------------------------------------------------
def test_a_call_runs_at_its_point_of_the_sequence() -> None:
    w, e, tweens = _world()
    seen: list[tuple[str, float]] = []
    tweens.start(e, TweenSequence(
        Tween(Transform, "x", 5.0, 0.5), Call(lambda tag: seen.append((tag, _x(w, e))), "half"),
        Tween(Transform, "x", 9.0, 0.5), Call(lambda: seen.append(("end", _x(w, e)))),
    ))  # fmt: skip
    tweens.advance(0.4, fixed=False)
    assert seen == []
    tweens.advance(0.2, fixed=False)
    assert seen == [("half", pytest.approx(5.8))]  # called once its time passed
    finished = tweens.advance(0.5, fixed=False)
    assert seen[-1] == ("end", 9.0) and len(finished) == 1


def test_a_looping_sequence_calls_on_every_pass_and_a_timer_needs_no_tween() -> None:
    _, e, tweens = _world()
    beats: list[int] = []
    h = tweens.start(e, TweenSequence(Tween(Transform, "x", 1.0, 0.25), Call(beats.append, 1),
                                      repeat=-1))  # fmt: skip
    for _ in range(11):
        tweens.advance(0.1, fixed=False)
    assert len(beats) == 4  # at 0.25, 0.5, 0.75, 1.0
    h.cancel()
    tweens.advance(1.0, fixed=False)
    assert len(beats) == 4
    rang: list[str] = []
    timer = tweens.start(e, TweenSequence(Delay(0.5), Call(rang.append, "ring")))
    tweens.advance(0.3, fixed=False)
    assert rang == [] and not timer.done
    tweens.advance(0.3, fixed=False)
    assert rang == ["ring"] and timer.done
    with pytest.raises(ValidationError, match="takes no time"):
        tweens.start(e, TweenSequence(Call(print), repeat=-1))
    with pytest.raises(ValidationError, match="needs a function"):
        Call("print")


# -- a function as the target ----------------------------------------------------------------------
def test_tweening_a_function() -> None:
    _, _, tweens = _world()
    got: list[float] = []
    tweens.method(got.append, 0.0, 10.0, 1.0, ease="quad_in")
    tweens.advance(0.5, fixed=False)
    tweens.advance(0.5, fixed=False)
    assert got == [pytest.approx(2.5), pytest.approx(10.0)]
    colours: list[tuple[int, ...]] = []
    tweens.method(colours.append, (0, 0, 0), (200, 100, 50), 1.0)
    tweens.advance(0.5, fixed=False)
    assert colours == [(100.0, 50.0, 25.0)]
    with pytest.raises(ValidationError, match="needs a function"):
        tweens.method(3, 0.0, 1.0, 1.0)  # type: ignore[arg-type]


# -- pause, resume, speed -------------------------------------------------------------------------
def test_pause_resume_and_speed_are_per_tween() -> None:
    w, e, tweens = _world()
    f = w.spawn(Transform())
    a = tweens.to(e, Transform, "x", 13.0, 1.0)
    b = tweens.to(f, Transform, "x", 10.0, 1.0)
    tweens.advance(0.25, fixed=False)
    a.pause()
    assert a.paused and not b.paused
    tweens.advance(0.25, fixed=False)
    assert _x(w, e) == pytest.approx(5.5) and _x(w, f) == pytest.approx(5.0)
    a.resume()
    b.speed = 2.0
    tweens.advance(0.25, fixed=False)
    assert _x(w, e) == pytest.approx(8.0) and b.done and _x(w, f) == 10.0
    a.speed = 0.5
    assert a.speed == 0.5
    tweens.advance(0.5, fixed=False)
    assert _x(w, e) == pytest.approx(10.5)
    with pytest.raises(ValidationError, match="speed must be >= 0"):
        a.speed = -1.0
    with pytest.raises(ValidationError, match="speed"):
        a.speed = float("nan")
    assert a.speed == 0.5
    assert b.speed == 1.0 and not b.paused  # a finished tween answers the defaults
