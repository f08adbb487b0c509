"""The game-layer feature rows of ``kge bench`` run and report (timings never asserted)."""

from __future__ import annotations

from benchmarks import run
from benchmarks.features import (
    feature_lines,
    feature_targets,
    measure_gizmos,
    measure_particle_forces,
    measure_timings,
)


def test_the_timings_row_measures_both_modes() -> None:
    r = measure_timings(extra=5, frames=2, repeats=2)
    assert r["systems"] > 5 and r["off_ms"] > 0 and r["on_ms"] > 0
    assert r["overhead_us_per_system"] >= 0


def test_the_gizmo_row_records_and_draws() -> None:
    r = measure_gizmos(50, repeats=2)
    assert r["lines"] == 50 and r["record_us_per_line"] > 0 and r["bulk_ms"] > 0


def test_the_particle_forces_row_runs_both_kinds_of_step() -> None:
    r = measure_particle_forces(500, repeats=2)
    assert r["particles"] == 500 and r["plain_ms"] > 0 and r["forces_ms"] > 0 and r["ratio"] > 0
    text = "\n".join(feature_lines({"particle_forces": r}))
    assert "Particle forces about the origin, 500 particles" in text


def test_the_section_reaches_the_report_and_its_targets() -> None:
    features = {"timings": {"systems": 60, "off_ms": 0.1, "on_ms": 0.15,
                            "overhead_us_per_system": 0.8, "overhead_share": 0.5},
                "gizmos": {"lines": 1000, "record_us_per_line": 2.0, "bulk_ms": 0.1,
                           "draw_ms": 1.0}}  # fmt: skip
    text = "\n".join(feature_lines(features))
    assert "| 0.100 | 0.150 | 0.80 µs | 50 % |" in text
    assert "| 2.00 µs per line |" in text
    rows = feature_targets(features)
    assert rows[0][1] == 0.8 and rows[1][1] == 2.0
    assert feature_targets({})[0][1] is None
    report = {"features": features, "results": [], "largest_fitting": {}, "render": {},
              "animation": {}, "targets": [], "date": "", "machine": "", "versions": {},
              "seconds": 0, "quick": True, "skipped": []}  # fmt: skip
    assert "Per-system timings" in run.markdown(report, None)
