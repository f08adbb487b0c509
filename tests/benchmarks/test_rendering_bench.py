"""The rendering rows of ``kge bench`` run and report (timings never asserted)."""

from __future__ import annotations

from benchmarks.rendering import lines, run_section, targets


def test_every_rendering_row_runs_and_reports_both_variants() -> None:
    rows, why = run_section(quick=True, progress=lambda msg: None)
    assert why is None, why
    assert set(rows) == {"lights", "lights_soft", "lights_bare", "text", "materials",
                         "materials_each", "post", "cameras"}  # fmt: skip
    for name, r in rows.items():
        assert r["a_cpu"] > 0.0 and r["b_cpu"] > 0.0, name
        assert r["ratio"] == r["a_cpu"] / r["b_cpu"]
    assert rows["text"]["measure_ms"] > 0.0
    table = "\n".join(lines(rows))
    assert "| lights | 6 lights with shadows |" in table and "measure()" in table
    (target,) = targets(rows)
    assert target["value"] == rows["lights"]["ratio"] and target["goal"] == 2.0
    assert target["met"] == (rows["lights"]["ratio"] <= 2.0)
