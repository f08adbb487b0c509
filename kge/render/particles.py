"""Drawing particles: one vertex list per emitter, written with numpy each frame.

Each particle is a quad of 4 vertices whose corners are fixed (``corner``,
written once); each frame the emitter's live particles write their centre,
size and angle (one vec4) and RGBA colour into the vertex buffers of the world's batch
with one numpy ``repeat`` per attribute, and the shader turns corner, size and
angle into the quad. Quads past the live count get size 0 and are not drawn: a
particle domain draws each emitter's live quads only (:class:`LiveDraw`), so an
emitter's spare capacity costs no vertex work. The vertex list sits under the
emitter's layer group, so particles sort with sprites of that layer.

The list grows (by re-allocation) with the emitter's pool, which is capped by
``max_particles``; it never shrinks while the emitter lives.
"""

from __future__ import annotations

import math
from typing import Any, ClassVar

import numpy as np
import pyglet
from pyglet import gl

from kge.components.blend import Blend
from kge.components.material import Material
from kge.components.particles import ParticleEmitter
from kge.errors import KgeError, ValidationError
from kge.particles.emitter import EmitterState, Particles
from kge.render.glutil import program
from kge.render.groups import WORLD, Groups
from kge.render.images import PixelImage
from kge.render.programs import (
    DEFAULT_EFFECT,
    MaterialGroup,
    apply_frame_uniforms,
    fragment_source,
    material_program,
    set_blend,
)
from kge.render.textures import TextureCache

_VERTEX = """#version 150 core
in vec4 particle;
in vec2 corner;
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
    float c = cos(particle.w);
    float s = sin(particle.w);
    vec2 p = corner * particle.z;
    vec2 w = particle.xy + vec2(c * p.x - s * p.y, s * p.x + c * p.y);
    gl_Position = window.projection * window.view * vec4(w, 0.0, 1.0);
    v_color = colors;
    v_uv = corner + 0.5;
    v_world = w;
}
"""


_CORNERS = np.array([[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]], np.float32)
_QUAD = np.array([0, 1, 2, 0, 2, 3], np.intp)


def soft_dot(size: int = 64) -> PixelImage:
    """A white disc whose alpha falls smoothly from the centre to the rim."""
    ys, xs = np.mgrid[0:size, 0:size]
    r = np.hypot(xs + 0.5 - size / 2, ys + 0.5 - size / 2) / (size / 2)
    alpha = np.clip(1.0 - r, 0.0, 1.0) ** 1.5
    rgba = np.empty((size, size, 4), np.uint8)
    rgba[..., :3] = 255
    rgba[..., 3] = np.rint(alpha * 255).astype(np.uint8)
    return PixelImage(size, size, rgba.tobytes())


SOFT_DOT = soft_dot()
SQUARE = PixelImage(1, 1, b"\xff\xff\xff\xff")

def particle_program(material: Material | None = None, vertex: str = _VERTEX,
                     name: str = "particle") -> Any:  # fmt: skip
    """The particle program: kge's default effect, or a material's (None when its shader
    does not compile: the caller keeps the default); ``vertex`` and ``name`` for another
    vertex layout (:mod:`kge.render.particle_effects`)."""
    if material is not None:
        return material_program(material.shader, name, vertex=vertex)
    return program(f"kge-{name}", vertex, fragment_source(DEFAULT_EFFECT))


#: the vertex attributes of the particle program and their buffer formats
FORMATS = {"particle": "f", "corner": "f", "colors": "Bn"}


_ROWS = np.zeros(0, np.intp)


def _vertex_rows(n: int) -> np.ndarray:
    """0, 0, 0, 0, 1, 1, 1, 1, ...: the particle of each of 4 n vertices (cached, grown)."""
    global _ROWS
    if len(_ROWS) < 4 * n:
        _ROWS = np.repeat(np.arange(max(n, 2 * len(_ROWS) // 4)), 4)
    return _ROWS[: 4 * n]


class ParticleGroup(pyglet.graphics.Group):
    """Texture, blend mode and shader of particles in one layer."""

    def __init__(self, texture: Any, blend: Blend, program: Any, parent: Any) -> None:
        super().__init__(order=0, parent=parent)
        self.texture = texture
        self.blend = blend
        self.program = program

    def set_state(self) -> None:
        self.program.use()
        apply_frame_uniforms(self.program)
        gl.glActiveTexture(gl.GL_TEXTURE0)
        gl.glBindTexture(self.texture.target, self.texture.id)
        set_blend(self.blend)

    def unset_state(self) -> None:
        gl.glDisable(gl.GL_BLEND)
        self.program.stop()

    def __eq__(self, other: object) -> bool:
        return (
            isinstance(other, ParticleGroup)
            and self.texture.id == other.texture.id
            and self.blend == other.blend
            and self.parent is other.parent
            and self.program is other.program
        )

    def __hash__(self) -> int:
        return hash((self.texture.id, self.blend, id(self.parent), id(self.program)))


def _quad_list(program: Any, batch: Any, group: Any, quads: int,
               formats: dict[str, str] = FORMATS) -> Any:  # fmt: skip
    """An indexed vertex list of ``quads`` particle quads, filled with numpy.

    ``ShaderProgram.vertex_list_indexed`` converts indices and initial data one
    Python int at a time (a third of a second for 50,000 quads, a hitch each
    time an emitter grows); this asks the batch for the domain and writes the
    corners and indices straight into its buffers instead.
    """
    attributes = program.attributes.copy()
    for name, fmt in formats.items():
        attributes[name] = {**attributes[name], "format": fmt, "instance": False}
    domain = batch.get_domain(True, False, gl.GL_TRIANGLES, group, attributes)
    vl = domain.create(quads * 4, quads * 6)
    arr, buf = _view(vl, "corner")
    arr[vl.start : vl.start + 4 * quads] = np.tile(_CORNERS, (quads, 1))
    buf.invalidate_region(vl.start, 4 * quads)
    arr, buf = _view(vl, "particle")
    arr[vl.start : vl.start + 4 * quads] = 0.0  # size 0: nothing drawn until written
    buf.invalidate_region(vl.start, 4 * quads)
    ib = domain.index_buffer
    idx = np.ctypeslib.as_array(ib.data)
    quad = (np.arange(quads)[:, None] * 4 + _QUAD).ravel() + vl.start
    idx[vl.index_start : vl.index_start + 6 * quads] = quad
    ib.invalidate_region(vl.index_start, 6 * quads)
    return vl


class LiveDraw:
    """A particle domain's draw: the live quads of each emitter's list, in buffer order.

    pyglet draws every index a domain holds, so an emitter's dead quads (size 0:
    nothing on screen) would still go through the vertex stage, which software GL
    runs on the game thread. This draws ``6 * live`` indices from each list's start
    instead: the same triangles that cover pixels, in the same order. A domain
    holding a list this does not know (its index total differs) is drawn whole.
    """

    __slots__ = ("domain", "live", "whole")

    def __init__(self, domain: Any) -> None:
        self.domain = domain
        self.whole = domain.draw  # pyglet's own
        self.live: dict[Any, int] = {}  #: vertex list -> live quads

    @staticmethod
    def of(vertex_list: Any) -> LiveDraw:
        domain = vertex_list.domain
        draw = domain.__dict__.get("draw")
        if not isinstance(draw, LiveDraw):
            draw = LiveDraw(domain)
            domain.draw = draw  # the batch's draw list calls domain.draw(mode)
        return draw

    def __call__(self, mode: int) -> None:
        d = self.domain
        _, sizes = d.index_allocator.get_allocated_regions()
        if sum(sizes) != sum(vl.index_count for vl in self.live):
            self.whole(mode)
            return
        d.vao.bind()
        for buffer, _ in d.buffer_attributes:
            buffer.commit()
        d.index_buffer.commit()
        size = d.index_element_size
        runs = sorted((vl.index_start, 6 * n) for vl, n in self.live.items() if n)
        for start, count in runs:
            gl.glDrawElements(mode, count, d.index_gl_type, d.index_buffer.ptr + start * size)


class _EmitterMesh:
    """The vertex list of one emitter and what it was made for."""

    __slots__ = ("capacity", "key", "rows", "vertex_list", "written")

    def __init__(self, vertex_list: Any, capacity: int, key: tuple[Any, ...]) -> None:
        self.vertex_list = vertex_list
        self.capacity = capacity
        self.key = key
        self.written = 0  #: quads with a non-zero size after the last frame
        #: x, y, size, angle per particle, reused every frame (no 16-byte-per-particle
        #: allocation per frame: fresh pages are what a loaded machine makes slow)
        self.rows = np.empty((capacity, 4), np.float32)


def _view(vertex_list: Any, name: str) -> tuple[np.ndarray, Any]:
    buf = vertex_list.domain.attrib_name_buffers[name]
    arr = np.ctypeslib.as_array(buf.data).reshape(-1, buf.count)
    return arr, buf


class ParticleDrawer:
    """Uploads every emitter's particles into the world's batch (a before-pass)."""

    #: the vertex shader, its attributes' formats and its program's name (a subclass
    #: with more attributes changes them)
    VERTEX = _VERTEX
    FORMATS: ClassVar[dict[str, str]] = FORMATS
    NAME = "particle"

    def __init__(self, world: Any, batch: Any, groups: Groups) -> None:
        self.world = world
        self.batch = batch
        self.groups = groups
        self.program = particle_program(None, self.VERTEX, self.NAME)
        self.textures = TextureCache(world)
        self.meshes: dict[int, _EmitterMesh] = {}

    def _texture(self, em: ParticleEmitter) -> Any:
        image = SQUARE if em.flat else (SOFT_DOT if em.texture is None else em.texture)
        return self.textures.texture(image, filter="linear" if image is SOFT_DOT else "nearest")

    def _mesh(self, entity: int, em: ParticleEmitter, capacity: int) -> _EmitterMesh:
        try:
            tex = self._texture(em)
        except (KgeError, OSError) as exc:  # a texture name written after the spawn check
            raise ValidationError(
                f"entity {entity}, ParticleEmitter.texture {em.texture!r}: {exc}"
            ) from exc
        material = self.world.try_get(entity, Material)
        prog = particle_program(material, self.VERTEX, self.NAME) if material is not None else None
        prog = prog or self.program
        key = (tex.id, em.blend, em.layer, em.order, id(prog), id(material))
        mesh = self.meshes.get(entity)
        if mesh is not None and mesh.key == key and mesh.capacity >= capacity:
            return mesh
        if mesh is not None:
            _delete(mesh.vertex_list)
        parent = self.groups.get(em.layer, WORLD, em.order)
        if prog is not self.program and material is not None:
            parent = MaterialGroup(material, prog, self.textures, parent)
        group = ParticleGroup(tex, em.blend, prog, parent)
        vl = _quad_list(prog, self.batch, group, capacity, self.FORMATS)
        mesh = self.meshes[entity] = _EmitterMesh(vl, capacity, key)
        return mesh

    def draw(self, frame: Any) -> None:
        particles = self.world.try_resource(Particles)
        if particles is None:
            return
        for entity in [e for e in self.meshes if e not in particles.states]:
            self.drop(entity)
        for entity, st in particles.states.items():
            em = self.world.try_get(entity, ParticleEmitter)
            if em is None:
                continue
            self.upload(entity, em, st)

    def upload(self, entity: int, em: ParticleEmitter, st: EmitterState) -> None:
        """Write the emitter's live particles into its vertex list."""
        pool = st.pool
        n = pool.count if em.visible else 0
        if pool.capacity == 0 and entity not in self.meshes:
            return
        mesh = self._mesh(entity, em, max(pool.capacity, 1))
        vl = mesh.vertex_list
        lo = vl.start
        if n:
            rows = mesh.rows[:n]  # x, y, size, angle
            sizes, colors = st.looks()
            rows[:, 2] = sizes
            if em.space == "local":
                x, y, a = st.pose
                c, s = math.cos(a), math.sin(a)
                px, py = pool.pos[:n, 0], pool.pos[:n, 1]
                rows[:, 0] = x + c * px - s * py
                rows[:, 1] = y + s * px + c * py
                rows[:, 3] = pool.angle[:n] + np.float32(a)
            else:
                rows[:, 0:2] = pool.pos[:n]
                rows[:, 3] = pool.angle[:n]
            self.more(entity, em, st, mesh, n)
            # each particle's row onto its 4 vertices: a gather straight into the vertex
            # buffer (no temporary: a 50,000-particle frame allocates nothing here)
            idx = _vertex_rows(n)
            arr, buf = _view(vl, "particle")
            np.take(rows, idx, axis=0, out=arr[lo : lo + 4 * n], mode="clip")
            buf.invalidate_region(lo, 4 * n)
            arr, buf = _view(vl, "colors")  # 4 bytes per vertex, written as one uint32
            np.take(colors, idx, out=arr.view(np.uint32)[lo : lo + 4 * n, 0], mode="clip")
            buf.invalidate_region(lo, 4 * n)
        if mesh.written > n:  # quads that died since: size 0
            arr, buf = _view(vl, "particle")
            arr[lo + 4 * n : lo + 4 * mesh.written, 2] = 0.0
            buf.invalidate_region(lo + 4 * n, 4 * (mesh.written - n))
        mesh.written = n
        LiveDraw.of(vl).live[vl] = n

    def more(self, entity: int, em: ParticleEmitter, st: EmitterState, mesh: _EmitterMesh,
             n: int) -> None:  # fmt: skip
        """Before the rows are written: a subclass adjusts ``mesh.rows[:n]`` and writes its
        own attributes of the ``n`` live particles."""

    def drop(self, entity: int) -> None:
        """Free ``entity``'s vertex list, if it has one, and forget it in its domain's
        :class:`LiveDraw` (a list deleted without that stays in ``LiveDraw.live``)."""
        mesh = self.meshes.pop(entity, None)
        if mesh is not None:
            _delete(mesh.vertex_list)

    def close(self) -> None:
        for mesh in self.meshes.values():
            _delete(mesh.vertex_list)
        self.meshes.clear()


def _delete(vertex_list: Any) -> None:
    """Free an emitter's vertex list (and forget it in its domain's :class:`LiveDraw`)."""
    draw = vertex_list.domain.__dict__.get("draw")
    if isinstance(draw, LiveDraw):
        draw.live.pop(vertex_list, None)
    vertex_list.delete()
