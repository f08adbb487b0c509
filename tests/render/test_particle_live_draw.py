"""An emitter's spare capacity is not drawn: each particle domain draws 6 indices per live
particle (counted, never timed), with the same pixels as drawing every quad."""

from __future__ import annotations

from typing import Any

import numpy as np
import pyglet.gl

from kge import Transform
from kge.components.camera import Camera
from kge.components.particles import ParticleEmitter
from kge.particles import Particles
from kge.render import particles as particle_render

from .conftest import pixels


def _scene(world: Any) -> None:
    world.insert_resource(Camera(pixels_per_meter=20.0))
    for k, x in enumerate((-2.0, 2.0)):  # two emitters in one domain (same look)
        world.spawn(Transform(x, 0.0), ParticleEmitter(
            burst=7 + 5 * k, speed=1.0, spread=6.28, lifetime=5.0, size=0.3, flat=True,
            color=(255, 200, 40), max_particles=500, seed=k))  # fmt: skip


def _drawn_indices(app: Any, monkeypatch: Any) -> tuple[list[int], np.ndarray]:
    counts: list[int] = []
    real = pyglet.gl.glDrawElements

    def counting(mode: int, count: int, kind: int, offset: Any) -> None:
        counts.append(count)
        real(mode, count, kind, offset)

    monkeypatch.setattr(particle_render.gl, "glDrawElements", counting)
    px = pixels(app)
    monkeypatch.undo()
    return counts, px


def test_only_live_particles_are_drawn_and_the_frame_is_the_same(make_app, monkeypatch) -> None:
    app = make_app(_scene)
    app.step(3)
    live = sorted(s.pool.count for s in app.world.resource(Particles).states.values())
    assert live == [7, 12]
    counts, px = _drawn_indices(app, monkeypatch)
    assert sorted(counts) == [6 * 7, 6 * 12]  # not 6 * 500 each
    # drawn whole (pyglet's own draw of every quad, the dead ones at size 0): same pixels
    monkeypatch.setattr(particle_render.LiveDraw, "__call__", lambda self, mode: self.whole(mode))
    _, px_whole = _drawn_indices(app, monkeypatch)
    assert np.array_equal(px_whole, px) and px[..., :3].any()


def test_despawned_emitters_leave_no_vertex_list_in_the_live_draw(make_app, monkeypatch) -> None:
    """Deleted vertex lists are forgotten by their domain's LiveDraw (they were kept for
    ever: one per despawned emitter, 0.23 a frame in the game soak)."""
    app = make_app(_scene)
    app.step(3)
    used: list[Any] = []
    real_of = particle_render.LiveDraw.of

    def recording(vertex_list: Any) -> Any:
        used.append(real_of(vertex_list))
        return used[-1]

    monkeypatch.setattr(particle_render.LiveDraw, "of", staticmethod(recording))
    pixels(app)
    monkeypatch.undo()
    assert used and sum(len(d.live) for d in set(used)) == 2
    for entity, _ in list(app.world.query(ParticleEmitter)):
        app.world.despawn(entity)
    app.step(1)
    pixels(app)
    assert [len(d.live) for d in set(used)] == [0] * len(set(used))
