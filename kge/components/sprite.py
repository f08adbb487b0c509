"""``Sprite``: draw an image at the entity's pose.

A sprite is pure data: *which* image, *how big* in metres, *where* its pivot is
and *in what order* it is drawn. The render system owns the pyglet objects and
keeps them in step with this component (writes are tracked, so an unchanged
sprite costs nothing to sync).

* ``image``: an asset name or path (resolved through the asset store when there
  is one), or an in-memory image such as :func:`kge.render.images.solid`.
* ``size``: (width, height) in metres; ``None`` means image pixels divided by
  the camera's ``pixels_per_meter``, so 64 px art is 1 m at the default scale.
* ``anchor``: the pivot as a fraction of the size, (0, 0) bottom-left,
  (0.5, 0.5) the centre. The entity's Transform places and rotates this point.
* ``region``: part of a sprite sheet. Either ``(x, y, w, h)`` in pixels from the
  image's top-left corner (as image editors show it), or a frame index into a
  ``grid=(columns, rows)`` counted row by row from the top-left.
* ``layer`` then ``order`` decide drawing order: higher draws on top.
* ``filter``: :class:`TextureFilter` ``NEAREST`` (crisp pixel art, the default) or
  ``LINEAR`` (painted art scaled or turned); ``mipmaps=True`` adds smaller copies
  for art drawn much smaller than its pixels.
* ``wrap``: :class:`TextureWrap` ``REPEAT`` (or ``MIRROR``) tiles the image over
  ``size``, one copy per ``tile`` metres (default: the image's own size): a whole
  sky is one sprite; ``scroll`` shifts the pattern (fractions of a tile; tween it
  for parallax).
* ``nine_patch=(left, bottom, right, top)`` pixels of border stay their size while
  the middle stretches to ``size`` (panels, buttons, speech bubbles).
* ``blend``: a :class:`~kge.components.blend.Blend` (``ALPHA``, ``ADDITIVE`` for glows
  and fire, ``MULTIPLY`` for shade, ``SCREEN`` for soft light, ``PREMULTIPLIED``).
* ``normal_map``: an image of surface normals (same size as the sprite's pixels) that
  lights shade it with (:mod:`kge.components.lights`).

>>> s = Sprite("ship.png", size=(1.0, 0.5), layer=2)
>>> s.anchor, s.visible
((0.5, 0.5), True)
>>> s.opacity = 300
Traceback (most recent call last):
...
kge.errors.ValidationError: Sprite.opacity must be an int in 0..255, got 300
>>> Sprite("sheet.png", region=5)
Traceback (most recent call last):
...
kge.errors.ValidationError: Sprite.region: a frame index needs grid=(columns, rows)
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from enum import StrEnum
from typing import Any, ClassVar

from kge.components.blend import Blend
from kge.components.color import RGB, byte, rgb
from kge.components.tracked import Check, Tracked
from kge.errors import ComponentTypeError, ValidationError
from kge.validate import Vec2, anchor, boolean, choice, extent, integer, vec2

Rect4 = tuple[int, int, int, int]
#: how a drawable's colour combines with what is under it


class TextureFilter(StrEnum):
    """How an image is sampled when drawn at another size or turned."""

    NEAREST = "nearest"  #: crisp pixels (pixel art)
    LINEAR = "linear"  #: smooth (painted art)


class TextureWrap(StrEnum):
    """What lies past an image's edge when a sprite is larger than one copy of it."""

    CLAMP = "clamp"  #: one copy, stretched over the size
    REPEAT = "repeat"  #: copies side by side
    MIRROR = "mirror"  #: copies, every other one mirrored (no seams)



def _optional_image(value: Any, owner: str, field: str) -> Any:
    return None if value is None else _image(value, owner, field)


def _nine_patch(value: Any, owner: str, field: str) -> Rect4 | None:
    if value is None:
        return None
    if not isinstance(value, (tuple, list)) or len(value) != 4:
        raise ComponentTypeError(
            f"{owner}.{field} must be (left, bottom, right, top) border pixels, got {value!r}"
        )
    left, bottom, right, top = (integer(v, owner, f"{field}[{i}]") for i, v in enumerate(value))
    if min(left, bottom, right, top) < 0:
        raise ValidationError(f"{owner}.{field} borders must be >= 0 pixels, got {value!r}")
    return (left, bottom, right, top)


def _image(value: Any, owner: str, field: str) -> Any:
    if value is None or isinstance(value, (int, float, bool, bytes)):
        raise ComponentTypeError(
            f"{owner}.{field} must be an asset name/path or an image, got {value!r}"
        )
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    if isinstance(value, str) and not value:
        raise ValidationError(f"{owner}.{field} must not be an empty string")
    return value


def _optional_size(value: Any, owner: str, field: str) -> Vec2 | None:
    if value is None:
        return None
    w, h = vec2(value, owner, field)
    extent(w, owner, f"{field}[0]")
    extent(h, owner, f"{field}[1]")
    return (w, h)



def _region(value: Any, owner: str, field: str) -> int | Rect4 | None:
    if value is None:
        return None
    if isinstance(value, int) and not isinstance(value, bool):
        if value < 0:
            raise ValidationError(f"{owner}.{field} frame index must be >= 0, got {value}")
        return value
    if isinstance(value, (tuple, list)) and len(value) == 4:
        x, y, w, h = (integer(v, owner, f"{field}[{i}]") for i, v in enumerate(value))
        if x < 0 or y < 0 or w <= 0 or h <= 0:
            raise ValidationError(
                f"{owner}.{field} must be (x >= 0, y >= 0, w > 0, h > 0) pixels, got {value!r}"
            )
        return (x, y, w, h)
    raise ComponentTypeError(
        f"{owner}.{field} must be None, a frame index or (x, y, w, h) pixels, got {value!r}"
    )


def _grid(value: Any, owner: str, field: str) -> tuple[int, int] | None:
    if value is None:
        return None
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise ComponentTypeError(f"{owner}.{field} must be (columns, rows), got {value!r}")
    cols, rows = (integer(v, owner, f"{field}[{i}]") for i, v in enumerate(value))
    if cols < 1 or rows < 1:
        raise ValidationError(f"{owner}.{field} must be (columns >= 1, rows >= 1), got {value!r}")
    return (cols, rows)


def _int(value: Any, owner: str, field: str) -> int:
    return integer(value, owner, field)


@dataclass(slots=True)
class Sprite(Tracked):
    """An image drawn at the entity's (interpolated) pose. See the module docstring."""

    #: an image name is looked up in the world's asset store at every write
    _world_fields: ClassVar[frozenset[str]] = frozenset({"image", "normal_map"})

    _checks: ClassVar[dict[str, Check]] = {
        "image": _image,
        "layer": _int,
        "order": _int,
        "anchor": anchor,
        "tint": rgb,
        "opacity": byte,
        "visible": boolean,
        "flip_x": boolean,
        "flip_y": boolean,
        "size": _optional_size,
        "region": _region,
        "grid": _grid,
        "filter": choice(TextureFilter),
        "mipmaps": boolean,
        "wrap": choice(TextureWrap),
        "tile": _optional_size,
        "scroll": vec2,
        "nine_patch": _nine_patch,
        "blend": choice(Blend),
        "normal_map": _optional_image,
    }

    image: Any
    layer: int = 0
    anchor: Vec2 = (0.5, 0.5)
    tint: RGB = (255, 255, 255)
    opacity: int = 255
    visible: bool = True
    flip_x: bool = False
    flip_y: bool = False
    size: Vec2 | None = None
    order: int = 0
    region: int | Rect4 | None = None
    grid: tuple[int, int] | None = None
    filter: TextureFilter = TextureFilter.NEAREST
    mipmaps: bool = False
    wrap: TextureWrap = TextureWrap.CLAMP
    #: metres per repeat of the image when ``wrap`` repeats (None: its own size)
    tile: Vec2 | None = None
    #: the repeated pattern's shift, in tiles
    scroll: Vec2 = (0.0, 0.0)
    nine_patch: Rect4 | None = None
    blend: Blend = Blend.ALPHA
    normal_map: Any = None

    def __post_init__(self) -> None:
        if isinstance(self.region, int) and self.grid is None:
            raise ValidationError("Sprite.region: a frame index needs grid=(columns, rows)")
        if self.wrap != "clamp" and self.nine_patch is not None:
            raise ValidationError("Sprite: nine_patch and a repeating wrap cannot be combined")

    def frame_rect(self, image_width: int, image_height: int) -> Rect4:
        """The (x, y, w, h) pixel rectangle to draw, from the image's **bottom**-left.

        Pure arithmetic, so sprite-sheet maths is testable without a window.

        >>> Sprite("s.png", region=5, grid=(4, 2)).frame_rect(64, 32)
        (16, 0, 16, 16)
        >>> Sprite("s.png", region=(0, 0, 8, 4)).frame_rect(64, 32)
        (0, 28, 8, 4)
        """
        region = self.region
        if region is None:
            return (0, 0, image_width, image_height)
        if isinstance(region, int):
            if self.grid is None:
                raise ValidationError("Sprite.region: a frame index needs grid=(columns, rows)")
            cols, rows = self.grid
            if region >= cols * rows:
                raise ValidationError(
                    f"Sprite.region: frame {region} is outside the {cols}x{rows} grid"
                )
            w, h = image_width // cols, image_height // rows
            col, row = region % cols, region // cols
            return (col * w, image_height - (row + 1) * h, w, h)
        x, y, w, h = region
        if x + w > image_width or y + h > image_height:
            raise ValidationError(
                f"Sprite.region {region!r} is outside the {image_width}x{image_height} image"
            )
        return (x, image_height - y - h, w, h)
