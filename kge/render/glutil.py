"""Small GL helpers shared by the passes that draw offscreen: programs, streams, targets.

* :func:`program` compiles a shader program once per GL object space (programs and
  textures are shared between pyglet's windows; vertex arrays and framebuffers are not);
* :class:`Stream`: a vertex array + buffer of interleaved float attributes, refilled
  with one numpy upload per frame;
* :class:`RenderTarget`: draw into a texture (a framebuffer per context), restoring the
  framebuffer, viewport and blend state it found, so a pass can run inside another
  (text baked while a camera draws into its post-processing buffer);
* :func:`fullscreen` draws a quad covering the viewport (post effects, composites).
"""

from __future__ import annotations

import ctypes
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import numpy as np
import pyglet
from pyglet import gl

#: vertex shader of a full-viewport quad: ``uv`` runs 0..1 across it
FULLSCREEN_VS = """#version 150 core
in vec2 position;
out vec2 uv;
void main()
{
    gl_Position = vec4(position, 0.0, 1.0);
    uv = position * 0.5 + 0.5;
}
"""


def program(name: str, vertex: str, fragment: str) -> Any:
    """The compiled program ``name`` of the current context's object space (built once)."""
    ctx: Any = gl.current_context
    space = ctx.object_space
    cache = getattr(space, "kge_programs", None)
    if cache is None:
        cache = space.kge_programs = {}
    prog = cache.get(name)
    if prog is None:
        prog = cache[name] = pyglet.graphics.shader.ShaderProgram(
            pyglet.graphics.shader.Shader(vertex, "vertex"),
            pyglet.graphics.shader.Shader(fragment, "fragment"),
        )
    return prog


def per_context(key: str, make: Any) -> Any:
    """An object of the *current context* (vertex arrays, framebuffers), made once."""
    ctx: Any = gl.current_context
    store = getattr(ctx, "kge_objects", None)
    if store is None:
        store = ctx.kge_objects = {}
    obj = store.get(key)
    if obj is None:
        obj = store[key] = make()
    return obj


class Stream:
    """A vertex array and buffer of interleaved float attributes, re-filled each frame.

    Attribute locations come from ``prog``; with ``prog=None`` the layout's order is
    the location (shaders that say ``layout(location = N)``, so several programs
    share one vertex array).
    """

    def __init__(self, prog: Any, layout: list[tuple[str, int]]) -> None:
        self.vao = gl.GLuint()
        self.vbo = gl.GLuint()
        gl.glGenVertexArrays(1, self.vao)
        gl.glGenBuffers(1, self.vbo)
        gl.glBindVertexArray(self.vao)
        gl.glBindBuffer(gl.GL_ARRAY_BUFFER, self.vbo)
        stride = sum(n for _, n in layout) * 4
        offset = 0
        for index, (name, n) in enumerate(layout):
            if prog is None:
                found: Any = {"location": index}
            else:  # None: the compiler removed an unused input
                found = prog.attributes.get(name)
            if found is not None:
                loc = found["location"]
                gl.glEnableVertexAttribArray(loc)
                gl.glVertexAttribPointer(loc, n, gl.GL_FLOAT, gl.GL_FALSE, stride, offset)
            offset += n * 4
        gl.glBindVertexArray(0)
        self.floats = stride // 4

    def upload(self, data: np.ndarray) -> None:
        data = np.ascontiguousarray(data, np.float32)
        gl.glBindBuffer(gl.GL_ARRAY_BUFFER, self.vbo)
        gl.glBufferData(
            gl.GL_ARRAY_BUFFER, data.nbytes, data.ctypes.data_as(ctypes.c_void_p),
            gl.GL_STREAM_DRAW,
        )  # fmt: skip

    def draw(self, first: int, count: int, mode: int = gl.GL_TRIANGLES) -> None:
        if count <= 0:
            return
        gl.glBindVertexArray(self.vao)
        gl.glDrawArrays(mode, first, count)
        gl.glBindVertexArray(0)

    def delete(self) -> None:
        gl.glDeleteBuffers(1, self.vbo)
        gl.glDeleteVertexArrays(1, self.vao)


_QUAD = np.array([-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1], np.float32)


def fullscreen(prog: Any) -> None:
    """Draw a quad over the whole viewport with ``prog`` (which must be in use)."""
    key = f"fullscreen-{prog.id}"

    def make() -> Stream:
        s = Stream(prog, [("position", 2)])
        s.upload(_QUAD)
        return s

    per_context(key, make).draw(0, 6)


class _Framebuffer:
    """A bare framebuffer object (no attachment bookkeeping)."""

    def __init__(self) -> None:
        self.id = gl.GLuint()
        gl.glGenFramebuffers(1, self.id)

    def attach(self, texture: Any, stencil: Any = None) -> None:
        gl.glFramebufferTexture2D(gl.GL_FRAMEBUFFER, gl.GL_COLOR_ATTACHMENT0, texture.target,
                                  texture.id, 0)  # fmt: skip
        gl.glFramebufferRenderbuffer(gl.GL_FRAMEBUFFER, gl.GL_DEPTH_STENCIL_ATTACHMENT,
                                     gl.GL_RENDERBUFFER, 0 if stencil is None else stencil.id)


def new_texture(width: int, height: int, linear: bool = True) -> Any:
    """An RGBA8 texture to draw into (clamped at the edges)."""
    f = gl.GL_LINEAR if linear else gl.GL_NEAREST
    tex = pyglet.image.Texture.create(int(width), int(height), min_filter=f, mag_filter=f)
    gl.glBindTexture(tex.target, tex.id)
    gl.glTexParameteri(tex.target, gl.GL_TEXTURE_WRAP_S, gl.GL_CLAMP_TO_EDGE)
    gl.glTexParameteri(tex.target, gl.GL_TEXTURE_WRAP_T, gl.GL_CLAMP_TO_EDGE)
    return tex


def current_framebuffer() -> int:
    found = gl.GLint()
    gl.glGetIntegerv(gl.GL_DRAW_FRAMEBUFFER_BINDING, found)
    return int(found.value)


def current_viewport() -> tuple[int, int, int, int]:
    vp = (gl.GLint * 4)()
    gl.glGetIntegerv(gl.GL_VIEWPORT, vp)
    return (int(vp[0]), int(vp[1]), int(vp[2]), int(vp[3]))


_depth = 0


@contextmanager
def drawing_into(
    texture: Any, width: int | None = None, height: int | None = None, stencil: Any = None
) -> Iterator[None]:
    """Draw into ``texture`` (its ``width`` x ``height`` corner) until the block ends.

    The framebuffer, viewport, scissor and blend state found are restored afterwards.
    """
    global _depth
    fbo = per_context(f"render-target-fbo-{_depth}", _Framebuffer)  # one per nesting level
    _depth += 1
    previous = current_framebuffer()
    viewport = current_viewport()
    scissor = gl.glIsEnabled(gl.GL_SCISSOR_TEST)
    blend = gl.glIsEnabled(gl.GL_BLEND)
    gl.glBindFramebuffer(gl.GL_FRAMEBUFFER, fbo.id)
    fbo.attach(texture, stencil)
    gl.glViewport(0, 0, int(width or texture.width), int(height or texture.height))
    gl.glDisable(gl.GL_SCISSOR_TEST)
    try:
        yield
    finally:
        _depth -= 1
        gl.glBindFramebuffer(gl.GL_FRAMEBUFFER, previous)
        gl.glViewport(*viewport)
        (gl.glEnable if scissor else gl.glDisable)(gl.GL_SCISSOR_TEST)
        (gl.glEnable if blend else gl.glDisable)(gl.GL_BLEND)
        if blend:
            gl.glBlendFunc(gl.GL_SRC_ALPHA, gl.GL_ONE_MINUS_SRC_ALPHA)


def clear(color: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)) -> None:
    gl.glClearColor(*color)
    gl.glClear(gl.GL_COLOR_BUFFER_BIT)
