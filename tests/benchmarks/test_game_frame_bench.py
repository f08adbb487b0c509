"""The game-frame bench runs quickly and reports every group (timings never asserted)."""

from __future__ import annotations

from benchmarks import game_frame


def test_game_frame_bench_reports_every_group_and_its_targets() -> None:
    got = game_frame.measure(quick=True)
    for name, _ in game_frame.GROUPS:
        assert got[name] >= 0.0
    assert got["total"] > 0 and got["pymunk_step"] > 0 and got["physics"] > 0
    assert got["hud_syncs"] == 0  # an unchanged HUD re-syncs no widget
    assert 2600 <= got["particles_live"] <= 2900
    rows = game_frame.targets(got)
    assert [r[0].split(",")[0] for r in rows] == ["game frame"] * 3
    assert game_frame.lines(got)[-1].startswith(f"| {got['total']:.2f} |")
