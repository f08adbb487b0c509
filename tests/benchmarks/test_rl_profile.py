"""``python -m benchmarks.rl --profile``: exclusive wall time per part of a batched step."""

from __future__ import annotations

import re
import time
import types

import pytest

from benchmarks.rl import Exclusive, breakdown


def test_a_part_is_timed_without_the_parts_it_calls() -> None:
    ns = types.SimpleNamespace()
    ns.inner = lambda: time.sleep(0.02)

    def outer() -> None:
        time.sleep(0.01)
        ns.inner()

    ns.outer = outer
    parts = Exclusive()
    parts.wrap(ns, "outer", "outer")
    parts.wrap(ns, "inner", "inner")
    ns.outer()
    assert parts.acc["inner"] == pytest.approx(0.02, abs=0.008)
    assert parts.acc["outer"] == pytest.approx(0.01, abs=0.008)  # its callee's time excluded
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
