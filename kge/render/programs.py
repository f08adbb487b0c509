"""kge's shader programs for sprites, shapes and particles, blend modes, and materials.

Every drawable kind has one vertex shader (pyglet's vertex layout, so pyglet's
sprites and vertex lists feed it unchanged) that hands the fragment stage a colour,
a texture coordinate and the world position, and one fragment *wrapper* that calls
``vec4 effect(vec4 color, sampler2D tex, vec2 uv, vec2 world)`` and writes
**premultiplied** colour. The default effect is ``texture(tex, uv) * color``; a
:class:`~kge.components.material.Material`'s shader supplies its own. Premultiplied
output is what makes the blend modes exact with any alpha:

==============  ======================================  =============================
blend           factors (source, destination)           result
==============  ======================================  =============================
alpha           ONE, ONE_MINUS_SRC_ALPHA                 src over dst
premultiplied   same (the texture is premultiplied)      src over dst
add             ONE, ONE                                 dst + src
multiply        DST_COLOR, ONE_MINUS_SRC_ALPHA           dst x src (alpha: dst)
screen          ONE, ONE_MINUS_SRC_COLOR                 1 - (1 - dst)(1 - src)
==============  ======================================  =============================

A material shader that does not compile is reported once with a
:class:`~kge.components.material.ShaderWarning` naming the shader and the line of
*its* source, and the drawable keeps the default program.
"""

from __future__ import annotations

import re
import warnings
from typing import Any

import pyglet
from pyglet import gl

from kge.components.blend import Blend
from kge.components.material import Shader, ShaderWarning
from kge.render.glutil import program

BLEND_FACTORS = {
    Blend.ALPHA: (gl.GL_ONE, gl.GL_ONE_MINUS_SRC_ALPHA),
    Blend.PREMULTIPLIED: (gl.GL_ONE, gl.GL_ONE_MINUS_SRC_ALPHA),
    Blend.ADDITIVE: (gl.GL_ONE, gl.GL_ONE),
    Blend.MULTIPLY: (gl.GL_DST_COLOR, gl.GL_ONE_MINUS_SRC_ALPHA),
    Blend.SCREEN: (gl.GL_ONE, gl.GL_ONE_MINUS_SRC_COLOR),
}


def set_blend(mode: Blend) -> None:
    """Enable blending in ``mode`` (alpha always accumulates as "over")."""
    src, dst = BLEND_FACTORS[mode]
    gl.glEnable(gl.GL_BLEND)
    gl.glBlendFuncSeparate(src, dst, gl.GL_ONE, gl.GL_ONE_MINUS_SRC_ALPHA)


_WINDOW = """uniform WindowBlock
{
    mat4 projection;
    mat4 view;
} window;
uniform float snap;  // world units per design pixel (0: no snapping)
vec2 snapped(vec2 p) { return snap > 0.0 ? floor(p / snap + 0.5) * snap : p; }
"""

SPRITE_VS = (
    "#version 150 core\n"
    + _WINDOW
    + """
in vec3 translate;
in vec4 colors;
in vec3 tex_coords;
in vec2 scale;
in vec3 position;
in float rotation;
out vec4 v_color;
out vec2 v_uv;
out vec2 v_world;
out float v_angle;   // radians counter-clockwise (normal maps turn with the sprite)
out vec2 v_sign;     // the flips
void main()
{
    float a = -radians(rotation);
    v_angle = a;
    v_sign = sign(scale);
    vec2 p = position.xy * scale;
    vec2 w = snapped(translate.xy) + vec2(cos(a) * p.x - sin(a) * p.y, sin(a) * p.x + cos(a) * p.y);
    gl_Position = window.projection * window.view * vec4(w, translate.z + position.z, 1.0);
    v_color = colors;
    v_uv = tex_coords.xy;
    v_world = w;
}
"""
)

SHAPE_VS = (
    "#version 150 core\n"
    + _WINDOW
    + """
in vec2 position;
in vec4 colors;
in vec2 translation;
in float rotation;
in float zposition;
out vec4 v_color;
out vec2 v_uv;
out vec2 v_world;
void main()
{
    float a = -radians(rotation);
    vec2 p = position;
    vec2 w = snapped(translation) + vec2(cos(a) * p.x - sin(a) * p.y, sin(a) * p.x + cos(a) * p.y);
    gl_Position = window.projection * window.view * vec4(w, zposition, 1.0);
    v_color = colors;
    v_uv = position;
    v_world = w;
}
"""
)

FS_HEAD = """#version 150 core
in vec4 v_color;
in vec2 v_uv;
in vec2 v_world;
out vec4 kge_out;
uniform sampler2D kge_texture;
uniform float time;
"""
#: how the wrapper turns ``effect``'s colour into the output (straight -> premultiplied)
_FS_MAIN = {
    "straight": "\nvoid main() { vec4 c = effect(v_color, kge_texture, v_uv, v_world); "
    "kge_out = vec4(c.rgb * c.a, c.a); }\n",
    "premultiplied": "\nvoid main() { kge_out = effect(v_color, kge_texture, v_uv, v_world); }\n",
}
DEFAULT_EFFECT = """vec4 effect(vec4 color, sampler2D tex, vec2 uv, vec2 world)
{
    return texture(tex, uv) * color;
}
"""
SHAPE_EFFECT = """vec4 effect(vec4 color, sampler2D tex, vec2 uv, vec2 world)
{
    return color;
}
"""
_HEAD_LINES = FS_HEAD.count("\n")
_VERTEX = {"sprite": SPRITE_VS, "shape": SHAPE_VS}


NORMAL_FS = """#version 150 core
in vec4 v_color;
in vec2 v_uv;
in float v_angle;
in vec2 v_sign;
out vec4 kge_out;
uniform sampler2D kge_texture;
void main()
{
    vec4 t = texture(kge_texture, v_uv);
    if (t.a < 0.5) discard;
    vec3 n = t.rgb * 2.0 - 1.0;
    n.xy *= v_sign;
    float c = cos(v_angle);
    float s = sin(v_angle);
    n.xy = vec2(c * n.x - s * n.y, s * n.x + c * n.y);
    kge_out = vec4(normalize(n) * 0.5 + 0.5, 1.0);
}
"""


def normal_program() -> Any:
    """Draws normal maps into the lights' normal buffer, turned and flipped with the sprite."""
    return program("kge-sprite-normals", SPRITE_VS, NORMAL_FS)


def fragment_source(effect: str, output: str = "straight") -> str:
    """The whole fragment shader around an ``effect`` function."""
    return FS_HEAD + effect + _FS_MAIN[output]


def default_program(kind: str, output: str = "straight") -> Any:
    """kge's program for ``kind`` ("sprite" or "shape") with the default effect."""
    effect = SHAPE_EFFECT if kind == "shape" else DEFAULT_EFFECT
    return program(f"kge-{kind}-{output}", _VERTEX[kind], fragment_source(effect, output))


_failed: dict[tuple[str, int], str] = {}
_LINE = re.compile(r"\b0:(\d+)\(\d+\):\s*(.*)")


def compile_error(exc: BaseException, head_lines: int) -> str:
    """The first compiler message of ``exc``, with its line counted in the user's source."""
    text = str(exc)
    found = _LINE.search(text)
    if found is None:
        last = [ln for ln in text.strip().splitlines() if ln.strip()]
        return last[-1] if last else "the shader did not compile"
    line = int(found.group(1)) - head_lines
    return f"line {max(line, 1)}: {found.group(2).strip()}"


def material_program(shader: Shader, kind: str, vertex: str | None = None,
                     head: str = FS_HEAD, main: str | None = None) -> Any | None:  # fmt: skip
    """The compiled program of ``shader`` for a drawable ``kind`` (cached), or None when it
    does not compile (reported once with a :class:`ShaderWarning`)."""
    key = (kind, hash(shader))
    if key in _failed:
        return None
    source = head + shader.source + "\n" + (main or _FS_MAIN["straight"])
    try:
        return program(f"kge-material-{kind}-{hash(shader)}", vertex or _VERTEX[kind], source)
    except pyglet.graphics.shader.ShaderException as exc:
        message = compile_error(exc, head.count("\n"))
        _failed[key] = message
        warnings.warn(
            f"shader {shader.name!r} did not compile ({message}); drawing with the plain "
            "material meanwhile",
            ShaderWarning,
            stacklevel=2,
        )
        return None


def shader_error(shader: Shader, kind: str = "sprite") -> str | None:
    """The compile error of ``shader`` for ``kind`` once it was tried, else None."""
    return _failed.get((kind, hash(shader)))


class FrameUniforms:
    """Values every kge program reads, set once per frame (and per camera)."""

    time = 0.0
    snap = 0.0


_names: dict[int, frozenset[str]] = {}


def uniform_names(prog: Any) -> frozenset[str]:
    """The active uniforms of ``prog`` (cached: pyglet builds a dict per query)."""
    found = _names.get(prog.id)
    if found is None:
        found = _names[prog.id] = frozenset(prog.uniforms)
    return found


def apply_frame_uniforms(prog: Any) -> None:
    names = uniform_names(prog)
    if "time" in names:
        prog["time"] = FrameUniforms.time
    if "snap" in names:
        prog["snap"] = FrameUniforms.snap


def set_uniforms(prog: Any, values: dict[str, Any], textures: Any = None,
                 kinds: dict[str, str] | None = None) -> None:  # fmt: skip
    """Material ``values`` into ``prog`` (textures bound from unit 1 up); a value the
    program rejects is skipped (it was checked against the declaration already)."""
    unit = 1
    names = uniform_names(prog)
    for name, value in values.items():
        if name not in names:
            continue  # declared but unused: the compiler removed it
        if kinds is not None and kinds.get(name) == "sampler2D":
            if textures is None:
                continue
            tex = textures.texture(value, filter="linear")
            gl.glActiveTexture(gl.GL_TEXTURE0 + unit)
            gl.glBindTexture(tex.target, tex.id)
            gl.glActiveTexture(gl.GL_TEXTURE0)
            prog[name] = unit
            unit += 1
            continue
        try:
            prog[name] = value
        except Exception:  # pragma: no cover - values were validated at the call
            continue


class SpriteGroup(pyglet.sprite.SpriteGroup):
    """A sprite group that blends with :func:`set_blend` and sets the frame uniforms."""

    def set_state(self) -> None:
        self.program.use()
        apply_frame_uniforms(self.program)
        gl.glActiveTexture(gl.GL_TEXTURE0)
        gl.glBindTexture(self.texture.target, self.texture.id)
        gl.glEnable(gl.GL_BLEND)
        gl.glBlendFuncSeparate(self.blend_src, self.blend_dest, gl.GL_ONE,
                               gl.GL_ONE_MINUS_SRC_ALPHA)  # fmt: skip


class KgeSprite(pyglet.sprite.Sprite):
    """pyglet's Sprite drawn through :class:`SpriteGroup` (kge's blending and uniforms)."""

    group_class = SpriteGroup


class MaterialGroup(pyglet.graphics.Group):
    """Parent of a material's drawables: sets its uniforms (read at draw time, so a
    tween changes them without touching a vertex)."""

    def __init__(self, material: Any, prog: Any, textures: Any, parent: Any) -> None:
        super().__init__(parent=parent)
        self.material = material
        self.program = prog
        self.textures = textures

    def set_state(self) -> None:
        m = self.material
        set_uniforms(self.program, m.uniforms, self.textures, m.shader.uniforms)

    def __eq__(self, other: object) -> bool:
        return self is other

    def __hash__(self) -> int:
        return id(self)
