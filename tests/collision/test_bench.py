"""The kge.collision bench rows run and measure the same questions (no timing asserted)."""

from __future__ import annotations

from benchmarks import collision as bench
from benchmarks.engines import box2d_available


def test_collision_rows_run_quickly_and_render() -> None:
    rows = bench.measure(quick=True)
    assert [r["row"] for r in rows] == ["distance", "collide", "tree query"]
    for r in rows:
        assert r["kge"] > 0
    if box2d_available() is None:
        assert rows[0]["pybox2d"] > 0 and rows[1]["pybox2d"] > 0
    assert rows[2]["numpy scan"] > 0 and rows[2]["python scan"] > 0
    text = bench.table(rows)
    assert "tree query" in text and "x numpy scan" in text
    assert any("| tree query |" in line for line in bench.markdown(rows))
