"""``python -m benchmarks.rl --profile``: exclusive wall time per part of a batched step."""

from __future__ import annotations

import re
import types

import pytest

from benchmarks.rl import Exclusive, breakdown


class FakeClock:
    """A clock that moves only when the code under test says it worked (no sleeps, so
    the test asserts what is counted where, whatever the machine's load)."""

    def __init__(self) -> None:
        self.now = 0.0

    def __call__(self) -> float:
        return self.now

    def work(self, seconds: float) -> None:
        self.now += seconds


def test_a_part_is_timed_without_the_parts_it_calls() -> None:
    clock = FakeClock()
    ns = types.SimpleNamespace()
    ns.inner = lambda: clock.work(0.02)

    def outer() -> None:
        clock.work(0.01)
        ns.inner()
        clock.work(0.005)
        ns.inner()

    ns.outer = outer
    parts = Exclusive(clock)
    parts.wrap(ns, "outer", "outer")
    parts.wrap(ns, "inner", "inner")
    ns.outer()
    assert parts.acc["inner"] == pytest.approx(0.04)  # both calls
    assert parts.acc["outer"] == pytest.approx(0.015)  # its callee's time excluded
    ns.inner()  # called on its own: counted once more, outer unchanged
    assert parts.acc == pytest.approx({"inner": 0.06, "outer": 0.015})
    parts.restore()
    assert ns.outer is outer  # unwrapped


def test_the_breakdown_accounts_for_the_whole_step() -> None:
    pytest.importorskip("gymnasium")
    text = breakdown(2, env_steps=40)
    rows = dict(re.findall(r"^\| (.+?) \| ([\d.-]+) \| -?\d+% \|$", text, re.M))
    total = float(re.search(r"N = 2: ([\d.]+) µs", text).group(1))  # type: ignore[union-attr]
    assert float(rows["pymunk space.step: the solver (C), kge's contact callbacks"]) > 0.0
    assert float(rows["joints after the step: position pass, read-back"]) > 0.0
    # every part plus the rest is the measured step (to the printed rounding)
    assert sum(float(v) for v in rows.values()) == pytest.approx(total, abs=0.1 * len(rows))


def test_the_single_env_breakdown_names_the_env_parts() -> None:
    pytest.importorskip("gymnasium")
    text = breakdown(1, env_steps=30, warmup=5)
    rows = dict(re.findall(r"^\| (.+?) \| ([\d.-]+) \| -?\d+% \|$", text, re.M))
    total = float(re.search(r"LunarLander: ([\d.]+) µs", text).group(1))  # type: ignore[union-attr]
    assert float(rows["observation: components read, floats, checks"]) > 0.0
    assert float(rows["pymunk space.step: the solver (C), kge's contact callbacks"]) > 0.0
    assert sum(float(v) for v in rows.values()) == pytest.approx(total, abs=0.1 * len(rows))
