"""In-memory images that need no file and no GL context: ``solid``, ``checker``, arrays.

A :class:`PixelImage` is plain data (size and RGBA bytes, rows bottom-up as
OpenGL stores them), so it can sit in a :class:`~kge.components.sprite.Sprite`
component and be hashed: equal images share one texture. Tests, prototypes
and generated art use these instead of PNG files.

>>> img = solid(2, 1, (255, 0, 0))
>>> img.width, img.height, img.pixels
(2, 1, b'\\xff\\x00\\x00\\xff\\xff\\x00\\x00\\xff')
>>> board = checker(4, 4, 2, (0, 0, 0), (255, 255, 255))
>>> board.pixel(0, 0), board.pixel(2, 0)
((0, 0, 0, 255), (255, 255, 255, 255))
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from kge.components.color import rgba
from kge.errors import ValidationError


@dataclass(slots=True, frozen=True)
class PixelImage:
    """``width`` x ``height`` RGBA pixels, rows bottom-up (OpenGL order)."""

    width: int
    height: int
    pixels: bytes

    def __post_init__(self) -> None:
        if self.width < 1 or self.height < 1:
            raise ValidationError(f"PixelImage size must be >= 1x1, got {self.width}x{self.height}")
        if len(self.pixels) != self.width * self.height * 4:
            raise ValidationError(
                f"PixelImage needs {self.width * self.height * 4} bytes of RGBA, "
                f"got {len(self.pixels)}"
            )

    def pixel(self, x: int, y: int) -> tuple[int, int, int, int]:
        """RGBA at column ``x``, row ``y`` (from the bottom)."""
        i = (y * self.width + x) * 4
        r, g, b, a = self.pixels[i : i + 4]
        return (r, g, b, a)

    def __repr__(self) -> str:
        return f"PixelImage({self.width}x{self.height})"


def solid(width: int, height: int, color: Any = (255, 255, 255, 255)) -> PixelImage:
    """A ``width`` x ``height`` image of one colour (RGB or RGBA 0-255)."""
    c = rgba(color, "solid", "color")
    return PixelImage(int(width), int(height), bytes(c) * (int(width) * int(height)))


def checker(width: int, height: int, cell: int, a: Any, b: Any) -> PixelImage:
    """A checkerboard of ``cell``-pixel squares; colour ``a`` at the bottom-left."""
    ca, cb = (
        np.array(rgba(a, "checker", "a"), np.uint8),
        np.array(rgba(b, "checker", "b"), np.uint8),
    )
    ys, xs = np.mgrid[0:height, 0:width]
    mask = ((xs // cell + ys // cell) % 2).astype(bool)
    arr = np.where(mask[..., None], cb, ca).astype(np.uint8)
    return PixelImage(int(width), int(height), arr.tobytes())


def from_array(array: Any, *, top_down: bool = True) -> PixelImage:
    """An image from an (h, w, 3|4) uint8 array; rows top-down (as numpy/PIL) by default."""
    arr = np.asarray(array)
    if arr.ndim != 3 or arr.shape[2] not in (3, 4):
        raise ValidationError(f"from_array needs an (h, w, 3|4) array, got shape {arr.shape}")
    arr = np.clip(arr, 0, 255).astype(np.uint8)
    if arr.shape[2] == 3:
        arr = np.concatenate([arr, np.full((*arr.shape[:2], 1), 255, np.uint8)], axis=2)
    if top_down:
        arr = arr[::-1]
    h, w = arr.shape[:2]
    return PixelImage(w, h, np.ascontiguousarray(arr).tobytes())


#: texture sampling options (see :mod:`kge.render.textures`)
FILTERS = ("nearest", "linear")
WRAPS = ("clamp", "repeat", "mirror")


@dataclass(slots=True, frozen=True)
class ImageRegion:
    """Part of another image, usable wherever an image is: ``rect`` = (x, y, w, h) pixels
    from the image's top-left corner (as image editors show it).

    >>> ImageRegion("atlas.png", (32, 0, 16, 16))
    ImageRegion('atlas.png', (32, 0, 16, 16))
    >>> ImageRegion("atlas.png", (0, 0, 0, 16))
    Traceback (most recent call last):
    ...
    kge.errors.ValidationError: ImageRegion.rect must be (x >= 0, y >= 0, w > 0, h > 0) ...
    """

    image: Any
    rect: tuple[int, int, int, int]

    def __post_init__(self) -> None:
        r = self.rect
        if (
            not isinstance(r, tuple) or len(r) != 4
            or not all(isinstance(v, int) and not isinstance(v, bool) for v in r)
            or r[0] < 0 or r[1] < 0 or r[2] <= 0 or r[3] <= 0
        ):  # fmt: skip
            raise ValidationError(
                f"ImageRegion.rect must be (x >= 0, y >= 0, w > 0, h > 0) pixels, got {r!r}"
            )
        if isinstance(self.image, (ImageRegion, RenderTexture)):
            raise ValidationError("ImageRegion.image must be a whole image (a name or pixels)")

    def __repr__(self) -> str:
        return f"ImageRegion({self.image!r}, {self.rect!r})"


@dataclass(slots=True, frozen=True)
class RenderTexture:
    """What a camera with ``Camera(target="name")`` draws, as an image a Sprite can show.

    >>> RenderTexture("minimap")
    RenderTexture('minimap')
    """

    name: str

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not self.name:
            raise ValidationError(f"RenderTexture.name must be a non-empty str, got {self.name!r}")

    def __repr__(self) -> str:
        return f"RenderTexture({self.name!r})"
