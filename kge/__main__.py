"""Command line: ``kge new NAME`` (a game project), ``kge demo`` (the README's demo
command), ``kge testbed``, ``kge bench``, ``kge export`` (a standalone build), ``kge
schedule`` (the frame order).

Also reachable as ``python -m kge ...``. Each command forwards its remaining
arguments to its own parser (``kge testbed --help``).
"""

from __future__ import annotations

import runpy
import sys
from collections.abc import Callable
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


DEMO_HELP = """usage: kge demo [--testbed] [testbed options]

The demo. First Lantern Woods, kge's showcase game (examples/lantern.py, in a source
checkout): with a display, its window (the testbed opens when you close it); without
one, it plays itself for ten seconds, prints what it did and saves its last frame
(out/lantern.png). Then the testbed: with a display, its window (every sample, by
category); without one, every sample runs for a few simulated seconds, a line per
sample, and a contact sheet (out/testbed-contact-sheet.png).

  kge demo --testbed              the testbed only
Any other option is the testbed's (see `kge testbed --help`) and skips the game, e.g.
  kge demo --sample pyramid       open (or run headless) one sample
  kge demo --showcase --seconds 1 the headless showcase, one second per sample
"""


def _showcase_game() -> int:
    """Lantern Woods: a window, or ten seconds of self-play headless (a line and a frame)."""
    from kge.app import has_display

    sys.path.insert(0, str(ROOT / "examples"))
    import lantern

    if has_display():
        print("kge demo: Lantern Woods, kge's showcase game (close it for the testbed)")
        app = lantern.make_app()
        app.run()
        app.close()
        return 0
    app = lantern.make_app(headless=True)
    run = lantern.play(app, seconds=10.0)
    out = Path("out") / "lantern.png"
    app.screenshot(str(out))
    p = run.last
    jars = f"{p.jars}/{p.total} jars, {p.time:.1f} s" if p is not None else "not started"
    print(f"kge demo: Lantern Woods played itself for 10 s ({jars}); last frame {out}")
    app.close()
    return 0


def _demo(args: list[str]) -> int:
    """The main job a user runs: the showcase game, then the testbed (a window, or the
    headless showcase)."""
    if args[:1] in (["-h"], ["--help"]):
        print(DEMO_HELP, end="")
        return 0
    if args == ["--testbed"]:
        args = []
    elif not args and (ROOT / "examples" / "lantern.py").exists():
        _showcase_game()
    try:
        from kge.testbed.cli import main as testbed_main
    except ImportError:  # a trimmed install without the testbed: the hello-world example
        script = ROOT / "examples" / "hello_world.py"
        if not script.exists():
            print("kge demo: the testbed is not installed and examples/ is missing")
            return 1
        sys.argv = [str(script), *args]
        runpy.run_path(str(script), run_name="__main__")
        return 0
    return int(testbed_main(args) or 0)


def _testbed(args: list[str]) -> int:
    from kge.testbed.cli import main as testbed_main

    return int(testbed_main(args) or 0)


def _bench(args: list[str]) -> int:
    """Benchmarks live beside the package (benchmarks/), in a source checkout."""
    if not (ROOT / "benchmarks" / "run.py").exists():
        print("kge bench: benchmarks/ not found (run it from a source checkout)")
        return 1
    sys.path.insert(0, str(ROOT))
    from benchmarks.run import main as bench_main

    return int(bench_main(args) or 0)


EDIT_HELP = """usage: kge edit [FILE] [--game GAME.py ...] [--headless --frames N --screenshot PNG]

The scene editor: a window on the scene file FILE (.scene.toml; a new one when it does
not exist yet). --game imports a Python file first, so its registered components and
Behaviour scripts can be placed and played (it reloads when you change it).
--headless --frames N runs N frames without a window and --screenshot saves the last.
"""


def _edit(args: list[str]) -> int:
    import argparse
    import importlib.util

    parser = argparse.ArgumentParser(prog="kge edit", add_help=False)
    parser.add_argument("file", nargs="?")
    parser.add_argument("--game", action="append", default=[])
    parser.add_argument("--headless", action="store_true")
    parser.add_argument("--frames", type=int)
    parser.add_argument("--screenshot")
    parser.add_argument("-h", "--help", action="store_true")
    opts = parser.parse_args(args)
    if opts.help:
        print(EDIT_HELP, end="")
        return 0
    for game in opts.game:  # the game's own code, named on the command line by its user
        path = Path(game).resolve()
        sys.path.insert(0, str(path.parent))
        spec = importlib.util.spec_from_file_location(path.stem, path)
        if spec is None or spec.loader is None:
            print(f"kge edit: cannot import {game}", file=sys.stderr)
            return 2
        module = importlib.util.module_from_spec(spec)
        sys.modules[path.stem] = module
        spec.loader.exec_module(module)
    from kge.editor.app import editor_app

    target = None if opts.file is None else Path(opts.file).resolve()
    app, _ = editor_app(target, headless=True if opts.headless else None)
    app.run(opts.frames, opts.screenshot)
    app.close()
    return 0


def _new(args: list[str]) -> int:
    from kge.scaffold import main as new_main

    return new_main(args)


def _schedule(args: list[str]) -> int:
    from kge.schedule_cli import main as schedule_main

    return schedule_main(args)


def _export(args: list[str]) -> int:
    from kge.export.cli import main as export_main

    return export_main(args)


COMMANDS: dict[str, tuple[Callable[[list[str]], int], str]] = {
    "new": (_new, "create a small game project with a test: kge new NAME"),
    "demo": (_demo, "the demo: the testbed window, or a headless showcase without a display"),
    "testbed": (_testbed, "the Box2D-style testbed (kge testbed --help)"),
    "edit": (_edit, "the scene editor: kge edit levels/one.scene.toml"),
    "bench": (_bench, "benchmarks: kge beside raw pymunk and pybox2d (kge bench --help)"),
    "export": (_export, "a standalone build of a game project: kge export [PROJECT]"),
    "schedule": (_schedule, "print the frame order: stages, sets, systems (kge schedule --help)"),
}


def version() -> str:
    """kge's version, as installed (or as the source checkout declares it)."""
    from importlib.metadata import PackageNotFoundError
    from importlib.metadata import version as installed

    try:
        return installed("kge")
    except PackageNotFoundError:  # run from a source tree that was never installed
        import tomllib

        with open(ROOT / "pyproject.toml", "rb") as f:
            return str(tomllib.load(f)["project"]["version"])


def usage() -> str:
    names = ",".join(COMMANDS)
    lines = [f"usage: kge [--version] {{{names}}} [options]", ""]
    lines += [f"  {name:<9} {text}" for name, (_, text) in COMMANDS.items()]
    lines += ["", "Each command has its own help: kge COMMAND --help"]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else list(argv)
    if args[:1] in (["--version"], ["-V"]):
        print(f"kge {version()}")
        return 0
    if not args or args[0] not in COMMANDS:
        known = args[:1] in ([], ["-h"], ["--help"])
        if not known:
            print(f"kge: unknown command {args[0]!r}\n", file=sys.stderr)
        print(usage(), file=sys.stdout if known else sys.stderr)
        return 0 if known else 2
    func, _ = COMMANDS[args[0]]
    return func(args[1:])


if __name__ == "__main__":
    sys.exit(main())
