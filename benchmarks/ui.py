"""UI cost per widget and frame: layout, input handling and drawing, beside a naive redraw.

What is timed, interleaved in the same run (medians over repetitions), for a grid of
N buttons with labels (headless EGL):

* ``layout``: :func:`kge.ui.layout.compute_layout` for the N nodes;
* ``input``: :func:`kge.ui.interact.handle_input` with a pointer move (hover) — layout
  included, as the UI system runs it once per frame;
* ``draw``: the UI after-pass (``kge.render.ui.UIDrawer``): pyglet shapes and labels
  kept per widget and updated in place, one batch draw;
* ``rebuild``: the naive alternative, a fresh pyglet ``RoundedRectangle`` and ``Label``
  per widget every frame, drawn in a new batch (what the drawer's cache avoids).

Run ``python benchmarks/ui.py`` (``--sizes 50 200``) for the table; :func:`measure`
with a small N is what ``kge bench --quick`` and the test suite call.
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from collections.abc import Callable
from typing import Any

os.environ.setdefault("PYGLET_HEADLESS", "1")

if __package__ in (None, ""):  # run as a script: make the repository importable
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

VARIANTS = ("layout", "input", "draw", "rebuild")


def _app(n: int) -> Any:
    from kge import App, Button, Panel, UINode, World

    def scene(world: World) -> None:
        grid = world.spawn(UINode(width="90%", height="90%", layout="grid", columns=10,
                                  padding=8, spacing=4), Panel())  # fmt: skip
        for i in range(n):
            world.spawn(UINode(parent=grid, height=24), Button(f"B{i}"))

    app = App(scene, headless=True, size=(960, 540))
    app.step()
    app.render()  # create the drawer and every widget's pyglet objects
    return app


def measure(n: int, repeats: int = 9, frames: int = 10) -> dict[str, float]:
    """Median µs per widget and frame of each variant (see the module docstring)."""
    import pyglet

    from kge.host import Host
    from kge.render.setup import renderer_for
    from kge.render.ui import drawer_for
    from kge.ui.interact import UIState, handle_input
    from kge.ui.layout import compute_layout
    from kge.ui.theme import DEFAULT_THEME

    app = _app(n)
    world = app.world
    state = world.resource(UIState)
    boxes = list(state.layout.boxes.values())
    assert drawer_for(world).items, "the drawer holds the widgets' pyglet objects"
    window = renderer_for(world.resource(Host)).window  # type: ignore[union-attr]
    k = 0

    def layout() -> None:
        compute_layout(world, app.size)

    def input_() -> None:
        nonlocal k
        k += 1
        app.input.move_mouse(*boxes[k % len(boxes)].center)
        handle_input(world, app.input, app.size, state, DEFAULT_THEME)
        app.input.end_frame()

    def draw() -> None:
        app.render()

    def rebuild() -> None:
        window.switch_to()
        batch = pyglet.graphics.Batch()
        keep: list[Any] = []
        for e, b in state.layout.boxes.items():
            w = state.layout.widget.get(e)
            rect = pyglet.shapes.RoundedRectangle(
                b.x, b.y, b.w, b.h, 8, segments=6, color=(52, 60, 78, 255), batch=batch
            )
            keep.append(rect)
            if w is not None:
                x, y = b.center
                label = pyglet.text.Label(
                    w.text,
                    font_size=16,
                    x=x,
                    y=y,
                    anchor_x="center",
                    anchor_y="center",
                    batch=batch,
                )
                keep.append(label)
        batch.draw()
        for obj in keep:
            obj.delete()

    fns: dict[str, Callable[[], None]] = {
        "layout": layout, "input": input_, "draw": draw, "rebuild": rebuild,
    }  # fmt: skip
    samples: dict[str, list[float]] = {v: [] for v in VARIANTS}
    for _ in range(repeats):
        for name in VARIANTS:  # interleaved: background load hits every variant alike
            fn = fns[name]
            start = time.perf_counter()
            for _ in range(frames):
                fn()
            samples[name].append((time.perf_counter() - start) / frames / n * 1e6)
    app.close()
    return {name: statistics.median(v) for name, v in samples.items()}


def table(results: dict[int, dict[str, float]]) -> str:
    lines = [f"{'widgets':>8}" + "".join(f"{c:>12}" for c in (*VARIANTS, "rebuild/draw"))]
    for n, r in sorted(results.items()):
        lines.append(f"{n:>8}" + "".join(f"{r[c]:>12.2f}" for c in VARIANTS)
                     + f"{r['rebuild'] / r['draw']:>12.1f}")  # fmt: skip
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="*", default=[50, 200])
    parser.add_argument("--repeats", type=int, default=9)
    args = parser.parse_args(argv)
    results = {n: measure(n, args.repeats) for n in args.sizes}
    print("µs per widget and frame (median):")
    print(table(results))
    return 0


if __name__ == "__main__":
    sys.exit(main())


def bench_section(
    quick: bool, progress: Callable[[str], None]
) -> tuple[dict[str, Any], str | None]:
    """The ``kge bench`` UI section: results by size, or why it could not run."""
    try:
        out = {}
        for n in (20,) if quick else (50, 200):
            progress(f"ui [{n} widgets]")
            out[str(n)] = measure(n, 2 if quick else 9)
        return out, None
    except Exception as err:  # no GL (headless EGL missing): report, do not fail the run
        return {}, f"ui skipped: {type(err).__name__}: {err}"


def markdown_lines(results: dict[str, dict[str, float]]) -> list[str]:
    """The UI table of ``benchmarks/results/bench.md``."""
    if not results:
        return []
    out = ["", "UI, µs per widget and frame (median; `draw` = kge's cached after-pass, "
           "`rebuild` = fresh pyglet shapes and labels every frame):", "",
           "| widgets | layout | input | draw | rebuild | rebuild/draw |",
           "|---:|---:|---:|---:|---:|---:|"]  # fmt: skip
    for n, r in sorted(results.items(), key=lambda kv: int(kv[0])):
        out.append(f"| {n} | {r['layout']:.1f} | {r['input']:.1f} | {r['draw']:.1f} "
                   f"| {r['rebuild']:.1f} | {r['rebuild'] / r['draw']:.1f} |")  # fmt: skip
    return out
