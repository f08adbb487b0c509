"""Time and API inputs: refused with the field named, and the game keeps running.

The catalogue (``catalogue.py``) checks each refusal and its message; these tests
check what happens next: a refused ``advance(nan)`` must not stop the clock, and
valid spellings (numpy ints, keys) still work.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import kge
from kge import App, Behaviour, Transform
from kge.errors import ComponentTypeError, ValidationError


def test_a_refused_nan_frame_leaves_the_clock_running() -> None:
    app = App(headless=True)
    app.push_scene(lambda world: None)
    with pytest.raises(ValidationError, match="frame_dt must be finite"):
        app.advance(math.nan)
    assert app.timestep.accumulator == 0.0
    assert app.advance(app.fixed_dt) == 1  # not frozen
    with pytest.raises(ValidationError):
        app.advance(math.inf)
    assert app.advance(app.fixed_dt) == 1


def test_valid_spellings_still_work() -> None:
    app = App(headless=True)
    app.push_scene(lambda world: None)
    app.step(np.int64(2))  # type: ignore[arg-type]
    app.time_scale = 2  # an int is a number
    assert app.time_scale == 2.0
    assert app.world.resource(kge.scene.Time).step == 2
    with pytest.raises(ComponentTypeError):
        app.step(2.0)  # type: ignore[arg-type]  # a float count is a mistake, not 2 steps
    app.input.press(kge.Key.SPACE)
    app.input.move_mouse(np.float32(3.0), 4)  # type: ignore[arg-type]
    assert app.input.mouse_screen == (3.0, 4.0)


class Counter(kge.Script):
    def __init__(self) -> None:
        self.calls = 0

    def on_update(self, dt: float) -> None:
        self.calls += 1


def test_hooks_are_looked_up_per_instance() -> None:
    app = App(headless=True)
    app.push_scene(lambda world: None)
    w = app.world
    special = Counter()
    seen: list[float] = []
    special.on_fixed_update = seen.append  # type: ignore[attr-defined]  # only this one
    w.spawn(Transform(), Behaviour(special))
    plain = Counter()
    w.spawn(Transform(), Behaviour(plain))  # the class must not inherit special's hook
    app.step(3)
    assert len(seen) == 3
    assert special.calls == plain.calls == 3
