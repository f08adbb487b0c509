"""Arcade 3's ``TextureAnimationSprite``, timed the way benchmarks/animation.py times kge.

Runs in its own virtual environment (Arcade pins pymunk 6.9, kge needs 7.3), made
by ``make bench`` as ``.venv-arcade``; it imports nothing from kge. For N sprites
of one ``SpriteList`` playing the same 8 frames of 1/60 s (16 ms keyframes: every
sprite changes frame every frame), per frame: ``SpriteList.update_animation(dt)``
(Arcade's per-sprite Python path) and ``write_sprite_buffers_to_gpu()`` (its
upload of the changed texture coordinates), in microseconds per sprite, median
over the repetitions. Prints one JSON object: ``{"N": {"arcade_sprite": us}}``.

    .venv-arcade/bin/python benchmarks/arcade_animation.py --sizes 1000 10000
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import time

os.environ.setdefault("ARCADE_HEADLESS", "1")
DT = 1.0 / 60.0


def measure(n: int, repeats: int) -> float:
    import arcade
    from PIL import Image

    textures = [
        arcade.Texture(Image.new("RGBA", (8, 8), (30 * i, 255 - 30 * i, 128, 255)),
                       hash=f"frame-{i}")
        for i in range(8)
    ]
    animation = arcade.TextureAnimation([arcade.TextureKeyframe(t, 16) for t in textures])
    sprites = arcade.SpriteList()
    for i in range(n):
        sprites.append(arcade.TextureAnimationSprite(
            center_x=(i * 37) % 900, center_y=(i * 91) % 500, animation=animation))
    sprites.write_sprite_buffers_to_gpu()
    before = [s._current_keyframe_index for s in sprites]
    sprites.update_animation(DT)
    changed = sum(a != s._current_keyframe_index for a, s in zip(before, sprites, strict=True))
    assert changed >= 0.9 * n, f"only {changed} of {n} sprites changed frame"
    samples = []
    for _ in range(3 + repeats):
        t0 = time.perf_counter()
        sprites.update_animation(DT)
        sprites.write_sprite_buffers_to_gpu()
        samples.append(time.perf_counter() - t0)
    return statistics.median(samples[3:]) * 1e6 / n


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--sizes", type=int, nargs="+", default=[1000, 10000])
    parser.add_argument("--repeats", type=int, default=9)
    args = parser.parse_args()
    import arcade

    window = arcade.Window(64, 64, visible=False)
    out = {str(n): {"arcade_sprite": measure(n, args.repeats)} for n in args.sizes}
    window.close()
    print(json.dumps(out))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
