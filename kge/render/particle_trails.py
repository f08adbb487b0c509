"""Drawing particle trails and ribbons: one indexed triangle list per emitter.

Each trail is a strip of ``2 x m`` vertices (the left and right edges at its ``m``
points); its triangles' indices are fixed, written once when the list is made. Each
frame the edges (:func:`kge.particles.trails.strip`) and colours (the trail's colour
over its length times the particle's current colour) of all trails are computed with
numpy and written into the vertex buffers at once. Strips past the live count are
collapsed to a point. The list sits in the emitter's layer, drawn with its blend mode
and a white texture, under the emitter's particles.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from pyglet import gl

from kge.components.particle_trail import ParticleTrail, TrailMode
from kge.components.particles import ParticleEmitter
from kge.particles import trails
from kge.particles.emitter import EmitterState, Particles
from kge.render.glutil import program
from kge.render.groups import WORLD, Groups
from kge.render.particles import SQUARE, ParticleGroup, _view
from kge.render.programs import DEFAULT_EFFECT, fragment_source
from kge.render.textures import TextureCache

_VERTEX = """#version 150 core
in vec2 position;
in vec4 colors;
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
    gl_Position = window.projection * window.view * vec4(position, 0.0, 1.0);
    v_color = colors;
    v_uv = vec2(0.5, 0.5);
    v_world = position;
}
"""


def _strip_indices(strips: int, m: int) -> np.ndarray:
    """Two triangles per segment of each of ``strips`` strips of ``m`` points."""
    j = np.arange(m - 1) * 2
    seg = np.stack([j, j + 1, j + 2, j + 1, j + 3, j + 2], axis=1).ravel()
    return (np.arange(strips)[:, None] * (2 * m) + seg).ravel()


class _TrailMesh:
    __slots__ = ("key", "lines", "points", "shades", "strips", "vertex_list", "work", "written")

    def __init__(self, vertex_list: Any, strips: int, points: int, key: tuple[Any, ...]) -> None:
        self.vertex_list = vertex_list
        self.strips = strips
        self.points = points
        self.key = key
        self.written = 0
        # scratch reused every frame (no fresh pages per frame)
        self.lines = np.empty((2, strips, points), np.float32)
        self.work = (np.empty((strips, points), np.complex64),
                     np.empty((strips, points), np.complex64),
                     np.empty((strips, points), np.float32))  # fmt: skip
        self.shades = np.empty((strips, points, 4), np.uint16)


class TrailDrawer:
    """Writes every trailed emitter's strips into the world's batch."""

    def __init__(self, world: Any, batch: Any, groups: Groups) -> None:
        self.world = world
        self.batch = batch
        self.groups = groups
        self.program = program("kge-particle-trail", _VERTEX, fragment_source(DEFAULT_EFFECT))
        self.textures = TextureCache(world)
        self.meshes: dict[int, _TrailMesh] = {}

    def _mesh(self, entity: int, em: ParticleEmitter, strips: int, points: int) -> _TrailMesh:
        key = (em.blend, em.layer, em.order)
        mesh = self.meshes.get(entity)
        if mesh is not None and (mesh.key, mesh.points) == (key, points) and mesh.strips >= strips:
            return mesh
        if mesh is not None:
            mesh.vertex_list.delete()
        tex = self.textures.texture(SQUARE)
        group = ParticleGroup(tex, em.blend, self.program, self.groups.get(em.layer, WORLD,
                                                                            em.order - 1))
        attributes = self.program.attributes.copy()
        for name, fmt in (("position", "f"), ("colors", "Bn")):
            attributes[name] = {**attributes[name], "format": fmt, "instance": False}
        domain = self.batch.get_domain(True, False, gl.GL_TRIANGLES, group, attributes)
        quads = strips * (points - 1)
        vl = domain.create(strips * points * 2, quads * 6)
        arr, buf = _view(vl, "position")
        arr[vl.start : vl.start + strips * points * 2] = 0.0
        buf.invalidate_region(vl.start, strips * points * 2)
        ib = domain.index_buffer
        idx = np.ctypeslib.as_array(ib.data)
        idx[vl.index_start : vl.index_start + quads * 6] = _strip_indices(strips, points) + vl.start
        ib.invalidate_region(vl.index_start, quads * 6)
        mesh = self.meshes[entity] = _TrailMesh(vl, strips, points, key)
        return mesh

    def draw(self) -> None:
        particles = self.world.try_resource(Particles)
        if particles is None:
            return
        world = self.world
        for entity in list(self.meshes):
            if entity not in particles.states or not world.has(entity, ParticleTrail):
                self.meshes.pop(entity).vertex_list.delete()
        for entity, (trail, em) in world.query(ParticleTrail, ParticleEmitter):
            st = particles.states.get(entity)
            if st is not None:
                self.upload(entity, em, st, trail)

    def upload(self, entity: int, em: ParticleEmitter, st: EmitterState,
               trail: ParticleTrail) -> None:  # fmt: skip
        """Write the emitter's trails (or ribbon) into its vertex list."""
        n = st.pool.count if em.visible else 0
        ribbon = trail.mode is TrailMode.RIBBON
        if ribbon:
            strips, points = 1, max(st.pool.capacity, 2)
            lines = trails.ribbon(st) if n >= 2 else np.zeros((2, 0, 2), np.float32)
            if len(lines[0]) == 0 and entity not in self.meshes:
                return
        else:
            ts = trails.state(st, trail.points)
            strips, points = max(st.pool.capacity, 1), trail.points + 1
            if n == 0 and entity not in self.meshes:
                return
        mesh = self._mesh(entity, em, strips, points)
        if not ribbon:
            lines = (trails.polylines(st, ts, mesh.lines) if n
                     else np.zeros((2, 0, points), np.float32))  # fmt: skip
        live, m = lines.shape[1], lines.shape[2]
        vl = mesh.vertex_list
        lo = vl.start
        pos, pbuf = _view(vl, "position")
        col, cbuf = _view(vl, "colors")
        # the strips' vertices: (strip, point, edge, x/y) and (strip, point, edge, rgba)
        pos4 = pos[lo : lo + 2 * strips * points].reshape(strips, points, 2, 2)
        col4 = col[lo : lo + 2 * strips * points].reshape(strips, points, 2, 4)
        if live:
            if em.space == "local":
                x, y, a = st.pose
                c, s = np.float32(math.cos(a)), np.float32(math.sin(a))
                lx, ly = lines[0].copy(), lines[1].copy()
                lines[0] = np.float32(x) + c * lx - s * ly
                lines[1] = np.float32(y) + s * lx + c * ly
            widths, rgba = trails.looks(trail, m)
            trails.strip(lines, widths, out=pos4[:live, :m], work=mesh.work)
            if ribbon:
                shades = rgba[None].astype(np.uint8)
                pos4[0, m:] = pos4[0, m - 1, 0]  # the unused rest: one point
            else:  # times each particle's current colour: (a x b + 255) >> 8 ~ a x b / 255
                _, colors = st.looks()
                tint = colors.view(np.uint8).reshape(-1, 1, 4)
                wide = mesh.shades[:live, :m]
                np.multiply(tint, rgba[None], out=wide)
                wide += 255
                wide >>= 8
                shades = wide.astype(np.uint8)
            rgba32 = shades.view(np.uint32)[..., 0]  # (live, m): one word per vertex
            col32 = col4.view(np.uint32)[..., 0]  # (strips, points, 2)
            col32[:live, :m, 0] = rgba32
            col32[:live, :m, 1] = rgba32
        written = 2 * points * (1 if ribbon else live)
        if mesh.written > written:  # strips of particles that died: one point
            pos[lo + written : lo + mesh.written] = 0.0
        if ribbon and live == 0:
            pos[lo : lo + 2 * points] = 0.0
        top = max(written, mesh.written)
        pbuf.invalidate_region(lo, top)
        cbuf.invalidate_region(lo, top)
        mesh.written = written

    def close(self) -> None:
        for mesh in self.meshes.values():
            mesh.vertex_list.delete()
        self.meshes.clear()
