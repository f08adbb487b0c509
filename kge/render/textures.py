"""Turn image values into pyglet textures, once per distinct image and sampling options.

Accepted values: an asset name or path (looked up through the world's asset store,
:func:`kge.assets.assets_for`, else loaded from the path), a
:class:`kge.render.images.PixelImage`, an :class:`~kge.render.images.ImageRegion`
(part of another image), a :class:`~kge.render.images.RenderTexture` (what a camera
draws into), or a pyglet image object. Equal keys share one texture, so all sprites
of one image land in one vertex domain and draw in one call.

Sampling belongs to the texture: ``filter`` (``"nearest"`` keeps pixel art crisp,
``"linear"`` smooths painted art that is scaled or turned), ``mipmaps`` (smaller
copies for art drawn much smaller than its pixels: no shimmer) and ``wrap``
(``"clamp"``, ``"repeat"``: a tiled sky is one sprite, ``"mirror"``). The same image
with other options is another texture.
"""

from __future__ import annotations

import os
import weakref
from collections.abc import Callable
from typing import Any

from kge.errors import ValidationError
from kge.render.images import FILTERS, WRAPS, ImageRegion, PixelImage, RenderTexture


def _resolves_to(name: str, world: Any) -> str | None:
    if world is not None:
        from kge.assets import assets_for

        found = assets_for(world).find(name)
        return None if found is None or found.path is None else os.path.realpath(found.path)
    return os.path.realpath(name)


def forget_file(path: str) -> list[str]:
    """Every cache drops the textures made from the file ``path`` (its image changed);
    returns the image names that pointed at it, so their sprites can be redrawn."""
    names: list[str] = []
    for cache in list(_CACHES):
        names += cache.forget_file(path)
    return names


def _load_path(name: str, world: Any) -> Any:
    if world is not None:
        from kge.assets import assets_for

        return assets_for(world).image(name)
    import pyglet

    try:
        return pyglet.image.load(name)
    except FileNotFoundError as exc:
        raise ValidationError(f"image {name!r} not found") from exc


def check_options(filter: str, wrap: str) -> None:
    if filter not in FILTERS:
        raise ValidationError(f"texture filter must be one of {FILTERS}, got {filter!r}")
    if wrap not in WRAPS:
        raise ValidationError(f"texture wrap must be one of {WRAPS}, got {wrap!r}")


#: every live cache, so a changed image file reaches them all (hot reload)
_CACHES: weakref.WeakSet[TextureCache] = weakref.WeakSet()


class TextureCache:
    """Image value (and sampling options) -> pyglet texture (with its pixel size)."""

    def __init__(self, world: Any = None) -> None:
        self.world = world
        self._cache: dict[Any, Any] = {}
        #: ``fn(name) -> texture``: the textures cameras draw into (set by the renderer)
        self.render_textures: Callable[[str], Any] | None = None
        _CACHES.add(self)

    def forget_file(self, path: str) -> list[str]:
        """Drop the textures of image names that resolve to the file ``path`` (with any
        sampling options); the names."""
        target = os.path.realpath(path)
        dropped: list[str] = []
        for key in [k for k in self._cache if isinstance(k[0], str)]:
            if _resolves_to(key[0], self.world) == target:
                del self._cache[key]
                if key[0] not in dropped:
                    dropped.append(key[0])
        return dropped

    @staticmethod
    def key(image: Any) -> Any:
        if isinstance(image, (str, PixelImage, ImageRegion, RenderTexture)):
            return image
        return ("object", id(image))

    def texture(self, image: Any, filter: str = "nearest", mipmaps: bool = False,
                wrap: str = "clamp") -> Any:  # fmt: skip
        """The pyglet Texture for ``image`` (loaded and uploaded on first use)."""
        if isinstance(image, RenderTexture):
            if self.render_textures is None:
                raise ValidationError(f"{image!r}: no camera draws into it")
            return self.render_textures(image.name)
        if isinstance(image, ImageRegion):
            whole = self.texture(image.image, filter, mipmaps, wrap)
            x, y, w, h = image.rect
            if x + w > whole.width or y + h > whole.height:
                raise ValidationError(
                    f"{image!r} is outside the {whole.width}x{whole.height} image"
                )
            return whole.get_region(x, whole.height - y - h, w, h)
        k = (self.key(image), filter, mipmaps, wrap)
        tex = self._cache.get(k)
        if tex is None:
            check_options(filter, wrap)
            tex = self._cache[k] = self._make(image, filter, mipmaps, wrap)
        return tex

    def _make(self, image: Any, filter: str, mipmaps: bool, wrap: str) -> Any:
        import pyglet
        from pyglet import gl

        if isinstance(image, PixelImage):
            img = pyglet.image.ImageData(image.width, image.height, "RGBA", image.pixels)
        elif isinstance(image, str):
            img = _load_path(image, self.world)
        elif hasattr(image, "get_texture"):
            img = image
        else:
            raise ValidationError(f"cannot draw {image!r}: not an asset name, PixelImage or image")
        linear = filter == "linear"
        mag = gl.GL_LINEAR if linear else gl.GL_NEAREST
        if mipmaps:
            minf = gl.GL_LINEAR_MIPMAP_LINEAR if linear else gl.GL_NEAREST_MIPMAP_NEAREST
        else:
            minf = mag
        data = img.get_image_data()
        tex = pyglet.image.Texture.create(data.width, data.height, min_filter=minf, mag_filter=mag)
        tex.blit_into(data, 0, 0, 0)
        gl.glBindTexture(tex.target, tex.id)
        mode = {"clamp": gl.GL_CLAMP_TO_EDGE, "repeat": gl.GL_REPEAT,
                "mirror": gl.GL_MIRRORED_REPEAT}[wrap]  # fmt: skip
        gl.glTexParameteri(tex.target, gl.GL_TEXTURE_WRAP_S, mode)
        gl.glTexParameteri(tex.target, gl.GL_TEXTURE_WRAP_T, mode)
        if mipmaps:
            gl.glGenerateMipmap(tex.target)
        return tex

    def clear(self) -> None:
        self._cache.clear()
