"""The pyglet ``Sprite`` behind each :class:`kge.components.sprite.Sprite` component.

:meth:`SpriteStore.sync` runs only when a Sprite component was added or
written (tracked writes); moving sprites is done in bulk by
:class:`kge.render.bulk.BulkPoser`. Size, flip and visibility live in the
per-sprite *scale* handed to the poser, so hiding, flipping or culling a
sprite is one number, not a vertex-list rebuild.
"""

from __future__ import annotations

import math
from typing import Any

import pyglet

from kge.components.sprite import Sprite
from kge.errors import KgeError, ValidationError
from kge.render.bulk import BulkPoser
from kge.render.groups import WORLD, Groups
from kge.render.poses import PoseTable
from kge.render.textures import TextureCache


class SpriteStore:
    """entity -> pyglet Sprite, in one batch."""

    def __init__(
        self, batch: Any, groups: Groups, textures: TextureCache, poses: PoseTable
    ) -> None:
        self.batch = batch
        self.groups = groups
        self.textures = textures
        self.poses = poses
        self.poser = BulkPoser("translate", "rotation", scale="scale")
        self.sprites: dict[int, Any] = {}
        self._keys: dict[int, tuple[Any, Any]] = {}  # entity -> (texture id, group)
        self._rows: dict[int, int] = {}
        #: ``fn(entity) -> (texture, (x, y, w, h)) | None``: where an entity's pixels come
        #: from when not from ``Sprite.image`` (animated sprites draw from an atlas)
        self.frame_source: Any = None
        #: bumped when a pyglet sprite is created or deleted (bulk writers re-index then)
        self.version = 0

    def __len__(self) -> int:
        return len(self.sprites)

    def sync(self, entity: int, comp: Sprite, transform: Any, ppm: float) -> None:
        """Create or update the pyglet sprite of ``entity`` from its component."""
        try:
            source = None if self.frame_source is None else self.frame_source(entity)
            if source is None:
                tex = self.textures.texture(comp.image)
                x, y, w, h = comp.frame_rect(tex.width, tex.height)
            else:
                tex, (x, y, w, h) = source
        except (KgeError, OSError) as exc:  # unknown asset, undecodable file, bad region
            raise ValidationError(f"entity {entity}, Sprite.image {comp.image!r}: {exc}") from exc
        region = tex.get_region(x, y, w, h)
        region.anchor_x = comp.anchor[0] * w
        region.anchor_y = comp.anchor[1] * h
        group = self.groups.get(comp.layer, WORLD, comp.order)
        key = (tex.id, group)
        ps = self.sprites.get(entity)
        if ps is not None and self._keys.get(entity) == key:
            # same texture and group: new sub-rectangle and pivot in place
            ps._vertex_list.tex_coords[:] = region.tex_coords
            ps._texture = region
            ps._update_position()
        else:
            if ps is not None:
                self.poser.remove(entity)
                ps.delete()
            ps = pyglet.sprite.Sprite(region, batch=self.batch, group=group, subpixel=True)
            self.version += 1
            self.sprites[entity] = ps
            self._keys[entity] = key
        ps.color = (*comp.tint, comp.opacity)
        if comp.size is None:
            wm, hm = w / ppm, h / ppm
        else:
            wm, hm = comp.size
        sx = wm / w * (-1.0 if comp.flip_x else 1.0)
        sy = hm / h * (-1.0 if comp.flip_y else 1.0)
        if not comp.visible:
            sx = sy = 0.0
        ax, ay = comp.anchor
        radius = math.hypot(max(abs(ax), abs(1 - ax)) * wm, max(abs(ay), abs(1 - ay)) * hm)
        row = self._rows.get(entity)
        if row is None:
            row = self._rows[entity] = self.poses.acquire(entity, transform)
        self.poser.add(entity, ps._vertex_list, row, (sx, sy), radius)

    def remove(self, entity: int) -> None:
        ps = self.sprites.pop(entity, None)
        if ps is None:
            return
        self.poser.remove(entity)
        self._keys.pop(entity, None)
        ps.delete()
        self.version += 1
        if self._rows.pop(entity, None) is not None:
            self.poses.release(entity)

    def clear(self) -> None:
        for e in list(self.sprites):
            self.remove(e)
