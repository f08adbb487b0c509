"""Generate the example games' sprites and sounds in code (no downloads, no third-party art).

    python tools/make_assets.py            # writes examples/assets/
    python tools/make_assets.py --out DIR

Every file is a pure function of this script: PNGs come from a tiny zlib PNG
writer below (no pyglet, no PIL), the GIF from Pillow's encoder, WAVs from
:mod:`kge.sound` through the ``wave`` module. Output is deterministic (seeded
noise, no timestamps), so re-running it leaves the committed files byte-identical.

Pong: ``pad_left.png`` (red), ``pad_right.png`` (blue), ``ball.png``,
``background.png``; ``paddle_hit.wav``, ``wall_hit.wav``, ``score.wav``,
``music_loop.wav``.
Shooter: ``ship.png``, ``enemy.png``, ``laser.png``; ``laser.wav``,
``explosion.wav``, ``death.wav`` (and the shared ``music_loop.wav``).
Animation (sheets, one row of frames each): ``hero_walk.png`` (8 frames of
32x32, a walk cycle), ``explosion_sheet.png`` (8 frames of 32x32),
``thruster.png`` (4 frames of 16x16); ``coin.gif`` (a spinning coin, 8 frames
with their own delays).
Lantern Woods (the showcase game, ``examples/lantern.py``): ``lantern_*.png``,
``lantern_*.wav`` and the Tiled level ``lantern_woods.tmx``, from
``tools/lantern_art.py``.
"""

from __future__ import annotations

import argparse
import math
import struct
import sys
import zlib
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:  # run from a checkout without installing kge
    sys.path.insert(0, str(ROOT))

from kge.sound import SoundData, melody, mix, silence, tone  # noqa: E402
from kge.testbed import png  # noqa: E402
from kge.testbed.art import SHEETS, coin_gif  # noqa: E402
from tools import lantern_art  # noqa: E402

RGBA = tuple[int, int, int, int]
Pixel = Callable[[float, float], RGBA]


# -- PNG ------------------------------------------------------------------------------
def png_bytes(width: int, height: int, pixel: Pixel) -> bytes:
    """An 8-bit RGBA PNG; ``pixel(x, y)`` gets the pixel centre, y down, in pixels."""
    rows = bytearray()
    for y in range(height):
        rows.append(0)  # filter type 0 (none) for this scanline
        for x in range(width):
            rows.extend(pixel(x + 0.5, y + 0.5))

    def chunk(kind: bytes, data: bytes) -> bytes:
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    return (
        b"\x89PNG\r\n\x1a\n"
        + chunk(b"IHDR", header)
        + chunk(b"IDAT", zlib.compress(bytes(rows), 9))
        + chunk(b"IEND", b"")
    )


def _clamp(v: float) -> int:
    return max(0, min(255, round(v)))


def glow(color: tuple[int, int, int], dist: Callable[[float, float], float], width: float) -> Pixel:
    """A neon shape: solid where ``dist <= 0``, fading out over ``width`` pixels."""

    def pixel(x: float, y: float) -> RGBA:
        d = dist(x, y)
        if d <= 0:
            core = min(1.0, -d / 2.0)  # whiten the middle of the stroke
            r, g, b = (c + (255 - c) * 0.35 * core for c in color)
            return (_clamp(r), _clamp(g), _clamp(b), 255)
        a = max(0.0, 1.0 - d / width) ** 2
        return (*color, _clamp(255 * a))

    return pixel


def rounded_bar(w: int, h: int, margin: float) -> Callable[[float, float], float]:
    """Signed distance to a capsule filling the image minus ``margin``."""
    r = (w - 2 * margin) / 2

    def dist(x: float, y: float) -> float:
        cy = min(max(y, margin + r), h - margin - r)
        return math.hypot(x - w / 2, y - cy) - r

    return dist


def ring(size: int, outer: float, inner: float) -> Callable[[float, float], float]:
    def dist(x: float, y: float) -> float:
        d = math.hypot(x - size / 2, y - size / 2)
        return max(d - outer, inner - d)

    return dist


def polygon(points: Sequence[tuple[float, float]]) -> Callable[[float, float], float]:
    """Signed distance to a convex polygon (negative inside)."""

    def dist(x: float, y: float) -> float:
        best = -math.inf
        n = len(points)
        for i in range(n):
            (x1, y1), (x2, y2) = points[i], points[(i + 1) % n]
            ex, ey = x2 - x1, y2 - y1
            length = math.hypot(ex, ey)
            # outward normal of a clockwise-in-image (counter-clockwise on screen) edge
            nx, ny = ey / length, -ex / length
            best = max(best, (x - x1) * nx + (y - y1) * ny)
        return best

    return dist


def background(size: int) -> Pixel:
    """Dark field with a faint green crosshair (KGE's pong background, redrawn)."""
    mid = size / 2

    def pixel(x: float, y: float) -> RGBA:
        d = min(abs(x - mid), abs(y - mid))
        a = max(0.0, 1.0 - d / 3.0) * 0.6
        base = 10
        return (base, _clamp(base + 180 * a), _clamp(base + 60 * a), 255)

    return pixel


def images() -> dict[str, bytes]:
    ship = [(32, 6), (58, 56), (32, 46), (6, 56)]
    enemy = [(24, 4), (44, 38), (24, 30), (4, 38)]  # nose up (image y is down), like the ship
    return {
        "pad_left.png": png_bytes(24, 116, glow((230, 40, 40), rounded_bar(24, 116, 5), 5)),
        "pad_right.png": png_bytes(24, 116, glow((50, 110, 255), rounded_bar(24, 116, 5), 5)),
        "ball.png": png_bytes(32, 32, glow((255, 190, 40), ring(32, 11, 6), 5)),
        "background.png": png_bytes(64, 64, background(64)),
        "ship.png": png_bytes(64, 64, glow((120, 200, 255), polygon(ship), 4)),
        "enemy.png": png_bytes(48, 48, glow((120, 255, 120), polygon(enemy), 4)),
        "laser.png": png_bytes(8, 24, glow((255, 80, 200), rounded_bar(8, 24, 2), 2)),
        **{name: png_bytes(*_array_pixels(make())) for name, make in SHEETS.items()},
        "coin.gif": coin_gif(),
    }


def _array_pixels(arr: Any) -> tuple[int, int, Pixel]:
    """An (h, w, 4) RGBA array (rows top-down) as ``png_bytes`` arguments."""
    h, w = arr.shape[:2]
    return w, h, lambda x, y: tuple(int(v) for v in arr[int(y), int(x)])  # type: ignore[return-value]


# -- WAV ------------------------------------------------------------------------------
RATE = 22050
MUSIC_RATE = 11025


def music_loop() -> SoundData:
    """Four bars of a minor arpeggio over a bass line, 120 bpm, loopable."""
    beat = 0.25
    arps = [
        (220.0, 261.63, 329.63),
        (174.61, 220.0, 261.63),
        (196.0, 246.94, 293.66),
        (164.81, 207.65, 246.94),
    ]
    notes: list[tuple[float, float]] = []
    for chord in arps:
        for i in range(8):
            notes.append((chord[i % 3] * (2 if i >= 4 else 1), beat / 2))
    lead = melody(notes, volume=0.22, shape="triangle", rate=MUSIC_RATE)
    bass = melody([(c[0] / 2, beat * 4) for c in arps], volume=0.25, shape="sine", rate=MUSIC_RATE)
    return mix(lead, bass)


def sounds() -> dict[str, SoundData]:
    return {
        "paddle_hit.wav": tone(660, 0.07, shape="square", volume=0.35, rate=RATE),
        "wall_hit.wav": tone(330, 0.06, shape="square", volume=0.3, rate=RATE),
        "score.wav": melody(
            [(523.25, 0.08), (659.25, 0.08), (783.99, 0.16)], volume=0.35, shape="square", rate=RATE
        ),
        "laser.wav": tone(1400, 0.16, shape="square", slide_to=300, volume=0.25, rate=RATE),
        "explosion.wav": tone(120, 0.45, shape="noise", volume=0.5, release=0.3, rate=RATE),
        "death.wav": tone(440, 0.9, shape="saw", slide_to=55, volume=0.35, release=0.3, rate=RATE)
        + silence(0.1, RATE),
        "music_loop.wav": music_loop(),
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=ROOT / "examples" / "assets")
    args = parser.parse_args(argv)
    out: Path = args.out
    out.mkdir(parents=True, exist_ok=True)
    total = 0
    files: dict[str, bytes] = dict(images())
    files.update({name: snd.to_wav() for name, snd in sounds().items()})
    files.update({name: snd.to_wav() for name, snd in lantern_art.sounds().items()})
    for name, data in sorted(files.items()):
        (out / name).write_bytes(data)
    for name, arr in lantern_art.images().items():  # Lantern Woods: numpy art, fast writer
        png.write(out / name, arr)
        files[name] = (out / name).read_bytes()
    files["lantern_woods.tmx"] = lantern_art.write_level(out).read_bytes()
    for name, data in sorted(files.items()):
        total += len(data)
        print(f"{name:18s} {len(data):7d} bytes")
    print(f"{len(files)} files, {total / 1024:.0f} KiB in {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
