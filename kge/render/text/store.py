"""The drawn side of every :class:`~kge.components.text.Text` component of a world.

Each Text is a :class:`~kge.render.text.sprite.TextSprite`. World text lives in the
layer's WORLD group (vertex data in metres, like sprites) and moves with its
entity's blended pose through a :class:`~kge.render.bulk.BulkPoser`, in bulk; its
``offset`` is folded into the sprite's pivot, so it turns with the entity. Screen
text lives in the SCREEN group at whole pixels.

World text is baked at the size it covers on screen (the cameras' largest zoom
times the window's pixels per design pixel), so it stays crisp at any zoom. While
the zoom keeps changing it is baked again only when the size is 25 % off; once the
zoom rests, at the exact size.
"""

from __future__ import annotations

from typing import Any

from kge.components.text import Text
from kge.render.bulk import BulkPoser
from kge.render.groups import SCREEN, WORLD, Groups
from kge.render.poses import PoseTable
from kge.render.text.fonts import WorldFaces
from kge.render.text.raster import TextRaster
from kge.render.text.sprite import TextSprite
from kge.render.textures import TextureCache

#: while zooming, re-bake world text only beyond this ratio of size; at rest, beyond 1 %
_MOVING, _RESTING = 1.25, 1.01


class TextStore:
    """entity -> TextSprite (see the module docstring)."""

    def __init__(self, batch: Any, groups: Groups, poses: PoseTable,
                 textures: TextureCache) -> None:  # fmt: skip
        self.batch = batch
        self.groups = groups
        self.poses = poses
        self.faces = WorldFaces(textures)
        self.raster = TextRaster(self.faces)
        self.poser = BulkPoser("translate", "rotation", scale="scale")
        self.labels: dict[int, TextSprite] = {}
        self._comp: dict[int, Text] = {}
        self._rows: dict[int, int] = {}
        self._groups: dict[int, Any] = {}
        #: texture pixels per text pixel for world text and for screen text
        self.world_scale = 1.0
        self.screen_scale = 1.0
        self._last_world_scale = 1.0
        self._ppm = 64.0
        self.baked = 0  #: labels baked since the store was made (stats, tests)

    def __len__(self) -> int:
        return len(self.labels)

    def sync(self, entity: int, comp: Text, transform: Any, ppm: float) -> None:
        """Create or update the label of ``entity`` from its component."""
        if not comp.visible:
            self.remove(entity)
            return
        self._ppm = ppm
        space = SCREEN if comp.screen_space else WORLD
        group = self.groups.get(comp.layer, space, comp.order)
        label = self.labels.get(entity)
        if label is not None and (self._groups[entity] is not group
                                  or self._comp[entity] is not comp):  # fmt: skip
            self.remove(entity)
            label = None
        if label is None:
            label = self.labels[entity] = TextSprite(self.batch, group, self.raster)
            self._comp[entity] = comp
            self._groups[entity] = group
        where = f"entity {entity}, Text.font"
        self.faces.where = where
        scale = self.screen_scale if comp.screen_space else self.world_scale
        if label.set(comp.text, comp.style(1.0 if comp.screen_space else ppm), scale):
            self.baked += 1
        label.fade(comp.opacity)
        if comp.screen_space:
            row = self._rows.pop(entity, None)
            if row is not None:
                self.poser.remove(entity)
                self.poses.release(entity)
            label.anchor_at(comp.anchor)
            label.move(round(comp.offset[0]), round(comp.offset[1]))
            return
        label.anchor_at(comp.anchor, comp.offset, ppm)
        row = self._rows.get(entity)
        if row is None:
            row = self._rows[entity] = self.poses.acquire(entity, transform)
        self._pose(entity, label, row)

    def _pose(self, entity: int, label: TextSprite, row: int) -> None:
        baked = label.baked
        if baked is None or label.vertex_list is None:
            return
        k = 1.0 / (baked.scale * self._ppm)
        radius = (baked.width + baked.height) * k
        self.poser.add(entity, label.vertex_list, row, (k, k), radius)

    def rescale(self, world_scale: float, screen_scale: float) -> int:
        """Bake again the labels whose raster scale is off (see the module docstring)."""
        moving = world_scale != self._last_world_scale
        self._last_world_scale = world_scale
        limit = _MOVING if moving else _RESTING
        self.world_scale = world_scale
        redone = 0
        if screen_scale != self.screen_scale:
            self.screen_scale = screen_scale
            for entity, comp in self._comp.items():
                if comp.screen_space:
                    self.sync(entity, comp, None, self._ppm)
                    redone += 1
        for entity, comp in list(self._comp.items()):
            if comp.screen_space:
                continue
            label = self.labels[entity]
            ratio = world_scale / max(label.scale, 1e-9)
            if ratio > limit or ratio < 1.0 / limit:
                label.set(comp.text, comp.style(self._ppm), world_scale)
                self.baked += 1
                self._pose(entity, label, self._rows[entity])
                redone += 1
        return redone

    def remove(self, entity: int) -> None:
        label = self.labels.pop(entity, None)
        if label is None:
            return
        self.poser.remove(entity)
        label.delete()
        self._comp.pop(entity, None)
        self._groups.pop(entity, None)
        if self._rows.pop(entity, None) is not None:
            self.poses.release(entity)

    def clear(self) -> None:
        for e in list(self.labels):
            self.remove(e)
        self.raster.close()
