"""The pyglet side of each :class:`kge.components.sprite.Sprite` component.

:meth:`SpriteStore.sync` runs only when a Sprite (or the entity's Material) was
added or written (tracked writes); moving sprites is done in bulk by
:class:`kge.render.bulk.BulkPoser`. Size, flip and visibility live in the
per-sprite *scale* handed to the poser, so hiding, flipping or culling a sprite
is one number, not a vertex-list rebuild.

A plain sprite is a pyglet sprite (4 vertices) drawn with kge's sprite program
(:mod:`kge.render.programs`: blend modes, materials). A repeating sprite is one
quad whose texture coordinates run past 1 (a wrapping texture of its own). A
nine-patch is a 4 x 4 grid of vertices in the same vertex layout, so the same
bulk poser moves it: its border rows and columns keep their pixel size while the
middle stretches.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pyglet

from kge.components.blend import Blend
from kge.components.material import Material
from kge.components.sprite import Sprite
from kge.errors import KgeError, ValidationError
from kge.render.bulk import BulkPoser
from kge.render.groups import WORLD, Groups
from kge.render.images import RenderTexture
from kge.render.material_share import SharedMaterials
from kge.render.poses import PoseTable
from kge.render.programs import (
    BLEND_FACTORS,
    KgeSprite,
    MaterialGroup,
    SpriteGroup,
    default_program,
    material_program,
    normal_program,
)
from kge.render.textures import TextureCache

#: vertex indices of a nine-patch's 3 x 3 cells (two triangles each) in its 4 x 4 grid
_NINE = [
    i
    for r in range(3)
    for c in range(3)
    for i in (r * 4 + c, r * 4 + c + 1, (r + 1) * 4 + c + 1,
              r * 4 + c, (r + 1) * 4 + c + 1, (r + 1) * 4 + c)
]  # fmt: skip


def _split(length: float, first: float, last: float) -> list[float]:
    """Four cuts 0, first, length - last, length (borders shrunk to fit a short side)."""
    if first + last > length > 0:
        k = length / (first + last)
        first, last = first * k, last * k
    return [0.0, first, length - last, length]


def nine_patch_arrays(
    width: float, height: float, anchor: tuple[float, float], borders_m: tuple[float, ...],
    uv: tuple[float, float, float, float], borders_uv: tuple[float, ...],
) -> tuple[np.ndarray, np.ndarray]:  # fmt: skip
    """(16, 3) positions around the pivot and (16, 3) texture coordinates of a nine-patch.

    >>> pos, tex = nine_patch_arrays(4.0, 2.0, (0.5, 0.5), (0.5, 0.5, 0.5, 0.5),
    ...                              (0.0, 0.0, 1.0, 1.0), (0.25, 0.25, 0.25, 0.25))
    >>> pos[:4, 0].tolist(), tex[:4, 0].tolist()
    ([-2.0, -1.5, 1.5, 2.0], [0.0, 0.25, 0.75, 1.0])
    """
    left, bottom, right, top = borders_m
    xs = np.array(_split(width, left, right)) - anchor[0] * width
    ys = np.array(_split(height, bottom, top)) - anchor[1] * height
    u0, v0, u1, v1 = uv
    bl, bb, br, bt = borders_uv
    us = np.array([u0, u0 + bl, u1 - br, u1])
    vs = np.array([v0, v0 + bb, v1 - bt, v1])
    pos = np.zeros((16, 3), np.float32)
    tex = np.zeros((16, 3), np.float32)
    gy, gx = np.meshgrid(np.arange(4), np.arange(4), indexing="ij")
    pos[:, 0], pos[:, 1] = xs[gx.ravel()], ys[gy.ravel()]
    tex[:, 0], tex[:, 1] = us[gx.ravel()], vs[gy.ravel()]
    return pos, tex


class NinePatch:
    """A nine-patch vertex list in kge's sprite layout (moved by the same bulk poser)."""

    def __init__(self, batch: Any, group: Any, prog: Any, pos: np.ndarray, tex: np.ndarray,
                 color: tuple[int, int, int, int]) -> None:  # fmt: skip
        self._vertex_list = prog.vertex_list_indexed(
            16, 4, _NINE, batch, group,  # GL_TRIANGLES
            position=("f", pos.ravel().tolist()), tex_coords=("f", tex.ravel().tolist()),
            colors=("Bn", color * 16), translate=("f", (0.0,) * 48),
            scale=("f", (1.0,) * 32), rotation=("f", (0.0,) * 16),
        )  # fmt: skip

    def reshape(self, pos: np.ndarray, tex: np.ndarray, color: tuple[int, int, int, int]) -> None:
        vl = self._vertex_list
        vl.position[:] = pos.ravel().tolist()
        vl.tex_coords[:] = tex.ravel().tolist()
        vl.colors[:] = color * 16

    def delete(self) -> None:
        self._vertex_list.delete()


class NormalStore:
    """The normal maps of normal-mapped sprites, in a batch of their own that the lights
    draw into their normal buffer, moved with the sprites (same pose rows)."""

    def __init__(self, textures: TextureCache) -> None:
        self.textures = textures
        self.batch = pyglet.graphics.Batch()
        self.poser = BulkPoser("translate", "rotation", scale="scale")
        self.items: dict[int, Any] = {}
        self._groups: dict[tuple[int, int], Any] = {}

    def draws(self) -> bool:
        return bool(self.items)

    def draw(self) -> None:
        self.batch.draw()

    def put(self, entity: int, comp: Sprite, rect: tuple[int, int, int, int],
            image_size: tuple[int, int], row: int, scale: tuple[float, float],
            radius: float) -> None:  # fmt: skip
        tex = self.textures.texture(comp.normal_map, comp.filter, comp.mipmaps)
        if (tex.width, tex.height) != image_size:
            raise ValidationError(
                f"entity {entity}, Sprite.normal_map is {tex.width}x{tex.height} pixels; the "
                f"image is {image_size[0]}x{image_size[1]} (a normal map matches its image)"
            )
        x, y, w, h = rect
        region = tex.get_region(x, y, w, h)
        region.anchor_x, region.anchor_y = comp.anchor[0] * w, comp.anchor[1] * h
        key = (comp.layer, comp.order)
        group = self._groups.get(key)
        if group is None:
            group = self._groups[key] = pyglet.graphics.Group(order=comp.layer * 4096 + comp.order)
        self.remove(entity)
        ps = KgeSprite(region, batch=self.batch, group=group, subpixel=True,
                       program=normal_program())  # fmt: skip
        self.items[entity] = ps
        self.poser.add(entity, ps._vertex_list, row, scale, radius)

    def remove(self, entity: int) -> None:
        ps = self.items.pop(entity, None)
        if ps is not None:
            self.poser.remove(entity)
            ps.delete()

    def clear(self) -> None:
        for e in list(self.items):
            self.remove(e)


class SpriteStore:
    """entity -> pyglet sprite (or nine-patch), in one batch."""

    def __init__(
        self, batch: Any, groups: Groups, textures: TextureCache, poses: PoseTable
    ) -> None:
        self.batch = batch
        self.groups = groups
        self.textures = textures
        self.poses = poses
        self.poser = BulkPoser("translate", "rotation", scale="scale")
        self.sprites: dict[int, Any] = {}
        self._keys: dict[int, tuple[Any, ...]] = {}
        self._rows: dict[int, int] = {}
        self._material_groups: dict[int, MaterialGroup] = {}
        #: alike materials share a group (one draw call); changed ones are drawn alone
        self.shared = SharedMaterials()
        self.normals = NormalStore(textures)
        #: ``fn(entity) -> (texture, (x, y, w, h)) | None``: where an entity's pixels come
        #: from when not from ``Sprite.image`` (animated sprites draw from an atlas)
        self.frame_source: Any = None
        #: bumped when a pyglet sprite is created or deleted (bulk writers re-index then)
        self.version = 0

    def __len__(self) -> int:
        return len(self.sprites)

    def _texture(self, entity: int, comp: Sprite) -> tuple[Any, tuple[int, int, int, int]]:
        source = None if self.frame_source is None else self.frame_source(entity)
        if source is not None:
            tex, rect = source
            return tex, rect
        tex = self.textures.texture(comp.image, comp.filter, comp.mipmaps, comp.wrap)
        if comp.wrap != "clamp" and comp.region is not None:
            raise ValidationError("a repeating Sprite (wrap) draws its whole image: no region")
        return tex, comp.frame_rect(tex.width, tex.height)

    def _program(self, entity: int, comp: Sprite, material: Material | None,
                 parent: Any) -> tuple[Any, Any]:  # fmt: skip
        """(program, parent group) of the sprite: its material's, or kge's default."""
        if material is not None:
            prog = material_program(material.shader, "sprite")
            if prog is not None:
                shared = self.shared.group(entity, material, prog, parent, self.textures)
                if shared is not None:
                    self._material_groups.pop(entity, None)
                    return prog, shared
                group = self._material_groups.get(entity)
                if group is None or group.material is not material or group.parent is not parent:
                    group = self._material_groups[entity] = MaterialGroup(
                        material, prog, self.textures, parent
                    )
                return prog, group
        self._material_groups.pop(entity, None)
        self.shared.forget(entity)
        output = "premultiplied" if self._blend(comp) == "premultiplied" else "straight"
        return default_program("sprite", output), parent

    @staticmethod
    def _blend(comp: Sprite) -> Blend:
        # a camera's render texture holds premultiplied colour
        if isinstance(comp.image, RenderTexture) and comp.blend is Blend.ALPHA:
            return Blend.PREMULTIPLIED
        return comp.blend

    def sync(self, entity: int, comp: Sprite, transform: Any, ppm: float,
             material: Material | None = None) -> None:  # fmt: skip
        """Create or update the pyglet sprite of ``entity`` from its component."""
        try:
            tex, (x, y, w, h) = self._texture(entity, comp)
        except (KgeError, OSError) as exc:  # unknown asset, undecodable file, bad region
            raise ValidationError(f"entity {entity}, Sprite.image {comp.image!r}: {exc}") from exc
        region = tex.get_region(x, y, w, h)
        region.anchor_x = comp.anchor[0] * w
        region.anchor_y = comp.anchor[1] * h
        layer_group = self.groups.get(comp.layer, WORLD, comp.order)
        prog, parent = self._program(entity, comp, material, layer_group)
        blend = self._blend(comp)
        src, dst = BLEND_FACTORS[blend]
        if comp.size is None:
            wm, hm = w / ppm, h / ppm
        else:
            wm, hm = comp.size
        kind = "nine" if comp.nine_patch is not None else "quad"
        key = (tex.id, parent, prog, blend, kind)
        ps = self.sprites.get(entity)
        color = (*comp.tint, comp.opacity)
        if kind == "nine":
            pos, uv = self._nine(comp, region, w, h, wm, hm, ppm)
            if ps is not None and self._keys.get(entity) == key:
                ps.reshape(pos, uv, color)
            else:
                self._drop(entity)
                ps = NinePatch(self.batch, SpriteGroup(tex, src, dst, prog, parent), prog, pos,
                               uv, color)  # fmt: skip
                self._adopt(entity, ps, key)
            sx = sy = 1.0
        else:
            if ps is not None and self._keys.get(entity) == key:
                # same texture and group: new sub-rectangle and pivot in place
                ps._vertex_list.tex_coords[:] = region.tex_coords
                ps._texture = region
                ps._update_position()
            else:
                self._drop(entity)
                ps = KgeSprite(region, batch=self.batch, group=parent, subpixel=True,
                               blend_src=src, blend_dest=dst, program=prog)  # fmt: skip
                self._adopt(entity, ps, key)
            ps.color = color
            if comp.wrap != "clamp":
                self._repeat(ps, comp, w, h, wm, hm, ppm)
            sx, sy = wm / w, hm / h
        sx *= -1.0 if comp.flip_x else 1.0
        sy *= -1.0 if comp.flip_y else 1.0
        if not comp.visible:
            sx = sy = 0.0
        ax, ay = comp.anchor
        radius = math.hypot(max(abs(ax), abs(1 - ax)) * wm, max(abs(ay), abs(1 - ay)) * hm)
        row = self._rows.get(entity)
        if row is None:
            row = self._rows[entity] = self.poses.acquire(entity, transform)
        self.poser.add(entity, ps._vertex_list, row, (sx, sy), radius)
        if comp.normal_map is not None and kind == "quad":
            self.normals.put(entity, comp, (x, y, w, h), (tex.width, tex.height), row,
                             (sx, sy), radius)  # fmt: skip
        else:
            self.normals.remove(entity)

    @staticmethod
    def _repeat(ps: Any, comp: Sprite, w: int, h: int, wm: float, hm: float, ppm: float) -> None:
        """Texture coordinates past 1: one copy of the image per ``tile`` metres."""
        tw, th = comp.tile if comp.tile is not None else (w / ppm, h / ppm)
        u0, v0 = comp.scroll
        u1, v1 = u0 + wm / tw, v0 + hm / th
        # an axis that shows one copy or less stays half a texel inside it: filtering at
        # its edge would otherwise blend in the opposite edge of the image
        if u0 >= 0.0 and u1 <= 1.0 + 1e-6:
            u0, u1 = max(u0, 0.5 / w), min(u1, 1.0 - 0.5 / w)
        if v0 >= 0.0 and v1 <= 1.0 + 1e-6:
            v0, v1 = max(v0, 0.5 / h), min(v1, 1.0 - 0.5 / h)
        ps._vertex_list.tex_coords[:] = (u0, v0, 0.0, u1, v0, 0.0, u1, v1, 0.0, u0, v1, 0.0)

    @staticmethod
    def _nine(comp: Sprite, region: Any, w: int, h: int, wm: float, hm: float,
              ppm: float) -> tuple[np.ndarray, np.ndarray]:  # fmt: skip
        left, bottom, right, top = comp.nine_patch or (0, 0, 0, 0)
        if left + right > w or bottom + top > h:
            raise ValidationError(
                f"Sprite.nine_patch {comp.nine_patch} borders are wider than the {w}x{h} image"
            )
        t = region.tex_coords
        u0, v0, u1, v1 = t[0], t[1], t[6], t[7]
        du, dv = (u1 - u0) / w, (v1 - v0) / h
        return nine_patch_arrays(
            wm, hm, comp.anchor, (left / ppm, bottom / ppm, right / ppm, top / ppm),
            (u0, v0, u1, v1), (left * du, bottom * dv, right * du, top * dv),
        )  # fmt: skip

    def _adopt(self, entity: int, ps: Any, key: tuple[Any, ...]) -> None:
        self.sprites[entity] = ps
        self._keys[entity] = key
        self.version += 1

    def _drop(self, entity: int) -> None:
        ps = self.sprites.pop(entity, None)
        if ps is None:
            return
        self.poser.remove(entity)
        self._keys.pop(entity, None)
        ps.delete()
        self.version += 1

    def remove(self, entity: int) -> None:
        if entity not in self.sprites:
            return
        self._drop(entity)
        self.normals.remove(entity)
        self._material_groups.pop(entity, None)
        self.shared.forget(entity, gone=True)
        if self._rows.pop(entity, None) is not None:
            self.poses.release(entity)

    def clear(self) -> None:
        for e in list(self.sprites):
            self.remove(e)
        self.normals.clear()
