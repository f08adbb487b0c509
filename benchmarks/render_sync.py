"""Render sync cost per sprite: kge's bulk numpy path beside pyglet's ``Sprite.update``.

What is timed, per frame, for N moving sprites (same texture, one batch,
headless EGL), all in the same run and interleaved so background load hits
every variant alike; the report gives medians over the repetitions:

* ``bulk_write``: kge's :class:`~kge.render.bulk.BulkPoser` writing N poses
  (translation, rotation, culling scale) into the batch's vertex buffers; this
  is the part that replaces one Python call per sprite;
* ``blend``: blending previous/current poses of N entities by alpha after a
  physics step moved them all. Nothing is read from the Transforms: physics
  handed its history over (``record`` + ``adopt``), so it is numpy over the table;
* ``blend_written``: the same after user code wrote all N Transforms outside
  the fixed step (an ``on_update`` script moving everything every frame), the
  worst case: each written Transform is read again (not part of ``kge_sync``);
* ``kge_sync``: both together, i.e. everything kge does per frame to move N
  sprites before the draw call;
* ``frame``: a whole ``app.render()`` (sync, GL upload and llvmpipe drawing);
* ``record``: what the renderer does once per *fixed step* (not per frame): roll
  the history, read the Transforms user code wrote (none here: physics' sync-out
  writes without marks) and adopt physics' previous/current poses;
* ``sprite_update``: ``pyglet.sprite.Sprite.update(x=, y=, rotation=)`` for N
  sprites, the per-sprite Python path kge avoids;
* ``sprite_props``: ``sprite.position = ...; sprite.rotation = ...``, pyglet
  2.1's recommended setters.

Run ``python benchmarks/render_sync.py`` (add ``--sizes 1000 5000``) for the
table; :func:`measure` with a small N is what the test suite calls.
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from typing import Any

os.environ.setdefault("PYGLET_HEADLESS", "1")

if __package__ in (None, ""):  # run as a script: make the repository importable
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

import numpy as np

from kge.components.tracked import raw_set

VARIANTS = (
    "bulk_write",
    "blend",
    "kge_sync",
    "frame",
    "record",
    "blend_written",
    "sprite_update",
    "sprite_props",
)


def _build(n: int) -> tuple[Any, Any, list[Any], list[Any]]:
    import pyglet

    from kge import App, Transform
    from kge.components.camera import Camera
    from kge.components.sprite import Sprite
    from kge.render.images import solid
    from kge.systems.render import RenderSystem

    img = solid(8, 8, (255, 200, 0))
    rng = np.random.default_rng(1)
    xs = rng.uniform(-7.0, 7.0, n)
    ys = rng.uniform(-4.0, 4.0, n)

    def scene(world: Any) -> None:
        world.insert_resource(Camera(pixels_per_meter=64))
        for x, y in zip(xs, ys, strict=True):
            world.spawn(Transform(float(x), float(y)), Sprite(img, size=(0.125, 0.125)))

    app = App(scene, headless=True, size=(960, 540))
    app.render()
    system = app.world.get_system(RenderSystem)
    assert system is not None, "App.render() adds the RenderSystem"
    view = system.view
    transforms = [t for _, (t,) in sorted(app.world.query(Transform), key=lambda item: item[0])]
    batch = pyglet.graphics.Batch()
    tex = pyglet.image.ImageData(8, 8, "RGBA", bytes((255, 200, 0, 255)) * 64).get_texture()
    plain = [
        pyglet.sprite.Sprite(tex, float(x) * 64, float(y) * 64, batch=batch)
        for x, y in zip(xs, ys, strict=True)
    ]
    return app, view, transforms, plain


def measure(n: int, repeats: int = 7) -> dict[str, float]:
    """Median microseconds per sprite for each variant, measured in one run."""
    app, view, transforms, plain = _build(n)
    samples: dict[str, list[float]] = {v: [] for v in VARIANTS}
    viewport = (-7.5, -4.2, 7.5, 4.2)
    rng = np.random.default_rng(2)

    def write() -> None:
        """User code moves every Transform a little (tracked writes)."""
        jitter = rng.uniform(-0.01, 0.01, (len(transforms), 2))
        for t, (dx, dy) in zip(transforms, jitter, strict=True):
            t.x += float(dx)
            t.y += float(dy)
            t.angle += 0.01

    from kge import Transform

    entities = np.array(sorted(e for e, _ in app.world.query(Transform)))
    now = np.array([(t.x, t.y, t.angle) for t in transforms])

    def move() -> None:
        """What a physics step does: sync-out writes every Transform (no marks), then
        the renderer records the step and adopts physics' history of the bodies."""
        nonlocal now
        before = now
        now = before + rng.uniform(-0.01, 0.01, before.shape)
        for t, (x, y, a) in zip(transforms, now.tolist(), strict=True):
            raw_set(t, "x", x)
            raw_set(t, "y", y)
            raw_set(t, "angle", a)
        t0 = time.perf_counter()
        view.poses.record()
        view.poses.adopt(entities, before, now)
        samples["record"].append(time.perf_counter() - t0)

    for rep in range(repeats):
        move()
        t0 = time.perf_counter()
        poses = view.poses.blend(0.5)
        samples["blend"].append(time.perf_counter() - t0)

        t0 = time.perf_counter()
        view.sprites.poser.write(poses, viewport)
        samples["bulk_write"].append(time.perf_counter() - t0)

        move()
        t0 = time.perf_counter()
        poses = view.poses.blend(0.5)
        view.sprites.poser.write(poses, viewport)
        samples["kge_sync"].append(time.perf_counter() - t0)

        t0 = time.perf_counter()
        app.render()
        samples["frame"].append(time.perf_counter() - t0)

        write()  # outside the fixed step: every row is marked
        t0 = time.perf_counter()
        view.poses.blend(0.5)
        samples["blend_written"].append(time.perf_counter() - t0)

        a = 0.01 * rep
        t0 = time.perf_counter()
        for s in plain:
            s.update(x=s._x + 0.1, y=s._y, rotation=a)
        samples["sprite_update"].append(time.perf_counter() - t0)

        t0 = time.perf_counter()
        for s in plain:
            s.position = (s._x + 0.1, s._y, 0.0)
            s.rotation = a
        samples["sprite_props"].append(time.perf_counter() - t0)
    for s in plain:
        s.delete()
    app.close()
    return {k: statistics.median(v) / n * 1e6 for k, v in samples.items()}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[1000, 5000, 10000])
    parser.add_argument("--repeats", type=int, default=9)
    args = parser.parse_args(argv)
    print("render sync, microseconds per sprite (median of", args.repeats, "repetitions)")
    print(f"{'sprites':>8} " + " ".join(f"{v:>13}" for v in VARIANTS) + "  update/bulk")
    for n in args.sizes:
        r = measure(n, args.repeats)
        ratio = r["sprite_update"] / r["bulk_write"] if r["bulk_write"] else float("nan")
        print(f"{n:>8} " + " ".join(f"{r[v]:>13.3f}" for v in VARIANTS) + f"  {ratio:>10.1f}x")
    return 0


if __name__ == "__main__":
    sys.exit(main())
