"""The particle and light rows of ``kge bench`` run and report (timings never asserted)."""

from __future__ import annotations

from benchmarks import run
from benchmarks.particles_lights import game_lines, game_targets, measure_particles


def test_particle_row_keeps_the_population_and_reports_each_phase() -> None:
    r = measure_particles(1000, repeats=3)
    assert 900 <= r["live"] <= 1100  # rate n/s x 1 s lifetime: a steady n
    for key in ("update", "upload", "total", "render", "us_per_particle"):
        assert r[key] > 0.0


def test_the_section_reaches_the_report_and_its_targets() -> None:
    game = {"particles": {"50000": {"live": 5e4, "update": 1.0, "upload": 1.0, "total": 2.0,
                                    "us_per_particle": 0.04, "render": 50.0}}}  # fmt: skip
    assert "| 50,000 | 1.00 | 1.00 | 2.00 |" in "\n".join(game_lines(game))
    rows = run.targets([], {}, {}, game=game)
    row = next(t for t in rows if t["target"].startswith("50,000 live particles"))
    assert row["value"] == 2.0 and row["met"] is True
    assert game_targets({})[0][1] is None


def test_without_an_arcade_venv_the_comparison_says_why(monkeypatch) -> None:
    from benchmarks.particles_lights import game_ratios, measure_arcade

    monkeypatch.delenv("KGE_ARCADE_PYTHON", raising=False)
    why = measure_arcade(100, 2)
    assert isinstance(why, str) and "KGE_ARCADE_PYTHON" in why
    assert game_ratios({})[0][1] is None
    game = {"arcade": {"5000": {"arcade_live": 5e3, "arcade_total": 50.0, "kge_live": 5e3,
                                "kge_total": 0.5, "ratio": 100.0}}}  # fmt: skip
    assert "| kge | 5,000 | 0.50 | 100x |" in "\n".join(game_lines(game))
    assert game_ratios(game)[0][1] == 100.0
