"""Animation cost per item and frame: kge's numpy path beside pyglet's animated Sprite.

What is timed, for N animated sprites whose clip changes frame *every* frame
(8 frames of 1/60 s, the worst case), headless EGL, all in the same run and
interleaved so background load hits every variant alike; medians over the
repetitions, in microseconds per sprite (or tween) per frame:

* ``advance``: :class:`~kge.systems.animation.AnimationSystem` for one frame
  (component sync, the numpy advance of every animator, events);
* ``texcoords``: the render pass writing every animated sprite's texture
  coordinates into the batch's vertex buffers (numpy gather + assignment);
* ``upload``: committing that buffer to the GPU (``glBufferSubData``);
* ``kge_total``: the three together, what kge pays per frame to animate N sprites;
* ``pyglet_sprite``: N ``pyglet.sprite.Sprite`` playing a ``pyglet.image.Animation``
  of the same 8 frames, driven by pyglet's clock (one ``_animate`` call and one
  texture swap per sprite per frame: pyglet's own path);
* ``tweens``: :class:`~kge.systems.animation.TweenSystem` advancing N live tweens
  (``Transform.x``, sine in-out, yoyo forever) and writing them back;
* ``crossfade``: the same N sprites all cross-fading between two clips (a fade longer
  than the run): the advance, the texture coordinates and the ghost sprites that draw
  the outgoing frames (:mod:`kge.render.crossfade`); fades are transient, so this is the
  cost per sprite *while* it fades;
* ``timeline``: :class:`~kge.systems.timeline.TimelineSystem` playing N looping
  timelines of two property tracks each (``Transform.x`` linear, ``Transform.y``
  cubic), per player and frame (sampling + the write-back into the components);
* ``arcade_sprite``: Arcade 3's ``TextureAnimationSprite`` (``update_animation`` +
  buffer upload), run by ``benchmarks/arcade_animation.py`` in ``.venv-arcade``
  (Arcade pins pymunk 6.9) when that venv exists; ``make bench`` creates it.

Run ``python benchmarks/animation.py`` (``--sizes 1000 10000``) for the table;
:func:`measure` with a small N is what the test suite calls.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

os.environ.setdefault("PYGLET_HEADLESS", "1")

if __package__ in (None, ""):  # run as a script: make the repository importable
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

import numpy as np

VARIANTS = ("advance", "texcoords", "upload", "kge_total", "pyglet_sprite", "tweens",
            "crossfade", "timeline")
DT = 1.0 / 60.0


def _sheet() -> Any:
    from kge.render.images import PixelImage

    arr = np.zeros((8, 64, 4), np.uint8)
    for i in range(8):
        arr[:, 8 * i : 8 * i + 8] = (30 * i, 255 - 30 * i, 128, 255)
    return PixelImage(64, 8, arr.tobytes())


def _kge(n: int, fading: bool = False) -> tuple[Any, Any, Any, Any]:
    from kge import Animator, App, Camera, Clip, Sprite, Transform
    from kge.render.passes import RenderPasses
    from kge.systems.animation import AnimationSystem, _AtlasPass

    sheet = _sheet()
    clip = Clip.grid(sheet, (8, 1), duration=DT)
    rng = np.random.default_rng(1)
    xs, ys = rng.uniform(-7.0, 7.0, n), rng.uniform(-4.0, 4.0, n)

    def scene(world: Any) -> None:
        world.insert_resource(Camera(pixels_per_meter=64))
        for x, y in zip(xs.tolist(), ys.tolist(), strict=True):
            world.spawn(Transform(x, y), Sprite(sheet, size=(0.125, 0.125)),
                        Animator({"run": clip, "back": back}))

    back = Clip.grid(sheet, (8, 1), duration=DT, flip_x=True)
    app = App(scene, headless=True, size=(960, 540))
    app.render()
    if fading:
        for _, (anim,) in app.world.query(Animator):
            anim.play("back", fade=3600.0)
        app.render()
    system = app.world.get_system(AnimationSystem)
    atlas = next(p for p in app.world.resource(RenderPasses).before() if isinstance(p, _AtlasPass))
    return app, system, atlas, clip


def _pyglet(n: int) -> tuple[Any, Any]:
    import pyglet

    fake = [0.0]
    clock = pyglet.clock.Clock(time_function=lambda: fake[0])
    old = pyglet.clock._default
    pyglet.clock._default = clock  # pyglet's Sprite schedules on the default clock
    try:
        sheet = _sheet()
        tex = pyglet.image.ImageData(64, 8, "RGBA", sheet.pixels).get_texture()
        # regions of one texture: pyglet's fast path (a texture swap only rewrites tex coords)
        frames = [tex.get_region(8 * i, 0, 8, 8) for i in range(8)]
        anim = pyglet.image.Animation.from_image_sequence(frames, DT, loop=True)  # type: ignore[arg-type]
        batch = pyglet.graphics.Batch()
        rng = np.random.default_rng(1)
        sprites = [pyglet.sprite.Sprite(anim, float(x), float(y), batch=batch)
                   for x, y in rng.uniform(0, 900, (n, 2)).tolist()]
    finally:
        pyglet.clock._default = old

    def tick() -> None:
        # each ``_animate`` reschedules itself on the default clock: keep ours there
        fake[0] += DT
        saved = pyglet.clock._default
        pyglet.clock._default = clock
        try:
            clock.tick()
        finally:
            pyglet.clock._default = saved

    return sprites, tick


def _tweens(n: int) -> tuple[Any, Any]:
    from kge import Transform, Tweens, World
    from kge.systems.animation import AnimationPlugin, TweenSystem

    w = World()
    w.add_plugins(AnimationPlugin())
    tweens = w.resource(Tweens)
    for i in range(n):
        e = w.spawn(Transform(float(i % 100), 0.0))
        tweens.to(e, Transform, "x", float(i % 100) + 1.0, 0.5 + (i % 7) * 0.1,
                  ease="sine_in_out", repeat=-1, yoyo=True)
    system = w.get_system(TweenSystem)
    assert system is not None
    return w, system


def _timelines(n: int) -> tuple[Any, Any]:
    from kge import Transform, World
    from kge.components.timeline import Keys, Timeline, TimelinePlayer
    from kge.systems.animation import AnimationPlugin
    from kge.systems.timeline import TimelineSystem

    w = World()
    w.add_plugins(AnimationPlugin())
    tl = Timeline([Keys(Transform, "x", [(0.0, 0.0), (0.5, 1.0), (1.0, 0.0)]),
                   Keys(Transform, "y", [(0.0, 0.0), (0.3, 1.0), (0.7, -1.0), (1.0, 0.0)],
                        interp="cubic")], loop=True)
    for i in range(n):
        w.spawn(Transform(), TimelinePlayer({"bob": tl}, speed=0.5 + (i % 7) * 0.1))
    system = w.get_system(TimelineSystem)
    assert system is not None
    return w, system


def measure(n: int, repeats: int = 9) -> dict[str, float]:
    """Median microseconds per sprite (tween) and frame for each variant, in one run."""
    app, system, atlas, _ = _kge(n)
    frames = atlas.frames
    fade_app, fade_system, fade_atlas, _ = _kge(n, fading=True)
    sprites, tick = _pyglet(n)
    tw_world, tw_system = _tweens(n)
    tl_world, tl_system = _timelines(n)
    samples: dict[str, list[float]] = {v: [] for v in VARIANTS}
    buffers = [d[0].attrib_name_buffers["tex_coords"] for d in frames._domains] or []
    for _ in range(3):  # warm-up (first writes index the domains)
        system.process(DT)
        frames.write()
        tick()
        tw_system.process(DT)
        tl_system.process(DT)
    buffers = [d[0].attrib_name_buffers["tex_coords"] for d in frames._domains]
    assert frames.write() == n, "every animated sprite is on the atlas"
    for _ in range(repeats):
        t0 = time.perf_counter()
        system.process(DT)
        t1 = time.perf_counter()
        frames.write()
        t2 = time.perf_counter()
        for buf in buffers:
            buf.commit()
        t3 = time.perf_counter()
        samples["advance"].append(t1 - t0)
        samples["texcoords"].append(t2 - t1)
        samples["upload"].append(t3 - t2)
        samples["kge_total"].append(t3 - t0)

        t0 = time.perf_counter()
        tick()
        samples["pyglet_sprite"].append(time.perf_counter() - t0)

        t0 = time.perf_counter()
        tw_system.process(DT)
        samples["tweens"].append(time.perf_counter() - t0)

        t0 = time.perf_counter()
        fade_system.process(DT)
        fade_atlas(fade_atlas.current)
        samples["crossfade"].append(time.perf_counter() - t0)

        t0 = time.perf_counter()
        tl_system.process(DT)
        samples["timeline"].append(time.perf_counter() - t0)
    assert len(fade_atlas.ghosts) == n, "every fading sprite has a ghost"
    for s in sprites:
        s.delete()
    fade_app.close()
    tl_world.close()
    app.close()
    tw_world.close()
    return {k: statistics.median(v) * 1e6 / n for k, v in samples.items()}


ARCADE_PYTHON = Path(__file__).resolve().parents[1] / ".venv-arcade" / "bin" / "python"


def measure_arcade(sizes: tuple[int, ...], repeats: int, python: str | None = None
                   ) -> dict[int, float]:
    """Arcade 3's TextureAnimationSprite in its own venv (``make bench`` makes it):
    µs per sprite and frame by size. Raises when that venv is missing or fails."""
    exe = python or os.environ.get("KGE_ARCADE_PYTHON") or str(ARCADE_PYTHON)
    if not Path(exe).exists():
        raise FileNotFoundError(f"no Arcade venv at {exe} (make bench creates .venv-arcade)")
    script = Path(__file__).with_name("arcade_animation.py")
    done = subprocess.run(
        [exe, str(script), "--sizes", *map(str, sizes), "--repeats", str(repeats)],
        capture_output=True, text=True, timeout=900, check=False,
    )
    if done.returncode != 0:
        raise RuntimeError(f"Arcade run failed: {done.stderr.strip().splitlines()[-1:]}")
    data = json.loads(done.stdout.strip().splitlines()[-1])
    return {int(n): float(r["arcade_sprite"]) for n, r in data.items()}


def table(results: dict[int, dict[str, float]]) -> str:
    extra = any("arcade_sprite" in r for r in results.values())
    cols = (*VARIANTS, "arcade_sprite") if extra else VARIANTS
    lines = [f"{'N':>8}" + "".join(f"{c:>15}" for c in cols) + f"{'pyglet/kge':>12}"
             + (f"{'arcade/kge':>12}" if extra else "")]
    for n, r in sorted(results.items()):
        line = f"{n:>8}" + "".join(f"{r.get(c, float('nan')):>15.3f}" for c in cols)
        line += f"{r['pyglet_sprite'] / r['kge_total']:>12.1f}"
        if extra:
            line += f"{r.get('arcade_sprite', float('nan')) / r['kge_total']:>12.1f}"
        lines.append(line)
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0] if __doc__ else "")
    parser.add_argument("--sizes", type=int, nargs="+", default=[1000, 10000])
    parser.add_argument("--repeats", type=int, default=15)
    args = parser.parse_args(argv)
    results = {n: measure(n, args.repeats) for n in args.sizes}
    try:
        for n, us in measure_arcade(tuple(args.sizes), args.repeats).items():
            results[n]["arcade_sprite"] = us
    except (OSError, RuntimeError, ValueError) as err:
        print(f"Arcade skipped: {err}", file=sys.stderr)
    print("µs per sprite (tween) per frame, median:")
    print(table(results))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
