"""``TextSprite``: one piece of laid-out, baked text drawn as a quad in a pyglet batch.

The building block of world text, HUD text and UI labels: give it text and a
:class:`~kge.components.text.TextStyle`, say where its anchor goes, and it lays the
text out (:mod:`kge.text.layout`), bakes it (:mod:`kge.render.text.raster`) and shows
it as a sprite with premultiplied blending. It lays out again only when the text or
the style changes, and bakes again only then or when the raster scale changes.

Use in a UI drawer (``raster`` is a :class:`~kge.render.text.raster.TextRaster`)::

    label = TextSprite(batch, group, raster)
    label.set("Hello [b]world[/b]", TextStyle(size=18, markup=True, width=200))
    label.move(20, 300, anchor=(0, 1))      # top-left corner at (20, 300)
    label.layout.lines[0].width             # the measured box of the first line
"""

from __future__ import annotations

from typing import Any

import pyglet
from pyglet import gl

from kge.components.text import TextStyle
from kge.render.text.raster import Baked, TextRaster
from kge.text.layout import TextLayout, layout
from kge.text.markup import spans_of


class TextSprite:
    """Laid-out text baked into a texture and drawn as one sprite (see the module docstring)."""

    def __init__(self, batch: Any, group: Any, raster: TextRaster) -> None:
        self.batch = batch
        self.group = group
        self.raster = raster
        self.sprite: Any = None
        self.layout: TextLayout | None = None
        self.baked: Baked | None = None
        self._key: tuple[str, TextStyle] | None = None
        self._texture_id: int | None = None
        self._anchor = (0.0, 0.0)
        self._offset = (0.0, 0.0)
        self._units = 1.0
        self.opacity = 255
        self.visible = True

    # -- content -------------------------------------------------------------------------------
    def set(self, text: str, style: TextStyle, scale: float = 1.0) -> bool:
        """Show ``text`` in ``style``, rasterised at ``scale`` texture pixels per text pixel.

        Returns True when it was laid out or baked again.
        """
        key = (text, style)
        changed = key != self._key
        if changed:
            self.layout = layout(spans_of(text, style.markup), style, self.raster.faces)
            self._key = key
        if changed or self.baked is None or abs(self.baked.scale - scale) > 1e-9:
            assert self.layout is not None
            self.baked = self.raster.bake(self.layout, style, scale, self.baked)
            self._show()
            return True
        return False

    @property
    def scale(self) -> float:
        """Texture pixels per text pixel of the current bake (0 before the first)."""
        return 0.0 if self.baked is None else self.baked.scale

    def _show(self) -> None:
        b = self.baked
        assert b is not None
        region = b.texture.get_region(0, 0, b.width, b.height)
        if self.sprite is not None and self._texture_id == b.texture.id:
            self.sprite._vertex_list.tex_coords[:] = region.tex_coords
            self.sprite._texture = region
        else:
            if self.sprite is not None:
                self.sprite.delete()
            self.sprite = pyglet.sprite.Sprite(
                region, batch=self.batch, group=self.group, subpixel=True,
                blend_src=gl.GL_ONE, blend_dest=gl.GL_ONE_MINUS_SRC_ALPHA,
            )  # fmt: skip
            self._texture_id = b.texture.id
        self._apply()

    # -- placement -------------------------------------------------------------------------------
    def anchor_at(self, anchor: tuple[float, float], offset: tuple[float, float] = (0.0, 0.0),
                  units: float = 1.0) -> None:  # fmt: skip
        """The box point ``anchor`` (fractions) goes to the sprite's position, shifted by
        ``offset`` (in ``units`` text pixels per unit, turned with the sprite)."""
        if (anchor, offset, units) != (self._anchor, self._offset, self._units):
            self._anchor, self._offset, self._units = anchor, offset, units
            if self.sprite is not None:
                self._apply()

    def _apply(self) -> None:
        b, s = self.baked, self.sprite
        assert b is not None and s is not None
        k = b.scale
        ax = b.origin[0] + (self._anchor[0] * b.box[0] - self._offset[0] * self._units) * k
        ay = b.origin[1] + (self._anchor[1] * b.box[1] - self._offset[1] * self._units) * k
        region = s._texture
        region.anchor_x, region.anchor_y = ax, ay
        s._update_position()
        o = self.opacity
        s.color = (o, o, o, o)
        s.visible = self.visible

    def move(self, x: float, y: float, anchor: tuple[float, float] | None = None,
             rotation_degrees: float = 0.0) -> None:  # fmt: skip
        """Put the anchor at window/design pixel (``x``, ``y``) at scale 1/raster scale."""
        if anchor is not None:
            self.anchor_at(anchor)
        s = self.sprite
        if s is None or self.baked is None:
            return
        inv = 1.0 / self.baked.scale
        s.update(x=x, y=y, rotation=rotation_degrees, scale_x=inv, scale_y=inv)

    def fade(self, opacity: int, visible: bool = True) -> None:
        if (opacity, visible) != (self.opacity, self.visible):
            self.opacity, self.visible = opacity, visible
            if self.sprite is not None:
                self.sprite.color = (opacity, opacity, opacity, opacity)
                self.sprite.visible = visible

    @property
    def vertex_list(self) -> Any:
        return None if self.sprite is None else self.sprite._vertex_list

    def delete(self) -> None:
        if self.sprite is not None:
            self.sprite.delete()
            self.sprite = None
        if self.baked is not None:
            self.baked.delete()
            self.baked = None
        self._key = None
