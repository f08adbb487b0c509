"""The animation bench rows run (timings are never asserted: benchmarks/ reports them)."""

from __future__ import annotations

from benchmarks import run
from benchmarks.animation import VARIANTS, measure, table


def test_animation_bench_measures_every_variant_side_by_side() -> None:
    r = measure(200, repeats=2)
    assert set(r) == set(VARIANTS)
    assert all(v > 0 for v in r.values())
    assert "pyglet/kge" in table({200: r})
    rows = {t["target"]: t for t in run.targets([], {}, {}, animation={200: r})}
    assert rows["live tweens per tween and frame (largest N)"]["value"] == r["tweens"]
    fading = "cross-fading animated sprites per sprite and frame (advance + ghosts, largest N)"
    assert rows[fading]["value"] == r["crossfade"]
    assert rows["keyframe timelines (2 tracks) per player and frame (largest N)"][
        "value"] == r["timeline"]
    ratio = rows["pyglet animated Sprite / kge per animated sprite (largest N)"]["value"]
    assert ratio == r["pyglet_sprite"] / r["kge_total"]


def test_arcade_column_comes_from_its_own_venv_or_is_reported_missing(tmp_path) -> None:
    import pytest

    from benchmarks.animation import measure_arcade

    with pytest.raises(FileNotFoundError, match="make bench creates .venv-arcade"):
        measure_arcade((10,), 1, python=str(tmp_path / "no-python"))
    r = {"advance": 1.0, "texcoords": 1.0, "upload": 1.0, "kge_total": 0.1,
         "pyglet_sprite": 2.0, "tweens": 0.2, "arcade_sprite": 3.0}
    rows = {t["target"]: t for t in run.targets([], {}, {}, animation={10: r})}
    assert rows["Arcade TextureAnimationSprite / kge per animated sprite (largest N)"][
        "value"] == pytest.approx(30.0)
    assert "arcade/kge" in table({10: r})
