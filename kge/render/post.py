"""Post-processing: a camera's picture through its stack of full-screen passes.

A camera with ``post`` effects draws its scene into a texture (``PostChain.begin``);
:meth:`PostChain.finish` then runs each enabled effect as a full-screen pass,
ping-ponging between two textures, and the last pass draws into the camera's
viewport in the real target (window, design canvas or render texture). Pictures
are premultiplied throughout.

* Bloom: a bright pass at half size (pixels above the threshold, eased in over the
  softness), a separable Gaussian blur (horizontal, then vertical) of about
  ``radius`` pixels, then the source plus ``intensity`` times the blur.
* ColorGrade, Vignette and CRT: one pass each (see :mod:`kge.components.post`).
* A :class:`~kge.components.material.Material`: its shader's
  ``effect(color, tex, uv, pixel)`` over the picture so far.
"""

from __future__ import annotations

import math
from typing import Any

from pyglet import gl

from kge.components.material import Material
from kge.components.post import CRT, Bloom, ColorGrade, PostEffect, Vignette
from kge.render.glutil import FULLSCREEN_VS, clear, drawing_into, fullscreen, new_texture, program
from kge.render.programs import FrameUniforms, material_program, set_uniforms, uniform_names

_HEAD = """#version 150 core
in vec2 uv;
out vec4 frag;
uniform sampler2D src;
uniform vec2 size;       // pixels of the picture
vec3 straight(vec4 c) { return c.a > 0.0 ? c.rgb / c.a : vec3(0.0); }
"""

_GRADE = _HEAD + """
uniform float brightness;
uniform float contrast;
uniform float saturation;
uniform float gamma;
uniform vec3 tint;
void main()
{
    vec4 c = texture(src, uv);
    vec3 rgb = straight(c);
    rgb = (rgb - 0.5) * contrast + 0.5 + brightness;
    float grey = dot(rgb, vec3(0.2126, 0.7152, 0.0722));
    rgb = mix(vec3(grey), rgb, saturation) * tint;
    rgb = pow(clamp(rgb, 0.0, 1.0), vec3(1.0 / gamma));
    frag = vec4(rgb * c.a, c.a);
}
"""

_VIGNETTE = _HEAD + """
uniform float strength;
uniform float radius;
uniform float softness;
uniform vec3 color;
void main()
{
    vec4 c = texture(src, uv);
    float d = length((uv - 0.5) * 2.0);
    float v = smoothstep(radius, radius + softness, d) * strength;
    frag = vec4(mix(c.rgb, color * c.a, v), c.a);
}
"""

_CRT = _HEAD + """
uniform float scanlines;
uniform float curvature;
uniform float aberration;  // pixels
uniform float rows;        // design pixel rows across the picture
void main()
{
    vec2 cc = uv - 0.5;
    cc *= 1.0 + curvature * dot(cc, cc) * 4.0;
    vec2 p = cc + 0.5;
    if (p.x < 0.0 || p.y < 0.0 || p.x > 1.0 || p.y > 1.0) {
        frag = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    vec2 off = vec2(aberration / size.x, 0.0);
    vec4 mid = texture(src, p);
    vec3 rgb = vec3(texture(src, p + off).r, mid.g, texture(src, p - off).b);
    float line = 0.5 - 0.5 * cos(6.2831853 * p.y * rows);
    rgb *= 1.0 - scanlines * line;
    frag = vec4(rgb, mid.a);
}
"""

_BRIGHT = _HEAD + """
uniform float threshold;
uniform float knee;
void main()
{
    vec4 c = texture(src, uv);
    float l = dot(straight(c), vec3(0.2126, 0.7152, 0.0722));
    float w = smoothstep(threshold - knee, threshold + knee, l);
    frag = c * w;
}
"""

_BLUR = _HEAD + """
uniform vec2 step;       // texels between taps, along the blur's direction
void main()
{
    vec4 sum = texture(src, uv) * 0.2270270;
    sum += (texture(src, uv + step * 1.3846154) + texture(src, uv - step * 1.3846154)) * 0.3162162;
    sum += (texture(src, uv + step * 3.2307692) + texture(src, uv - step * 3.2307692)) * 0.0702703;
    frag = sum;
}
"""

_ADD = _HEAD + """
uniform sampler2D glow;
uniform float intensity;
void main()
{
    vec4 c = texture(src, uv);
    frag = vec4(c.rgb + texture(glow, uv).rgb * intensity, c.a);
}
"""

_COPY = _HEAD + """
void main() { frag = texture(src, uv); }
"""

#: wrapper of a Material used as a post pass: effect(color, tex, uv, pixel), straight RGBA
_MATERIAL_HEAD = """#version 150 core
in vec2 uv;
out vec4 kge_out;
uniform sampler2D kge_texture;
uniform float time;
uniform vec2 kge_size;
"""
_MATERIAL_MAIN = """
void main()
{
    vec4 c = texture(kge_texture, uv);
    vec4 o = effect(vec4(c.a > 0.0 ? c.rgb / c.a : vec3(0.0), c.a), kge_texture, uv, uv * kge_size);
    kge_out = vec4(o.rgb * o.a, o.a);
}
"""


def _prog(name: str, fs: str) -> Any:
    return program(f"kge-post-{name}", FULLSCREEN_VS, fs)


class PostChain:
    """The textures and passes of one camera's post-processing stack."""

    def __init__(self) -> None:
        self.size = (0, 0)
        self.textures: list[Any] = []
        self.half: list[Any] = []

    def _fit(self, size: tuple[int, int]) -> None:
        if size == self.size:
            return
        self.close()
        w, h = size
        self.textures = [new_texture(w, h), new_texture(w, h)]
        hw, hh = max(1, w // 2), max(1, h // 2)
        self.half = [new_texture(hw, hh), new_texture(hw, hh)]
        self.size = size

    def begin(self, size: tuple[int, int]) -> Any:
        """The texture the camera draws its scene into (``size`` pixels)."""
        self._fit((max(1, int(size[0])), max(1, int(size[1]))))
        return self.textures[0]

    def finish(self, effects: tuple[Any, ...], rect: tuple[int, int, int, int], rows: float,
               textures: Any) -> None:  # fmt: skip
        """Run ``effects`` over the drawn scene; the last one lands in ``rect`` of the
        framebuffer that was bound before (rows: design pixel rows, for scanlines)."""
        active = [e for e in effects if not isinstance(e, PostEffect) or e.enabled]
        src = 0
        for i, effect in enumerate(active):
            last = i == len(active) - 1
            if isinstance(effect, Bloom):
                self._bloom(effect, self.textures[src])
            if last:
                self._to_target(effect, self.textures[src], rect, rows, textures)
            else:
                dst = 1 - src
                with drawing_into(self.textures[dst]):
                    clear()
                    self._pass(effect, self.textures[src], rows, textures)
                src = dst
        if not active:
            self._to_target(None, self.textures[src], rect, rows, textures)

    def _to_target(self, effect: Any, src: Any, rect: tuple[int, int, int, int], rows: float,
                   textures: Any) -> None:  # fmt: skip
        gl.glViewport(*rect)
        gl.glEnable(gl.GL_SCISSOR_TEST)
        gl.glScissor(*rect)
        self._pass(effect, src, rows, textures, over=True)
        gl.glDisable(gl.GL_SCISSOR_TEST)

    def _pass(self, effect: Any, src: Any, rows: float, textures: Any,
              over: bool = False) -> None:  # fmt: skip
        """One full-screen pass of ``effect`` (None: a copy) reading ``src``."""
        if over:  # into the target: premultiplied "over" what the target holds
            gl.glEnable(gl.GL_BLEND)
            gl.glBlendFunc(gl.GL_ONE, gl.GL_ONE_MINUS_SRC_ALPHA)
        else:
            gl.glDisable(gl.GL_BLEND)
        prog = self._program(effect)
        prog.use()
        size = (float(self.size[0]), float(self.size[1]))
        names = uniform_names(prog)
        if "size" in names:
            prog["size"] = size
        if isinstance(effect, ColorGrade):
            prog["brightness"], prog["contrast"] = effect.brightness, effect.contrast
            prog["saturation"], prog["gamma"] = effect.saturation, effect.gamma
            prog["tint"] = tuple(c / 255.0 for c in effect.tint)
        elif isinstance(effect, Vignette):
            prog["strength"], prog["radius"] = effect.strength, effect.radius
            prog["softness"] = effect.softness
            prog["color"] = tuple(c / 255.0 for c in effect.color)
        elif isinstance(effect, CRT):
            prog["scanlines"], prog["curvature"] = effect.scanlines, effect.curvature
            prog["aberration"], prog["rows"] = effect.aberration, float(rows)
        elif isinstance(effect, Bloom):
            prog["intensity"] = effect.intensity
            prog["glow"] = 1
            gl.glActiveTexture(gl.GL_TEXTURE1)
            gl.glBindTexture(self.half[0].target, self.half[0].id)
        elif isinstance(effect, Material):
            if "time" in names:
                prog["time"] = FrameUniforms.time
            if "kge_size" in names:
                prog["kge_size"] = size
            set_uniforms(prog, effect.uniforms, textures, effect.shader.uniforms)
        gl.glActiveTexture(gl.GL_TEXTURE0)
        gl.glBindTexture(src.target, src.id)
        fullscreen(prog)
        prog.stop()
        gl.glDisable(gl.GL_BLEND)

    @staticmethod
    def _program(effect: Any) -> Any:
        if isinstance(effect, ColorGrade):
            return _prog("grade", _GRADE)
        if isinstance(effect, Vignette):
            return _prog("vignette", _VIGNETTE)
        if isinstance(effect, CRT):
            return _prog("crt", _CRT)
        if isinstance(effect, Bloom):
            return _prog("bloom-add", _ADD)
        if isinstance(effect, Material):
            prog = material_program(effect.shader, "post", vertex=FULLSCREEN_VS,
                                    head=_MATERIAL_HEAD, main=_MATERIAL_MAIN)  # fmt: skip
            if prog is not None:
                return prog
        return _prog("copy", _COPY)

    def _bloom(self, bloom: Bloom, src: Any) -> None:
        """Bright pass and blur into ``self.half[0]`` (half size)."""
        a, b = self.half
        bright = _prog("bloom-bright", _BRIGHT)
        with drawing_into(a):
            gl.glDisable(gl.GL_BLEND)
            bright.use()
            bright["threshold"] = bloom.threshold
            bright["knee"] = max(bloom.softness * 0.5 * max(bloom.threshold, 0.05), 1e-3)
            gl.glActiveTexture(gl.GL_TEXTURE0)
            gl.glBindTexture(src.target, src.id)
            fullscreen(bright)
        blur = _prog("bloom-blur", _BLUR)
        # the 5-tap kernel spans about 3.2 taps each side: spread so it reaches ``radius``
        spread = max(bloom.radius / 2.0 / 3.2, 0.5)
        passes = max(1, math.ceil(spread / 2.0))  # wide blurs: repeat instead of gaps
        step = spread / passes
        for _ in range(passes):
            for direction, (s, d) in (((1.0, 0.0), (a, b)), ((0.0, 1.0), (b, a))):
                with drawing_into(d):
                    blur.use()
                    blur["step"] = (direction[0] * step / a.width, direction[1] * step / a.height)
                    gl.glBindTexture(s.target, s.id)
                    fullscreen(blur)
        blur.stop()

    def close(self) -> None:
        for tex in (*self.textures, *self.half):
            tex.delete()
        self.textures, self.half = [], []
        self.size = (0, 0)
