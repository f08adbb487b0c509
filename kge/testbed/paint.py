"""Painted art drawn in code: smooth images for linear filtering, normal maps, panels, a
pixel font. Used by the rendering samples, the platformer and night examples, the
docs pictures and the render benchmarks; every image is a pure function (no files,
no randomness beyond fixed seeds).

Arrays are (height, width, 4) uint8 RGBA, rows top-down (numpy / PNG order); turn
them into sprite images with :func:`kge.render.images.from_array`.

>>> sky(8, 4).shape, crate(32).shape, bool(crate_normals(32)[16, 16, 2] > 200)
((4, 8, 4), (32, 32, 4), True)
>>> PIXEL_CHARS in pixel_font_sheet()[1]
True
"""

from __future__ import annotations

import numpy as np

Image = np.ndarray


def _grid(w: int, h: int) -> tuple[np.ndarray, np.ndarray]:
    """Pixel centres scaled to 0..1 (x right, y down)."""
    y, x = np.mgrid[0:h, 0:w].astype(float)
    return (x + 0.5) / w, (y + 0.5) / h


def _pack(rgb: np.ndarray, alpha: np.ndarray | float = 1.0) -> Image:
    a = np.broadcast_to(np.asarray(alpha, float), rgb.shape[:2])
    out = np.concatenate([rgb, a[..., None] * 255.0], axis=-1)
    return np.clip(np.rint(out), 0, 255).astype(np.uint8)


def _mix(a: tuple[float, ...], b: tuple[float, ...], t: np.ndarray) -> np.ndarray:
    return np.asarray(a, float) * (1 - t[..., None]) + np.asarray(b, float) * t[..., None]


def sky(w: int = 256, h: int = 128, top: tuple[int, int, int] = (40, 70, 140),
        bottom: tuple[int, int, int] = (250, 190, 140)) -> Image:  # fmt: skip
    """A dusk gradient with soft, wide clouds."""
    x, y = _grid(w, h)
    rgb = _mix(top, bottom, y**1.4)
    clouds = np.clip(np.sin(x * 9.0 + np.sin(y * 7.0) * 1.5) * np.sin(y * 5.0 + 1.0), 0, 1)
    rgb = rgb + clouds[..., None] * 40.0 * (1.0 - y[..., None])
    return _pack(rgb)


def hills(w: int = 256, h: int = 96, color: tuple[int, int, int] = (60, 110, 80),
          waves: int = 3, seed: float = 0.0) -> Image:  # fmt: skip
    """A strip of rolling hills, transparent above, that tiles left to right (``waves``
    whole periods across), shaded lighter at the crests."""
    x, y = _grid(w, h)
    t = 2 * np.pi * x
    crest = 0.45 + 0.18 * np.sin(waves * t + seed) + 0.08 * np.sin(2 * waves * t + 2 * seed + 1)
    inside = np.clip((y - crest) * h / 1.5, 0.0, 1.0)  # anti-aliased edge
    shade = np.clip(1.15 - (y - crest) * 1.2, 0.6, 1.15)
    rgb = np.asarray(color, float)[None, None, :] * shade[..., None]
    return _pack(rgb, inside)


def crate(size: int = 64) -> Image:
    """A painted wooden crate: planks, bevelled frame, a diagonal brace."""
    x, y = _grid(size, size)
    wood = 0.85 + 0.15 * np.sin(y * size * 0.9 + np.sin(x * 13.0) * 2.0)
    rgb = np.stack([165 * wood, 110 * wood, 60 * wood], axis=-1)
    edge = np.minimum(np.minimum(x, 1 - x), np.minimum(y, 1 - y))
    frame = edge < 0.14
    brace = np.abs(x - y) < 0.09
    dark = frame | brace
    rgb[dark] *= 0.72
    bevel = np.clip(1.0 - edge / 0.04, 0.0, 1.0)
    rgb *= (1.0 - 0.35 * bevel)[..., None]
    return _pack(rgb)


def crate_normals(size: int = 64) -> Image:
    """The crate's normal map: the frame and brace raised, bevels sloping out, planks
    grooved (x right, y up, z out of the picture; packed as 0.5 + 0.5 * n)."""
    x, y = _grid(size, size)
    edge = np.minimum(np.minimum(x, 1 - x), np.minimum(y, 1 - y))
    height = np.where((edge < 0.14) | (np.abs(x - y) < 0.09), 1.0, 0.0)
    height = height + np.clip(edge / 0.05, 0.0, 1.0) * 0.6  # bevel to the outer rim
    height = height - 0.25 * (np.sin(y * size * 0.9) > 0.93)  # plank grooves
    gy, gx = np.gradient(height * size * 0.08)
    n = np.stack([-gx, gy, np.ones_like(gx)], axis=-1)  # image y runs down: flip its slope
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    return _pack((n * 0.5 + 0.5) * 255.0)


def hero(size: int = 64, body: tuple[int, int, int] = (225, 80, 70)) -> Image:
    """A round, softly shaded character with eyes (transparent around it)."""
    x, y = _grid(size, size)
    dx, dy = (x - 0.5) / 0.42, (y - 0.55) / 0.44
    d = np.hypot(dx, dy)
    inside = np.clip((1.0 - d) * size * 0.4, 0.0, 1.0)
    light = np.clip(1.1 - 0.5 * (dx + 0.6) ** 2 - 0.5 * (dy + 0.6) ** 2, 0.55, 1.15)
    rgb = np.asarray(body, float)[None, None, :] * light[..., None]
    for ex in (0.38, 0.62):
        eye = np.hypot(x - ex, y - 0.45) < 0.08
        pupil = np.hypot(x - ex - 0.02, y - 0.46) < 0.04
        rgb[eye] = 250.0
        rgb[pupil] = 25.0
    return _pack(rgb, inside)


def orb(size: int = 32, color: tuple[int, int, int] = (255, 220, 90)) -> Image:
    """A glowing coin-like orb: a bright core fading out (for bloom and glow)."""
    x, y = _grid(size, size)
    d = np.hypot(x - 0.5, y - 0.5) / 0.5
    alpha = np.clip(1.0 - d, 0.0, 1.0) ** 0.7
    core = np.clip(1.0 - d / 0.55, 0.0, 1.0)
    rgb = np.asarray(color, float)[None, None, :] * (0.75 + 0.25 * core[..., None])
    rgb = rgb + (255.0 - rgb) * core[..., None] ** 2
    return _pack(rgb, alpha)


def panel(size: int = 24, border: int = 6, fill: tuple[int, int, int] = (40, 46, 70),
          rim: tuple[int, int, int] = (200, 170, 90)) -> Image:  # fmt: skip
    """A UI panel for nine-patch drawing: a rounded gold rim ``border`` pixels wide."""
    y, x = np.mgrid[0:size, 0:size].astype(float) + 0.5
    inner = size / 2 - border
    q = np.maximum(np.abs(x - size / 2) - inner, 0.0), np.maximum(np.abs(y - size / 2) - inner, 0)
    r = np.hypot(*q)
    rgb = np.where((r > 1.0)[..., None], np.asarray(rim, float), np.asarray(fill, float))
    alpha = np.clip(border - r + 0.5, 0.0, 1.0)
    return _pack(rgb, alpha)


#: the characters of :func:`pixel_font_sheet`, in sheet order
PIXEL_CHARS = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ:!"
_GLYPHS = {  # 5 x 7, one string per row, top first
    "0": "01110 10001 10011 10101 11001 10001 01110",
    "1": "00100 01100 00100 00100 00100 00100 01110",
    "2": "01110 10001 00001 00110 01000 10000 11111",
    "3": "11110 00001 00001 01110 00001 00001 11110",
    "4": "00010 00110 01010 10010 11111 00010 00010",
    "5": "11111 10000 11110 00001 00001 10001 01110",
    "6": "00110 01000 10000 11110 10001 10001 01110",
    "7": "11111 00001 00010 00100 01000 01000 01000",
    "8": "01110 10001 10001 01110 10001 10001 01110",
    "9": "01110 10001 10001 01111 00001 00010 01100",
    "A": "01110 10001 10001 11111 10001 10001 10001",
    "B": "11110 10001 10001 11110 10001 10001 11110",
    "C": "01110 10001 10000 10000 10000 10001 01110",
    "D": "11110 10001 10001 10001 10001 10001 11110",
    "E": "11111 10000 10000 11110 10000 10000 11111",
    "F": "11111 10000 10000 11110 10000 10000 10000",
    "J": "00111 00010 00010 00010 00010 10010 01100",
    "Q": "01110 10001 10001 10001 10101 10010 01101",
    "W": "10001 10001 10001 10101 10101 10101 01010",
    "Z": "11111 00001 00010 00100 01000 10000 11111",
    "G": "01110 10001 10000 10111 10001 10001 01111",
    "H": "10001 10001 10001 11111 10001 10001 10001",
    "I": "01110 00100 00100 00100 00100 00100 01110",
    "K": "10001 10010 10100 11000 10100 10010 10001",
    "L": "10000 10000 10000 10000 10000 10000 11111",
    "M": "10001 11011 10101 10101 10001 10001 10001",
    "N": "10001 11001 10101 10011 10001 10001 10001",
    "O": "01110 10001 10001 10001 10001 10001 01110",
    "P": "11110 10001 10001 11110 10000 10000 10000",
    "R": "11110 10001 10001 11110 10100 10010 10001",
    "S": "01111 10000 10000 01110 00001 00001 11110",
    "T": "11111 00100 00100 00100 00100 00100 00100",
    "U": "10001 10001 10001 10001 10001 10001 01110",
    "V": "10001 10001 10001 10001 10001 01010 00100",
    "X": "10001 10001 01010 00100 01010 10001 10001",
    "Y": "10001 10001 01010 00100 00100 00100 00100",
    ":": "00000 00100 00100 00000 00100 00100 00000",
    "!": "00100 00100 00100 00100 00100 00000 00100",
}  # fmt: skip


def pixel_font_sheet(color: tuple[int, int, int] = (255, 255, 255)) -> tuple[Image, str]:
    """A bitmap font sheet: 6 x 8 cells (5 x 7 glyphs, a baseline row), 11 per row;
    returns the image and its characters (for :class:`kge.text.bitmap.BitmapFont`)."""
    cols = 11
    rows = -(-len(PIXEL_CHARS) // cols)
    sheet = np.zeros((rows * 8, cols * 6, 4), np.uint8)
    for i, ch in enumerate(PIXEL_CHARS):
        r, c = divmod(i, cols)
        bits = np.array([[int(b) for b in row] for row in _GLYPHS[ch].split()], bool)
        cell = sheet[r * 8 : r * 8 + 7, c * 6 : c * 6 + 5]
        cell[bits] = (*color, 255)
    return sheet, PIXEL_CHARS
