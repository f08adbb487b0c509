"""Arcade 3's ``load_tilemap`` on a map file, timed: run by *Arcade's* Python.

kge and Arcade need different pyglet and pymunk versions, so Arcade lives in its
own virtual environment and this script runs there (it imports nothing of kge):

    python -m venv /tmp/arcade-venv && /tmp/arcade-venv/bin/pip install "arcade>=3,<4"
    KGE_ARCADE_PYTHON=/tmp/arcade-venv/bin/python python benchmarks/tilemap.py --size 300

It prints one line: seconds and sprites. Arcade makes one sprite per tile (with a
spatial hash for the layer, as its platformer tutorial does), kge merged colliders.
"""

import os
import sys
import time

os.environ.setdefault("ARCADE_HEADLESS", "1")


def main() -> None:
    import arcade

    path, layer = sys.argv[1], sys.argv[2]
    t0 = time.perf_counter()
    tile_map = arcade.load_tilemap(
        path, scaling=1.0, layer_options={layer: {"use_spatial_hash": True}}
    )
    seconds = time.perf_counter() - t0
    print(f"{seconds} {len(tile_map.sprite_lists[layer])}")


if __name__ == "__main__":
    main()
