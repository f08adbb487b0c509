"""The CI-sized soaks: churn a few hundred steps, with and without rendering, of physics
(``tools/soak.py``) and of the whole game layer (``tools/game_soak.py``).

The long runs (100,000 steps, memory figures) are those tools with no arguments;
their results are in benchmarks/results/reliability.md. Memory growth needs
the long run to mean anything, so here only the exact checks apply: invariants
at every sample, balanced events, nothing left in pymunk or pyglet after
everything is despawned.
"""

from __future__ import annotations

import importlib.util
import os
import sys
from pathlib import Path
from types import ModuleType

import pytest

ROOT = Path(__file__).resolve().parents[2]


def _soak(name: str = "soak") -> ModuleType:
    spec = importlib.util.spec_from_file_location(f"kge_tools_{name}",
                                                  ROOT / "tools" / f"{name}.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


def _exact_problems(report: object) -> list[str]:
    return [p for p in report.problems if " grew " not in p]  # type: ignore[attr-defined]


def test_short_churn_keeps_every_invariant() -> None:
    soak = _soak()
    report = soak.run(steps=400, interval=50, population=40, trace=False)
    assert _exact_problems(report) == []
    assert report.spawned > 400
    last = report.samples[-1]
    assert last.begins > 100 and last.bodies > 20


def test_short_render_churn_leaks_no_pyglet_objects() -> None:
    os.environ.setdefault("PYGLET_HEADLESS", "1")
    try:
        import pyglet.gl  # noqa: F401

        from kge.render.setup import ensure_renderer  # noqa: F401
    except Exception as err:  # pragma: no cover - no GL on this machine
        pytest.skip(f"headless GL is not available: {err}")
    soak = _soak()
    report = soak.run(steps=150, interval=50, population=30, render=True, render_every=5,
                      trace=False)
    assert _exact_problems(report) == []
    rc = report.render_objects
    assert rc["sprites"] + rc["meshes"] > 0, "the render soak drew nothing"


def test_short_game_churn_returns_every_table_to_its_size() -> None:
    """Animated sprites with their own clips, tweens, emitters and bursts, lights, text,
    UI widgets, set_tile, bodies, overlays pushed and popped, drawn when GL is here:
    after the teardown every internal table is back to its size before the churn."""
    os.environ.setdefault("PYGLET_HEADLESS", "1")
    soak = _soak("game_soak")
    report = soak.run(frames=600, interval=100, population=40, render_every=10, trace=False)
    assert _exact_problems(report) == []
    assert report.spawned >= 500 and report.overlays >= 1
    peak = report.peak
    # the churn reached every table it is meant to exercise
    for table in ("Animations.state.table._ends", "Tweens.group", "Particles.states",
                  "UIState.layout.nodes", "Physics._sim.poses.ids", "World.entities"):
        assert peak[table] > report.before.get(table, 0), table
    assert report.after["Animations.state.table._ends"] == 0
    assert report.after["Tweens.group"] == 0 and report.after["Particles.states"] == 0
    # the churn's own bookkeeping holds live entities only (it kept every id it ever
    # spawned: 1.25 ints a frame, the steady allocator growth of the long run)
    for sample in report.samples:
        assert sample.held <= sample.entities, (sample.frame, sample.held, sample.entities)
