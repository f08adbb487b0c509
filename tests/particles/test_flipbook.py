"""Flipbook particle textures: frames over lifetime or at a fps, random start frames."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from kge import App, ParticleEmitter, Particles, Transform, ValidationError, World
from kge.components.particle_flipbook import ParticleFlipbook
from kge.errors import ComponentTypeError
from kge.particles import flipbook


def _frames(book: ParticleFlipbook, steps: int, **emitter: Any) -> np.ndarray:
    fb = ParticleFlipbook(book.columns, book.rows, book.frames, book.fps, book.cycles, book.loop,
                          book.random_start)  # one instance per world  # fmt: skip

    def scene(world: World) -> None:
        world.spawn(Transform(), ParticleEmitter(**{"burst": 50, "speed": 0.0, "lifetime": 1.0,
                                                    "seed": 4, **emitter}), fb)  # fmt: skip

    app = App(scene, headless=True)
    app.step(steps)
    st = app.world.resource(Particles).state(1)
    n = st.pool.count
    row = st.extras[flipbook.KEY]["row"]
    return flipbook.frame_index(st.pool.age[:n], st.pool.life[:n], st.pool.data[row, :n],
                                fb.count, fb.fps, fb.cycles, fb.loop)  # fmt: skip


def test_over_the_lifetime_each_particle_walks_through_every_frame_once() -> None:
    fb = ParticleFlipbook(4, 2, frames=6)
    seen = [set(_frames(fb, s).tolist()) for s in (1, 12, 30, 58)]
    # 6 frames over a 1 s life: frame = floor(age / life x 6)
    assert seen == [{0}, {1}, {2}, {5}]  # ages 0, 11, 29 and 57 frames


def test_at_a_fps_frames_follow_age_and_loop_or_hold() -> None:
    fb = ParticleFlipbook(2, 2, fps=10.0)
    age = np.array([0.0, 0.15, 0.45, 1.0])
    assert flipbook.frame_index(age, np.ones(4), np.zeros(4), 4, 10.0, 1.0, True).tolist() == [
        0, 1, 0, 2]  # fmt: skip
    assert flipbook.frame_index(age, np.ones(4), np.zeros(4), 4, 10.0, 1.0, False).tolist() == [
        0, 1, 3, 3]  # fmt: skip
    assert set(_frames(fb, 1 + 15, lifetime=10.0).tolist()) == {2}  # 0.25 s at 10 fps


def test_random_start_frames_differ_per_particle_and_repeat_with_the_seed() -> None:
    fb = ParticleFlipbook(4, 4, fps=8.0, random_start=True)
    first = _frames(fb, 1, lifetime=10.0)
    assert len(set(first.tolist())) > 8  # spread over the 16 frames
    assert np.array_equal(first, _frames(ParticleFlipbook(4, 4, fps=8.0, random_start=True), 1,
                                         lifetime=10.0))  # fmt: skip
    assert not np.array_equal(first, _frames(ParticleFlipbook(4, 4, fps=8.0, random_start=True),
                                             1, lifetime=10.0, seed=5))  # fmt: skip
    assert set(_frames(ParticleFlipbook(4, 4, fps=8.0), 1, lifetime=10.0).tolist()) == {0}


def test_sheet_cells_map_to_texture_rectangles_top_left_first() -> None:
    rects = flipbook.uv_rects(np.array([0, 1, 2, 3]), 2, 2)
    assert rects.tolist() == [[0.0, 0.5, 0.5, 1.0], [0.5, 0.5, 1.0, 1.0],
                              [0.0, 0.0, 0.5, 0.5], [0.5, 0.0, 1.0, 0.5]]  # fmt: skip


@pytest.mark.parametrize(("fields", "message"), [
    ({"columns": 0}, "ParticleFlipbook.columns must be in 1..256"),
    ({"rows": 1000}, "ParticleFlipbook.rows must be in 1..256"),
    ({"columns": 2, "rows": 2, "frames": 5}, r"ParticleFlipbook.frames must be in 1..4"),
    ({"frames": 0}, "ParticleFlipbook.frames must be >= 1"),
    ({"fps": 0.0}, "ParticleFlipbook.fps must be > 0"),
    ({"fps": float("nan")}, "ParticleFlipbook.fps must be finite"),
    ({"cycles": -1.0}, "ParticleFlipbook.cycles must be > 0"),
    ({"random_start": "yes"}, "ParticleFlipbook.random_start"),
])  # fmt: skip
def test_bad_flipbooks_are_refused_at_the_call(fields: dict[str, Any], message: str) -> None:
    with pytest.raises((ValidationError, ComponentTypeError), match=message):
        ParticleFlipbook(**fields)


def test_a_write_that_would_leave_frames_off_the_sheet_is_refused_and_undone() -> None:
    app = App(lambda w: w.spawn(Transform(), ParticleEmitter(),
                                ParticleFlipbook(4, 2, frames=7)), headless=True)  # fmt: skip
    fb = app.world.get(1, ParticleFlipbook)
    with pytest.raises(ValidationError, match=r"entity 1, ParticleFlipbook.frames must be in 1..4"):
        fb.columns = 2
    with pytest.raises(ValidationError, match=r"entity 1, ParticleFlipbook.frames must be in 1..8"):
        fb.frames = 9
    assert (fb.columns, fb.rows, fb.frames) == (4, 2, 7)
