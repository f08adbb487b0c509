"""The editor benchmark runs at a small size and reports every variant beside the game
(timings never asserted)."""

from __future__ import annotations

from benchmarks import editor


def test_editor_bench_measures_the_editor_and_the_game() -> None:
    got = editor.measure(50, repeats=1, frames=2)
    assert set(editor.VARIANTS) <= set(got) and all(got[v] > 0 for v in editor.VARIANTS)
    assert got["frame/game"] == got["frame"] / got["game"]
    assert "frame/game" in editor.table({50: got})
    lines = editor.markdown_lines({"50": got})
    assert lines[-1].startswith("| 50 |") and "| game |" in lines[-3]
