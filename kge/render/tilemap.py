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
from kge.render.glutil import per_context
from kge.render.groups import WORLD
from kge.render.images import PixelImage
from kge.render.passes import Frame
from kge.render.programs import FS_HEAD, apply_frame_uniforms, material_program, set_uniforms
from kge.render.textures import TextureCache
from kge.render.tileobjects import ObjectQuads, layer_objects, object_entities, place
from kge.tilemap.model import (
    FLIP_D,
    FLIP_H,
    FLIP_V,
    LayerStyle,
    MapData,
    TileLayerData,
)
from kge.tilemap.objects import DEPTH_BASE, DEPTH_STEPS
from kge.tilemap.runtime import CHUNK, TileMap, TileMaps

# ``local`` is the point inside the tile image (0..1, flips applied; beyond 1 on
# repeated image layers), ``rect`` the image's (u0, v0, u1, v1) in its texture.
# Sampling is clamped half a texel inside the rect, so a tile never shows its
# neighbour's texels in the sheet: no seams at fractional camera positions,
# zooms below 1 or fractional layer offsets.
_VERTEX = """#version 330 core
in vec2 position;
in vec2 local;
in vec4 rect;
out vec2 v_local;
out vec4 v_rect;
uniform WindowBlock { mat4 projection; mat4 view; } window;
uniform vec2 shift;
void main() {
    v_local = local;
    v_rect = rect;
    gl_Position = window.projection * window.view * vec4(position + shift, 0.0, 1.0);
}
"""
_FRAGMENT = """#version 330 core
in vec2 v_local;
in vec4 v_rect;
out vec4 color;
uniform sampler2D tile_texture;
uniform vec4 tint;
uniform int wrap;
void main() {
    vec2 t = wrap == 1 ? fract(v_local) : clamp(v_local, 0.0, 1.0);
    vec2 half_texel = 0.5 / vec2(textureSize(tile_texture, 0));
    vec2 uv = clamp(mix(v_rect.xy, v_rect.zw, t), v_rect.xy + half_texel, v_rect.zw - half_texel);
    color = texture(tile_texture, uv) * tint;
}
"""
# a tile layer drawn with a Material: the user's ``effect`` gets the layer's tint as its
# colour and the clamped texture coordinate (see :mod:`kge.components.material`)
_MATERIAL_VERTEX = """#version 150 core
in vec2 position;
in vec2 local;
in vec4 rect;
out vec4 v_color;
out vec2 v_uv;
out vec2 v_world;
flat out vec4 v_rect;
uniform WindowBlock { mat4 projection; mat4 view; } window;
uniform vec2 shift;
uniform vec4 tint;
void main() {
    v_world = position + shift;
    v_uv = mix(rect.xy, rect.zw, local);
    v_rect = rect;
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
    """The tile shader program of the current GL context (one per context: its
    uniforms change per layer, see :mod:`kge.render.program_life`)."""
    return per_context(
        "tiles",
        lambda: pyglet.graphics.shader.ShaderProgram(
            pyglet.graphics.shader.Shader(_VERTEX, "vertex"),
            pyglet.graphics.shader.Shader(_FRAGMENT, "fragment"),
        ),
    )


class LayerGroup(pyglet.graphics.Group):
    """One layer's texture, tint and shift (offset + parallax), read at draw time."""

    def __init__(self, program: Any, texture: Any, parent: Any, order: int = 0,
                 wrap: bool = False, material: Material | None = None,
                 textures: Any = None) -> None:  # fmt: skip
        super().__init__(order=order, parent=parent)
        self.program = program
        self.texture = texture
        self.wrap = int(wrap)
        self.shift = (0.0, 0.0)
        self.tint = (1.0, 1.0, 1.0, 1.0)
        self.material = material if program is not tile_program() else None
        self.textures = textures

    def set_state(self) -> None:
        self.program.use()
        self.program["shift"] = self.shift
        self.program["tint"] = self.tint
        m = self.material
        if m is None:
            self.program["wrap"] = self.wrap
        else:  # read now: a tween changes them without touching a vertex
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
) -> tuple[np.ndarray, np.ndarray]:
    """Per corner (BL, BR, TR, TL) of n tiles: the point inside the tile (n, 4, 2), flips
    applied, and the tile's (u0, v0, u1, v1) texture rect (n, 4, 4).

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
    local = np.empty((len(gids), 4, 2), np.float32)
    local[..., 0] = sx
    local[..., 1] = 1.0 - sy  # v up
    # the tile's rect in the texture (u right, v up from the image's bottom)
    u0 = b[:, 0] + x / iw * (b[:, 2] - b[:, 0])
    u1 = b[:, 0] + (x + w) / iw * (b[:, 2] - b[:, 0])
    v0 = b[:, 1] + (1.0 - (y + h) / ih) * (b[:, 3] - b[:, 1])
    v1 = b[:, 1] + (1.0 - y / ih) * (b[:, 3] - b[:, 1])
    rect = np.repeat(np.stack([u0, v0, u1, v1], axis=-1)[:, None, :], 4, axis=1)
    return local, rect.astype(np.float32)


def tile_quads(data: MapData, rows: np.ndarray, cols: np.ndarray, gids: np.ndarray) -> np.ndarray:
    """(n, 4, 2) world positions of tiles at grid (rows, cols): BL, BR, TR, TL.

    A tile image sits on its cell's bottom-left corner (taller tiles reach up),
    moved by its tileset's tile offset, as Tiled draws it.
    """
    u = data.units
    t = data.tiles
    w, h = t.rect[gids, 2].astype(float), t.rect[gids, 3].astype(float)
    ox, oy = t.offset[gids, 0].astype(float), t.offset[gids, 1].astype(float)
    if data.grid is None:
        left = u.left_px + cols * u.tile_w + ox
        bottom = (u.row0 + rows + 1) * u.tile_h + oy
    else:
        bx, by, _, bh = data.grid.cell_boxes(cols, rows)
        left, bottom = bx + ox, by + bh + oy
    px = left[:, None] + _SX * w[:, None]
    py = bottom[:, None] - (1.0 - _SY) * h[:, None]
    x, y = u.points(px, py)
    return np.stack([x, y], axis=-1).astype(np.float32)


@dataclass(slots=True)
class _Chunk:
    lists: list[Any] = field(default_factory=list)
    anim_key: tuple[int, ...] = ()


def map_image(path: Any, key: tuple[int, int, int] | None) -> PixelImage:
    """A map image as RGBA pixels (Pillow), its transparent colour made transparent."""
    from PIL import Image

    with Image.open(path) as im:
        rgba = np.asarray(im.convert("RGBA"), np.uint8).copy()
    if key is not None:
        rgba[(rgba[..., :3] == np.array(key, np.uint8)).all(axis=-1)] = 0
    return PixelImage(rgba.shape[1], rgba.shape[0], rgba[::-1].tobytes())


def _quad_list(
    program: Any, n: int, batch: Any, group: Any, pos: Any, local: Any, rect: Any
) -> Any:
    base = (np.arange(n) * 4)[:, None]
    idx = (base + np.array([0, 1, 2, 0, 2, 3])).ravel()
    return program.vertex_list_indexed(
        n * 4,
        gl.GL_TRIANGLES,
        idx.tolist(),
        batch=batch,
        group=group,
        position=("f", np.ascontiguousarray(pos, np.float32).ravel()),
        local=("f", np.ascontiguousarray(local, np.float32).ravel()),
        rect=("f", np.ascontiguousarray(rect, np.float32).ravel()),
    )


class MapDrawing:
    """The drawing state of one map: textures, groups and live chunks.

    Orthogonal layers draw layer by layer, as Tiled does. On isometric, staggered
    and hexagonal maps each chunk draws its tiles in Tiled's order (back to front)
    and chunks draw back to front too (taller tiles overlap the row behind them);
    a tile layer with the property ``depth_sort: true`` draws each row of tiles at
    its own depth order instead, so sprites with ``TileMap.depth_order`` (and the
    map's tile objects) are drawn between the rows in front and behind them.
    """

    def __init__(self, tmap: TileMap, textures: TextureCache, poses: Any = None) -> None:
        self.map = tmap
        self.textures = textures
        #: () -> the world's pose table (sprites' blended poses), or None
        self.poses = poses
        self.object_quads: list[ObjectQuads] = []
        self._held: list[int] = []
        self.program = tile_program()
        data = tmap.data
        self.tex = [
            textures.texture(map_image(p, k))
            for p, k in zip(data.tiles.images, data.tiles.image_keys or [None] * 0, strict=False)
        ]
        self.bounds = [_tex_bounds(t) for t in self.tex]
        self.groups: dict[tuple[int, int, int], LayerGroup] = {}
        self.chunks: dict[tuple[int, int, int], _Chunk] = {}
        self.images: dict[int, Any] = {}  # image layer position -> (vertex list, group, view)
        self.extras: list[tuple[Any, LayerGroup, Any]] = []  # (list, group, style)
        self.animated = np.zeros(max(data.tiles.size, 1), bool)
        self.materials: dict[int, Material | None] = {}  #: tile layer position -> drawn with
        self._shaders: dict[int, int | None] = {}
        for g in data.tiles.animations:
            self.animated[g] = True
        self._objects_built = False

    def group(
        self, frame: Frame, li: int, image: int, sub: int, draw_layer: int, order: int
    ) -> LayerGroup:
        g = self.groups.get((li, image, sub))
        if g is None:
            parent = frame.groups.get(draw_layer, WORLD, order)
            material = self.materials.get(li)
            g = self.groups[(li, image, sub)] = LayerGroup(
                layer_program(material), self.tex[image], parent, order=sub,
                material=material, textures=self.textures,
            )  # fmt: skip
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
            for (gl_li, _, _), g in self.groups.items():
                if gl_li == li:
                    g.shift, g.tint = shift, tint
        for key in [k for k in self.chunks if k not in wanted]:
            self._drop(key)
        self._background(frame)
        self._image_layers(frame)
        self._tile_objects(frame)

    def _placement(self, props: dict[str, Any], index: int) -> tuple[int, int]:
        layer = props.get("layer", self.map.draw_layer)
        return int(layer), index - 1000

    def _visible(
        self, frame: Frame, li: int, shift: tuple[float, float]
    ) -> list[tuple[int, int, int]]:
        data = self.map.data
        u = data.units
        left, bottom, right, top = frame.view
        grid = data.grid
        if grid is not None and grid.orientation != "orthogonal":
            return self._visible_cells(frame, li, shift)
        tw, th = u.tile_size
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

    def _visible_cells(
        self, frame: Frame, li: int, shift: tuple[float, float]
    ) -> list[tuple[int, int, int]]:
        """Chunks whose cells' boxes (grown by the tallest tile) meet the view."""
        data = self.map.data
        grid = data.grid
        assert grid is not None
        u = data.units
        left, bottom, right, top = frame.view
        x0, y0 = u.pixel(left - shift[0], top - shift[1])  # map pixels, y down
        x1, y1 = u.pixel(right - shift[0], bottom - shift[1])
        tall = float(data.tiles.rect[:, 3].max(initial=0)) + abs(
            float(data.tiles.offset.min(initial=0))
        )
        wide = float(data.tiles.rect[:, 2].max(initial=0))
        y1 += tall  # a tall tile below the view reaches up into it
        x0 -= wide
        nr, nc = -(-data.rows // CHUNK), -(-data.cols // CHUNK)
        key = ("cells", nr, nc)
        boxes = self.__dict__.get("_chunk_boxes")
        if boxes is None or boxes[0] != key:
            cr, cc = np.meshgrid(np.arange(nr), np.arange(nc), indexing="ij")
            corners = []
            for dr, dc in ((0, 0), (0, 1), (1, 0), (1, 1)):
                rr = np.minimum(cr * CHUNK + dr * (CHUNK - 1), data.rows - 1)
                ccs = np.minimum(cc * CHUNK + dc * (CHUNK - 1), data.cols - 1)
                bx, by, w, h = grid.cell_boxes(ccs, rr)
                corners.append((bx, by, bx + w, by + h))
            lo_x = np.minimum.reduce([c[0] for c in corners])
            lo_y = np.minimum.reduce([c[1] for c in corners])
            hi_x = np.maximum.reduce([c[2] for c in corners])
            hi_y = np.maximum.reduce([c[3] for c in corners])
            boxes = (key, cr, cc, lo_x, lo_y, hi_x, hi_y)
            self.__dict__["_chunk_boxes"] = boxes
        _, cr, cc, lo_x, lo_y, hi_x, hi_y = boxes
        hit = (hi_x >= x0) & (lo_x <= x1) & (hi_y >= y0) & (lo_y <= y1)
        return [(li, int(r), int(c)) for r, c in zip(cr[hit], cc[hit], strict=True)]

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
        rr, cols = rr + r0, cols + c0
        grid = data.grid
        flat = grid is None or grid.orientation == "orthogonal"
        if not flat:  # Tiled's order: back to front
            assert grid is not None
            sort = grid.depth(cols, rr)
            rr, cols = rr[sort], cols[sort]
        gids = layer.gids[rr, cols].astype(np.int64)
        flags = layer.flags[rr, cols]
        shown = self.map.shown[gids] if anim else gids
        quads = tile_quads(data, rr, cols, gids)
        local, rect = tile_uvs(data, shown, flags, self.bounds)
        images = data.tiles.image[shown]
        if flat:
            subs = np.zeros(len(gids), np.int64)
        elif _truthy(layer.properties.get("depth_sort")):
            assert grid is not None
            _, by, _, bh = grid.cell_boxes(cols, rr)
            subs = np.round((by + bh / 2) * DEPTH_STEPS / grid.tile_h).astype(np.int64) - 1
            order = DEPTH_BASE  # the sub-order is the depth, sprites interleave
        else:
            subs = np.full(len(gids), cr + cc if grid.orientation == "isometric" else cr)  # type: ignore[union-attr]
        for image, s_ in sorted({(int(i), int(k)) for i, k in zip(images, subs, strict=True)}):
            sel = (images == image) & (subs == s_)
            parent_order = order + s_ if order == DEPTH_BASE else order
            g = self.group(frame, li, image, s_, draw_layer, parent_order)
            vl = _quad_list(
                g.program, int(sel.sum()), frame.batch, g, quads[sel], local[sel], rect[sel]
            )
            chunk.lists.append(vl)
        return chunk

    def _drop(self, key: tuple[int, int, int]) -> None:
        chunk = self.chunks.pop(key, None)
        if chunk is not None:
            for vl in chunk.lists:
                vl.delete()

    def _background(self, frame: Frame) -> None:
        """The map's background colour under everything of its draw layer, over the view."""
        bg = self.map.data.background
        if bg is None:
            return
        entry = self.__dict__.get("_bg")
        if entry is None:
            tex = self.textures.texture(PixelImage(1, 1, bytes((255, 255, 255, 255))))
            g = LayerGroup(self.program, tex, frame.groups.get(self.map.draw_layer, WORLD, -2000))
            b = _tex_bounds(tex)
            vl = _quad_list(
                self.program, 1, frame.batch, g, np.zeros((4, 2)), _SX_LOCAL, np.tile(b, (4, 1))
            )
            entry = self.__dict__["_bg"] = (vl, g)
            self.extras.append((vl, g, None))
        vl, g = entry
        left, bottom, right, top = frame.view
        vl.position[:] = [left, bottom, right, bottom, right, top, left, top]
        g.tint = tuple(c / 255 for c in bg)

    def _image_layers(self, frame: Frame) -> None:
        data = self.map.data
        for i, layer in enumerate(data.image_layers):
            if not layer.style.visible:
                continue
            entry = self.images.get(i)
            shift = _shift(frame, data, layer.style)
            u = data.units
            iw, ih = layer.size
            x0, y1 = u.point(u.left_px, u.row0 * u.tile_h if data.grid is None else 0.0)
            w, h = u.length(iw), u.length(ih)
            # repeated axes cover the view (in whole image steps from the layer's origin)
            left, bottom, right, top = frame.view
            rx, ry = layer.repeat
            a0, a1 = (0.0, 1.0)
            if rx:
                a0 = math.floor((left - shift[0] - x0) / w)
                a1 = math.ceil((right - shift[0] - x0) / w)
            b0, b1 = (0.0, 1.0)
            if ry:
                b0 = math.floor((y1 - (top - shift[1])) / h)
                b1 = math.ceil((y1 - (bottom - shift[1])) / h)
            view = (a0, a1, b0, b1)
            if entry is None or entry[2] != view:
                if entry is not None:
                    entry[0].delete()
                tex = self.textures.texture(map_image(layer.image, layer.key))
                draw_layer, order = self._placement(layer.properties, layer.index)
                g = (
                    entry[1]
                    if entry is not None
                    else LayerGroup(
                        self.program, tex, frame.groups.get(draw_layer, WORLD, order), wrap=rx or ry
                    )
                )
                xa, xb = x0 + a0 * w, x0 + a1 * w
                ya, yb = y1 - b1 * h, y1 - b0 * h
                pos = np.array([[xa, ya], [xb, ya], [xb, yb], [xa, yb]], float)
                loc = np.array([[a0, -b1 + 1], [a1, -b1 + 1], [a1, -b0 + 1], [a0, -b0 + 1]])
                loc = np.array([[p[0], p[1]] for p in loc], float)
                b = _tex_bounds(tex)
                vl = _quad_list(self.program, 1, frame.batch, g, pos, loc, np.tile(b, (4, 1)))
                entry = self.images[i] = (vl, g, view)
            entry[1].shift = shift
            entry[1].tint = _tint(layer.style)

    def _tile_objects(self, frame: Frame) -> None:
        """Tile objects of parallax object layers: drawn with the map, shifted like their
        layer, around their entities' poses (:mod:`kge.render.tileobjects`)."""
        data = self.map.data
        world = self.map.world
        if not self._objects_built:
            self._objects_built = True
            by_id = object_entities(world, self.map.objects)
            for layer in data.object_layers:
                if layer.style.parallax == (1.0, 1.0) or not layer.style.visible:
                    continue
                self._object_layer(frame, layer, by_id)
        for q in self.object_quads:
            q.group.shift, q.group.tint = _shift(frame, data, q.style), _tint(q.style)
            place(q, frame, world, self._release)

    def _object_layer(self, frame: Frame, layer: Any, by_id: dict[tuple[str, int], int]) -> None:
        data = self.map.data
        objs, gids, flags, entities, sizes = layer_objects(data, layer, by_id)
        if not objs:
            return
        for e in entities:
            self._hold(e)
        local, rect = tile_uvs(data, gids, flags, self.bounds)
        images = data.tiles.image[gids]
        draw_layer, order = self._placement(layer.properties, layer.index)
        for image in np.unique(images).tolist():
            sel = images == image
            n = int(sel.sum())
            grp = LayerGroup(
                self.program, self.tex[image], frame.groups.get(draw_layer, WORLD, order)
            )
            vl = _quad_list(
                self.program, n, frame.batch, grp, np.zeros((n, 4, 2)), local[sel], rect[sel]
            )
            ents = [e for e, keep in zip(entities, sel.tolist(), strict=True) if keep]
            self.object_quads.append(ObjectQuads(vl, grp, layer.style, ents, sizes[sel]))

    def _hold(self, entity: int) -> None:
        """Keep a pose-table row for an object entity (blended with the sprites)."""
        table = self.poses() if self.poses is not None else None
        if table is not None:
            from kge.components.transform import Transform

            table.acquire(entity, self.map.world.try_get(entity, Transform))
            self._held.append(entity)

    def _release(self, entity: int) -> None:
        table = self.poses() if self.poses is not None else None
        if table is not None and entity in self._held:
            self._held.remove(entity)
            table.release(entity)

    def delete(self) -> None:
        for key in list(self.chunks):
            self._drop(key)
        for vl, _, _ in self.images.values():
            vl.delete()
        self.images.clear()
        for vl, _, _ in self.extras:
            vl.delete()
        self.extras.clear()
        for q in self.object_quads:
            q.vlist.delete()
        self.object_quads.clear()
        for e in list(self._held):
            self._release(e)
        self.__dict__.pop("_bg", None)


_SX_LOCAL = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])


def _truthy(value: Any) -> bool:
    return value is True or (isinstance(value, str) and value.lower() in ("true", "1", "yes"))


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

    def __init__(self, world: Any, poses: Any = None) -> None:
        self.world = world
        self.poses = poses  #: () -> the world's pose table, or None
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
                d = self.drawings[key] = MapDrawing(tmap, self.textures, self.poses)
            d.draw(frame)

    @property
    def chunk_count(self) -> int:
        """Chunks (per layer) in the batch now: what the camera sees, not the map size."""
        return sum(len(d.chunks) for d in self.drawings.values())
