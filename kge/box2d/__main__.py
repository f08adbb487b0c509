"""``python -m kge.box2d script.py [args...]``: run a pybox2d program on kge.

Installs ``kge.box2d`` as ``Box2D`` and runs the script as ``__main__``, with
``sys.argv`` set to the script and its arguments.
"""

from __future__ import annotations

import runpy
import sys


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    if not args or args[0] in ("-h", "--help"):
        print("usage: python -m kge.box2d script.py [args...]", file=sys.stderr)
        return 2
    from kge.box2d import install

    install()
    sys.argv = list(args)
    runpy.run_path(args[0], run_name="__main__")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
