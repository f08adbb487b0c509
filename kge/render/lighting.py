"""The light map: lights (and their shadows) drawn offscreen, multiplied over the scene.

Each frame, before the batch is drawn, :class:`LightMap` renders into its own
framebuffer (a texture the size of the window plus a stencil buffer):

1. clear to the ambient colour;
2. lights without shadows: one draw call, additive blending; each light is a
   quad around its radius whose fragment shader computes the falloff and the
   spot cone;
3. each light with shadows: its shadow quads (:mod:`kge.lighting.shadows`) mark
   the stencil buffer, then its quad is drawn where the stencil is clear.

The scene is multiplied by that texture by a full-screen quad that lives *in
the world's batch*, in a group placed after everything of layer
``Lighting.unlit_layer - 1``: layers below are lit, layers from ``unlit_layer``
up (UI, emissive sprites) are drawn after the multiply, unlit.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pyglet
from pyglet import gl

from kge.components.lights import Light, Lighting
from kge.components.transform import Transform
from kge.lighting.occluders import Occluders
from kge.lighting.shadows import quads_to_triangles, shadow_quads
from kge.render.glutil import Stream, program
from kge.render.groups import SCREEN, Groups

_TRANSFORM = """
uniform vec2 cam;
uniform vec2 half_view;  // half the viewport in pixels, over pixels per metre
vec4 to_clip(vec2 world) { return vec4((world - cam) / half_view, 0.0, 1.0); }
"""

_LIGHT_VS = (
    "#version 150 core\n"
    + _TRANSFORM
    + """
in vec2 world;
in vec2 center;
in vec3 color;
in vec4 shape;  // radius, falloff, direction, half cone
in float softness;
out vec2 v_world;
out vec2 v_center;
out vec3 v_color;
out vec4 v_shape;
out float v_soft;
void main()
{
    gl_Position = to_clip(world);
    v_world = world;
    v_center = center;
    v_color = color;
    v_shape = shape;
    v_soft = softness;
}
"""
)

_LIGHT_FS = """#version 150 core
in vec2 v_world;
in vec2 v_center;
in vec3 v_color;
in vec4 v_shape;
in float v_soft;
out vec4 frag;
const float PI = 3.14159265;
void main()
{
    vec2 d = v_world - v_center;
    float base = clamp(1.0 - length(d) / v_shape.x, 0.0, 1.0);
    float att = base > 0.0 ? pow(base, v_shape.y) : 0.0;
    float spot = 1.0;
    if (v_shape.w < PI - 1e-4) {
        float a = abs(mod(atan(d.y, d.x) - v_shape.z + PI, 2.0 * PI) - PI);
        float inner = v_shape.w * (1.0 - v_soft);
        spot = a <= inner ? 1.0 : 1.0 - smoothstep(inner, v_shape.w + 1e-5, a);
    }
    frag = vec4(v_color * att * spot, 1.0);
}
"""

_SHADOW_VS = (
    "#version 150 core\n"
    + _TRANSFORM
    + """
in vec2 world;
void main() { gl_Position = to_clip(world); }
"""
)

_SHADOW_FS = """#version 150 core
out vec4 frag;
void main() { frag = vec4(0.0); }
"""

_COMPOSITE_VS = """#version 150 core
in vec2 position;
out vec2 uv;
void main()
{
    gl_Position = vec4(position, 0.0, 1.0);
    uv = position * 0.5 + 0.5;
}
"""

_COMPOSITE_FS = """#version 150 core
in vec2 uv;
out vec4 frag;
uniform sampler2D light_map;
void main() { frag = vec4(texture(light_map, uv).rgb, 1.0); }
"""

#: floats per light vertex: world (2), center (2), color (3), shape (4), softness (1)
_LIGHT_FLOATS = 12
_ORDER_LAST = 1 << 30

class CompositeGroup(pyglet.graphics.Group):
    """Multiplies what is already drawn by the light map (blend DST_COLOR, ZERO)."""

    def __init__(self, light_map: LightMap, parent: Any) -> None:
        super().__init__(order=_ORDER_LAST, parent=parent)
        self.light_map = light_map

    def set_state(self) -> None:
        tex = self.light_map.texture
        self.light_map.composite.use()
        gl.glActiveTexture(gl.GL_TEXTURE0)
        gl.glBindTexture(tex.target, tex.id)
        gl.glEnable(gl.GL_BLEND)
        gl.glBlendFunc(gl.GL_DST_COLOR, gl.GL_ZERO)

    def unset_state(self) -> None:
        gl.glDisable(gl.GL_BLEND)
        self.light_map.composite.stop()


#: shadow samples of a light with ``shadow_softness`` > 0 (each adds 1/N of its light)
SOFT_SAMPLES = 8
_GOLDEN = math.pi * (3.0 - math.sqrt(5.0))


def soft_offsets(radius: float, n: int = SOFT_SAMPLES) -> np.ndarray:
    """``n`` points spread evenly over a disc of ``radius`` (a sunflower pattern)."""
    k = np.arange(n)
    r = radius * np.sqrt((k + 0.5) / n)
    return np.stack([r * np.cos(k * _GOLDEN), r * np.sin(k * _GOLDEN)], axis=1)


def light_rows(
    lights: list[tuple[Light, tuple[float, float, float]]],
    weights: list[float] | None = None,
) -> np.ndarray:
    """(L * 6, 12) light vertices: a quad around each light's radius (pure numpy)."""
    if not lights:
        return np.zeros((0, _LIGHT_FLOATS), np.float32)
    rows = np.empty((len(lights), 6, _LIGHT_FLOATS), np.float32)
    corners = np.array([[-1, -1], [1, -1], [1, 1], [-1, -1], [1, 1], [-1, 1]], np.float32)
    for i, (light, (x, y, a)) in enumerate(lights):
        k = light.intensity / 255.0 * (1.0 if weights is None else weights[i])
        r = light.radius
        rows[i, :, 0:2] = (x, y) + corners * r
        rows[i, :, 2:4] = (x, y)
        rows[i, :, 4:7] = (light.color[0] * k, light.color[1] * k, light.color[2] * k)
        rows[i, :, 7:11] = (r, light.falloff, a + light.direction, light.cone / 2)
        rows[i, :, 11] = light.softness
    return rows.reshape(-1, _LIGHT_FLOATS)


def light_poses(world: Any, pose_of: Any) -> list[tuple[int, Light, tuple[float, float, float]]]:
    """Every enabled light with its world position (offset applied) and facing angle."""
    out = []
    for e, (light,) in world.query(Light):
        if not light.enabled or light.intensity <= 0.0:
            continue
        pose = pose_of(e)
        if pose is None:
            t = world.try_get(e, Transform)
            pose = (0.0, 0.0, 0.0) if t is None else (t.x, t.y, t.angle)
        x, y, a = pose
        ox, oy = light.offset
        c, s = math.cos(a), math.sin(a)
        out.append((e, light, (x + c * ox - s * oy, y + s * ox + c * oy, a)))
    return out


class LightMap:
    """The offscreen light map of one world and the quad that multiplies it in."""

    def __init__(self, world: Any, batch: Any, groups: Groups, occluders: Occluders) -> None:
        self.world = world
        self.batch = batch
        self.groups = groups
        self.occluders = occluders
        self.light_program = program("kge-light", _LIGHT_VS, _LIGHT_FS)
        self.shadow_program = program("kge-shadow", _SHADOW_VS, _SHADOW_FS)
        self.composite = program("kge-light-composite", _COMPOSITE_VS, _COMPOSITE_FS)
        layout = [("world", 2), ("center", 2), ("color", 3), ("shape", 4), ("softness", 1)]
        self.lights = Stream(self.light_program, layout)
        self.shadows = Stream(self.shadow_program, [("world", 2)])
        self.size = (0, 0)
        self.texture: Any = None
        self.fbo: Any = None
        self.stencil: Any = None
        self.quad: Any = None
        self.quad_layer: int | None = None
        self.stats = {"lights": 0, "shadowed": 0, "shadow_quads": 0}
        self.window: Any = groups.state.window  #: whose context owns the GL objects

    def _target(self, size: tuple[int, int]) -> None:
        if size == self.size:
            return
        if self.fbo is not None:
            self.fbo.delete()
            self.stencil.delete()
        w, h = size
        self.texture = pyglet.image.Texture.create(w, h, min_filter=gl.GL_LINEAR,
                                                   mag_filter=gl.GL_LINEAR)  # fmt: skip
        self.stencil = pyglet.image.buffer.Renderbuffer(w, h, gl.GL_DEPTH24_STENCIL8)
        self.fbo = pyglet.image.buffer.Framebuffer()
        self.fbo.attach_texture(self.texture)
        self.fbo.attach_renderbuffer(self.stencil, attachment=gl.GL_DEPTH_STENCIL_ATTACHMENT)
        self.size = size

    def _composite_quad(self, layer: int | None) -> None:
        if layer == self.quad_layer:
            return
        if self.quad is not None:
            self.quad.delete()
            self.quad = None
        self.quad_layer = layer
        if layer is None:
            return
        group = CompositeGroup(self, self.groups.get(layer - 1, SCREEN, _ORDER_LAST))
        self.quad = self.composite.vertex_list_indexed(
            4, gl.GL_TRIANGLES, [0, 1, 2, 0, 2, 3], batch=self.batch, group=group,
            position=("f", (-1.0, -1.0, 1.0, -1.0, 1.0, 1.0, -1.0, 1.0)),
        )  # fmt: skip

    def draw(self, frame: Any, lighting: Lighting) -> None:
        """Render the light map for ``frame`` (a before-pass)."""
        if not lighting.enabled:
            self._composite_quad(None)
            return
        self._target((int(frame.viewport[0]), int(frame.viewport[1])))
        self._composite_quad(lighting.unlit_layer)
        found = light_poses(self.world, frame.pose)
        left, bottom, right, top = frame.view
        found = [
            f for f in found
            if f[2][0] + f[1].radius >= left and f[2][0] - f[1].radius <= right
            and f[2][1] + f[1].radius >= bottom and f[2][1] - f[1].radius <= top
        ]  # fmt: skip
        shadowed = [f for f in found if f[1].shadows]
        plain = [f for f in found if not f[1].shadows]
        # a soft-shadowed light is drawn as several samples, each shadowed from a point
        # of its disc and adding a share of its light: the penumbra is where they differ
        samples: list[tuple[Light, tuple[float, float, float], float, float, float]] = []
        for _, light, (x, y, a) in shadowed:
            if light.shadow_softness > 0.0:
                for dx, dy in soft_offsets(light.shadow_softness):
                    samples.append((light, (x, y, a), x + dx, y + dy, 1.0 / SOFT_SAMPLES))
            else:
                samples.append((light, (x, y, a), x, y, 1.0))
        rows = light_rows(
            [(s[0], s[1]) for s in samples] + [(light, pose) for _, light, pose in plain],
            [s[4] for s in samples] + [1.0] * len(plain),
        )
        tris = np.zeros((0, 2))
        owner = np.zeros(0, np.intp)
        if samples:
            edges, closed = self.occluders.edges(self.world, lighting.static_shadows, frame.pose)
            centers = np.array([(s[2], s[3]) for s in samples], float)
            radii = np.array([s[0].radius for s in samples], float)
            quads, owner = shadow_quads(centers, radii, edges, closed)
            tris = quads_to_triangles(quads)
        self.stats = {"lights": len(found), "shadowed": len(shadowed), "shadow_quads": len(owner)}
        viewport = (gl.GLint * 4)()
        gl.glGetIntegerv(gl.GL_VIEWPORT, viewport)
        self.fbo.bind()
        try:
            gl.glViewport(0, 0, self.size[0], self.size[1])
            r, g, b = (c / 255.0 for c in lighting.ambient)
            gl.glClearColor(r, g, b, 1.0)
            gl.glClear(gl.GL_COLOR_BUFFER_BIT | gl.GL_STENCIL_BUFFER_BIT)
            half = (frame.viewport[0] / (2 * frame.scale), frame.viewport[1] / (2 * frame.scale))
            for prog in (self.light_program, self.shadow_program):
                prog.use()
                prog["cam"] = (float(frame.center[0]), float(frame.center[1]))
                prog["half_view"] = (float(half[0]), float(half[1]))
            self.lights.upload(rows)
            gl.glEnable(gl.GL_BLEND)
            gl.glBlendFunc(gl.GL_ONE, gl.GL_ONE)
            if samples:
                self._shadowed(len(samples), tris, owner)
            self.light_program.use()
            self.lights.draw(6 * len(samples), 6 * len(plain))
            self.light_program.stop()
            gl.glDisable(gl.GL_BLEND)
        finally:
            self.fbo.unbind()
            gl.glViewport(*viewport)

    def _shadowed(self, count: int, tris: np.ndarray, owner: np.ndarray) -> None:
        """Each shadowed light: mark its shadows in the stencil, light where it is clear."""
        self.shadows.upload(tris)
        starts = np.searchsorted(owner, np.arange(count + 1)) * 6
        gl.glEnable(gl.GL_STENCIL_TEST)
        for i in range(count):
            gl.glClear(gl.GL_STENCIL_BUFFER_BIT)
            self.shadow_program.use()
            gl.glColorMask(gl.GL_FALSE, gl.GL_FALSE, gl.GL_FALSE, gl.GL_FALSE)
            gl.glStencilFunc(gl.GL_ALWAYS, 1, 0xFF)
            gl.glStencilOp(gl.GL_KEEP, gl.GL_KEEP, gl.GL_REPLACE)
            self.shadows.draw(int(starts[i]), int(starts[i + 1] - starts[i]))
            gl.glColorMask(gl.GL_TRUE, gl.GL_TRUE, gl.GL_TRUE, gl.GL_TRUE)
            gl.glStencilFunc(gl.GL_EQUAL, 0, 0xFF)
            gl.glStencilOp(gl.GL_KEEP, gl.GL_KEEP, gl.GL_KEEP)
            self.light_program.use()
            self.lights.draw(6 * i, 6)
        gl.glDisable(gl.GL_STENCIL_TEST)

    def close(self) -> None:
        """Free the GL objects now, in this map's own context (framebuffers and vertex
        arrays belong to one context: deleting them from another, or leaving them to
        the garbage collector, frees objects of the wrong context)."""
        if self.window is None or getattr(self.window, "context", None) is None:
            return  # the window (and its context, with every object in it) is gone
        self.window.switch_to()
        self._composite_quad(None)
        self.lights.delete()
        self.shadows.delete()
        if self.fbo is not None:
            self.fbo.delete()
            self.stencil.delete()
            self.texture.delete()
            self.fbo = self.stencil = self.texture = None
        self.size = (0, 0)
