"""``kge schedule``: print the frame order an App really runs.

::

    kge schedule                                   # the default plugins
    kge schedule --plugins PhysicsPlugin,mygame.plugins:ScorePlugin
    kge schedule --scene mygame.levels:level_one   # what a scene's setup adds, too
    kge schedule --render                          # draw one headless frame first, so
                                                   # the drawing systems join the table
    kge schedule --scene mygame:level --timings 300  # run 300 frames headless and print
                                                     # each system's measured cost

Each line is one system: its stage, its position in the stage, its set
(:class:`~kge.schedule.SystemSet`), its own ``before`` / ``after`` constraints and
the plugin that added it. Pairs of systems that run one after the other with no
order between them are marked ``TIE`` (they run in the order they were added).
"""

from __future__ import annotations

import argparse
import importlib
import runpy
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from kge.app import App
from kge.plugin import PluginLike
from kge.render.passes import RenderPasses


def _load(ref: str, what: str) -> Any:
    """``module:attr`` (or ``path/file.py:attr``; a bare name is looked up in ``kge``)."""
    module_name, _, attr = ref.rpartition(":")
    if not module_name:
        module_name, attr = "kge", ref
    try:
        if module_name.endswith(".py"):
            namespace = runpy.run_path(str(Path(module_name)), run_name="kge_schedule")
            return namespace[attr]
        return getattr(importlib.import_module(module_name), attr)
    except (ImportError, AttributeError, KeyError, FileNotFoundError) as exc:
        raise SystemExit(f"kge schedule: cannot load the {what} {ref!r}: {exc}") from None


def _plugins(spec: str | None) -> list[PluginLike] | None:
    if spec is None:
        return None
    return [_load(ref.strip(), "plugin") for ref in spec.split(",") if ref.strip()]


def frame_table(
    plugins: list[PluginLike] | None = None, scene: Any = None, render: bool = False,
    timings: int = 0,
) -> str:
    """The text ``kge schedule`` prints, for an App of ``plugins`` running ``scene``
    (with ``timings`` > 0: after running that many frames with per-system timings)."""
    app = App(scene if scene is not None else (lambda world: None), headless=True,
              plugins=plugins)  # fmt: skip
    try:
        if render:
            app.render()
        world = app.world
        if timings > 0:
            measured = world.schedule.enable_timings()
            for _ in range(timings):
                app.step(1)
                if render:
                    app.render()
            return (f"plugins: {', '.join(p.name for p in world.plugins) or 'none'}\n\n"
                    f"per-system cost over {timings} frames (ms; slowest first):\n"
                    + measured.describe())  # fmt: skip
        names = ", ".join(p.name for p in world.plugins) or "none"
        lines = [f"plugins: {names}", "", world.schedule.describe(plugins=True), ""]
        ties = world.schedule.ties()
        if ties:
            lines += [f"ties ({len(ties)}): systems of one set with no order between them "
                      "run in the order they were added:"]  # fmt: skip
            lines += [f"  {st.name}: {type(a).__name__} then {type(b).__name__}"
                      for st, a, b in ties]  # fmt: skip
        else:
            lines.append("ties: none (every pair of systems is ordered)")
        passes = world.try_resource(RenderPasses)
        if passes is not None:
            lines.append(
                "render passes: before the batch: "
                + (", ".join(passes.names("before")) or "none")
                + "; per camera: "
                + (", ".join(passes.names("view")) or "none")
                + "; after it: "
                + (", ".join(passes.names("after")) or "none")
            )
            lines += [f"  pass TIE ({phase}): {a} then {b}" for phase, a, b in passes.ties()]
        if not render and app.frontend is not None:
            lines.append(
                "drawing: App.render() adds RenderStepClock (FIXED, FIRST), "
                "RenderStepRecorder (FIXED, LAST) and RenderSystem (RENDER, DRAW); "
                "--render shows them"
            )
        return "\n".join(lines)
    finally:
        app.close()


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="kge schedule", description="Print the frame order (stages, sets, systems)."
    )
    parser.add_argument("--plugins", help="comma-separated plugins (Name in kge, or module:Name)")
    parser.add_argument("--scene", help="a scene to set up first (module:name or file.py:name)")
    parser.add_argument("--render", action="store_true", help="draw one headless frame first")
    parser.add_argument("--timings", type=int, default=0, metavar="FRAMES",
                        help="run FRAMES frames headless and print each system's cost")
    args = parser.parse_args(list(sys.argv[1:] if argv is None else argv))
    scene = _load(args.scene, "scene") if args.scene else None
    print(frame_table(_plugins(args.plugins), scene, args.render, args.timings))
    return 0
