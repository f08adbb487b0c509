"""The editor's frame time on a large scene, beside the same scene run as a game.

A scene of N entities (boxes with colliders and sprites-free drawables, a grid of
them) is saved to a file and opened two ways in one run, interleaved:

* ``editor``: ``kge edit``'s App (edited scene, editor UI, grid, selection markers),
  one frame = ``advance(1/60)`` plus a headless render, with an entity selected and
  the pointer moving over the viewport;
* ``game``: the same file in a plain ``App`` (physics stepping), one frame the same way.

The ratio says what editing costs over playing; the goal is that the editor stays
interactive (a frame well under 1/30 s) at 2,000 entities.
"""

from __future__ import annotations

import os
import statistics
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

os.environ.setdefault("PYGLET_HEADLESS", "1")

if __package__ in (None, ""):
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def write_scene(n: int, folder: Path) -> Path:
    from kge import App, Box, Collider, Name, RigidBody, Transform, World, draw
    from kge.scenefile import save_scene

    def scene(world: World) -> None:
        world.spawn(Name("ground"), Transform(0.0, -1.0), Collider(Box(200.0, 1.0)))
        side = max(1, int(n ** 0.5))
        for i in range(n - 1):
            x, y = (i % side) * 1.2 - side * 0.6, (i // side) * 1.2 + 0.5
            world.spawn(Name(f"box {i}"), Transform(x, y), RigidBody(allow_sleep=True),
                        Collider(Box(0.4, 0.4)), draw.Rect(0.8, 0.8, color=(200, 120, 60)))

    app = App(scene, headless=True, plugins=[])
    path = save_scene(app.world, folder / f"bench-{n}.scene.toml")
    app.close()
    return path


def measure(n: int, repeats: int = 5, frames: int = 10) -> dict[str, float]:
    """Median ms per frame of the editor and of the game on an ``n``-entity scene."""
    from kge import App
    from kge.editor.app import editor_app

    folder = Path(tempfile.mkdtemp())
    path = write_scene(n, folder)
    editor, ed = editor_app(path, headless=True, hot_reload=False)
    game = App(str(path), headless=True)
    ed.model.select(ed.model.entities()[n // 2])
    for app in (editor, game):
        app.advance(1 / 60)
        app.render()
    k = 0

    def editor_frame() -> None:
        nonlocal k
        k += 1
        editor.input.move_mouse(400.0 + (k % 50), 300.0)
        editor.advance(1 / 60)
        editor.render()

    def game_frame() -> None:
        game.advance(1 / 60)
        game.render()

    samples: dict[str, list[float]] = {"editor": [], "game": []}
    for _ in range(repeats):
        for name, fn in (("editor", editor_frame), ("game", game_frame)):
            t = time.perf_counter()
            for _ in range(frames):
                fn()
            samples[name].append((time.perf_counter() - t) * 1000.0 / frames)
    editor.close()
    game.close()
    out = {name: statistics.median(v) for name, v in samples.items()}
    out["editor/game"] = out["editor"] / out["game"] if out["game"] > 0 else float("nan")
    return out


def table(rows: dict[int, dict[str, float]]) -> str:
    lines = ["entities  editor ms/frame  game ms/frame  editor/game"]
    for n, r in sorted(rows.items()):
        lines.append(f"{n:>8}  {r['editor']:>15.2f}  {r['game']:>13.2f}  {r['editor/game']:>11.2f}")
    return "\n".join(lines)


def run_section(quick: bool, progress: Any) -> tuple[dict[str, dict[str, float]], str]:
    """``kge bench``'s editor rows: {N: timings} (or why they were skipped)."""
    try:
        import pyglet  # noqa: F401
    except ImportError as exc:  # pragma: no cover
        return {}, f"editor: skipped ({exc})"
    rows = {}
    for n in (200,) if quick else (2000,):
        progress(f"editor, {n} entities")
        rows[str(n)] = measure(n, repeats=2 if quick else 5, frames=3 if quick else 10)
    return rows, ""


if __name__ == "__main__":
    print(table({2000: measure(2000)}))
