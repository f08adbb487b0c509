"""The UI benchmark runs at a small size and reports every variant (timings never asserted)."""

from __future__ import annotations

from benchmarks import ui


def test_ui_bench_measures_every_variant_and_formats_its_tables() -> None:
    got = ui.measure(10, repeats=1, frames=2)
    assert set(ui.VARIANTS) <= set(got) and all(got[v] > 0 for v in ui.VARIANTS)
    assert got["static_syncs"] == 0  # an unchanged frame syncs no widget
    assert "resync/static" in ui.table({10: got})
    lst = ui.measure_lists((200,), repeats=1, frames=2)[200]
    assert set(lst) == set(ui.LIST_VARIANTS) and all(v > 0 for v in lst.values())
    assert "resync/static" in ui.text({"10": got, "list-200": lst})
    rows = {"10": got, "list-200": lst}
    lines = ui.markdown_lines(rows)
    assert any(line.startswith("| 10 |") for line in lines)
    assert lines[-1].startswith("| 200 |")
