"""The Ray examples on a local Ray instance: a task sweep and two PPO iterations."""

from __future__ import annotations

import math
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
import ray

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
if str(EXAMPLES) not in sys.path:
    sys.path.insert(0, str(EXAMPLES))

from rl import ppo_lander, sweep  # noqa: E402


@pytest.fixture(scope="module")
def local_ray() -> Iterator[None]:
    # the workers import the example module by name, as they would on a cluster
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False,
             runtime_env={"env_vars": {"PYTHONPATH": str(EXAMPLES)}})
    try:
        yield
    finally:
        ray.shutdown()


@pytest.mark.slow
def test_sweep_runs_as_ray_tasks_and_draws_a_chart(local_ray, tmp_path):
    rows = sweep.sweep([-5.0, -10.0], seeds=range(3))
    assert [(r["gravity"], r["seed"]) for r in rows] == [
        (g, s) for g in (-5.0, -10.0) for s in range(3)]
    # each task is the same seeded episode a local run gives
    local = sweep.fly(-10.0, 1)
    assert rows[4] == local
    summary = sweep.summarise(rows)
    assert [s["gravity"] for s in summary] == [-5.0, -10.0]
    assert all(s["episodes"] == 3 and s["landed"] == 1.0 for s in summary)
    assert all(s["mean_return"] > 200 for s in summary)
    text = sweep.table(summary)
    assert text.count("\n") == 3 and "| -10.0 | 3 |" in text
    png = sweep.chart(summary, tmp_path / "sweep.png")
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and png.stat().st_size > 5000


@pytest.mark.slow
def test_ppo_trains_two_iterations(local_ray, capsys):
    means = ppo_lander.train(2, batch=400, minibatch=100, epochs=1)
    assert len(means) == 2
    assert all(math.isfinite(m) and -1000 < m < 400 for m in means)  # episodes did end
    out = capsys.readouterr().out
    assert "iteration 1: reward mean" in out and "iteration 2: reward mean" in out
