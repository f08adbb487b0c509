"""The light map: lights and soft shadows drawn offscreen, multiplied over the scene.

For each camera (a ``view`` pass, :mod:`kge.render.passes`), :class:`LightMap`
renders into a texture ``Lighting.resolution`` times the size of the camera's
viewport (light is smooth: half size costs a quarter of the pixels):

1. clear to the ambient colour (alpha 0);
2. lights without shadows or a cookie: one draw call, added up;
3. each other light, scissored to its own rectangle: its occluders' *penumbra
   wedges* write, into the alpha channel, the share of the light's source that each
   pixel does not see; the light is then added times ``1 - alpha`` (blending, no
   texture read), and its ``shadow_color`` times ``alpha``.

The penumbra is computed per pixel (the light's bulb is a segment ``2 *
shadow_softness`` wide facing the pixel; each occluder edge hides an interval of
it), so soft shadows are smooth, and hard ones (a bulb one pixel wide) have
anti-aliased edges. Edges come from :class:`~kge.lighting.occluders.Occluders`,
uploaded once per frame; the vertex shader extrudes each away from each light and
drops edges facing the light (closed outlines) or out of its reach.

Normal-mapped sprites are drawn into a normal buffer first (same size); each light
is then multiplied there by ``N . L`` over what a flat surface would get (``L.z``),
with the light ``height`` metres above: a normal map adds relief without making a
sprite darker than an unmapped one.

The scene is multiplied by the map by a quad that lives *in the world's batch*, in
the VIEW space of layer ``Lighting.unlit_layer - 1``: layers below are lit, layers
from ``unlit_layer`` up (UI, emissive sprites) are drawn after the multiply,
unlit. Light halos (``glow``) are added right after the multiply.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pyglet
from pyglet import gl

from kge.components.lights import DirectionalLight, Light, Lighting
from kge.components.transform import Transform
from kge.lighting.occluders import Occluders
from kge.render.glutil import Stream, clear, drawing_into, new_texture, program
from kge.render.groups import VIEW, Groups

_LIGHT_VS = """#version 330 core
uniform mat4 to_clip;
layout(location = 0) in vec2 world;
layout(location = 1) in vec2 center;
layout(location = 2) in vec3 color;
layout(location = 3) in vec3 shade;
layout(location = 4) in vec4 shape;   // radius, falloff, direction, half cone
layout(location = 5) in vec3 extra;   // cone softness, height, unused
out vec2 v_world;
out vec2 v_center;
out vec3 v_color;
out vec4 v_shape;
out vec3 v_extra;
void main()
{
    gl_Position = to_clip * vec4(world, 0.0, 1.0);
    v_world = world;
    v_center = center;
#ifdef SHADE
    v_color = shade;
#else
    v_color = color;
#endif
    v_shape = shape;
    v_extra = extra;
}
"""

# One program per kind of light and option (``#define``): llvmpipe runs every branch a
# fragment could take, so a plain point light must not pay for cones, cookies and normals.
_LIGHT_FS = """#version 330 core
in vec2 v_world;
in vec2 v_center;
in vec3 v_color;
in vec4 v_shape;
in vec3 v_extra;
out vec4 frag;
uniform sampler2D normals;
uniform sampler2D cookie;
uniform vec2 map_size;
const float PI = 3.14159265;
void main()
{
    vec2 d = v_world - v_center;
    vec3 c = v_color;
#ifdef SUN
    float att = 1.0;
    vec3 to_light = normalize(vec3(-cos(v_shape.z), -sin(v_shape.z), v_extra.y));
#else
    float base = clamp(1.0 - length(d) / v_shape.x, 0.0, 1.0);
    float att = step(1e-6, base) * pow(max(base, 1e-6), v_shape.y);
    vec3 to_light = normalize(vec3(-d, v_extra.y));
#endif
#ifdef SPOT
    float a = abs(mod(atan(d.y, d.x) - v_shape.z + PI, 2.0 * PI) - PI);
    float inner = v_shape.w * (1.0 - v_extra.x);
    att *= a <= inner ? 1.0 : 1.0 - smoothstep(inner, v_shape.w + 1e-5, a);
#endif
#ifdef COOKIE
    float t = -v_shape.z;
    vec2 local = vec2(cos(t) * d.x - sin(t) * d.y, sin(t) * d.x + cos(t) * d.y) / v_shape.x;
    vec4 k = texture(cookie, local * 0.5 + 0.5);
    c *= k.rgb * k.a * step(abs(local.x), 1.0) * step(abs(local.y), 1.0);
#endif
#ifdef NORMALS
    // relief relative to a flat surface: a normal facing the viewer is lit exactly as an
    // unmapped sprite, one turned to the light brighter, one turned away darker
    vec4 n = texture(normals, gl_FragCoord.xy / map_size);
    float relief = max(dot(normalize(n.xyz * 2.0 - 1.0), to_light), 0.0) / max(to_light.z, 0.25);
    att *= n.a > 0.5 ? min(relief, 2.5) : 1.0;
#endif
    frag = vec4(c * att, 0.0);
}
"""

_SHADOW_VS = """#version 150 core
uniform mat4 to_clip;
uniform vec2 light;      // position (point) or travel direction (directional)
uniform float radius;    // reach of a point light
uniform float source;    // bulb radius, metres (point) or spread, radians (directional)
uniform float reach;     // how far edges are extruded
uniform int kind;        // 0 point, 1 directional
in vec4 seg;             // the edge's ends a, b
in vec2 corner;          // which end (0: a, 1: b), near or far (0, 1)
in float closed;         // 1: part of a counter-clockwise outline (one-sided)
out vec4 v_seg;
out vec2 v_world;
void main()
{
    vec2 a = seg.xy;
    vec2 b = seg.zw;
    vec2 normal = vec2(b.y - a.y, a.x - b.x);
    bool keep;
    if (kind == 1) {
        keep = closed < 0.5 || dot(light, normal) > 0.0;
    } else {
        vec2 ab = b - a;
        float t = clamp(dot(light - a, ab) / max(dot(ab, ab), 1e-12), 0.0, 1.0);
        bool away = closed < 0.5 || dot(a - light, normal) > 0.0;
        keep = length(a + ab * t - light) < radius && away;
    }
    vec2 p = corner.x < 0.5 ? a : b;
    vec2 other = corner.x < 0.5 ? b : a;
    vec2 pos = p;
    if (corner.y > 0.5) {
        vec2 dir = kind == 1 ? normalize(light) : normalize(p - light);
        vec2 side = vec2(-dir.y, dir.x);
        if (dot(side, p - other) < 0.0) side = -side;
        // the outer edge of the penumbra leaves the far side of the bulb
        vec2 out_dir = kind == 1 ? normalize(dir + side * tan(source))
                                 : normalize(p - (light - side * source));
        float far = reach;
        if (kind == 0) {
            // stop just past the light's circle: the wedge's far side, a chord between the
            // two far corners, stays outside it when they are r / cos(half the wedge) away
            vec2 da = normalize(a - light);
            vec2 db = normalize(b - light);
            float half_cos = sqrt(max((1.0 + dot(da, db)) * 0.5, 0.0));
            float want = radius / max(half_cos - source / max(length(p - light), 1e-6), 0.05);
            far = clamp(want - length(p - light), 0.0, reach);
        }
        pos = p + out_dir * far;
    }
    v_seg = seg;
    v_world = pos;
    gl_Position = keep ? to_clip * vec4(pos, 0.0, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
}
"""

_SHADOW_FS = """#version 150 core
in vec4 v_seg;
in vec2 v_world;
out vec4 frag;
uniform vec2 light;
uniform float source;
uniform int kind;

// the part of the light's bulb (-1..1 across it) hidden by the edge, seen from v_world
void main()
{
    vec2 p = v_world;
    vec2 to_light;
    float depth;
    if (kind == 1) {
        to_light = -normalize(light);
        depth = 1e9;
    } else {
        to_light = light - p;
        depth = length(to_light);
        to_light /= max(depth, 1e-9);
    }
    vec2 across = vec2(-to_light.y, to_light.x);
    vec2 a = v_seg.xy - p;
    vec2 b = v_seg.zw - p;
    float sa = dot(a, to_light);
    float sb = dot(b, to_light);
    // keep the part of the edge between the pixel and the light
    float lo = 0.0;
    float hi = 1.0;
    float eps = 1e-5;
    if (abs(sb - sa) > 1e-12) {
        float t0 = (eps - sa) / (sb - sa);
        float t1 = (depth - sa) / (sb - sa);
        if (sb > sa) { lo = max(lo, t0); hi = min(hi, t1); }
        else { lo = max(lo, t1); hi = min(hi, t0); }
    } else if (sa < eps || sa > depth) {
        hi = -1.0;
    }
    if (hi <= lo) { frag = vec4(0.0); return; }
    vec2 qa = mix(a, b, lo);
    vec2 qb = mix(a, b, hi);
    float ua, ub;
    if (kind == 1) {
        ua = atan(dot(qa, across), dot(qa, to_light)) / source;
        ub = atan(dot(qb, across), dot(qb, to_light)) / source;
    } else {
        ua = dot(qa, across) * depth / max(dot(qa, to_light), eps) / source;
        ub = dot(qb, across) * depth / max(dot(qb, to_light), eps) / source;
    }
    float covered = max(min(max(ua, ub), 1.0) - max(min(ua, ub), -1.0), 0.0) * 0.5;
    frag = vec4(0.0, 0.0, 0.0, covered);
}
"""

_COMPOSITE_VS = """#version 150 core
in vec2 position;
out vec2 uv;
uniform vec2 extent;    // share of the map texture in use
void main()
{
    gl_Position = vec4(position, 0.0, 1.0);
    uv = (position * 0.5 + 0.5) * extent;
}
"""

# a bare texture read: the multiply is the blending (software GL's cheapest full-screen pass)
_COMPOSITE_FS = """#version 150 core
in vec2 uv;
out vec4 frag;
uniform sampler2D light_map;
void main() { frag = texture(light_map, uv); }
"""

_GLOW_VS = """#version 150 core
uniform mat4 to_clip;
in vec2 world;
in vec2 center;
in vec4 color;      // rgb, radius
out vec2 v_d;
out vec4 v_color;
void main()
{
    gl_Position = to_clip * vec4(world, 0.0, 1.0);
    v_d = world - center;
    v_color = color;
}
"""

_GLOW_FS = """#version 150 core
in vec2 v_d;
in vec4 v_color;
out vec4 frag;
void main()
{
    float t = clamp(1.0 - length(v_d) / v_color.a, 0.0, 1.0);
    frag = vec4(v_color.rgb * t * t * t, 0.0);
}
"""

#: floats per light vertex: world 2, center 2, color 3, shade 3, shape 4, extra 3
_LIGHT_FLOATS = 17
_LAYOUT = [("world", 2), ("center", 2), ("color", 3), ("shade", 3), ("shape", 4), ("extra", 3)]
_ORDER_LAST = 1 << 30
_CORNERS = np.array([[-1, -1], [1, -1], [1, 1], [-1, -1], [1, 1], [-1, 1]], np.float32)
_RING = np.stack([np.cos(np.arange(8) * np.pi / 4 + np.pi / 8),
                  np.sin(np.arange(8) * np.pi / 4 + np.pi / 8)], axis=1) / np.cos(np.pi / 8)
#: an octagon around the unit circle, as 6 triangles: a fifth fewer pixels than a square
_OCTAGON = _RING[[i for k in range(1, 7) for i in (0, k, k + 1)]].astype(np.float32)
#: vertices per light
VERTS = len(_OCTAGON)
#: the square around the unit circle in as many vertices (two triangles, the rest empty):
#: a shadowed light covers its whole scissor square, so its draw resets all the alpha
#: its shadows wrote there (an octagon would leave the corners to the next light)
_SQUARE = np.concatenate([_CORNERS, np.zeros((VERTS - len(_CORNERS), 2), np.float32)])
#: (end, far) of the 6 vertices of an edge's wedge
_WEDGE = np.array([[0, 0], [1, 0], [1, 1], [0, 0], [1, 1], [0, 1]], np.float32)
#: a light's halo reaches this share of its radius
GLOW_REACH = 0.5


def light_rows(lights: list[tuple[Light, tuple[float, float, float]]]) -> np.ndarray:
    """(L * 18, 17) vertices: an octagon around each light's radius, a square around a
    shadowed one's (pure numpy)."""
    if not lights:
        return np.zeros((0, _LIGHT_FLOATS), np.float32)
    rows = np.empty((len(lights), VERTS, _LIGHT_FLOATS), np.float32)
    for i, (light, (x, y, a)) in enumerate(lights):
        k = light.intensity / 255.0
        r = light.radius
        rows[i, :, 0:2] = (x, y) + (_SQUARE if light.shadows else _OCTAGON) * r
        rows[i, :, 2:4] = (x, y)
        rows[i, :, 4:7] = tuple(c * k for c in light.color)
        rows[i, :, 7:10] = tuple(c * k for c in light.shadow_color)
        # below 2 pi before the float32 row: a finite angle of 1e300 would overflow it
        facing = math.remainder(math.remainder(a, math.tau) + light.direction, math.tau)
        rows[i, :, 10:14] = (r, light.falloff, facing, light.cone / 2)
        rows[i, :, 14:17] = (light.softness, light.height, 0.0)
    return rows.reshape(-1, _LIGHT_FLOATS)


def sun_rows(sun: DirectionalLight, view: tuple[float, float, float, float]) -> np.ndarray:
    """(18, 17) vertices of a directional light over the view rectangle."""
    x0, y0, x1, y1 = view
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    rows = np.empty((VERTS, _LIGHT_FLOATS), np.float32)
    rows[:, 0:2] = (cx, cy) + _OCTAGON * (math.hypot(x1 - x0, y1 - y0) / 2 + 1.0)
    rows[:, 2:4] = (cx, cy)
    k = sun.intensity / 255.0
    rows[:, 4:7] = tuple(c * k for c in sun.color)
    rows[:, 7:10] = tuple(c * k for c in sun.shadow_color)
    rows[:, 10:14] = (1.0, 0.0, sun.angle, math.pi)
    rows[:, 14:17] = (0.0, sun.height, 0.0)
    return rows


def light_program(kind: str, cookie: bool = False, normals: bool = False,
                  shade: bool = False) -> Any:  # fmt: skip
    """The light program for ``kind`` ("point", "spot", "sun") with those options."""
    flags = [f for f, on in (("SPOT", kind == "spot"), ("SUN", kind == "sun"),
                             ("COOKIE", cookie), ("NORMALS", normals), ("SHADE", shade)) if on]
    head = "".join(f"#define {f}\n" for f in flags)
    vs = _LIGHT_VS.replace("\n", "\n" + head, 1)
    fs = _LIGHT_FS.replace("\n", "\n" + head, 1)
    return program("kge-light-" + "-".join([kind, *flags]), vs, fs)


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


def wedge_rows(edges: np.ndarray, closed: np.ndarray) -> np.ndarray:
    """(E * 6, 7) vertices of the edges' shadow wedges: seg (4), corner (2), closed (1)."""
    n = len(edges)
    rows = np.empty((n, 6, 7), np.float32)
    rows[:, :, 0:4] = edges.reshape(n, 1, 4)
    rows[:, :, 4:6] = _WEDGE
    rows[:, :, 6] = closed.reshape(n, 1)
    return rows.reshape(-1, 7)


def clip_matrix(world_matrix: Any, size: tuple[float, float]) -> tuple[float, ...]:
    """World metres -> clip space over a view of ``size`` pixels (column-major)."""
    m = np.array(world_matrix, np.float64).reshape(4, 4).T
    ortho = np.diag([2.0 / size[0], 2.0 / size[1], 1.0, 1.0])
    ortho[0, 3], ortho[1, 3] = -1.0, -1.0
    return tuple((ortho @ m).T.ravel().tolist())


class CompositeGroup(pyglet.graphics.Group):
    """Multiplies what is already drawn by the light map, then adds the light halos."""

    def __init__(self, light_map: LightMap, parent: Any) -> None:
        super().__init__(order=_ORDER_LAST, parent=parent)
        self.light_map = light_map

    def set_state(self) -> None:
        lm = self.light_map
        tex = lm.texture
        prog = lm.composite
        prog.use()
        prog["extent"] = lm.extent
        gl.glActiveTexture(gl.GL_TEXTURE0)
        gl.glBindTexture(tex.target, tex.id)
        gl.glEnable(gl.GL_BLEND)  # colour times the map's; alpha kept
        gl.glBlendFuncSeparate(gl.GL_ZERO, gl.GL_SRC_COLOR, gl.GL_ZERO, gl.GL_ONE)

    def unset_state(self) -> None:
        self.light_map.draw_glows()
        gl.glDisable(gl.GL_BLEND)
        self.light_map.composite.stop()


class LightMap:
    """The offscreen light map of one world and the quad that multiplies it in."""

    def __init__(self, world: Any, batch: Any, groups: Groups, occluders: Occluders,
                 textures: Any = None) -> None:  # fmt: skip
        self.world = world
        self.batch = batch
        self.groups = groups
        self.occluders = occluders
        self.textures = textures
        self.shadow_program = program("kge-shadow", _SHADOW_VS, _SHADOW_FS)
        self.composite = program("kge-light-composite", _COMPOSITE_VS, _COMPOSITE_FS)
        self.glow_program = program("kge-light-glow", _GLOW_VS, _GLOW_FS)
        self.lights = Stream(None, _LAYOUT)  # every light program: layout(location = N)
        self.shadows = Stream(self.shadow_program, [("seg", 4), ("corner", 2), ("closed", 1)])
        self.glows = Stream(self.glow_program, [("world", 2), ("center", 2), ("color", 4)])
        self.texture: Any = None
        self.normal_texture: Any = None
        self.size = (0, 0)
        self.extent = (1.0, 1.0)
        self.quad: Any = None
        self.quad_layer: int | None = None
        self._glow_count = 0
        self._to_clip: tuple[float, ...] = ()
        self.stats = {"lights": 0, "shadowed": 0, "edges": 0}
        self.window: Any = groups.state.window  #: whose context owns the GL objects

    # -- targets --------------------------------------------------------------------------------
    def _fit(self, size: tuple[int, int]) -> None:
        """Textures at least ``size`` (grown in steps, so resizing does not churn)."""
        tex = self.texture
        if tex is None or tex.width < size[0] or tex.height < size[1]:
            if tex is not None:
                tex.delete()
                self.normal_texture.delete()
            w, h = (max(64, (s + 63) // 64 * 64) for s in size)
            self.texture = new_texture(w, h)
            self.normal_texture = new_texture(w, h, linear=False)
        self.size = size
        self.extent = (size[0] / self.texture.width, size[1] / self.texture.height)

    def _composite_quad(self, layer: int | None) -> None:
        if layer == self.quad_layer:
            return
        if self.quad is not None:
            self.quad.delete()
            self.quad = None
        self.quad_layer = layer
        if layer is None:
            return
        group = CompositeGroup(self, self.groups.get(layer - 1, VIEW, _ORDER_LAST))
        self.quad = self.composite.vertex_list_indexed(
            4, gl.GL_TRIANGLES, [0, 1, 2, 0, 2, 3], batch=self.batch, group=group,
            position=("f", (-1.0, -1.0, 1.0, -1.0, 1.0, 1.0, -1.0, 1.0)),
        )  # fmt: skip

    # -- a frame --------------------------------------------------------------------------------
    def draw(self, frame: Any, lighting: Lighting, normals: Any = None) -> None:
        """Render the light map for ``frame``'s camera (a view pass)."""
        if not lighting.enabled:
            self._composite_quad(None)
            return
        self._composite_quad(lighting.unlit_layer)
        shows = self.groups.state.shows
        if shows is not None and not shows(lighting.unlit_layer - 1, VIEW):
            return  # this camera does not draw the lit layers' multiply
        k = lighting.resolution
        size = (max(1, math.ceil(frame.rect[2] * k)), max(1, math.ceil(frame.rect[3] * k)))
        self._fit(size)
        to_clip = self._to_clip = clip_matrix(frame.world_matrix, frame.viewport)
        left, bottom, right, top = frame.view
        found = [
            (light, pose) for _, light, pose in light_poses(self.world, frame.pose)
            if pose[0] + light.radius >= left and pose[0] - light.radius <= right
            and pose[1] + light.radius >= bottom and pose[1] - light.radius <= top
        ]  # fmt: skip
        suns = [s for _, (s,) in self.world.query(DirectionalLight)
                if s.enabled and s.intensity > 0]  # fmt: skip
        # lights drawn together (no shadow, no cookie), points then spots; then the others
        points = [f for f in found if not f[0].shadows and f[0].texture is None
                  and not f[0].is_spot]  # fmt: skip
        spots = [f for f in found if not f[0].shadows and f[0].texture is None and f[0].is_spot]
        single = [f for f in found if f[0].shadows or f[0].texture is not None]
        ordered = points + spots + single
        self.lights.upload(np.concatenate([light_rows(ordered)]
                                          + [sun_rows(s, frame.view) for s in suns]))  # fmt: skip
        use_normals = normals is not None and normals.draws()
        edges = np.zeros((0, 2, 2))
        if any(light.shadows for light, _ in single) or any(s.shadows for s in suns):
            edges, closed = self.occluders.edges(self.world, lighting.static_shadows, frame.pose)
            if len(edges):
                self.shadows.upload(wedge_rows(edges, closed))
        self.stats = {"lights": len(found) + len(suns),
                      "shadowed": sum(1 for light, _ in single if light.shadows),
                      "edges": len(edges)}  # fmt: skip
        self._glows([f for f in found if f[0].glow > 0])
        with drawing_into(self.texture, *size):
            if use_normals:
                self._normals(normals, size, frame)
            r, g, b = (c / 255.0 for c in lighting.ambient)
            clear((r, g, b, 0.0))
            gl.glEnable(gl.GL_BLEND)
            gl.glBlendFunc(gl.GL_ONE, gl.GL_ONE)
            gl.glColorMask(gl.GL_TRUE, gl.GL_TRUE, gl.GL_TRUE, gl.GL_FALSE)
            if use_normals:
                gl.glActiveTexture(gl.GL_TEXTURE1)
                gl.glBindTexture(self.normal_texture.target, self.normal_texture.id)
                gl.glActiveTexture(gl.GL_TEXTURE0)
            self._batch("point", 0, len(points), use_normals)
            self._batch("spot", VERTS * len(points), len(spots), use_normals)
            gl.glEnable(gl.GL_SCISSOR_TEST)
            first = VERTS * (len(points) + len(spots))
            for i, (light, pose) in enumerate(single):
                rect = self._scissor(pose, light.radius, to_clip, size)
                if rect is not None:
                    gl.glScissor(*rect)
                    kind = "spot" if light.is_spot else "point"
                    self._one(first + VERTS * i, light, (pose[0], pose[1]), len(edges), frame, kind,
                              use_normals)  # fmt: skip
            first += VERTS * len(single)
            for j, sun in enumerate(suns):
                gl.glScissor(0, 0, *size)
                travel = (math.cos(sun.angle), math.sin(sun.angle))
                self._one(first + VERTS * j, sun, travel, len(edges), frame, "sun", use_normals)
            gl.glDisable(gl.GL_SCISSOR_TEST)
            gl.glColorMask(gl.GL_TRUE, gl.GL_TRUE, gl.GL_TRUE, gl.GL_TRUE)
            gl.glDisable(gl.GL_BLEND)

    def _use(self, kind: str, normals: bool, cookie: bool = False, shade: bool = False) -> Any:
        prog = light_program(kind, cookie, normals, shade)
        prog.use()
        prog["to_clip"] = self._to_clip
        if normals:
            prog["normals"] = 1
            prog["map_size"] = (float(self.texture.width), float(self.texture.height))
        if cookie:
            prog["cookie"] = 2
        return prog

    def _batch(self, kind: str, first: int, count: int, normals: bool) -> None:
        """Lights of one kind drawn together (no shadows, no cookies)."""
        if count:
            self._use(kind, normals)
            self.lights.draw(first, VERTS * count)

    def _one(self, first: int, light: Any, where: tuple[float, float], edges: int, frame: Any,
             kind: str, normals: bool) -> None:  # fmt: skip
        """A light drawn on its own: its shadows into alpha, then it (and its shadow colour).

        Alpha is 0 under the light's square when it starts (cleared with the map, and
        every light's own draw writes 0 there as it reads it), so no clear is needed.
        """
        shadowed = light.shadows and edges > 0
        texture = getattr(light, "texture", None)
        cookie = texture is not None and self.textures is not None
        if cookie:
            tex = self.textures.texture(texture, filter="linear")
            gl.glActiveTexture(gl.GL_TEXTURE2)
            gl.glBindTexture(tex.target, tex.id)
            gl.glActiveTexture(gl.GL_TEXTURE0)
        if not shadowed:
            self._use(kind, normals, cookie)
            self.lights.draw(first, VERTS)
            return
        gl.glColorMask(gl.GL_FALSE, gl.GL_FALSE, gl.GL_FALSE, gl.GL_TRUE)
        sp = self.shadow_program
        sp.use()
        sp["to_clip"] = self._to_clip
        sp["light"] = where
        sp["kind"] = 1 if kind == "sun" else 0
        # metres per light-map pixel: a hard shadow's bulb is half a pixel wide
        pixel = frame.viewport[0] / max(frame.scale * self.size[0], 1e-9)
        if kind == "sun":
            x0, y0, x1, y1 = frame.view
            sp["radius"] = 0.0
            sp["reach"] = float(math.hypot(x1 - x0, y1 - y0) * 2.0 + 1.0)
            sp["source"] = float(max(light.shadow_softness, 1e-3))
        else:
            sp["radius"] = float(light.radius)
            sp["reach"] = float(light.radius * 2.0 + 1.0)
            sp["source"] = float(max(light.shadow_softness, 0.5 * pixel))
        gl.glBlendFunc(gl.GL_ONE, gl.GL_ONE)
        self.shadows.draw(0, 6 * edges)
        gl.glColorMask(gl.GL_TRUE, gl.GL_TRUE, gl.GL_TRUE, gl.GL_TRUE)
        if any(light.shadow_color):  # light it casts into its shadows: times alpha, kept
            gl.glBlendFuncSeparate(gl.GL_DST_ALPHA, gl.GL_ONE, gl.GL_ZERO, gl.GL_ONE)
            self._use(kind, normals, cookie, shade=True)
            self.lights.draw(first, VERTS)
        # the light, times 1 - alpha; the alpha is reset to 0 for the next light
        gl.glBlendFuncSeparate(gl.GL_ONE_MINUS_DST_ALPHA, gl.GL_ONE, gl.GL_ZERO, gl.GL_ZERO)
        self._use(kind, normals, cookie)
        self.lights.draw(first, VERTS)
        gl.glColorMask(gl.GL_TRUE, gl.GL_TRUE, gl.GL_TRUE, gl.GL_FALSE)
        gl.glBlendFunc(gl.GL_ONE, gl.GL_ONE)

    @staticmethod
    def _scissor(pose: tuple[float, float, float], radius: float, to_clip: tuple[float, ...],
                 size: tuple[int, int]) -> tuple[int, int, int, int] | None:  # fmt: skip
        """The whole light-map pixels inside the light's square (None: off the map); inside,
        so that every pixel its shadows may darken is one its square's draw resets."""
        m = to_clip  # column-major: x' = m0 x + m4 y + m12, y' = m1 x + m5 y + m13
        xs, ys = [], []
        for dx in (-radius, radius):
            for dy in (-radius, radius):
                x, y = pose[0] + dx, pose[1] + dy
                xs.append((m[0] * x + m[4] * y + m[12]) * 0.5 + 0.5)
                ys.append((m[1] * x + m[5] * y + m[13]) * 0.5 + 0.5)
        x0, x1 = max(math.ceil(min(xs) * size[0]), 0), min(math.floor(max(xs) * size[0]), size[0])
        y0, y1 = max(math.ceil(min(ys) * size[1]), 0), min(math.floor(max(ys) * size[1]), size[1])
        if x1 <= x0 or y1 <= y0:
            return None
        return (x0, y0, x1 - x0, y1 - y0)

    def _normals(self, normals: Any, size: tuple[int, int], frame: Any) -> None:
        """Draw the normal-mapped sprites into the normal buffer (this camera's view)."""
        with drawing_into(self.normal_texture, *size):
            clear((0.5, 0.5, 1.0, 0.0))
            window = self.window
            window.projection = pyglet.math.Mat4.orthogonal_projection(
                0, frame.viewport[0], 0, frame.viewport[1], -255, 255
            )
            window.view = pyglet.math.Mat4(*frame.world_matrix)
            normals.draw()
            window.view = pyglet.math.Mat4()

    def _glows(self, glows: list[tuple[Light, tuple[float, float, float]]]) -> None:
        self._glow_count = len(glows)
        if not glows:
            return
        rows = np.empty((len(glows), 6, 8), np.float32)
        for i, (light, (x, y, _)) in enumerate(glows):
            r = light.radius * GLOW_REACH
            k = light.glow * light.intensity / 255.0
            rows[i, :, 0:2] = (x, y) + _CORNERS * r
            rows[i, :, 2:4] = (x, y)
            rows[i, :, 4:8] = (light.color[0] * k, light.color[1] * k, light.color[2] * k, r)
        self.glows.upload(rows.reshape(-1, 8))

    def draw_glows(self) -> None:
        """Add the light halos (after the multiply; called by the composite group)."""
        if not self._glow_count:
            return
        gp = self.glow_program
        gp.use()
        gp["to_clip"] = self._to_clip
        gl.glBlendFunc(gl.GL_ONE, gl.GL_ONE)
        self.glows.draw(0, 6 * self._glow_count)

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
        self.glows.delete()
        for tex in (self.texture, self.normal_texture):
            if tex is not None:
                tex.delete()
        self.texture = self.normal_texture = None
        self.size = (0, 0)
