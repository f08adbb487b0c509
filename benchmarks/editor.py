"""The editor's frame cost on a large scene, beside the same scene run as a game.

A scene of N entities (a static ground and a grid of named boxes, each with a body, a
collider and a rectangle) is saved to a file and opened two ways in one run; the
variants are timed interleaved (medians over repetitions of the process's CPU time, as
in ``benchmarks/ui.py``), headless EGL:

* ``step``: a frame of ``kge edit``'s logic with nothing changing (UI input, the
  hierarchy's tree and the status line kept current), the pointer moving over the
  viewport;
* ``select``: the same with a new selection every frame (the inspector's rows rebuilt);
* ``frame``: a ``step`` plus the drawn frame (llvmpipe);
* ``game``: the same file in a plain ``App`` (physics stepping), one frame drawn the same
  way.

``frame/game`` says what editing costs over playing; the goal is that the editor stays
interactive (a frame well under 1/30 s) at 2,000 entities.

Run ``python benchmarks/editor.py`` for the table; ``kge bench`` runs the row
(``--quick``: 200 entities) and the test suite calls :func:`measure` with a small N.
"""

from __future__ import annotations

import os
import shutil
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import Any

os.environ.setdefault("PYGLET_HEADLESS", "1")

if __package__ in (None, ""):  # run as a script: make the repository importable
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

from benchmarks.ui import median_cpu_us
from benchmarks.ui import table as ui_table

VARIANTS = ("step", "select", "frame", "game")


def write_scene(n: int, folder: Path) -> Path:
    """A scene file of ``n`` entities: a ground and ``n - 1`` boxes in a grid."""
    from kge import App, Box, Collider, Name, RigidBody, Transform, World, draw
    from kge.scenefile import save_scene

    def scene(world: World) -> None:
        world.spawn(Name("ground"), Transform(0.0, -1.0), Collider(Box(200.0, 1.0)))
        side = max(1, int(n**0.5))
        for i in range(n - 1):
            x, y = (i % side) * 1.2 - side * 0.6, (i // side) * 1.2 + 0.5
            world.spawn(Name(f"box {i}"), Transform(x, y), RigidBody(allow_sleep=True),
                        Collider(Box(0.4, 0.4)), draw.Rect(0.8, 0.8, color=(200, 120, 60)))

    app = App(scene, headless=True, plugins=[])
    path = save_scene(app.world, folder / f"bench-{n}.scene.toml")
    app.close()
    return path


def measure(n: int, repeats: int = 9, frames: int = 5) -> dict[str, float]:
    """Median µs of CPU per frame of each variant on an ``n``-entity scene, and
    ``frame/game``."""
    from kge import App
    from kge.editor.app import editor_app

    folder = Path(tempfile.mkdtemp())
    try:
        path = write_scene(n, folder)
        editor, ed = editor_app(path, headless=True, hot_reload=False, size=(1280, 720))
        game = App(str(path), headless=True)
        try:
            entities = ed.model.entities()
            ed.model.select(entities[len(entities) // 2])
            for app in (editor, game):
                app.step()
                app.render()
            k = [0]

            def step() -> None:
                k[0] += 1
                editor.input.move_mouse(400.0 + k[0] % 50, 300.0)
                editor.step()

            def select() -> None:
                ed.model.select(entities[k[0] % len(entities)])
                step()

            def frame() -> None:
                step()
                editor.render()

            def game_frame() -> None:
                game.step()
                game.render()

            fns: dict[str, Callable[[], None]] = {
                "step": step, "select": select, "frame": frame, "game": game_frame}  # fmt: skip
            out = median_cpu_us(fns, repeats, frames)
        finally:
            editor.close()
            game.close()
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    out["frame/game"] = out["frame"] / out["game"] if out["game"] > 0 else float("nan")
    return out


def table(rows: dict[int, dict[str, float]]) -> str:
    return ui_table(rows, VARIANTS, "entities", ("frame", "game"))


def run_section(quick: bool, progress: Any) -> tuple[dict[str, dict[str, float]], str]:
    """``kge bench``'s editor row: {N: timings}, or why it was skipped."""
    n = 200 if quick else 2000
    progress(f"editor, {n} entities")
    try:
        return {str(n): measure(n, 2 if quick else 9, 2 if quick else 5)}, ""
    except Exception as err:  # no GL (headless EGL missing): report, do not fail the run
        return {}, f"editor skipped: {type(err).__name__}: {err}"


def markdown_lines(rows: dict[str, dict[str, float]]) -> list[str]:
    """The editor table of ``benchmarks/results/bench.md``."""
    out = ["", "`kge edit`, µs of CPU per frame (median; `step` = its logic with nothing "
           "changing, `select` = a new selection each frame (the inspector rebuilt), "
           "`frame` = `step` and the drawn frame, `game` = the same scene file played in an "
           "`App`, one drawn frame):",
           "", "| entities | step | select | frame | game | frame/game |",
           "|---:|---:|---:|---:|---:|---:|"]  # fmt: skip
    for n, r in sorted(rows.items(), key=lambda kv: int(kv[0])):
        out.append(f"| {n} | {r['step']:.0f} | {r['select']:.0f} | {r['frame']:.0f} "
                   f"| {r['game']:.0f} | {r['frame/game']:.2f} |")  # fmt: skip
    return out


if __name__ == "__main__":
    print("µs of CPU per frame (median):")
    print(table({2000: measure(2000)}))
