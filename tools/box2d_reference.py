"""Measure the pybox2d-style programs in tests/box2d/programs with real pybox2d.

Run once with pybox2d installed (the ``bench`` extra)::

    .venv/bin/python tools/box2d_reference.py

It writes tests/box2d/reference.json, which the tests compare kge.box2d against,
so CI needs no pybox2d. Each program runs in a fresh interpreter where
``import Box2D`` is the real pybox2d.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PROGRAMS = ROOT / "tests" / "box2d" / "programs"
OUT = ROOT / "tests" / "box2d" / "reference.json"

_RUN = (
    "import json, runpy, sys, Box2D\n"
    "assert not Box2D.__name__.startswith('kge'), 'real pybox2d needed'\n"
    "print(json.dumps(runpy.run_path(sys.argv[1])['result']))\n"
)


def measure(path: Path) -> dict[str, float]:
    out = subprocess.run([sys.executable, "-c", _RUN, str(path)], check=True,
                         capture_output=True, text=True).stdout
    return {k: float(v) for k, v in json.loads(out.strip().splitlines()[-1]).items()}


def main() -> None:
    import Box2D  # noqa: F401  (fail early without pybox2d)

    data = {p.stem: measure(p) for p in sorted(PROGRAMS.glob("*.py"))}
    version = subprocess.run([sys.executable, "-c", "import Box2D; print(Box2D.__version__)"],
                             check=True, capture_output=True, text=True).stdout.strip()
    OUT.write_text(json.dumps({"pybox2d": version, "results": data}, indent=2) + "\n")
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
