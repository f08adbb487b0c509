"""Animated GIFs: a :class:`~kge.components.animation.Clip` with the file's own frame durations.

Pillow decodes the file. :func:`gif_clip` reads only what timing needs (frame
count and each frame's delay) and returns a clip whose frames name the GIF and a
frame number; the renderer decodes the pixels with :func:`gif_frames` when it
packs them into its atlas. GIF delays are hundredths of a second; a delay of 0
or 1 (which browsers also refuse) counts as 0.1 s.

``path`` is a file path, or an asset name when ``assets`` (an asset store:
``kge.assets.assets_for(world)``) is given to resolve it.
"""

from __future__ import annotations

import io
import os
from functools import lru_cache
from typing import Any

import numpy as np

from kge.components.animation import Clip, FrameRef, Loop
from kge.errors import ValidationError

DEFAULT_DELAY = 0.1


def _open(data: bytes, name: str) -> Any:
    from PIL import Image, UnidentifiedImageError

    try:
        img = Image.open(io.BytesIO(data))
    except UnidentifiedImageError as exc:
        raise ValidationError(f"GIF {name!r}: not an image Pillow can read") from exc
    if img.format != "GIF":
        raise ValidationError(f"GIF {name!r}: the file is a {img.format}, not a GIF")
    return img


def _read(path: Any, assets: Any = None) -> tuple[str, bytes]:
    if assets is not None:
        return str(path), assets.bytes(path)
    name = os.fspath(path)
    try:
        with open(name, "rb") as f:
            return name, f.read()
    except OSError as exc:
        raise ValidationError(f"GIF {name!r}: cannot read the file ({exc.strerror})") from exc


def gif_durations(data: bytes, name: str = "<gif>") -> list[float]:
    """Seconds per frame of a GIF held in ``data``."""
    img = _open(data, name)
    out = []
    for i in range(getattr(img, "n_frames", 1)):
        img.seek(i)
        ms = img.info.get("duration", 0) or 0
        out.append(ms / 1000.0 if ms > 10 else DEFAULT_DELAY)
    return out


def gif_clip(path: Any, *, assets: Any = None, **options: Any) -> Clip:
    """A clip playing the GIF at ``path`` with its own frame durations.

    ``options`` are :meth:`Clip.images`'s (``loop``, ``speed``, flips, ``events``);
    ``duration=`` or ``fps=`` override the file's timing.
    """
    name, data = _read(path, assets)
    durations = gif_durations(data, name)
    if "duration" not in options and "fps" not in options:
        options["duration"] = durations
    allowed = {"duration", "fps", "loop", "speed", "flip_x", "flip_y", "events"}
    unknown = sorted(set(options) - allowed)
    if unknown:
        raise TypeError(f"gif_clip() got unexpected options: {', '.join(unknown)}")
    refs = [FrameRef(os.fspath(path), gif_frame=i) for i in range(len(durations))]
    return Clip._make(
        refs,
        options.get("duration"),
        options.get("fps"),
        options.get("loop", Loop.LOOP),
        options.get("speed", 1.0),
        options.get("flip_x", False),
        options.get("flip_y", False),
        options.get("events"),
    )


@lru_cache(maxsize=32)
def _decoded(data: bytes) -> tuple[np.ndarray, ...]:
    img = _open(data, "<gif>")
    frames = []
    for i in range(getattr(img, "n_frames", 1)):
        img.seek(i)
        frames.append(np.asarray(img.convert("RGBA"), dtype=np.uint8)[::-1].copy())
    return tuple(frames)


def gif_frames(data: bytes) -> tuple[np.ndarray, ...]:
    """Every frame of a GIF as an (h, w, 4) RGBA array, rows bottom-up (OpenGL order),
    composed the way a browser shows it (Pillow applies disposal and transparency)."""
    return _decoded(data)
