"""The editor benchmark runs at a small size and reports both rows (timings never asserted)."""

from __future__ import annotations

from benchmarks import editor


def test_editor_bench_measures_the_editor_and_the_game() -> None:
    got = editor.measure(50, repeats=1, frames=2)
    assert got["editor"] > 0 and got["game"] > 0 and got["editor/game"] > 0
    assert "50" in editor.table({50: got})
