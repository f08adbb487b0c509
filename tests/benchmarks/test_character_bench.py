"""The character row of ``kge bench`` runs and reports (timings are never asserted)."""

from __future__ import annotations

from benchmarks import character, run


def test_the_character_row_runs_the_three_worlds_side_by_side() -> None:
    r = character.measure(30, frames=8, warmup=20, blocks=2)
    for key in ("characters_ms", "dynamic_ms", "kinematic_ms", "ratio"):
        assert r[key] > 0.0
    assert r["characters_standing"] == 30  # every controller stands on the hills
    assert r["dynamic_deepest_sink_m"] >= 0.0


def test_the_row_reaches_the_report_and_its_target() -> None:
    r = {"size": 1000.0, "characters_ms": 12.0, "dynamic_ms": 10.0, "kinematic_ms": 4.0,
         "controller_ms": 8.0, "ratio": 1.2, "characters_standing": 1000.0,
         "dynamic_deepest_sink_m": 0.01}
    assert "| 1,000 | 12.00 | 10.00 | 4.00 | 8.00 | 1.20 | 1000 | 0.010 |" in "\n".join(
        character.markdown_lines(r))
    row = character.targets(r)[0]
    assert row["met"] is True and row["value"] == 1.2
    report = {"date": "d", "machine": "m", "versions": {}, "results": [],
              "largest_fitting": {}, "targets": [row], "skipped": [], "characters": r}
    assert "Character controllers: 1,000 capsules" in run.markdown(report, None)
