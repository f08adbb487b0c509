"""Turning located files into pyglet objects, importing pyglet lazily.

``import pyglet.image`` and ``import pyglet.media`` both import pyglet's GL
module, which opens a display connection (pymunk-notes.md §4.1). On a machine
with no display that fails unless pyglet's headless mode was chosen *before*
the first GL import, so :func:`pyglet_module` switches headless mode on when
there is no display and GL is not loaded yet. Everything else in
:mod:`kge.assets` stays importable and testable without pyglet.

Decoder failures are translated into :class:`~kge.assets.errors.AssetDecodeError`
with a hint: pyglet reads WAV by itself, but OGG, MP3 and FLAC need FFmpeg's
shared libraries (or PyOgg for OGG/FLAC), and the error says so.
"""

from __future__ import annotations

import importlib
import io
import sys
from types import ModuleType
from typing import Any

from kge.assets.errors import AssetDecodeError, DecoderMissingError
from kge.assets.locate import Found
from kge.sound import SoundData

IMAGE_SUFFIXES = frozenset({".png", ".jpg", ".jpeg", ".bmp", ".gif", ".dds", ".tga"})
SOUND_SUFFIXES = frozenset({".wav", ".wave", ".ogg", ".oga", ".mp3", ".flac", ".opus", ".m4a"})
FONT_SUFFIXES = frozenset({".ttf", ".otf", ".ttc"})

_DECODER_HINTS = {
    ".ogg": "FFmpeg shared libraries (Debian/Ubuntu: apt install libavformat59 libavcodec59 "
    "libswresample4 libavutil57; macOS: brew install ffmpeg; Windows: put the FFmpeg DLLs "
    "on PATH) or PyOgg (pip install pyogg, plus libvorbisfile: apt install libvorbisfile3)",
    ".mp3": "FFmpeg shared libraries (Debian/Ubuntu: apt install libavformat59 libavcodec59 "
    "libswresample4 libavutil57; macOS: brew install ffmpeg; Windows: put the FFmpeg DLLs "
    "on PATH)",
}
_DECODER_HINTS[".oga"] = _DECODER_HINTS[".ogg"]
_DECODER_HINTS[".opus"] = _DECODER_HINTS[".ogg"]
_DECODER_HINTS[".flac"] = _DECODER_HINTS[".ogg"].replace("libvorbisfile3", "libflac12")


def pyglet_module(name: str) -> ModuleType:
    """Import ``pyglet.<name>``, choosing headless mode first when there is no display."""
    if "pyglet.gl" not in sys.modules:
        import pyglet

        from kge.platform import has_display

        if not has_display():
            pyglet.options["headless"] = True
    return importlib.import_module(f"pyglet.{name}")


def decoder_hint(suffix: str) -> str:
    """How to make pyglet decode ``suffix`` (``.ogg``...), in one sentence."""
    hint = _DECODER_HINTS.get(suffix.lower())
    if hint is None:
        return "pyglet decodes WAV without extra libraries; convert the file to WAV"
    return f"install {hint}, or convert the file to WAV (decoded with no extra dependency)"


def available_decoders(suffix: str) -> list[str]:
    """Names of the pyglet decoders registered for ``suffix`` on this machine."""
    media = pyglet_module("media")
    return [type(d).__name__ for d in media.codecs.registry.get_decoders(suffix)]


def load_image(found: Found) -> Any:
    """Decode an image file into a ``pyglet.image.AbstractImage`` (no GL texture yet)."""
    image_mod = pyglet_module("image")
    try:
        data = found.read_bytes()
        return image_mod.load(found.name, file=io.BytesIO(data))
    except OSError as exc:
        raise AssetDecodeError(found.name, found.where, f"unreadable: {exc}") from exc
    except Exception as exc:  # pyglet's ImageDecodeException and friends
        raise AssetDecodeError(
            found.name, found.where, f"not a readable image ({type(exc).__name__}: {exc})"
        ) from exc


def load_sound(found: Found, streaming: bool) -> Any:
    """Decode a sound file into a pyglet ``StaticSource`` or ``StreamingSource``."""
    media = pyglet_module("media")
    suffix = found.suffix
    try:
        path = found.path
        if streaming and path is not None:  # pyglet keeps reading the file while it plays
            return media.load(str(path), streaming=True)
        return media.load(found.name, file=io.BytesIO(found.read_bytes()), streaming=streaming)
    except OSError as exc:
        raise AssetDecodeError(found.name, found.where, f"unreadable: {exc}") from exc
    except Exception as exc:
        if not media.codecs.registry.get_decoders(suffix or found.name):
            raise DecoderMissingError(
                found.name,
                found.where,
                f"no audio decoder for {suffix or 'this file type'} is available on this "
                f"machine; {decoder_hint(suffix)}",
            ) from exc
        raise AssetDecodeError(
            found.name, found.where, f"the {suffix} decoder failed ({type(exc).__name__}: {exc})"
        ) from exc


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
