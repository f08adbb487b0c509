"""The pyglet ``Label`` behind each :class:`kge.components.text.Text`.

Glyph layout is the expensive part of text, so a label is rebuilt only when
the component is written (tracked), and moved only when its pose changed.
World text lives in the TEXT space (camera view with a 1/pixels_per_meter
pre-scale): its position is the entity's pose in "pixels at zoom 1", so it
scales with the zoom like everything else in the world.
"""

from __future__ import annotations

import math
from typing import Any, Literal

import pyglet

from kge.components.text import Text
from kge.render.groups import SCREEN, TEXT, Groups
from kge.render.poses import PoseTable
from kge.render.projection import to_pyglet_degrees

AnchorX = Literal["left", "center", "right"]
AnchorY = Literal["bottom", "center", "top"]


def _anchor_names(anchor: tuple[float, float]) -> tuple[AnchorX, AnchorY]:
    """Snap a fractional anchor to pyglet's named anchors (0, 0.5, 1)."""
    xs: tuple[AnchorX, ...] = ("left", "center", "right")
    ys: tuple[AnchorY, ...] = ("bottom", "center", "top")
    ix = min(2, max(0, round(anchor[0] * 2)))
    iy = min(2, max(0, round(anchor[1] * 2)))
    return xs[ix], ys[iy]


class LabelStore:
    """entity -> pyglet Label."""

    def __init__(self, batch: Any, groups: Groups, poses: PoseTable) -> None:
        self.batch = batch
        self.groups = groups
        self.poses = poses
        self.labels: dict[int, Any] = {}
        self._comp: dict[int, Text] = {}
        self._rows: dict[int, int] = {}
        self._placed: dict[int, tuple[float, float, float]] = {}
        self._styles: dict[int, tuple[Any, ...]] = {}

    def __len__(self) -> int:
        return len(self.labels)

    @staticmethod
    def _style(comp: Text) -> tuple[Any, ...]:
        return (
            comp.size,
            comp.color,
            comp.bold,
            comp.anchor,
            comp.screen_space,
            comp.offset,
            comp.layer,
            comp.order,
            comp.font,
            comp.visible,
        )

    def sync(self, entity: int, comp: Text, transform: Any) -> None:
        """Create the label, or just replace its text when only ``value`` changed."""
        label = self.labels.get(entity)
        style = self._style(comp)
        if label is not None and self._comp.get(entity) is comp and self._styles[entity] == style:
            if label.text != comp.value:
                label.text = comp.value
            return
        self.remove(entity)
        if not comp.visible:
            return
        ax, ay = _anchor_names(comp.anchor)
        space = SCREEN if comp.screen_space else TEXT
        label = pyglet.text.Label(
            comp.value,
            font_name=comp.font,
            font_size=comp.size,
            weight="bold" if comp.bold else "normal",
            color=comp.color,
            anchor_x=ax,
            anchor_y=ay,
            batch=self.batch,
            group=self.groups.get(comp.layer, space, comp.order),
        )
        self.labels[entity] = label
        self._comp[entity] = comp
        self._styles[entity] = style
        if comp.screen_space:
            label.position = (comp.offset[0], comp.offset[1], 0.0)
        else:
            self._rows[entity] = self.poses.acquire(entity, transform)

    def place(self, poses: Any, ppm: float) -> None:
        """Move world labels to their entities' blended poses (only those that moved)."""
        for entity, row in self._rows.items():
            x, y, a = (float(v) for v in poses[row])
            comp = self._comp[entity]
            ox, oy = comp.offset
            c, s = math.cos(a), math.sin(a)
            px, py = (x + c * ox - s * oy) * ppm, (y + s * ox + c * oy) * ppm
            key = (px, py, a)
            if self._placed.get(entity) != key:
                self._placed[entity] = key
                label = self.labels[entity]
                label.position = (px, py, 0.0)
                label.rotation = float(to_pyglet_degrees(a))

    def remove(self, entity: int) -> None:
        label = self.labels.pop(entity, None)
        if label is None:
            return
        label.delete()
        self._comp.pop(entity, None)
        self._styles.pop(entity, None)
        self._placed.pop(entity, None)
        if self._rows.pop(entity, None) is not None:
            self.poses.release(entity)

    def clear(self) -> None:
        for e in list(self.labels):
            self.remove(e)
