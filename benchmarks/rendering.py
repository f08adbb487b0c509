"""Rendering features per frame, headless on software GL: the rendering rows of ``kge bench``.

Each row is a pair of variants of one scene at 960 x 540, drawn alternately in the
same run (so background load hits both alike), ``glFinish`` after every frame;
medians of the process's CPU time per frame (llvmpipe rasterises on worker threads
of this process, so CPU time counts all of its work and little of other jobs'):

* ``lights``: a game frame (a painted sky and two layers of hills, a tiled ground, 36
  crates, rain, a HUD) with 6 lights casting shadows from the crates, beside the same
  frame with lighting off; ``lights_soft`` with 0.3 m soft shadows; ``lights_bare``
  the lights over a bare frame (one flat background and the crates: the cheapest
  unlit frame there is). The goal: lit / unlit <= 2;
* ``text``: 100 labels, static (drawn only), and one label of the 100 changing its
  text every frame (laid out and baked again);
* ``materials``: 1,000 sprites through a custom material shader beside the plain one
  (equal uniforms: they share one draw call); ``materials_each`` with a different
  uniform value each (a draw call each, as animated materials are drawn);
* ``post``: one camera with bloom, colour grading, vignette and CRT beside none;
* ``cameras``: split screen plus a minimap (three cameras) beside one camera.

Run ``python benchmarks/rendering.py`` for the table; :func:`run_section` is what
``kge bench`` calls (``quick``: a few frames, for the test suite).
"""

from __future__ import annotations

import math
import os
import statistics
import sys
import time
from collections.abc import Callable
from typing import Any

os.environ.setdefault("PYGLET_HEADLESS", "1")

if __package__ in (None, ""):  # run as a script: make the repository importable
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

import numpy as np

SIZE = (960, 540)
#: lit / unlit frame time on software GL, at most (issue 33)
LIGHT_GOAL = 2.0
Row = dict[str, float]


def from_array(arr: Any) -> Any:
    from kge.render.images import from_array as make

    return make(arr)


def _gradient(w: int, h: int, top: tuple[int, int, int], bottom: tuple[int, int, int]) -> Any:
    t = np.linspace(0.0, 1.0, h)[:, None, None]
    arr = np.broadcast_to((1 - t) * np.array(top) + t * np.array(bottom), (h, w, 3))
    return from_array(arr.astype(np.uint8))


def street(world: Any, lights: int = 6, softness: float = 0.0, bare: bool = False) -> None:
    """The lights scene (see the module docstring)."""
    from kge import (
        Camera,
        Collider,
        EmitBox,
        Light,
        Lighting,
        ParticleEmitter,
        Sprite,
        Text,
        TextureFilter,
        TextureWrap,
        Transform,
    )  # fmt: skip
    from kge.components.shapes import Box
    from kge.testbed import paint

    rng = np.random.default_rng(7)
    world.insert_resource(Camera(pixels_per_meter=32))
    world.insert_resource(Lighting(ambient=(30, 32, 50)))
    crate = from_array(paint.crate(32))
    if bare:
        world.spawn(Transform(0, 0), Sprite(_gradient(4, 4, (150, 140, 130), (150, 140, 130)),
                                            size=(31.0, 18.0)))  # fmt: skip
    else:
        world.spawn(Transform(0, 0), Sprite(from_array(paint.sky()), size=(31.0, 18.0),
                                            filter=TextureFilter.LINEAR))  # fmt: skip
        for y, color in ((-1.0, (70, 90, 110)), (-3.0, (60, 110, 80))):
            world.spawn(Transform(0, y), Sprite(from_array(paint.hills(color=color)),
                                                size=(31.0, 10.0), filter=TextureFilter.LINEAR,
                                                wrap=TextureWrap.REPEAT,
                                                tile=(15.5, 10.0)))  # fmt: skip
        world.spawn(Transform(0, -6.5), Sprite(crate, size=(31.0, 4.0), wrap=TextureWrap.REPEAT,
                                               tile=(1.0, 1.0)))  # fmt: skip
    for x, y in rng.uniform((-14, -4), (14, 7), (36, 2)):
        world.spawn(Transform(float(x), float(y), float(rng.uniform(0, 3))),
                    Collider(Box(0.4, 0.4)), Sprite(crate, size=(0.8, 0.8)))  # fmt: skip
    for x, y in rng.uniform((-12, -3), (12, 6), (lights, 2)):
        world.spawn(Transform(float(x), float(y)), Light(
            radius=7.0, color=(int(rng.integers(150, 256)), int(rng.integers(150, 256)), 255),
            shadows=True, shadow_softness=softness))  # fmt: skip
    if bare:
        return
    world.spawn(Transform(0, 9), ParticleEmitter(
        rate=600.0, shape=EmitBox(30.0, 0.1), direction=-math.pi / 2, speed=(9.0, 11.0),
        lifetime=1.6, size=0.06, color=(170, 190, 230), opacity=153, flat=True, seed=3))
    world.spawn(Text("score 1200", size=18, screen_space=True, offset=(12, 528), anchor=(0, 1)))


def _labels(world: Any, n: int = 100) -> None:
    from kge import Camera, Text, Transform

    world.insert_resource(Camera(pixels_per_meter=32))
    for i in range(n):
        world.spawn(Transform(-14 + (i % 10) * 3.0, -7 + (i // 10) * 1.5),
                    Text(f"label {i}", size=12, outline=1.0))  # fmt: skip


_SHADER = """
uniform float wave;
vec4 effect(vec4 color, sampler2D tex, vec2 uv, vec2 world)
{
    vec4 c = texture(tex, uv) * color;
    return vec4(c.rgb * (0.8 + 0.2 * sin(world.x * 3.0 + time * wave)), c.a);
}
"""


def _sprites(world: Any, material: bool, n: int = 1000, distinct: bool = False) -> None:
    from kge import Camera, Material, Shader, Sprite, Transform

    world.insert_resource(Camera(pixels_per_meter=32))
    from kge.testbed import paint

    crate, shader = from_array(paint.crate(32)), Shader(_SHADER, name="wave")
    rng = np.random.default_rng(1)
    for i, (x, y) in enumerate(rng.uniform((-14, -8), (14, 8), (n, 2))):
        wave = 2.0 + 0.001 * i if distinct else 2.0  # distinct values: a draw call each
        extra = (Material(shader, {"wave": wave}),) if material else ()
        world.spawn(Transform(float(x), float(y)), Sprite(crate, size=(0.5, 0.5)), *extra)


def _timed(app: Any) -> tuple[float, float]:
    """(CPU ms, wall ms) of one rendered frame, GL finished."""
    from pyglet import gl

    c0, w0 = time.process_time(), time.perf_counter()
    app.render()
    gl.glFinish()
    return (time.process_time() - c0) * 1e3, (time.perf_counter() - w0) * 1e3


def pair(app: Any, a: Callable[[], None], b: Callable[[], None], frames: int) -> Row:
    """Alternate ``a`` and ``b`` (each sets the scene up) frame by frame; medians."""
    got: dict[str, list[tuple[float, float]]] = {"a": [], "b": []}
    for _ in range(3):  # warm up both (programs, textures, bakes)
        a()
        _timed(app)
        b()
        _timed(app)
    for _ in range(frames):
        a()
        got["a"].append(_timed(app))
        b()
        got["b"].append(_timed(app))
    out = {}
    for key, samples in got.items():
        out[f"{key}_cpu"] = statistics.median(s[0] for s in samples)
        out[f"{key}_wall"] = statistics.median(s[1] for s in samples)
    out["ratio"] = out["a_cpu"] / max(out["b_cpu"], 1e-9)
    return out


def measure_lights(frames: int, softness: float = 0.0, bare: bool = False) -> Row:
    from kge import App, Lighting

    app = App(lambda w: street(w, softness=softness, bare=bare), headless=True, size=SIZE)
    app.step(30)
    lighting = app.world.resource(Lighting)

    def lit() -> None:
        lighting.enabled = True

    def unlit() -> None:
        lighting.enabled = False

    row = pair(app, lit, unlit, frames)
    app.close()
    return row


def measure_text(frames: int) -> Row:
    from kge import App, Text

    app = App(_labels, headless=True, size=SIZE)
    app.step(1)
    label = app.world.query(Text)[0][1][0]
    count = [0]

    def change() -> None:
        count[0] += 1
        label.text = f"label {count[0]}"

    row = pair(app, change, lambda: None, frames)
    started = time.perf_counter()
    from kge.render.text import measure

    for i in range(50):
        measure(f"Measured {i} times, wrapped in a box", size=14, width=120)
    row["measure_ms"] = (time.perf_counter() - started) * 1e3 / 50
    app.close()
    return row


def measure_materials(frames: int, distinct: bool = False) -> Row:
    from kge import App

    apps = [App(lambda w, m=m: _sprites(w, m, distinct=distinct), headless=True, size=SIZE)
            for m in (True, False)]  # fmt: skip
    for app in apps:
        app.step(1)
    a_cpu, b_cpu = [], []
    for _ in range(3 + frames):
        a_cpu.append(_timed(apps[0])[0])
        b_cpu.append(_timed(apps[1])[0])
    for app in apps:
        app.close()
    a, b = statistics.median(a_cpu[3:]), statistics.median(b_cpu[3:])
    return {"a_cpu": a, "b_cpu": b, "ratio": a / max(b, 1e-9)}


def measure_post(frames: int) -> Row:
    from kge import CRT, App, Bloom, Camera, ColorGrade, Vignette

    app = App(street, headless=True, size=SIZE)
    app.step(1)
    cam = app.world.resource(Camera)
    stack = (Bloom(), ColorGrade(saturation=1.2), Vignette(), CRT())

    def post() -> None:
        cam.post = stack

    def plain() -> None:
        cam.post = ()

    row = pair(app, post, plain, frames)
    app.close()
    return row


def measure_cameras(frames: int) -> Row:
    from kge import App, Camera

    app = App(street, headless=True, size=SIZE)
    app.step(1)
    main = app.world.resource(Camera)
    extra = [Camera(viewport=(0.5, 0.0, 0.5, 1.0), pixels_per_meter=32, center=(6.0, 0.0)),
             Camera(viewport=(0.75, 0.7, 0.23, 0.28), pixels_per_meter=8,
                    background=(0, 0, 0), order=1)]  # fmt: skip
    entities: list[int] = []

    def split() -> None:
        main.viewport = (0.0, 0.0, 0.5, 1.0)
        if not entities:
            entities.append(app.world.spawn(main))
            entities.extend(app.world.spawn(c) for c in extra)
            app.world.flush()

    def single() -> None:
        main.viewport = (0.0, 0.0, 1.0, 1.0)
        for e in entities:
            app.world.despawn(e)
        entities.clear()
        app.world.flush()

    row = pair(app, split, single, frames)
    app.close()
    return row


def run_section(quick: bool, progress: Callable[[str], None]) -> tuple[dict[str, Row], str | None]:
    """Every row (see the module docstring), or why it could not run."""
    frames = 3 if quick else 25
    try:
        rows: dict[str, Row] = {}
        for name, fn in (("lights", lambda: measure_lights(frames)),
                         ("lights_soft", lambda: measure_lights(frames, 0.3)),
                         ("lights_bare", lambda: measure_lights(frames, bare=True)),
                         ("text", lambda: measure_text(frames)),
                         ("materials", lambda: measure_materials(frames)),
                         ("materials_each", lambda: measure_materials(frames, True)),
                         ("post", lambda: measure_post(frames)),
                         ("cameras", lambda: measure_cameras(frames))):  # fmt: skip
            progress(f"rendering [{name}]")
            rows[name] = fn()
        return rows, None
    except Exception as err:  # no GL (headless EGL missing): report, do not fail the run
        return {}, f"rendering skipped: {type(err).__name__}: {err}"


_LABELS = {
    "lights": ("6 lights with shadows", "lighting off"),
    "lights_soft": ("6 lights, 0.3 m soft shadows", "lighting off"),
    "lights_bare": ("6 lights over a bare frame", "lighting off"),
    "text": ("100 labels, one changing each frame", "100 static labels"),
    "materials": ("1,000 sprites, one alike material", "1,000 plain sprites"),
    "materials_each": ("1,000 sprites, each its own uniforms", "1,000 plain sprites"),
    "post": ("bloom + grade + vignette + CRT", "no post effects"),
    "cameras": ("split screen + minimap (3 cameras)", "one camera"),
}


def lines(rows: dict[str, Row]) -> list[str]:
    """Markdown lines of the section."""
    out = ["", "Rendering features at 960 x 540 on software GL (llvmpipe), CPU ms per frame "
           "(median, the two variants alternated in one run):", "",
           "| row | variant | ms | beside | ms | ratio |", "|---|---|---:|---|---:|---:|"]
    for name, r in rows.items():
        a, b = _LABELS.get(name, (name, "baseline"))
        out.append(f"| {name} | {a} | {r['a_cpu']:.2f} | {b} | {r['b_cpu']:.2f} "
                   f"| {r['ratio']:.2f} |")  # fmt: skip
    if "text" in rows:
        out.append(f"\n`measure()` of a wrapped label: {rows['text']['measure_ms']:.3f} ms.")
    return out


def targets(rows: dict[str, Row]) -> list[dict[str, Any]]:
    """The issue's rendering targets beside the measured figures (``kge bench`` rows)."""
    lights = rows.get("lights")
    value = None if lights is None else lights["ratio"]
    return [{
        "target": "6 shadowed lights / lighting off, game frame, software GL 960x540 (CPU)",
        "value": value, "goal": LIGHT_GOAL, "at_most": True, "unit": "x",
        "met": None if value is None else value <= LIGHT_GOAL,
    }]  # fmt: skip


def main() -> int:
    rows, why = run_section(False, lambda msg: print(msg, file=sys.stderr))
    if why:
        print(why)
        return 1
    print("\n".join(lines(rows)))
    for t in targets(rows):
        print(f"{t['target']}: {t['value']:.2f} {t['unit']} (goal <= {t['goal']:g} {t['unit']})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
