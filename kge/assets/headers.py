"""Media headers checked when an asset is first named, not when it is first drawn or played.

A sprite, button, animator or sound naming a truncated PNG, a 0 x 0 image, a
100,000 x 100,000 image, a 7-bit WAV or a WAV claiming 4 GiB of samples used to
fail (or allocate until memory ran out) at the first frame drawn or the first
sound played. :func:`check_image` and :func:`check_sound` read what the file says
about itself (Pillow reads an image's header and walks its chunks' checksums
without decoding pixels; a WAV's header is parsed with the standard library) and
refuse what cannot load, so the error comes from the call that named the file.

The limits are module constants a game can raise before it loads anything.

>>> import io, struct, zlib
>>> def chunk(kind, data):
...     body = kind + data
...     return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))
>>> header = struct.pack(">IIBBBBB", 20_000, 10, 8, 6, 0, 0, 0)
>>> wide = b"\\x89PNG\\r\\n\\x1a\\n" + chunk(b"IHDR", header) + chunk(b"IEND", b"")
>>> image_size(wide)
Traceback (most recent call last):
...
ValueError: an image of 20000 x 10 pixels is larger than kge.assets.headers allows ...
"""

from __future__ import annotations

import io
import struct
import warnings
from typing import IO

#: the longest image side, pixels (what GPUs take as one texture)
MAX_IMAGE_SIDE = 16_384
#: the most pixels one image may have (64 Mpx: 256 MiB once decoded to RGBA)
MAX_IMAGE_PIXELS = 1 << 26
#: WAV sample widths pyglet's decoder plays, bits
WAV_BITS = (8, 16, 24, 32)
#: the most channels and the sample-rate range a WAV may declare
MAX_CHANNELS = 8
MIN_RATE, MAX_RATE = 1_000, 384_000
#: suffixes read as WAV (other formats go to their decoders at load)
WAV_SUFFIXES = (".wav", ".wave")


def image_size(data: bytes) -> tuple[int, int]:
    """(width, height) of the image ``data``, checked to decode; ``ValueError`` if not.

    The size is read from the header and bounded by :data:`MAX_IMAGE_SIDE` and
    :data:`MAX_IMAGE_PIXELS`; then Pillow's ``verify`` walks the file (chunk
    checksums for PNG) so a truncated or corrupt file is refused without decoding it.
    """
    from PIL import Image

    if not data:
        raise ValueError("an empty file (0 bytes)")
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error", Image.DecompressionBombWarning)
            with Image.open(io.BytesIO(data)) as img:
                w, h = int(img.width), int(img.height)
                _bounded(w, h)
                img.verify()
    except ValueError:
        raise
    except Image.UnidentifiedImageError:
        raise ValueError("not an image (no format Pillow reads starts this way)") from None
    except (Image.DecompressionBombError, Image.DecompressionBombWarning):
        raise ValueError(
            f"an image larger than kge.assets.headers allows ({MAX_IMAGE_SIDE} a side, "
            f"{MAX_IMAGE_PIXELS:,} pixels)"
        ) from None
    except Exception as exc:  # Pillow raises OSError, SyntaxError, struct.error...
        raise ValueError(f"not a readable image ({type(exc).__name__}: {exc})") from None
    return w, h


def _bounded(w: int, h: int) -> None:
    if w <= 0 or h <= 0:
        raise ValueError(f"an image of {w} x {h} pixels")
    if max(w, h) > MAX_IMAGE_SIDE or w * h > MAX_IMAGE_PIXELS:
        raise ValueError(
            f"an image of {w} x {h} pixels is larger than kge.assets.headers allows "
            f"({MAX_IMAGE_SIDE} a side, {MAX_IMAGE_PIXELS:,} pixels)"
        )


def wav_info(f: IO[bytes]) -> tuple[int, int, int, int]:
    """(channels, rate, bits, frames) of the WAV file ``f``; ``ValueError`` if it cannot play.

    Only the chunk headers are read (a long music file is not loaded to check it).

    >>> from kge.sound import tone
    >>> wav_info(io.BytesIO(tone(440, 0.5, rate=8000).to_wav()))
    (1, 8000, 16, 4000)
    >>> wav_info(io.BytesIO(b"RIFF"))
    Traceback (most recent call last):
    ...
    ValueError: not a WAV file (no RIFF/WAVE header)
    """
    total = f.seek(0, io.SEEK_END)
    f.seek(0)
    head = f.read(12)
    if len(head) < 12 or head[:4] != b"RIFF" or head[8:12] != b"WAVE":
        raise ValueError("not a WAV file (no RIFF/WAVE header)")
    fmt: tuple[int, int, int] | None = None
    pos = 12
    while pos + 8 <= total:
        f.seek(pos)
        kind, size = struct.unpack("<4sI", f.read(8))
        body = pos + 8
        if kind == b"fmt ":
            raw = f.read(16)
            if size < 16 or len(raw) < 16:
                raise ValueError("a WAV whose format chunk is cut short")
            _, channels, rate, _, block, bits = struct.unpack("<HHIIHH", raw)
            _check_format(channels, rate, bits, block)
            fmt = (channels, rate, bits)
        elif kind == b"data":
            if fmt is None:
                raise ValueError("a WAV whose samples come before its format")
            if size > total - body:
                raise ValueError(
                    f"a WAV claiming {size:,} bytes of samples but holding {total - body:,}"
                )
            if size == 0:
                raise ValueError("a WAV with no samples")
            channels, rate, bits = fmt
            return channels, rate, bits, size // (channels * bits // 8)
        pos = body + size + (size & 1)  # chunks are padded to even sizes
    raise ValueError("a WAV with no data chunk" if fmt is not None else "a WAV with no format")


def _check_format(channels: int, rate: int, bits: int, block: int) -> None:
    if bits not in WAV_BITS:
        raise ValueError(f"a WAV of {bits}-bit samples (kge plays {WAV_BITS} bits)")
    if not 1 <= channels <= MAX_CHANNELS:
        raise ValueError(f"a WAV of {channels} channels (1..{MAX_CHANNELS})")
    if not MIN_RATE <= rate <= MAX_RATE:
        raise ValueError(f"a WAV at {rate} Hz ({MIN_RATE}..{MAX_RATE})")
    if block != channels * bits // 8:
        raise ValueError(f"a WAV whose block size {block} does not fit its samples")
