"""Command line: ``python -m kge demo`` (the README's demo command) and friends."""

from __future__ import annotations

import argparse
import runpy
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def _demo(args: argparse.Namespace) -> int:
    """The main job a user runs. Until the testbed exists: the hello-world example."""
    try:
        from kge.testbed.cli import main as testbed_main
    except ImportError:
        script = ROOT / "examples" / "hello_world.py"
        if not script.exists():
            print("kge demo: examples/hello_world.py not found (run from a source checkout)")
            return 1
        sys.argv = [str(script), *args.rest]
        runpy.run_path(str(script), run_name="__main__")
        return 0
    return int(testbed_main(args.rest) or 0)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="kge", description="kge game engine tools")
    sub = parser.add_subparsers(dest="command", required=True)
    demo = sub.add_parser("demo", help="run the demo (a window, or a headless summary)")
    demo.add_argument("rest", nargs=argparse.REMAINDER)
    demo.set_defaults(func=_demo)
    args = parser.parse_args(argv)
    return int(args.func(args))


if __name__ == "__main__":
    sys.exit(main())
