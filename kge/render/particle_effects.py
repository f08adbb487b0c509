"""Drawing particles with flipbook frames or stretched along their velocity.

Emitters with a :class:`~kge.components.particle_flipbook.ParticleFlipbook` or a
:class:`~kge.components.particle_stretch.ParticleStretch` are drawn by
:class:`EffectDrawer`: the particle quads of :mod:`kge.render.particles` with two
more vertex attributes, each particle's texture rectangle (its sheet cell) and its
length along its direction (in sizes). Both are computed for all particles at once
with numpy and gathered onto the vertices like the other attributes. Every other
emitter goes to the plain drawer, unchanged.
"""

from __future__ import annotations

from typing import Any, ClassVar

import numpy as np

from kge.components.particle_flipbook import ParticleFlipbook
from kge.components.particle_stretch import ParticleStretch
from kge.components.particles import ParticleEmitter
from kge.particles import flipbook
from kge.particles.emitter import EmitterState, Particles
from kge.render.groups import Groups
from kge.render.particle_trails import TrailDrawer
from kge.render.particles import FORMATS, ParticleDrawer, _EmitterMesh, _vertex_rows, _view

_VERTEX = """#version 150 core
in vec4 particle;
in vec2 corner;
in vec4 colors;
in vec4 uvs;
in float stretch;
out vec4 v_color;
out vec2 v_uv;
out vec2 v_world;
uniform WindowBlock
{
    mat4 projection;
    mat4 view;
} window;
void main()
{
    float c = cos(particle.w);
    float s = sin(particle.w);
    vec2 p = corner * vec2(particle.z * stretch, particle.z);
    vec2 w = particle.xy + vec2(c * p.x - s * p.y, s * p.x + c * p.y);
    gl_Position = window.projection * window.view * vec4(w, 0.0, 1.0);
    v_color = colors;
    v_uv = mix(uvs.xy, uvs.zw, corner + 0.5);
    v_world = w;
}
"""

_WHOLE = np.array([0.0, 0.0, 1.0, 1.0], np.float32)


def _seed(entity: int, em: ParticleEmitter) -> int:
    return entity if em.seed is None else em.seed


def stretched(em: ParticleEmitter, st: EmitterState, stretch: ParticleStretch, sizes: np.ndarray,
              n: int) -> tuple[np.ndarray, np.ndarray]:  # fmt: skip
    """(angle, length in sizes) of the ``n`` live particles: along their velocity."""
    vel = st.pool.vel[:n]
    angle = np.arctan2(vel[:, 1], vel[:, 0])
    if em.space == "local":
        angle += np.float32(st.pose[2])
    length = sizes * np.float32(stretch.length_scale)
    length += np.hypot(vel[:, 0], vel[:, 1]) * np.float32(stretch.speed_scale)
    if stretch.max_length is not None:
        np.minimum(length, np.float32(stretch.max_length), out=length)
    ratio = np.divide(length, sizes, out=np.ones_like(sizes), where=sizes > 0)
    return angle, ratio


class EffectDrawer(ParticleDrawer):
    """The particle before-pass: flipbook and stretched emitters here, the rest plain."""

    VERTEX = _VERTEX
    FORMATS: ClassVar[dict[str, str]] = {**FORMATS, "uvs": "f", "stretch": "f"}
    NAME = "particle-effects"

    def __init__(self, world: Any, batch: Any, groups: Groups) -> None:
        super().__init__(world, batch, groups)
        self.plain = ParticleDrawer(world, batch, groups)
        self.trails = TrailDrawer(world, batch, groups)

    def draw(self, frame: Any) -> None:
        particles = self.world.try_resource(Particles)
        if particles is None:
            return
        world = self.world
        for drawer in (self, self.plain):
            for entity in [e for e in drawer.meshes if e not in particles.states]:
                drawer.drop(entity)
        for entity, st in particles.states.items():
            em = world.try_get(entity, ParticleEmitter)
            if em is None:
                continue
            rich = world.has(entity, ParticleFlipbook) or world.has(entity, ParticleStretch)
            mine, other = (self, self.plain) if rich else (self.plain, self)
            other.drop(entity)  # it changed kind: the other drawer's list goes
            mine.upload(entity, em, st)
        self.trails.draw()

    def more(self, entity: int, em: ParticleEmitter, st: EmitterState, mesh: _EmitterMesh,
             n: int) -> None:  # fmt: skip
        world = self.world
        fb = world.try_get(entity, ParticleFlipbook)
        uvs = flipbook.rects(st, fb, _seed(entity, em)) if fb is not None else None
        stretch = world.try_get(entity, ParticleStretch)
        ratio = None
        if stretch is not None:
            rows = mesh.rows[:n]
            rows[:, 3], ratio = stretched(em, st, stretch, rows[:, 2], n)
        vl = mesh.vertex_list
        lo = vl.start
        idx = _vertex_rows(n)
        arr, buf = _view(vl, "uvs")
        if uvs is None:
            arr[lo : lo + 4 * n] = _WHOLE
        else:
            np.take(uvs, idx, axis=0, out=arr[lo : lo + 4 * n], mode="clip")
        buf.invalidate_region(lo, 4 * n)
        arr, buf = _view(vl, "stretch")
        if ratio is None:
            arr[lo : lo + 4 * n] = 1.0
        else:
            np.take(ratio, idx, out=arr[lo : lo + 4 * n, 0], mode="clip")
        buf.invalidate_region(lo, 4 * n)

    def close(self) -> None:
        super().close()
        self.plain.close()
        self.trails.close()
