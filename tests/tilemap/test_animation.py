"""Tiled tile animations played by kge.animation's clips on game time (headless)."""

from __future__ import annotations

import os

os.environ.setdefault("PYGLET_HEADLESS", "1")

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from kge import App
from kge.components.camera import Camera
from kge.components.tilemap import TileCollider
from kge.systems.tilemap_animation import MapClips, TileAnimationSystem
from kge.tilemap import TileMap, load_map

from .maps import ANIM_A, COLORS, write_level

#: ANIM_A plays tile 4 for 0.1 s, tile 5 for 0.05 s, tile 6 for 0.2 s (gids 5, 6, 7)
THREE = [(4, 100), (5, 50), (6, 200)]


def _expected(t: float) -> int:
    """The gid ANIM_A shows at game time t, worked out by hand from THREE."""
    t %= 0.35
    return ANIM_A if t < 0.1 else ANIM_A + 1 if t < 0.15 else ANIM_A + 2


@pytest.fixture
def level(tmp_path: Path) -> Iterator[tuple[App, TileMap]]:
    g = np.zeros((8, 10), np.int64)
    g[2, 5] = ANIM_A
    g[6, 1] = ANIM_A
    path = write_level(tmp_path, g, animation=THREE)
    made: list[TileMap] = []

    def setup(world: Any) -> None:
        world.insert_resource(Camera(center=(5.0, 4.0), pixels_per_meter=20))
        made.append(load_map(world, path))

    app = App(setup, headless=True, size=(200, 160), background=(0, 0, 0))
    try:
        yield app, made[0]
    finally:
        app.close()


def test_a_tile_shows_frame_k_at_time_t(level: tuple[App, TileMap]) -> None:
    app, tmap = level
    dt = app.fixed_dt
    assert tmap.shown[ANIM_A] == ANIM_A  # time 0: the first frame
    seen = []
    for n in range(1, 50):  # 0.82 s: more than two laps of the 0.35 s clip
        app.step(1)
        t = n * dt
        if abs((t % 0.35) - 0.1) < 1e-6 or abs((t % 0.35) - 0.15) < 1e-6:
            continue  # exactly on a frame boundary
        assert tmap.shown[ANIM_A] == _expected(t), f"at t={t:.4f}"
        seen.append(int(tmap.shown[ANIM_A]))
    assert set(seen) == {ANIM_A, ANIM_A + 1, ANIM_A + 2}
    # gids that are not animated show themselves
    assert tmap.shown[ANIM_A + 1] == ANIM_A + 1


def test_tile_animations_stop_while_paused_and_follow_time_scale(
    level: tuple[App, TileMap],
) -> None:
    app, tmap = level
    app.step(3)  # 0.05 s
    app.paused = True
    for _ in range(30):
        app.advance(1 / 60)
    assert tmap.shown[ANIM_A] == ANIM_A  # no game time passed
    app.paused = False
    app.time_scale = 0.5
    for _ in range(6):  # 0.1 s of frames, 0.05 s of game time: t = 0.1 + a hair
        app.advance(1 / 60)
    assert tmap.shown[ANIM_A] == ANIM_A + 1


def test_the_drawn_pixels_follow_the_clip(level: tuple[App, TileMap]) -> None:
    from kge.render.setup import frame_pixels

    app, _ = level

    def colour(x: float, y: float) -> tuple[int, ...]:
        px = frame_pixels(app)
        return tuple(int(v) for v in px[int(80 + (y - 4.0) * 20), int(100 + (x - 5.0) * 20), :3])

    def near(a: tuple[int, ...], b: tuple[int, ...]) -> bool:
        return all(abs(p - q) <= 10 for p, q in zip(a, b, strict=True))

    for steps, frame_tile in ((0, 4), (7, 5), (3, 6), (12, 4)):  # t = 0, 0.117, 0.167, 0.367
        app.step(steps)
        app.render()
        # both tiles of the gid show the same frame (row 2 -> y 5..6, row 6 -> y 1..2)
        assert near(colour(5.5, 5.5), COLORS[frame_tile]), steps
        assert near(colour(1.5, 1.5), COLORS[frame_tile]), steps


def test_map_clips_use_the_animation_systems_clip_state(level: tuple[App, TileMap]) -> None:
    """One clip-table row per animated gid, advanced by ClipState (no ticker of its own)."""
    app, tmap = level
    assert [s for s in app.world.schedule.systems() if isinstance(s, TileAnimationSystem)]
    app.step(1)
    clips = tmap.clock
    assert isinstance(clips, MapClips) and clips.gids.tolist() == [ANIM_A]
    assert len(clips.state) == 1 and clips.state.playing.all()
    assert clips.state.table.infos[0].clip.durations == pytest.approx((0.1, 0.05, 0.2))
    tmap.unload()
    time = clips.state.time.copy()
    app.step(1)
    assert np.array_equal(clips.state.time, time)  # an unloaded map's clock stops


def test_the_platformer_levels_water_animates(tmp_path: Path) -> None:
    from kge.testbed.samples.tilemaps import WATER, write_levels

    level1, _ = write_levels(tmp_path)
    made: list[TileMap] = []
    app = App(lambda world: made.append(load_map(world, level1, unknown="ignore")), headless=True)
    try:
        (m,) = made
        assert int(np.count_nonzero(m.layer("Water").gids == WATER)) > 0
        assert not [e for e in m.collider_entities if m.world.get(e, TileCollider).layer == "Water"]
        shown = []
        for _ in range(4):
            shown.append(int(m.shown[WATER]))
            app.step(30)  # 0.5 s: the next 0.4 s frame
        assert shown == [WATER, WATER + 1, WATER, WATER + 1]
    finally:
        app.close()
