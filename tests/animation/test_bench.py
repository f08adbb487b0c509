"""The animation bench rows run (timings are never asserted: benchmarks/ reports them)."""

from __future__ import annotations

from benchmarks import run
from benchmarks.animation import VARIANTS, measure, table


def test_animation_bench_measures_every_variant_side_by_side() -> None:
    r = measure(200, repeats=2)
    assert set(r) == set(VARIANTS)
    assert all(v > 0 for v in r.values())
    assert "pyglet/kge" in table({200: r})
    rows = {t["target"]: t for t in run.targets([], {}, {}, {200: r})}
    assert rows["live tweens per tween and frame (largest N)"]["value"] == r["tweens"]
    ratio = rows["pyglet animated Sprite / kge per animated sprite (largest N)"]["value"]
    assert ratio == r["pyglet_sprite"] / r["kge_total"]
