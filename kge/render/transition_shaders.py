"""Drawing shader transitions (:mod:`kge.transition_shaders`): one full-window quad.

The user's ``transition(...)`` function is wrapped in a fragment shader that declares
``resolution`` and samples nothing itself; the quad covers the framebuffer in clip
space, so no projection is involved. Programs are compiled once per source and GL
context; one that does not compile is reported once (a ``ShaderWarning``) and the
transition is drawn as a crossfade of the old picture instead.
"""

from __future__ import annotations

import warnings
from typing import Any

import pyglet
from pyglet import gl

from kge.components.material import ShaderWarning
from kge.render.glutil import program
from kge.render.programs import compile_error
from kge.transition_shaders import Shaded
from kge.transitions import ActiveTransition

_VERTEX = """#version 150 core
in vec2 position;
out vec2 v_uv;
void main() {
    v_uv = position * 0.5 + 0.5;
    gl_Position = vec4(position, 0.0, 1.0);
}
"""
HEAD = """#version 150 core
in vec2 v_uv;
out vec4 kge_out;
uniform sampler2D old_scene;
uniform float progress;
uniform vec2 resolution;
"""
_MAIN = "\nvoid main() { kge_out = transition(old_scene, v_uv, progress); }\n"
_FALLBACK = "vec4 transition(sampler2D s, vec2 uv, float p) { return texture(s, uv) * " \
            "vec4(1.0, 1.0, 1.0, 1.0 - p); }"
_failed: dict[int, str] = {}


def _program(tr: Shaded) -> Any:
    source = tr.glsl()
    key = hash(source)
    if key not in _failed:
        try:
            return program(f"kge-transition-{key}", _VERTEX, HEAD + source + _MAIN)
        except pyglet.graphics.shader.ShaderException as exc:
            _failed[key] = compile_error(exc, HEAD.count("\n"))
            warnings.warn(
                f"{type(tr).__name__} shader did not compile ({_failed[key]}); drawing a "
                "crossfade meanwhile",
                ShaderWarning,
                stacklevel=2,
            )
    return program("kge-transition-fallback", _VERTEX, HEAD + _FALLBACK + _MAIN)


def shader_error(tr: Shaded) -> str | None:
    """The compile error of ``tr``'s shader once it was tried, else None."""
    return _failed.get(hash(tr.glsl()))


def draw_shaded(active: ActiveTransition, framebuffer: tuple[int, int]) -> None:
    """Draw ``active`` (a :class:`Shaded` transition) over the whole framebuffer."""
    tr = active.transition
    assert isinstance(tr, Shaded)
    if tr.needs_picture and (not active.swapped or active.picture is None):
        return  # the old scene is still on screen, or nothing was drawn to picture
    prog = _program(tr)
    prog.use()
    pic = active.picture
    gl.glActiveTexture(gl.GL_TEXTURE0)
    if pic is not None:
        gl.glBindTexture(pic.target, pic.id)
    values: dict[str, Any] = {
        "old_scene": 0,
        "progress": float(tr.progress(active.t, active.swapped)),
        "resolution": (float(framebuffer[0]), float(framebuffer[1])),
    }
    if shader_error(tr) is None:
        values.update(tr.uniform_values())
    declared = prog.uniforms  # the driver drops the ones the shader does not use
    for name, value in values.items():
        if name in declared:
            prog[name] = value
    gl.glEnable(gl.GL_BLEND)
    gl.glBlendFunc(gl.GL_SRC_ALPHA, gl.GL_ONE_MINUS_SRC_ALPHA)
    quad = prog.vertex_list_indexed(4, gl.GL_TRIANGLES, [0, 1, 2, 0, 2, 3],
                                    position=("f", (-1, -1, 1, -1, 1, 1, -1, 1)))  # fmt: skip
    try:
        quad.draw(gl.GL_TRIANGLES)
    finally:
        quad.delete()
        prog.stop()
