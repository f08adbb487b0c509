"""Turning located files into pyglet objects, importing pyglet lazily.

``import pyglet.image`` and ``import pyglet.media`` both import pyglet's GL
module, which opens a display connection (pymunk-notes.md §4.1). On a machine
with no display that fails unless pyglet's headless mode was chosen *before*
the first GL import, so :func:`pyglet_module` switches headless mode on when
there is no display and GL is not loaded yet. Everything else in
:mod:`kge.assets` stays importable and testable without pyglet.

Decoder failures are translated into :class:`~kge.assets.errors.AssetDecodeError`
naming the file. Sounds are decoded by soundfile (:mod:`kge.assets.sounds`):
WAV, OGG, MP3 and FLAC need no system library.
"""

from __future__ import annotations

import importlib
import io
import sys
from types import ModuleType
from typing import Any

from kge.assets.errors import AssetDecodeError
from kge.assets.locate import Found
from kge.sound import SoundData

IMAGE_SUFFIXES = frozenset({".png", ".jpg", ".jpeg", ".bmp", ".gif", ".dds", ".tga"})
SOUND_SUFFIXES = frozenset({".wav", ".wave", ".ogg", ".oga", ".mp3", ".flac", ".opus", ".m4a"})
FONT_SUFFIXES = frozenset({".ttf", ".otf", ".ttc"})

def pyglet_module(name: str) -> ModuleType:
    """Import ``pyglet.<name>``, choosing headless mode first when there is no display."""
    if "pyglet.gl" not in sys.modules:
        import pyglet

        from kge.platform import has_display

        if not has_display():
            pyglet.options["headless"] = True
    return importlib.import_module(f"pyglet.{name}")


#: largest image decoded (width x height); a game can raise it
MAX_IMAGE_PIXELS = 16384 * 16384


def load_image(found: Found) -> Any:
    """Decode an image file into a ``pyglet.image.ImageData`` (no GL texture yet).

    Pillow decodes the whole file here, so a truncated or zero-byte PNG, a PNG
    header of 0 x 0 pixels or an image over :data:`MAX_IMAGE_PIXELS` fails at
    this call (never at a later frame), and every image arrives as 8-bit RGBA
    (a 1 x 1 GIF without a colour table included).
    """
    pyglet_module("image")  # headless mode is chosen before Pillow runs
    return image_from_pixels(*decode_image(found))


def decode_image(found: Found) -> tuple[int, int, bytes]:
    """Read and decode an image with Pillow: (width, height, RGBA bytes bottom row first).
    Touches no pyglet, so a worker thread may call it."""
    try:
        data = found.read_bytes()
    except OSError as exc:
        raise AssetDecodeError(found.name, found.where, f"unreadable: {exc}") from exc
    if not data:
        raise AssetDecodeError(found.name, found.where, "the file is empty (0 bytes)")
    from PIL import Image

    try:
        with Image.open(io.BytesIO(data)) as im:
            w, h = im.size
            if w <= 0 or h <= 0:
                raise AssetDecodeError(found.name, found.where, f"the image is {w} x {h} pixels")
            if w * h > MAX_IMAGE_PIXELS:
                raise AssetDecodeError(
                    found.name, found.where,
                    f"{w} x {h} pixels is over kge.assets.loaders.MAX_IMAGE_PIXELS",
                )
            im.load()
            rgba = im.convert("RGBA").transpose(Image.Transpose.FLIP_TOP_BOTTOM)
            pixels = rgba.tobytes()
    except AssetDecodeError:
        raise
    except Exception as exc:  # Pillow's many decoder errors
        raise AssetDecodeError(
            found.name, found.where, f"not a readable image ({type(exc).__name__}: {exc})"
        ) from exc
    return w, h, pixels


def image_from_pixels(w: int, h: int, pixels: bytes) -> Any:
    """Decoded RGBA pixels as a ``pyglet.image.ImageData`` (the GL texture is made on the
    main thread at first draw)."""
    return pyglet_module("image").ImageData(w, h, "RGBA", pixels)


def load_sound(found: Found, streaming: bool) -> Any:
    """Decode a sound file into a pyglet ``StaticSource`` or ``StreamingSource``.

    Every format goes through soundfile (:mod:`kge.assets.sounds`): WAV of any
    common depth, OGG Vorbis/Opus, MP3 and FLAC, with no system library. Errors
    are raised here, at the call, never at a later frame.
    """
    from kge.assets.sounds import static_source, streaming_source

    try:
        data = found.read_bytes()
    except OSError as exc:
        raise AssetDecodeError(found.name, found.where, f"unreadable: {exc}") from exc
    media = pyglet_module("media")
    if streaming:
        return streaming_source(media, data, found.name, found.where)
    return static_source(media, data, found.name, found.where)


def sound_from_pcm(pcm: Any, rate: int) -> Any:
    """Decoded 16-bit frames (``kge.assets.sounds.decode``) as a pyglet ``StaticSource``."""
    from kge.assets.sounds import static_from_pcm

    return static_from_pcm(pyglet_module("media"), pcm, rate)


def load_generated(sound: SoundData) -> Any:
    """A generated sound as a pyglet ``StaticSource`` (through the built-in WAV decoder)."""
    media = pyglet_module("media")
    return media.load(f"{sound.name}.wav", file=io.BytesIO(sound.to_wav()), streaming=False)


def register_font(found: Found) -> None:
    """Make the font file's face available to text (kge's registry; pyglet on first draw).

    The registry (:data:`kge.text.fonts.FONTS`) knows each face's weight and slant, so
    a file whose face is a Light Italic is drawn as one, whatever style asks for it.
    """
    from kge.text.fonts import FONTS

    try:
        FONTS.register(found.read_bytes(), found.where)
    except OSError as exc:
        raise AssetDecodeError(found.name, found.where, f"unreadable: {exc}") from exc
