"""Anti-aliased UI shapes: rounded boxes (filled, outlined or both), circles, strokes and
gradients, each one quad drawn by a signed-distance shader.

The fragment shader measures how far each pixel is from the shape's edge (a rounded
box or a capsule around a segment) and covers it by that distance over one pixel
(``fwidth``), so corners, knobs, check marks and arrows are smooth at any size and
on high-DPI framebuffers. Every shape of the UI shares one program, so a batch draws
all the shapes of a depth level in one call.

:class:`ShapeStore` keeps one vertex list per key and rewrites a shape's vertices
only when its geometry or colours changed.
"""

from __future__ import annotations

from typing import Any

import pyglet
from pyglet import gl
from pyglet.graphics.shader import ShaderProgram

Color = tuple[int, ...]  #: RGBA (themes and components always hold four channels)

_VERTEX = """#version 150 core
in vec2 position;
in vec4 colors;
in vec4 shape;
in vec4 params;
in vec4 edge;
out vec4 v_color;
out vec4 v_shape;
out vec4 v_params;
out vec4 v_edge;
out vec2 v_pos;
uniform WindowBlock { mat4 projection; mat4 view; } window;
void main() {
    gl_Position = window.projection * window.view * vec4(position, 0.0, 1.0);
    v_color = colors;
    v_shape = shape;
    v_params = params;
    v_edge = edge;
    v_pos = position;
}
"""

_FRAGMENT = """#version 150 core
in vec4 v_color;
in vec4 v_shape;
in vec4 v_params;
in vec4 v_edge;
in vec2 v_pos;
out vec4 final_color;
float rounded_box(vec2 p, vec2 half_size, float r) {
    vec2 q = abs(p) - half_size + vec2(r);
    return length(max(q, 0.0)) + min(max(q.x, q.y), 0.0) - r;
}
float capsule(vec2 p, vec2 a, vec2 b) {
    vec2 pa = p - a, ba = b - a;
    float t = clamp(dot(pa, ba) / max(dot(ba, ba), 1e-6), 0.0, 1.0);
    return length(pa - ba * t);
}
void main() {
    float d;
    if (v_params.z < 0.5) {
        d = rounded_box(v_pos - v_shape.xy, v_shape.zw, v_params.x);
    } else {
        d = capsule(v_pos, v_shape.xy, v_shape.zw) - v_params.x;
    }
    float aa = max(fwidth(d), 1e-4);
    float cover = clamp(0.5 - d / aa, 0.0, 1.0);
    vec4 c = v_color;
    if (v_params.y > 0.0) {  // a border: the edge colour outside, the fill inside
        float inside = clamp(0.5 - (d + v_params.y) / aa, 0.0, 1.0);
        float a = v_color.a * inside + v_edge.a * (1.0 - inside);
        vec3 rgb = v_color.rgb * v_color.a * inside + v_edge.rgb * v_edge.a * (1.0 - inside);
        c = vec4(rgb / max(a, 1e-4), a);
    }
    final_color = vec4(c.rgb, c.a * cover);
    if (final_color.a <= 0.001) discard;
}
"""

def program() -> ShaderProgram:
    """The shape program of the current GL context (pyglet keeps one per context, and
    forgets it with the context)."""
    context = gl.current_context
    assert context is not None, "UI shapes need a current GL context"
    prog: ShaderProgram = context.create_program((_VERTEX, "vertex"), (_FRAGMENT, "fragment"))
    return prog


class ShapeGroup(pyglet.graphics.Group):
    """Binds the shape program with alpha blending (one per draw order and clip)."""

    def __init__(self, order: int, parent: pyglet.graphics.Group | None = None) -> None:
        super().__init__(order=order, parent=parent)
        self.program = program()

    def set_state(self) -> None:
        self.program.bind()
        gl.glEnable(gl.GL_BLEND)
        gl.glBlendFunc(gl.GL_SRC_ALPHA, gl.GL_ONE_MINUS_SRC_ALPHA)

    def unset_state(self) -> None:
        gl.glDisable(gl.GL_BLEND)
        self.program.unbind()

    def __eq__(self, other: object) -> bool:
        return self is other

    def __hash__(self) -> int:
        return id(self)


_INDICES = (0, 1, 2, 0, 2, 3)


class ShapeStore:
    """One quad per key: rounded boxes, strokes and gradients (see the module docstring)."""

    def __init__(self, batch: Any) -> None:
        self.batch = batch
        self.lists: dict[Any, Any] = {}
        self.data: dict[Any, tuple[Any, ...]] = {}
        self.groups: dict[Any, Any] = {}

    def _put(self, key: Any, group: Any, data: tuple[Any, ...]) -> None:
        vl = self.lists.get(key)
        if vl is not None and self.groups[key] is not group:
            vl.delete()
            vl = None
        if vl is None:
            pos, col, shape, params, edge = data
            vl = program().vertex_list_indexed(
                4, gl.GL_TRIANGLES, _INDICES, batch=self.batch, group=group,
                position=("f", pos), colors=("Bn", col), shape=("f", shape),
                params=("f", params), edge=("Bn", edge),
            )  # fmt: skip
            self.lists[key] = vl
            self.groups[key] = group
            self.data[key] = data
            return
        old = self.data[key]
        if old == data:
            return
        names = ("position", "colors", "shape", "params", "edge")
        for name, a, b in zip(names, old, data, strict=True):
            if a != b:
                getattr(vl, name)[:] = b
        self.data[key] = data

    def box(self, key: Any, group: Any, x: float, y: float, w: float, h: float, color: Color,
            radius: float = 0.0, border: float = 0.0, edge: Color = (0, 0, 0, 0),
            corners: tuple[Color, Color, Color, Color] | None = None) -> None:  # fmt: skip
        """A rounded box; ``border`` pixels of ``edge`` colour inside its outline.
        ``corners`` (bottom-left, bottom-right, top-right, top-left) make a gradient."""
        r = max(min(radius, w / 2, h / 2), 0.0)
        # the quad is the box itself: pixels outside it are never touched (edges that
        # fall between pixels stay crisp; the corners' curves are smoothed inside)
        pos = (x, y, x + w, y, x + w, y + h, x, y + h)
        shape = (x + w / 2, y + h / 2, w / 2, h / 2) * 4
        cols = tuple(c for corner in (corners or (color,) * 4) for c in corner)
        self._put(key, group, (pos, cols, shape, (r, border, 0.0, 0.0) * 4, edge * 4))

    def stroke(self, key: Any, group: Any, a: tuple[float, float], b: tuple[float, float],
               thickness: float, color: Color) -> None:  # fmt: skip
        """A line from ``a`` to ``b`` with round caps, ``thickness`` pixels wide."""
        r = thickness / 2
        m = r
        x0, x1 = min(a[0], b[0]) - m, max(a[0], b[0]) + m
        y0, y1 = min(a[1], b[1]) - m, max(a[1], b[1]) + m
        pos = (x0, y0, x1, y0, x1, y1, x0, y1)
        self._put(key, group, (pos, color * 4, (a[0], a[1], b[0], b[1]) * 4,
                               (r, 0.0, 1.0, 0.0) * 4, (0, 0, 0, 0) * 4))  # fmt: skip

    def delete(self, key: Any) -> None:
        vl = self.lists.pop(key, None)
        if vl is not None:
            vl.delete()
            self.data.pop(key, None)
            self.groups.pop(key, None)

    def clear(self) -> None:
        for vl in self.lists.values():
            vl.delete()
        self.lists.clear()
        self.data.clear()
        self.groups.clear()
