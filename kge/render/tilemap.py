"""Drawing Tiled maps: one vertex list per visible 32x32 chunk and texture.

The pass (registered by :class:`kge.systems.tilemap.TilemapPlugin`) runs before
the batch is drawn. For each tile layer it works out which chunks the camera
sees (through the layer's parallax factor), builds the vertex lists of chunks
coming into view from the map's numpy grids (positions in metres, texture
coordinates with Tiled's flips), and deletes those that left it: the batch
only ever holds the chunks on screen, so a frame costs the same on a 30x20
map and on a 1,000x1,000 one. Layer opacity, tint, offset and parallax are
uniforms of the layer's group, set per frame, never per tile. Animated tiles
rebuild their chunk when the frame they show changes: ``TileMap.shown``, which
the TilemapPlugin's clock advances with kge.animation's numpy clips on game
time (so they pause, slow down and single-step with the game).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import pyglet
from pyglet import gl

from kge.components.material import Material
from kge.render.groups import WORLD
from kge.render.passes import Frame
from kge.render.programs import FS_HEAD, apply_frame_uniforms, material_program, set_uniforms
from kge.render.textures import TextureCache
from kge.tilemap.model import FLIP_D, FLIP_H, FLIP_V, LayerStyle, MapData, TileLayerData
from kge.tilemap.runtime import CHUNK, TileMap, TileMaps

_VERTEX = """#version 330 core
in vec2 position;
in vec2 tex_coords;
in vec4 uv_rect;
out vec2 uv;
flat out vec4 rect;
uniform WindowBlock { mat4 projection; mat4 view; } window;
uniform vec2 shift;
void main() {
    uv = tex_coords;
    rect = uv_rect;
    gl_Position = window.projection * window.view * vec4(position + shift, 0.0, 1.0);
}
"""
_FRAGMENT = """#version 330 core
in vec2 uv;
flat in vec4 rect;
out vec4 color;
uniform sampler2D tile_texture;
uniform vec4 tint;
void main() {
    // stay half a texel inside the tile's own image: a fragment on a tile's edge,
    // wherever the camera sits, never samples the next tile of the sheet
    vec2 inset = 0.5 / vec2(textureSize(tile_texture, 0));
    vec2 lo = min(rect.xy, rect.zw) + inset;
    vec2 hi = max(rect.xy, rect.zw) - inset;
    color = texture(tile_texture, clamp(uv, lo, max(lo, hi))) * tint;
}
"""
# a tile layer drawn with a Material: the user's ``effect`` gets the layer's tint as its
# colour and the clamped texture coordinate (see :mod:`kge.components.material`)
_MATERIAL_VERTEX = """#version 150 core
in vec2 position;
in vec2 tex_coords;
in vec4 uv_rect;
out vec4 v_color;
out vec2 v_uv;
out vec2 v_world;
flat out vec4 v_rect;
uniform WindowBlock { mat4 projection; mat4 view; } window;
uniform vec2 shift;
uniform vec4 tint;
void main() {
    v_world = position + shift;
    v_uv = tex_coords;
    v_rect = uv_rect;
    v_color = tint;
    gl_Position = window.projection * window.view * vec4(v_world, 0.0, 1.0);
}
"""
_MATERIAL_HEAD = FS_HEAD + "flat in vec4 v_rect;\n"
_MATERIAL_MAIN = """
void main() {
    vec2 inset = 0.5 / vec2(textureSize(kge_texture, 0));
    vec2 lo = min(v_rect.xy, v_rect.zw) + inset;
    vec2 hi = max(v_rect.xy, v_rect.zw) - inset;
    kge_out = effect(v_color, kge_texture, clamp(v_uv, lo, max(lo, hi)), v_world);
}
"""
_program_cache: list[Any] = []


def layer_program(material: Material | None) -> Any:
    """The program a tile layer is drawn with: its material's, else kge's (also when the
    material's shader does not compile: a ShaderWarning says why, once)."""
    if material is not None:
        prog = material_program(material.shader, "tile", _MATERIAL_VERTEX, _MATERIAL_HEAD,
                                _MATERIAL_MAIN)  # fmt: skip
        if prog is not None:
            return prog
    return tile_program()


def tile_program() -> Any:
    if not _program_cache:
        _program_cache.append(
            pyglet.graphics.shader.ShaderProgram(
                pyglet.graphics.shader.Shader(_VERTEX, "vertex"),
                pyglet.graphics.shader.Shader(_FRAGMENT, "fragment"),
            )
        )
    return _program_cache[0]


class LayerGroup(pyglet.graphics.Group):
    """One layer's texture, tint and shift (offset + parallax), read at draw time."""

    def __init__(self, program: Any, texture: Any, parent: Any,
                 material: Material | None = None, textures: Any = None) -> None:  # fmt: skip
        super().__init__(parent=parent)
        self.program = program
        self.texture = texture
        self.shift = (0.0, 0.0)
        self.tint = (1.0, 1.0, 1.0, 1.0)
        self.material = material if program is not tile_program() else None
        self.textures = textures

    def set_state(self) -> None:
        self.program.use()
        self.program["shift"] = self.shift
        self.program["tint"] = self.tint
        m = self.material
        if m is not None:  # read now: a tween changes them without touching a vertex
            apply_frame_uniforms(self.program)
            set_uniforms(self.program, m.uniforms, self.textures, m.shader.uniforms)
        gl.glActiveTexture(gl.GL_TEXTURE0)
        gl.glBindTexture(self.texture.target, self.texture.id)
        gl.glEnable(gl.GL_BLEND)
        gl.glBlendFunc(gl.GL_SRC_ALPHA, gl.GL_ONE_MINUS_SRC_ALPHA)

    def unset_state(self) -> None:
        gl.glDisable(gl.GL_BLEND)
        self.program.stop()

    def __eq__(self, other: object) -> bool:  # never merged with another layer's group
        return self is other

    def __hash__(self) -> int:
        return id(self)


# screen corners of a quad (x right, y down in the tile): BL, BR, TR, TL
_SX = np.array([0.0, 1.0, 1.0, 0.0])
_SY = np.array([1.0, 1.0, 0.0, 0.0])


def tile_uvs(
    data: MapData,
    gids: np.ndarray,
    flags: np.ndarray,
    bounds: list[tuple[float, float, float, float]],
) -> np.ndarray:
    """(n, 4, 2) texture coordinates of n tiles (corners BL, BR, TR, TL), flips applied.

    ``bounds[i]`` is image i's (u0, v0, u1, v1) inside its texture. Tiled flips
    the image diagonally, then horizontally, then vertically; a corner on
    screen samples the image point found by undoing them in reverse order.
    """
    t = data.tiles
    img = t.image[gids]
    iw = np.array([s[0] for s in t.image_sizes], float)[img]
    ih = np.array([s[1] for s in t.image_sizes], float)[img]
    b = np.array(bounds, float)[img]
    x, y, w, h = (t.rect[gids, i].astype(float) for i in range(4))
    sx = np.broadcast_to(_SX, (len(gids), 4)).copy()
    sy = np.broadcast_to(_SY, (len(gids), 4)).copy()
    fv = (flags & FLIP_V) != 0
    fh = (flags & FLIP_H) != 0
    fd = (flags & FLIP_D) != 0
    sy[fv] = 1.0 - sy[fv]
    sx[fh] = 1.0 - sx[fh]
    sx[fd], sy[fd] = sy[fd].copy(), sx[fd].copy()
    # image fraction (u right, v up from the image's bottom)
    u = (x[:, None] + sx * w[:, None]) / iw[:, None]
    v = 1.0 - (y[:, None] + sy * h[:, None]) / ih[:, None]
    out = np.empty((len(gids), 4, 2), np.float32)
    out[..., 0] = b[:, 0, None] + u * (b[:, 2, None] - b[:, 0, None])
    out[..., 1] = b[:, 1, None] + v * (b[:, 3, None] - b[:, 1, None])
    return out


def uv_rects(uvs: np.ndarray) -> np.ndarray:
    """(n, 4, 4) per-corner (u0, v0, u1, v1) of each tile's image, from (n, 4, 2) uvs.

    The fragment shader clamps sampling inside it (no bleeding from neighbours).
    """
    rect = np.concatenate([uvs.min(axis=1), uvs.max(axis=1)], axis=-1)
    return np.repeat(rect[:, None, :], 4, axis=1).astype(np.float32)


def tile_quads(data: MapData, rows: np.ndarray, cols: np.ndarray, gids: np.ndarray) -> np.ndarray:
    """(n, 4, 2) world positions of tiles at grid (rows, cols): BL, BR, TR, TL.

    A tile image sits on its cell's bottom-left corner (taller tiles reach up),
    moved by its tileset's tile offset, as Tiled draws it.
    """
    u = data.units
    t = data.tiles
    w, h = t.rect[gids, 2].astype(float), t.rect[gids, 3].astype(float)
    ox, oy = t.offset[gids, 0].astype(float), t.offset[gids, 1].astype(float)
    left = u.left_px + cols * u.tile_w + ox
    bottom = (u.row0 + rows + 1) * u.tile_h + oy
    px = left[:, None] + _SX * w[:, None]
    py = bottom[:, None] - (1.0 - _SY) * h[:, None]
    x, y = u.points(px, py)
    return np.stack([x, y], axis=-1).astype(np.float32)


@dataclass(slots=True)
class _Chunk:
    lists: list[Any] = field(default_factory=list)
    anim_key: tuple[int, ...] = ()


class MapDrawing:
    """The drawing state of one map: textures, groups and live chunks."""

    def __init__(self, tmap: TileMap, textures: TextureCache) -> None:
        self.map = tmap
        self.textures = textures
        self.program = tile_program()
        data = tmap.data
        self.tex = [textures.texture(str(p)) for p in data.tiles.images]
        self.bounds = [_tex_bounds(t) for t in self.tex]
        self.groups: dict[tuple[int, int], LayerGroup] = {}
        self.chunks: dict[tuple[int, int, int], _Chunk] = {}
        self.images: dict[int, Any] = {}  # image layer position -> (vertex list, group)
        self.animated = np.zeros(max(data.tiles.size, 1), bool)
        self.materials: dict[int, Material | None] = {}  #: tile layer position -> drawn with
        self._shaders: dict[int, int | None] = {}
        for g in data.tiles.animations:
            self.animated[g] = True

    def group(
        self, frame: Frame, li: int, image: int, texture: Any, draw_layer: int, order: int
    ) -> LayerGroup:
        g = self.groups.get((li, image))
        if g is None:
            parent = frame.groups.get(draw_layer, WORLD, order)
            material = self.materials.get(li)
            g = self.groups[(li, image)] = LayerGroup(layer_program(material), texture, parent,
                                                      material, self.textures)  # fmt: skip
        return g

    def _materials_changed(self) -> None:
        """A layer whose Material was set, replaced or removed is drawn again from scratch
        (its vertex lists belong to the program they were made for)."""
        data = self.map.data
        for li, layer in enumerate(data.tile_layers):
            m = self.map.materials.get(layer.name)
            was = self.materials.get(li)
            if m is was and (m is None or self._shaders.get(li) == hash(m.shader)):
                continue
            self.materials[li] = m
            self._shaders[li] = hash(m.shader) if m is not None else None
            for key in [k for k in self.chunks if k[0] == li]:
                self._drop(key)
            for gkey in [k for k in self.groups if k[0] == li]:
                del self.groups[gkey]

    def draw(self, frame: Frame) -> None:
        tmap = self.map
        data = tmap.data
        for key in list(tmap.dirty):
            tmap.dirty.discard(key)
            self._drop(key)
        self._materials_changed()
        wanted: set[tuple[int, int, int]] = set()
        for li, layer in enumerate(data.tile_layers):
            style = layer.style
            if not style.visible or style.opacity <= 0:
                continue
            shift = _shift(frame, data, style)
            tint = _tint(style)
            draw_layer, order = self._placement(layer.properties, layer.index)
            for key in self._visible(frame, li, shift):
                wanted.add(key)
                chunk = self.chunks.get(key)
                anim = self._anim_key(layer, key)
                if chunk is None or chunk.anim_key != anim:
                    self._drop(key)
                    self.chunks[key] = self._build(frame, li, layer, key, anim, draw_layer, order)
            for (gl_li, _), g in self.groups.items():
                if gl_li == li:
                    g.shift, g.tint = shift, tint
        for key in [k for k in self.chunks if k not in wanted]:
            self._drop(key)
        self._image_layers(frame)

    def _placement(self, props: dict[str, Any], index: int) -> tuple[int, int]:
        layer = props.get("layer", self.map.draw_layer)
        return int(layer), index - 1000

    def _visible(
        self, frame: Frame, li: int, shift: tuple[float, float]
    ) -> list[tuple[int, int, int]]:
        data = self.map.data
        u = data.units
        tw, th = u.tile_size
        left, bottom, right, top = frame.view
        # the layer is drawn moved by ``shift``: look at the view moved back
        c0 = math.floor((left - shift[0] - u.origin[0]) / tw) - 1
        c1 = math.floor((right - shift[0] - u.origin[0]) / tw) + 1
        r0 = data.rows - 1 - math.floor((top - shift[1] - u.origin[1]) / th) - 1
        r1 = data.rows - 1 - math.floor((bottom - shift[1] - u.origin[1]) / th) + 1
        cc0, cc1 = max(c0, 0) // CHUNK, min(c1, data.cols - 1) // CHUNK
        cr0, cr1 = max(r0, 0) // CHUNK, min(r1, data.rows - 1) // CHUNK
        if c1 < 0 or r1 < 0 or c0 >= data.cols or r0 >= data.rows:
            return []
        return [(li, cr, cc) for cr in range(cr0, cr1 + 1) for cc in range(cc0, cc1 + 1)]

    def _anim_key(self, layer: TileLayerData, key: tuple[int, int, int]) -> tuple[int, ...]:
        """The frames the chunk's animated tiles show now: a change rebuilds the chunk."""
        if not len(self.map.data.tiles.animations):
            return ()
        _, cr, cc = key
        sub = layer.gids[cr * CHUNK : (cr + 1) * CHUNK, cc * CHUNK : (cc + 1) * CHUNK]
        found = np.unique(sub[self.animated[sub]])
        return tuple(self.map.shown[found].tolist())

    def _build(
        self,
        frame: Frame,
        li: int,
        layer: TileLayerData,
        key: tuple[int, int, int],
        anim: tuple[int, ...],
        draw_layer: int,
        order: int,
    ) -> _Chunk:
        data = self.map.data
        _, cr, cc = key
        r0, c0 = cr * CHUNK, cc * CHUNK
        sub = layer.gids[r0 : r0 + CHUNK, c0 : c0 + CHUNK]
        rr, cols = np.nonzero(sub)
        chunk = _Chunk(anim_key=anim)
        if not len(rr):
            return chunk
        gids = sub[rr, cols].astype(np.int64)
        flags = layer.flags[r0 : r0 + CHUNK, c0 : c0 + CHUNK][rr, cols]
        shown = self.map.shown[gids] if anim else gids
        quads = tile_quads(data, rr + r0, cols + c0, gids)
        uvs = tile_uvs(data, shown, flags, self.bounds)
        images = data.tiles.image[shown]
        for image in np.unique(images).tolist():
            sel = images == image
            n = int(sel.sum())
            base = (np.arange(n) * 4)[:, None]
            idx = (base + np.array([0, 1, 2, 0, 2, 3])).ravel()
            g = self.group(frame, li, image, self.tex[image], draw_layer, order)
            vl = g.program.vertex_list_indexed(
                n * 4,
                gl.GL_TRIANGLES,
                idx.tolist(),
                batch=frame.batch,
                group=g,
                position=("f", quads[sel].ravel()),
                tex_coords=("f", uvs[sel].ravel()),
                uv_rect=("f", uv_rects(uvs[sel]).ravel()),
            )
            chunk.lists.append(vl)
        return chunk

    def _drop(self, key: tuple[int, int, int]) -> None:
        chunk = self.chunks.pop(key, None)
        if chunk is not None:
            for vl in chunk.lists:
                vl.delete()

    def _image_layers(self, frame: Frame) -> None:
        data = self.map.data
        for i, layer in enumerate(data.image_layers):
            if not layer.style.visible:
                continue
            entry = self.images.get(i)
            if entry is None:
                tex = self.textures.texture(str(layer.image))
                draw_layer, order = self._placement(layer.properties, layer.index)
                g = LayerGroup(self.program, tex, frame.groups.get(draw_layer, WORLD, order))
                u = data.units
                x0, y1 = u.point(u.left_px, u.row0 * u.tile_h)
                x1, y0 = u.point(u.left_px + tex.width, u.row0 * u.tile_h + tex.height)
                pos = np.array([x0, y0, x1, y0, x1, y1, x0, y1], np.float32)
                b = _tex_bounds(tex)
                uv = np.array([b[0], b[1], b[2], b[1], b[2], b[3], b[0], b[3]], np.float32)
                vl = self.program.vertex_list_indexed(
                    4,
                    gl.GL_TRIANGLES,
                    [0, 1, 2, 0, 2, 3],
                    batch=frame.batch,
                    group=g,
                    position=("f", pos),
                    tex_coords=("f", uv),
                    uv_rect=("f", np.tile(np.array(b, np.float32), 4)),
                )
                entry = self.images[i] = (vl, g)
            entry[1].shift = _shift(frame, data, layer.style)
            entry[1].tint = _tint(layer.style)

    def delete(self) -> None:
        for key in list(self.chunks):
            self._drop(key)
        for vl, _ in self.images.values():
            vl.delete()
        self.images.clear()


def _tex_bounds(tex: Any) -> tuple[float, float, float, float]:
    tc = tex.tex_coords
    return (float(tc[0]), float(tc[1]), float(tc[6]), float(tc[7]))


def _shift(frame: Frame, data: MapData, style: LayerStyle) -> tuple[float, float]:
    """Where a layer is drawn relative to its map position: its offset plus parallax.

    A parallax factor p moves the layer with the camera by (1 - p) of the camera's
    travel from the map's parallax origin (Tiled's, by default the map's top-left
    corner), so p = 0 stays on screen and p = 1 is the map.
    """
    ox, oy = data.units.vector(*style.offset)
    px, py = style.parallax
    cx, cy = frame.center
    o = data.parallax_origin
    return (ox + (cx - o[0]) * (1.0 - px), oy + (cy - o[1]) * (1.0 - py))


def _tint(style: LayerStyle) -> tuple[float, float, float, float]:
    r, g, b, a = style.tint
    return (r / 255, g / 255, b / 255, a / 255 * style.opacity)


class TilemapRenderer:
    """The render pass: draws every map in the world's :class:`TileMaps`."""

    def __init__(self, world: Any) -> None:
        self.world = world
        self.textures: TextureCache | None = None
        self.drawings: dict[int, MapDrawing] = {}

    def __call__(self, frame: Frame) -> None:
        maps = self.world.try_resource(TileMaps)
        live = {id(m): m for m in (maps.maps if maps is not None else [])}
        for key in [k for k in self.drawings if k not in live]:
            self.drawings.pop(key).delete()
        if not live:
            return
        if self.textures is None:
            self.textures = TextureCache(self.world)
        for key, tmap in live.items():
            d = self.drawings.get(key)
            if d is None:
                d = self.drawings[key] = MapDrawing(tmap, self.textures)
            d.draw(frame)

    @property
    def chunk_count(self) -> int:
        """Chunks (per layer) in the batch now: what the camera sees, not the map size."""
        return sum(len(d.chunks) for d in self.drawings.values())
