"""The CI-sized soak: churn a few hundred steps, with and without rendering.

The long run (100,000 steps, memory figures) is ``tools/soak.py`` with no
arguments; its results are in benchmarks/results/reliability.md. Memory growth needs
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


def _soak() -> ModuleType:
    spec = importlib.util.spec_from_file_location("kge_tools_soak", ROOT / "tools" / "soak.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


def _exact_problems(report: object) -> list[str]:
    return [p for p in report.problems if "grew" not in p]  # type: ignore[attr-defined]


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
