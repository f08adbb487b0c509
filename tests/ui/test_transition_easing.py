"""Transitions with their own easing: the cover, picture alpha and shift follow it."""

from __future__ import annotations

import pytest

from kge import App, CubicBezier, ValidationError
from kge.transitions import ActiveTransition, Crossfade, Fade, Slide


def test_a_linear_fade_covers_in_proportion() -> None:
    smooth = ActiveTransition(Fade(0.4))
    linear = ActiveTransition(Fade(0.4, ease=lambda p: p))
    for active in (smooth, linear):
        active.advance(0.05)  # an eighth in: a quarter of the way to full cover
    assert linear.cover == pytest.approx(0.25)
    assert smooth.cover == pytest.approx(0.15625)  # smoothstep(0.25), the default


def test_a_bezier_shapes_slides_and_crossfades() -> None:
    ease_in = CubicBezier(0.7, 0.0, 1.0, 1.0)
    slide = ActiveTransition(Slide(1.0, direction="right", ease=ease_in))
    fade = ActiveTransition(Crossfade(1.0, ease=ease_in))
    for active in (slide, fade):
        active.advance(0.5)
    assert slide.shift[0] == pytest.approx(ease_in(0.5)) and slide.shift[0] < 0.3
    assert fade.picture_alpha == pytest.approx(1.0 - ease_in(0.5))


def test_an_overshooting_curve_is_clamped_and_a_bad_one_refused() -> None:
    wild = ActiveTransition(Fade(1.0, ease=lambda p: 2.0 * p))
    wild.advance(0.5)
    assert wild.cover == 1.0
    with pytest.raises(ValidationError, match="Fade.ease must be a function"):
        Fade(0.4, ease="quad_in")
    with pytest.raises(ValidationError, match="Wipe.ease failed"):
        from kge.transitions import Wipe

        Wipe(0.4, ease=lambda p: 1 / (p - 0.5))
    with pytest.raises(ValidationError, match="not all finite"):
        Fade(0.4, ease=lambda p: float("nan"))


def test_the_app_plays_a_custom_fade() -> None:
    app = App(lambda world: None, headless=True, fixed_dt=0.05)
    app.replace_scene(lambda world: None, transition=Fade(0.4, ease=lambda p: p))
    app.step(1)
    assert app.transition is not None and app.transition.cover == pytest.approx(0.25)
