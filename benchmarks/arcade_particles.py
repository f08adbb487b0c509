"""Arcade 3's particle system on the same workload as kge's particle row (run in Arcade's venv).

Arcade is not a kge dependency: it pins its own pyglet and pymunk, so it lives in
a virtual environment of its own, and ``kge bench`` runs this file there as a
subprocess (``KGE_ARCADE_PYTHON=/path/to/arcade-venv/bin/python``). It prints one
JSON object: median ms per frame for ``update`` (Arcade's ``Emitter.update``:
births, the per-particle ``update`` with the gravity and drag mutation, reaping)
and ``upload`` (``SpriteList.write_sprite_buffers_to_gpu``, Arcade's vertex
write), over N live particles kept steady as in kge's row: rate N/s, lifetime
1 s, gravity, drag, fading alpha, a soft-dot texture, additive-looking colours.

Usage: ``python benchmarks/arcade_particles.py 5000 30``.
"""

from __future__ import annotations

import json
import math
import os
import random
import statistics
import sys
import time

os.environ.setdefault("ARCADE_HEADLESS", "1")

import arcade
from arcade.particles import EmitInterval, Emitter, FadeParticle

PPM = 32.0  # Arcade works in pixels and per-frame velocities: 1 m = 32 px
DT = 1.0 / 60.0


def measure(n: int, repeats: int) -> dict[str, float]:
    arcade.Window(320, 240, visible=False)
    texture = arcade.make_soft_circle_texture(16, arcade.color.ORANGE)
    rng = random.Random(1)
    drag = 0.3

    def mutate(p: FadeParticle) -> None:
        # gravity 9.8 m/s^2 and linear drag, in Arcade's px-per-frame velocities
        p.change_y -= 9.8 * PPM * DT * DT
        p.change_x *= 1.0 - drag * DT
        p.change_y *= 1.0 - drag * DT

    def factory(emitter: Emitter) -> FadeParticle:
        speed = rng.uniform(2.0, 5.0) * PPM * DT
        angle = 1.5708 + rng.uniform(-0.6, 0.6)
        return FadeParticle(
            texture, (speed * math.cos(angle), speed * math.sin(angle)), lifetime=1.0,
            change_angle=rng.uniform(-2.0, 2.0), scale=0.5, mutation_callback=mutate,
        )  # fmt: skip

    emitter = Emitter((160.0, 40.0), EmitInterval(1.0 / n), factory)
    for _ in range(75):  # prewarm past one lifetime: a steady population
        emitter.update(DT)
    update, upload, live = [], [], []
    for _ in range(repeats):
        t0 = time.perf_counter()
        emitter.update(DT)
        t1 = time.perf_counter()
        emitter._particles.write_sprite_buffers_to_gpu()
        t2 = time.perf_counter()
        update.append((t1 - t0) * 1e3)
        upload.append((t2 - t1) * 1e3)
        live.append(emitter.get_count())
    return {
        "update": statistics.median(update),
        "upload": statistics.median(upload),
        "total": statistics.median(u + w for u, w in zip(update, upload, strict=True)),
        "live": float(statistics.median(live)),
        "version": arcade.version.VERSION,  # type: ignore[dict-item]
    }


if __name__ == "__main__":
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 5000
    reps = int(sys.argv[2]) if len(sys.argv) > 2 else 30
    print(json.dumps(measure(n, reps)))
