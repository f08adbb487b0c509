"""benchmarks.box2d_examples: its key script and one short run per engine."""

from __future__ import annotations

import importlib.util

import pytest

from benchmarks import box2d_examples
from kge.box2d.testbed import examples

pytestmark = pytest.mark.skipif(
    importlib.util.find_spec("Box2D") is None or examples.examples_dir() is None,
    reason="pybox2d (box2d 2.3.10, the dev extra) is not installed")


def test_presses_are_the_example_s_keys_then_space() -> None:
    got = [(p.frame, p.key, p.hold) for p in box2d_examples.presses("breakable")]
    assert got == [(60, "b", 20), (100, "SPACE", 20)]


def test_an_example_runs_on_both_engines() -> None:
    for engine in examples.ENGINES:
        backend, seconds, error = box2d_examples.run("breakable", engine, 110)
        assert error == "" and backend.frames_run == 110 and seconds > 0
        assert backend.test.broke  # b at frame 60


def test_the_sleep_cell_counts_awake_bodies_and_the_frame_all_slept() -> None:
    # the breakable body lands at frame 166, breaks, and its two pieces rest by frame 300
    assert box2d_examples.sleep_cell("breakable", "kge", 100) == "1 of 1 awake"  # falling
    cell = box2d_examples.sleep_cell("breakable", "pybox2d", 330)
    assert cell.startswith("0 of 2 awake, all asleep from frame ")
    assert 250 < int(cell.rsplit(" ", 1)[1]) < 330
