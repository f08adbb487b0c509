"""pybox2d's testbed examples run unmodified on kge.box2d, with scripted key presses.

The examples come from the installed pybox2d wheel (``Box2D/examples``; the dev
extra installs box2d 2.3.10) and run through ``kge.box2d.testbed``: kge's own
framework stand-in, headless. Every key an example's source handles
(``Keys.K_*``) is pressed and held a few frames, then space (the framework's
bomb). Example by example, what the keys must do is checked where it is
observable.
"""

from __future__ import annotations

import contextlib
import io
import math
from typing import Any

import pytest

from kge.box2d.testbed import examples
from kge.box2d.testbed.headless import HeadlessBackend
from kge.box2d.testbed.presses import Press

NAMES = examples.names()


def _keys(name: str) -> list[str]:
    return [*examples.keys_handled(name), "SPACE"]


def run(name: str, presses: list[Press], frames: int, engine: str = "kge") -> Any:
    backend = HeadlessBackend(frames, presses)
    with contextlib.redirect_stdout(io.StringIO()):  # main() prints "Loading ..."
        examples.run(name, backend, engine)
    return backend


def test_the_wheel_ships_the_examples() -> None:
    if examples.examples_dir() is None:
        pytest.skip("pybox2d (box2d 2.3.10, the dev extra) is not installed")
    assert len(NAMES) == 38 and "one_sided_platform" in NAMES and "framework" not in NAMES


@pytest.mark.parametrize("name", NAMES)
def test_example_runs_unmodified_with_its_keys(name: str) -> None:
    presses = [Press(8 + 6 * i, key, hold=3) for i, key in enumerate(_keys(name))]
    frames = max(30, presses[-1].frame + 8)
    backend = run(name, presses, frames)
    assert backend.frames_run == frames
    test = backend.test
    assert test.stepCount == frames and test.text[0][2] == test.name  # its title printed
    for body in test.world.bodies:
        assert all(math.isfinite(v) for v in (*body.position, body.angle)), (name, body)
    if test.world.bodyCount > 1:  # the framework's ground body plus the example's
        assert backend.record.counts(), name  # something was drawn this frame


def _presses(*keys: str, start: int = 5) -> list[Press]:
    return [Press(start + 4 * i, k) for i, k in enumerate(keys)]


def test_keys_reach_the_examples() -> None:
    breakable = run("breakable", _presses("b"), 10).test
    assert breakable.broke and breakable.world.bodyCount == 4  # b split it in two
    shapes = run("edge_shapes", _presses("1", "2", "3", "4", "5"), 30).test
    assert shapes.world.bodyCount >= 2 + 5  # ground, framework ground, one body per key
    types = run("body_types", _presses("s"), 10).test
    assert types.platform.type == 0  # s: the platform became static
    web = run("web", _presses("b"), 10).test
    assert web.world.jointCount < 12  # b broke a joint of the web
    car = run("top_down_car", [Press(5, "w", hold=60)], 70).test
    assert car.car.body.linearVelocity.length > 5.0  # w held: it drives


def test_framework_keys_zoom_bomb_and_pause() -> None:
    zoomed = run("empty", _presses("z", "z", "x"), 20).test
    assert zoomed.viewZoom == pytest.approx(10.0 * 1.1 * 1.1 * 0.9)
    bombed = run("empty", _presses("SPACE"), 10).test
    assert bombed.bomb is not None and bombed.bomb.linearVelocity.y < 0
    panned = run("empty", [Press(2, "LEFT", hold=4)], 10).test
    assert panned.viewCenter.x == pytest.approx(-2.0)
