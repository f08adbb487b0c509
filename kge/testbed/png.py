"""A minimal PNG writer (RGB or RGBA from a numpy array), so contact sheets and
generated images need no imaging library.

>>> import numpy as np, zlib
>>> data = encode(np.zeros((2, 3, 4), dtype=np.uint8))
>>> data[:8] == b"\\x89PNG\\r\\n\\x1a\\n"
True
"""

from __future__ import annotations

import struct
import zlib
from pathlib import Path

import numpy as np
import numpy.typing as npt


def _chunk(kind: bytes, payload: bytes) -> bytes:
    body = kind + payload
    return struct.pack(">I", len(payload)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def encode(pixels: npt.NDArray[np.uint8]) -> bytes:
    """PNG bytes of an (height, width, 3 or 4) uint8 array, first row at the top."""
    if pixels.ndim != 3 or pixels.shape[2] not in (3, 4) or pixels.dtype != np.uint8:
        raise ValueError(f"expected an (h, w, 3|4) uint8 array, got {pixels.shape} {pixels.dtype}")
    h, w, c = pixels.shape
    rows = np.concatenate([np.zeros((h, 1), dtype=np.uint8), pixels.reshape(h, w * c)], axis=1)
    header = struct.pack(">IIBBBBB", w, h, 8, 6 if c == 4 else 2, 0, 0, 0)
    return (
        b"\x89PNG\r\n\x1a\n"
        + _chunk(b"IHDR", header)
        + _chunk(b"IDAT", zlib.compress(rows.tobytes(), 6))
        + _chunk(b"IEND", b"")
    )


def write(path: str | Path, pixels: npt.NDArray[np.uint8]) -> None:
    Path(path).write_bytes(encode(pixels))
