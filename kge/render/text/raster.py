"""Draw a laid-out text into a texture of its own, with outline and drop shadow.

A label is rasterised once per change (text, style, or the on-screen scale of world
text) and drawn afterwards as one textured quad, like a sprite: moving, turning or
fading it costs nothing more. The texture holds *premultiplied* colour, so the
outline, shadow and glyph edges blend without dark fringes.

1. every glyph is a quad at whole pixels (crisp), textured from pyglet's glyph atlas
   of its face at the raster size (bitmap fonts from their sheet, inline images from
   theirs), drawn into the label's texture in premultiplied colour;
2. ``outline``: a pass takes, for each pixel, the highest glyph coverage within the
   outline's radius (16 directions, a ring per pixel of radius), and puts the
   outline colour under the text;
3. ``shadow``: a pass puts the text's (outlined) coverage, shifted by the offset and
   blurred by ``shadow_blur`` (a 7 x 7 Gaussian), under it in the shadow colour.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from pyglet import gl

from kge.components.text import TextStyle
from kge.render.glutil import (
    FULLSCREEN_VS,
    Stream,
    clear,
    drawing_into,
    fullscreen,
    new_texture,
    per_context,
    program,
)
from kge.render.text.fonts import FreeTypeFace, WorldFaces
from kge.text.bitmap import BitmapFace
from kge.text.layout import TextLayout

#: the largest side of a label's texture, pixels (bigger text is drawn scaled up)
MAX_TEXTURE = 4096

_GLYPH_VS = """#version 150 core
in vec2 position;
in vec2 tex;
in vec4 color;
out vec2 v_tex;
out vec4 v_color;
uniform vec2 target;
void main()
{
    gl_Position = vec4(position / target * 2.0 - 1.0, 0.0, 1.0);
    v_tex = tex;
    v_color = color;
}
"""

_GLYPH_FS = """#version 150 core
in vec2 v_tex;
in vec4 v_color;
out vec4 frag;
uniform sampler2D glyphs;
void main()
{
    vec4 t = texture(glyphs, v_tex);
    float a = t.a * v_color.a;
    frag = vec4(t.rgb * v_color.rgb * a, a);
}
"""

_EFFECT_FS = """#version 150 core
in vec2 uv;
out vec4 frag;
uniform sampler2D src;
uniform vec2 texel;      // 1 / size of the source texture
uniform vec2 extent;     // pixels of the source in use
uniform int mode;        // 0: outline, 1: shadow
uniform float radius;    // outline radius, pixels
uniform vec4 color;      // straight alpha
uniform vec2 offset;     // shadow offset, pixels
uniform float blur;      // shadow blur radius, pixels
const float TAU = 6.2831853;

float cover(vec2 p)
{
    if (p.x < 0.0 || p.y < 0.0 || p.x > extent.x || p.y > extent.y) return 0.0;
    return texture(src, p * texel).a;
}

void main()
{
    vec2 p = uv * extent;
    vec4 here = texture(src, p * texel);
    float a = 0.0;
    if (mode == 0) {
        a = here.a;
        int rings = int(ceil(radius));
        for (int r = 1; r <= rings; r++) {
            float d = radius * float(r) / float(rings);
            for (int k = 0; k < 16; k++) {
                float t = TAU * (float(k) + 0.5 * float(r)) / 16.0;
                a = max(a, cover(p + d * vec2(cos(t), sin(t))));
            }
        }
    } else {
        vec2 q = p - offset;
        if (blur <= 0.0) {
            a = cover(q);
        } else {
            float total = 0.0;
            for (int i = -3; i <= 3; i++) {
                for (int j = -3; j <= 3; j++) {
                    vec2 d = vec2(float(i), float(j)) / 3.0;
                    float w = exp(-2.0 * dot(d, d));
                    a += cover(q + d * blur) * w;
                    total += w;
                }
            }
            a /= total;
        }
    }
    float under = color.a * a;
    frag = here + vec4(color.rgb * under, under) * (1.0 - here.a);
}
"""

_FLOATS = 8  # position 2, tex 2, color 4


@dataclass(slots=True)
class Baked:
    """A label's texture and where its box sits in it."""

    texture: Any
    width: int  #: pixels of the texture in use
    height: int
    scale: float  #: texture pixels per text pixel
    origin: tuple[float, float]  #: texture pixel of the box's bottom-left corner
    box: tuple[float, float]  #: the box, text pixels

    def delete(self) -> None:
        if self.texture is not None:
            self.texture.delete()
            self.texture = None


def raster_scale(layout: TextLayout, style: TextStyle, wanted: float) -> float:
    """``wanted`` pixels per text pixel, lowered so the texture stays within bounds."""
    pad = style.padding
    reach = max(layout.width, layout.content_width, 1.0) + 2 * pad, max(
        layout.height, layout.content_height, 1.0) + 2 * pad  # fmt: skip
    s = min(wanted, (MAX_TEXTURE - 4) / reach[0], (MAX_TEXTURE - 4) / reach[1])
    return max(s, 1e-3)


class TextRaster:
    """Bakes laid-out text into textures (see the module docstring); one per world."""

    def __init__(self, faces: WorldFaces) -> None:
        self.faces = faces
        self._scratch: Any = None

    def _programs(self) -> tuple[Any, Any, Stream]:
        glyph = program("kge-text-glyph", _GLYPH_VS, _GLYPH_FS)
        effect = program("kge-text-effect", FULLSCREEN_VS, _EFFECT_FS)
        stream = per_context("kge-text-stream", lambda: Stream(glyph, [
            ("position", 2), ("tex", 2), ("color", 4)]))  # fmt: skip
        return glyph, effect, stream

    def quads(self, layout: TextLayout, scale: float, origin: tuple[float, float]
              ) -> list[tuple[Any, np.ndarray]]:  # fmt: skip
        """(texture, (n * 6, 8) vertices) per texture of the glyphs, in texture pixels."""
        groups: dict[int, tuple[Any, list[list[float]]]] = {}
        ox, oy = origin
        for g in layout.glyphs:
            pen = math.floor((g.x * scale) + ox + 0.5)
            base = math.floor((g.baseline * scale) + oy + 0.5)
            color = [c / 255.0 for c in g.color]
            if g.icon is not None:
                name, w, h = g.icon
                tex = self.faces.icon(name)
                x0, y0 = pen, math.floor(g.bottom * scale + oy + 0.5)
                quad: tuple[float, float, float, float] = (x0, y0, x0 + w * scale, y0 + h * scale)
                _add(groups, tex, quad, _uv_of(tex), [1.0, 1.0, 1.0, color[3]])
                continue
            face = g.face
            if isinstance(face, BitmapFace):
                sheet = self.faces.bitmap_texture(face.font)
                cell = face.font.cell
                k = g.size * scale / cell[1]
                x, y, w, h = face.font.cell_rect(g.char, sheet.width, sheet.height)
                bottom = base - face.font.baseline * k
                quad = (pen, bottom, pen + w * k, bottom + h * k)
                tw, th = sheet.width, sheet.height
                tc = _uv_of(sheet)
                su, sv = (tc[2] - tc[0]) / tw, (tc[3] - tc[1]) / th
                uv = (tc[0] + x * su, tc[1] + y * sv, tc[0] + (x + w) * su, tc[1] + (y + h) * sv)
                _add(groups, sheet, quad, uv, color)
                continue
            if not isinstance(face, FreeTypeFace):
                continue
            font, k = face.raster_font(g.size * scale)
            glyph = font.glyphs.get(g.char)
            if glyph is None:
                glyph = font.get_glyphs(g.char)[0][0]
            v = glyph.vertices
            quad = (pen + v[0] * k, base + v[1] * k, pen + v[2] * k, base + v[3] * k)
            t = glyph.tex_coords
            _add(groups, glyph.owner, quad, (t[0], t[1], t[6], t[7]), color)
        return [(tex, np.asarray(rows, np.float32).reshape(-1, _FLOATS))
                for tex, rows in groups.values()]  # fmt: skip

    def bake(self, layout: TextLayout, style: TextStyle, wanted: float,
             reuse: Baked | None = None) -> Baked:  # fmt: skip
        """Rasterise ``layout`` at ``wanted`` texture pixels per text pixel."""
        scale = raster_scale(layout, style, wanted)
        pad = style.padding * scale
        # what may be drawn: the box, and (overflow "visible") lines outside it
        x0, y0, x1, y1 = 0.0, 0.0, layout.width, layout.height
        if style.overflow == "visible":
            for ln in layout.lines:
                x0, x1 = min(x0, ln.x), max(x1, ln.x + ln.width)
                y0, y1 = min(y0, ln.y), max(y1, ln.y + ln.height)
        origin = (math.ceil(pad - x0 * scale), math.ceil(pad - y0 * scale))
        w = max(1, math.ceil((x1 - x0) * scale + 2 * pad))
        h = max(1, math.ceil((y1 - y0) * scale + 2 * pad))
        baked = self._target(reuse, w, h)
        baked.scale, baked.origin, baked.box = scale, origin, (layout.width, layout.height)
        glyph_prog, effect_prog, stream = self._programs()
        groups = self.quads(layout, scale, origin)
        effects = [(0, style.outline * scale)] if style.outline > 0 else []
        if style.shadow is not None:
            effects.append((1, 0.0))
        first = baked.texture if len(effects) != 1 else self._scratch_for(w, h)
        clip = None
        if style.overflow != "visible":
            clip = (origin[0], origin[1], math.ceil(layout.width * scale) + 1,
                    math.ceil(layout.height * scale) + 1)  # fmt: skip
        with drawing_into(first, w, h):
            clear()
            if groups:
                self._draw_glyphs(glyph_prog, stream, groups, (w, h), clip)
        src = first
        for i, (mode, radius) in enumerate(effects):
            last = i == len(effects) - 1
            dst = baked.texture if last else self._scratch_for(w, h)
            if dst is src:  # two effects: ping-pong through the scratch texture
                dst = self._scratch_for(w, h)
            with drawing_into(dst, w, h):
                clear()
                self._effect(effect_prog, src, (w, h), mode, radius, style, scale)
            src = dst
        if src is not baked.texture:  # pragma: no cover - effect chains end in the label
            raise AssertionError("text effects ended outside the label texture")
        return baked

    def _target(self, reuse: Baked | None, w: int, h: int) -> Baked:
        if reuse is not None and reuse.texture is not None:
            tex = reuse.texture
            if w <= tex.width and h <= tex.height and w * h * 3 >= tex.width * tex.height:
                reuse.width, reuse.height = w, h
                return reuse
            reuse.delete()
        tw, th = _rounded(w), _rounded(h)
        return Baked(new_texture(tw, th), w, h, 1.0, (0.0, 0.0), (0.0, 0.0))

    def _scratch_for(self, w: int, h: int) -> Any:
        s = self._scratch
        if s is None or s.width < w or s.height < h:
            if s is not None:
                s.delete()
            s = self._scratch = new_texture(_rounded(max(w, s.width if s else 0)),
                                            _rounded(max(h, s.height if s else 0)))  # fmt: skip
        return s

    @staticmethod
    def _draw_glyphs(
        prog: Any, stream: Stream, groups: list[tuple[Any, np.ndarray]],
        size: tuple[int, int], clip: tuple[int, int, int, int] | None,
    ) -> None:  # fmt: skip
        data = np.concatenate([rows for _, rows in groups])
        stream.upload(data)
        prog.use()
        prog["target"] = (float(size[0]), float(size[1]))
        gl.glEnable(gl.GL_BLEND)
        gl.glBlendFunc(gl.GL_ONE, gl.GL_ONE_MINUS_SRC_ALPHA)
        if clip is not None:
            gl.glEnable(gl.GL_SCISSOR_TEST)
            gl.glScissor(*clip)
        gl.glActiveTexture(gl.GL_TEXTURE0)
        first = 0
        for tex, rows in groups:
            gl.glBindTexture(tex.target, tex.id)
            stream.draw(first, len(rows))
            first += len(rows)
        gl.glDisable(gl.GL_SCISSOR_TEST)
        prog.stop()

    @staticmethod
    def _effect(prog: Any, src: Any, size: tuple[int, int], mode: int, radius: float,
                style: TextStyle, scale: float) -> None:  # fmt: skip
        prog.use()
        prog["texel"] = (1.0 / src.width, 1.0 / src.height)
        prog["extent"] = (float(size[0]), float(size[1]))
        prog["mode"] = mode
        color = style.outline_color if mode == 0 else style.shadow_color
        prog["color"] = tuple(c / 255.0 for c in color)
        prog["radius"] = float(radius)
        dx, dy = style.shadow if style.shadow is not None else (0.0, 0.0)
        prog["offset"] = (dx * scale, dy * scale)
        prog["blur"] = float(style.shadow_blur * scale)
        gl.glDisable(gl.GL_BLEND)
        gl.glActiveTexture(gl.GL_TEXTURE0)
        gl.glBindTexture(src.target, src.id)
        fullscreen(prog)
        prog.stop()

    def close(self) -> None:
        if self._scratch is not None:
            self._scratch.delete()
            self._scratch = None


def _rounded(n: int) -> int:
    """Texture sides in steps of 32 pixels, so a label growing by a digit keeps its texture."""
    return max(32, (int(n) + 31) // 32 * 32)


def _uv_of(tex: Any) -> tuple[float, float, float, float]:
    """(u0, v0, u1, v1) of a texture or texture region."""
    t = tex.tex_coords
    return (t[0], t[1], t[6], t[7])


def _add(groups: dict[int, tuple[Any, list[list[float]]]], tex: Any,
         quad: tuple[float, float, float, float], uv: tuple[float, float, float, float],
         color: list[float]) -> None:  # fmt: skip
    x0, y0, x1, y1 = quad
    u0, v0, u1, v1 = uv
    owner = getattr(tex, "owner", None) or tex
    entry = groups.get(owner.id)
    if entry is None:
        entry = groups[owner.id] = (owner, [])
    rows = entry[1]
    for x, y, u, v in ((x0, y0, u0, v0), (x1, y0, u1, v0), (x1, y1, u1, v1),
                       (x0, y0, u0, v0), (x1, y1, u1, v1), (x0, y1, u0, v1)):
        rows.append([x, y, u, v, *color])
