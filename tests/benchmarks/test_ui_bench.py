"""The UI benchmark runs at a small size and reports every variant (timings never asserted)."""

from __future__ import annotations

from benchmarks import ui


def test_ui_bench_measures_every_variant_and_formats_its_table() -> None:
    got = ui.measure(10, repeats=1, frames=2)
    assert set(got) == set(ui.VARIANTS) and all(v > 0 for v in got.values())
    assert "rebuild/draw" in ui.table({10: got})
    lines = ui.markdown_lines({"10": got})
    assert lines[-1].startswith("| 10 |")
