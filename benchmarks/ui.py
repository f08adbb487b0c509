"""UI cost per frame: what an unchanged UI, a changing HUD, hover and a 10,000-row list
cost, beside re-syncing every widget each frame and a naive redraw.

Timed interleaved in the same run (medians over repetitions of the process's CPU time:
every thread's, llvmpipe's rasteriser included, and steadier than wall time on a
shared machine), headless EGL, for a grid
of N buttons with labels; every variant runs the UI's frame work: the layout kept
current (:func:`kge.ui.current.current_layout`), the input handling
(:func:`kge.ui.interact.handle_input`) and one drawn frame (``app.render()``: the UI
after-pass over an empty world):

* ``layout``: a full layout of the N nodes (what any change to the UI costs once);
* ``static``: nothing changed (a HUD whose values stay put): the layout is reused and
  no widget is synced; the frame is the batch's draw;
* ``change``: one label's text changes every frame (a score): one new layout, the
  widgets whose boxes moved or changed are synced;
* ``hover``: the pointer moves to another button every frame: two widgets re-drawn;
* ``resync``: every widget's shapes and labels synced every frame (what the UI cost
  before it tracked changes);
* ``rebuild``: a fresh pyglet ``RoundedRectangle`` and ``Label`` per widget every frame.

The list rows time a ``ScrollList`` of 100 and of 10,000 rows, ``static`` and scrolled one
row per frame (``scroll``): only the rows in view are laid out and drawn, so the two
sizes cost the same.

The editor (``kge edit``) has its own rows: ``benchmarks/editor.py``.

Run ``python benchmarks/ui.py`` for the tables; :func:`measure` with small sizes is what
``kge bench --quick`` and the test suite call.
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

VARIANTS = ("layout", "static", "change", "hover", "resync", "rebuild")
LIST_VARIANTS = ("static", "scroll")


def _grid_app(n: int) -> Any:
    from kge import App, Button, Label, Panel, UINode, World

    def scene(world: World) -> None:
        grid = world.spawn(UINode(width="90%", height="90%", layout="grid", columns=25,
                                  padding=8, spacing=2), Panel())  # fmt: skip
        for i in range(n):
            world.spawn(UINode(parent=grid, height=14), Button(f"B{i}"))
        world.spawn(UINode(anchor="top_left", offset=(4, -4)), Label("Score 0"))

    app = App(scene, headless=True, size=(1280, 720))
    app.step()
    app.render()  # the drawer and every widget's pyglet objects
    return app


def _list_app(rows: int) -> Any:
    from kge import App, ScrollList, UINode, World

    def scene(world: World) -> None:
        world.spawn(UINode(width=300, height=400),
                    ScrollList([f"Row {i}" for i in range(rows)], row_height=20))  # fmt: skip

    app = App(scene, headless=True, size=(1280, 720))
    app.step()
    app.render()
    return app


def _frame(app: Any) -> None:
    """The UI's work for one frame: layout kept current, input, one drawn frame."""
    from kge.ui.current import current_layout
    from kge.ui.interact import handle_input
    from kge.ui.state import UIState

    world = app.world
    current_layout(world)
    handle_input(world, app.input, world.resource(UIState), 1 / 60)
    app.input.end_frame()
    app.render()


def median_cpu_us(
    fns: dict[str, Callable[[], None]], repeats: int, frames: int
) -> dict[str, float]:
    """Median µs of CPU per call of each function, timed interleaved (background load
    hits every variant alike)."""
    samples: dict[str, list[float]] = {k: [] for k in fns}
    for _ in range(repeats):
        for name, fn in fns.items():  # interleaved: background load hits every variant alike
            start = time.process_time()
            for _ in range(frames):
                fn()
            samples[name].append((time.process_time() - start) / frames * 1e6)
    return {k: statistics.median(v) for k, v in samples.items()}


def measure(n: int, repeats: int = 9, frames: int = 10) -> dict[str, float]:
    """Median µs per frame of each variant for N widgets (see the module docstring)."""
    import pyglet

    from kge import Button, Label
    from kge.host import Host
    from kge.render.setup import renderer_for
    from kge.render.ui import drawer_for
    from kge.ui.layout import compute_layout
    from kge.ui.state import UIState

    app = _grid_app(n)
    world = app.world
    state = world.resource(UIState)
    drawer = drawer_for(world)
    assert drawer.owned, "the drawer holds the widgets' pyglet objects"
    buttons = [e for e, _ in world.query(Button)]
    score = next(lbl for _, (lbl,) in world.query(Label))
    window = renderer_for(world.resource(Host)).window  # type: ignore[union-attr]
    k = [0]

    def layout() -> None:
        compute_layout(world, app.size)

    def static() -> None:
        _frame(app)

    def change() -> None:
        k[0] += 1
        score.text = f"Score {k[0]}"
        _frame(app)

    def hover() -> None:
        k[0] += 1
        app.input.move_mouse(*state.layout.boxes[buttons[k[0] % len(buttons)]].center)
        _frame(app)

    def resync() -> None:
        drawer.key = ()  # as if everything changed: every widget synced
        _frame(app)

    def rebuild() -> None:
        window.switch_to()
        batch = pyglet.graphics.Batch()
        keep: list[Any] = []
        for e, b in state.layout.boxes.items():
            w = state.layout.widget.get(e)
            keep.append(pyglet.shapes.RoundedRectangle(
                b.x, b.y, b.w, b.h, 8, segments=6, color=(52, 60, 78, 255), batch=batch))
            if w is not None:
                keep.append(pyglet.text.Label(
                    w.text, font_size=16, x=b.center[0], y=b.center[1], anchor_x="center",
                    anchor_y="center", batch=batch))
        batch.draw()
        for obj in keep:
            obj.delete()

    fns = {"layout": layout, "static": static, "change": change, "hover": hover,
           "resync": resync, "rebuild": rebuild}  # fmt: skip
    out = median_cpu_us(fns, repeats, frames)
    before = drawer.syncs
    static()
    out["static_syncs"] = float(drawer.syncs - before)  # widgets synced by an unchanged frame
    app.close()
    return out


def measure_lists(sizes: tuple[int, ...], repeats: int = 9,
                  frames: int = 10) -> dict[int, dict[str, float]]:  # fmt: skip
    """Median µs per frame of ScrollLists of each size, unchanged and scrolling one row
    per frame; every list and variant interleaved in one loop, so they compare."""
    from kge import ScrollList

    fns: dict[str, Callable[[], None]] = {}
    apps = []
    for rows in sizes:
        app = _list_app(rows)
        apps.append(app)
        lst = next(c for _, (c,) in app.world.query(ScrollList))

        def static(app: Any = app) -> None:
            _frame(app)

        def scroll(app: Any = app, lst: Any = lst, step: list[int] = [0]) -> None:  # noqa: B006
            step[0] = (step[0] + 1) % 60  # every list scrolls through its first 80 rows
            lst.scroll = step[0] * 20.0
            _frame(app)

        fns[f"{rows}:static"], fns[f"{rows}:scroll"] = static, scroll
    got = median_cpu_us(fns, repeats, frames)
    for app in apps:
        app.close()
    return {rows: {v: got[f"{rows}:{v}"] for v in LIST_VARIANTS} for rows in sizes}


def table(
    results: dict[int, dict[str, float]],
    variants: tuple[str, ...] = VARIANTS,
    first: str = "widgets",
    ratio: tuple[str, str] = ("resync", "static"),
) -> str:
    """A text table: a row per size, a column per variant and one for ``ratio``."""
    top, bottom = ratio
    lines = [f"{first:>8}" + "".join(f"{c:>10}" for c in variants) + f"{top + '/' + bottom:>14}"]
    for n, r in sorted(results.items()):
        lines.append(f"{n:>8}" + "".join(f"{r[c]:>10.0f}" for c in variants)
                     + f"{r[top] / r[bottom]:>14.2f}")  # fmt: skip
    return "\n".join(lines)


def list_table(results: dict[int, dict[str, float]]) -> str:
    lines = [f"{'rows':>8}" + "".join(f"{c:>10}" for c in LIST_VARIANTS)]
    for n, r in sorted(results.items()):
        lines.append(f"{n:>8}" + "".join(f"{r[c]:>10.0f}" for c in LIST_VARIANTS))
    return "\n".join(lines)


def text(results: dict[str, dict[str, float]]) -> str:
    """Both tables of a ``bench_section`` result, as text."""
    grids = {int(k): v for k, v in results.items() if k.isdigit()}
    lists = {int(k[5:]): v for k, v in results.items() if k.startswith("list-")}
    return table(grids) + "\n" + list_table(lists)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="*", default=[50, 1000])
    parser.add_argument("--rows", type=int, nargs="*", default=[100, 10_000])
    parser.add_argument("--repeats", type=int, default=9)
    args = parser.parse_args(argv)
    print("µs per frame (median):")
    print(table({n: measure(n, args.repeats) for n in args.sizes}))
    print(list_table(measure_lists(tuple(args.rows), args.repeats)))
    return 0


if __name__ == "__main__":
    sys.exit(main())


def bench_section(
    quick: bool, progress: Callable[[str], None]
) -> tuple[dict[str, Any], str | None]:
    """The ``kge bench`` UI section: results by size, or why it could not run."""
    try:
        out: dict[str, Any] = {}
        for n in (20,) if quick else (50, 1000):
            progress(f"ui [{n} widgets]")
            out[str(n)] = measure(n, 2 if quick else 9, 3 if quick else 10)
        sizes = (100, 1000) if quick else (100, 10_000)
        progress(f"ui [lists of {' and '.join(map(str, sizes))} rows]")
        lists = measure_lists(sizes, 2 if quick else 9, 3 if quick else 10)
        out.update({f"list-{rows}": r for rows, r in lists.items()})
        return out, None
    except Exception as err:  # no GL (headless EGL missing): report, do not fail the run
        return {}, f"ui skipped: {type(err).__name__}: {err}"


def markdown_lines(results: dict[str, dict[str, float]]) -> list[str]:
    """The UI tables of ``benchmarks/results/bench.md``."""
    grids = {k: v for k, v in results.items() if k.isdigit()}
    lists = {k[5:]: v for k, v in results.items() if k.startswith("list-")}
    out: list[str] = []
    if grids:
        out += ["", "UI, µs of CPU per frame (median; the UI's whole frame: layout kept current, "
                "input, one drawn frame; `static` = nothing changed, `change` = one label changes, "
                "`hover` = the pointer moves to another button, `resync` = every widget synced "
                "each frame, `rebuild` = fresh pyglet shapes and labels each frame):", "",
                "| widgets | layout | static | change | hover | resync | rebuild | resync/static |",
                "|---:|---:|---:|---:|---:|---:|---:|---:|"]  # fmt: skip
        for n, r in sorted(grids.items(), key=lambda kv: int(kv[0])):
            out.append(f"| {n} | {r['layout']:.0f} | {r['static']:.0f} | {r['change']:.0f} "
                       f"| {r['hover']:.0f} | {r['resync']:.0f} | {r['rebuild']:.0f} "
                       f"| {r['resync'] / r['static']:.1f} |")  # fmt: skip
    if lists:
        out += ["", "ScrollList, µs of CPU per frame (median; `scroll` = one row further each "
                "frame; only the rows in view are drawn):",
                "", "| rows | static | scroll |", "|---:|---:|---:|"]  # fmt: skip
        for n, r in sorted(lists.items(), key=lambda kv: int(kv[0])):
            out.append(f"| {n} | {r['static']:.0f} | {r['scroll']:.0f} |")
    return out
