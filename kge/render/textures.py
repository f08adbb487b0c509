"""Turn ``Sprite.image`` values into pyglet textures, once per distinct image.

Accepted values: an asset name or path (looked up through the world's asset
store, :func:`kge.assets.assets_for`, else loaded from the path), a
:class:`kge.render.images.PixelImage`, or a pyglet image object. Equal keys
share one texture, so all sprites of one image land in one vertex domain and
draw in one call.
"""

from __future__ import annotations

import os
import weakref
from typing import Any

from kge.errors import ValidationError
from kge.render.images import PixelImage


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


#: every live cache, so a changed image file reaches them all (hot reload)
_CACHES: weakref.WeakSet[TextureCache] = weakref.WeakSet()


class TextureCache:
    """Image value -> pyglet texture (with its pixel size)."""

    def __init__(self, world: Any = None) -> None:
        self.world = world
        self._cache: dict[Any, Any] = {}
        _CACHES.add(self)

    def forget_file(self, path: str) -> list[str]:
        """Drop the textures of image names that resolve to the file ``path``; the names."""
        target = os.path.realpath(path)
        dropped = []
        for key in [k for k in self._cache if isinstance(k, str)]:
            if _resolves_to(key, self.world) == target:
                del self._cache[key]
                dropped.append(key)
        return dropped

    @staticmethod
    def key(image: Any) -> Any:
        if isinstance(image, (str, PixelImage)):
            return image
        return ("object", id(image))

    def texture(self, image: Any) -> Any:
        """The pyglet Texture for ``image`` (loaded and uploaded on first use)."""
        k = self.key(image)
        tex = self._cache.get(k)
        if tex is None:
            tex = self._cache[k] = self._make(image)
        return tex

    def _make(self, image: Any) -> Any:
        import pyglet

        if isinstance(image, PixelImage):
            img = pyglet.image.ImageData(image.width, image.height, "RGBA", image.pixels)
        elif isinstance(image, str):
            img = _load_path(image, self.world)
        elif hasattr(image, "get_texture"):
            img = image
        else:
            raise ValidationError(f"cannot draw {image!r}: not an asset name, PixelImage or image")
        tex = img.get_texture()
        # Pixel art stays crisp when scaled up; smooth filtering blurs 16 px sprites.
        from pyglet import gl

        gl.glBindTexture(tex.target, tex.id)
        gl.glTexParameteri(tex.target, gl.GL_TEXTURE_MAG_FILTER, gl.GL_NEAREST)
        return tex

    def clear(self) -> None:
        self._cache.clear()
