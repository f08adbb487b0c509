"""``kge new NAME``: a small game project that runs and passes its tests with no edits.

The project holds a ``pyproject.toml``, a package with one scene and one Behaviour,
art and sound generated in code (no files to ship), and a pytest test that uses kge's
fixtures (``kge_app``, ``step_until``). Nothing here imports kge's engine: the files
are written from :mod:`kge.scaffold.templates`.
"""

from __future__ import annotations

import keyword
import re
from pathlib import Path

from kge.errors import KgeError
from kge.scaffold.templates import FILES


class ScaffoldError(KgeError, ValueError):
    """``kge new``: the name cannot name a Python package, or the folder exists."""


def package_name(name: str) -> str:
    """``my-game`` -> ``my_game``: the importable name of the project's package."""
    pkg = re.sub(r"[^0-9a-zA-Z_]", "_", name.strip()).lower()
    if not pkg or pkg[0].isdigit() or keyword.iskeyword(pkg) or pkg in ("kge", "test", "tests"):
        raise ScaffoldError(
            f"kge new: {name!r} cannot name a Python package; use letters, digits, - and _ "
            "(not starting with a digit), e.g. kge new space-miner"
        )
    return pkg


def create(name: str, parent: Path) -> Path:
    """Write the project ``parent/name`` and return its folder."""
    pkg = package_name(name)
    root = parent / name
    if root.exists():
        raise ScaffoldError(f"kge new: {root} already exists; choose another name or folder")
    title = name.replace("-", " ").replace("_", " ").title()
    for rel, text in FILES.items():
        path = root / rel.format(pkg=pkg)
        path.parent.mkdir(parents=True, exist_ok=True)
        for key, value in (("{{pkg}}", pkg), ("{{name}}", name), ("{{title}}", title)):
            text = text.replace(key, value)
        path.write_text(text)
    return root


def main(args: list[str]) -> int:
    """The ``kge new`` command."""
    if len(args) != 1 or args[0].startswith("-"):
        print("usage: kge new NAME   (creates ./NAME: a runnable game with a test)")
        return 0 if args in (["-h"], ["--help"]) else 2
    try:
        root = create(args[0], Path.cwd())
    except ScaffoldError as err:
        print(err)
        return 2
    steps = [
        (f"cd {args[0]}", ""),
        ("pip install -e .", "in the virtual environment that has kge"),
        (f"python -m {package_name(args[0])}", "play: arrows or A/D walk, space jumps"),
        ("pytest", "its tests, headless"),
    ]
    width = max(len(cmd) for cmd, _ in steps) + 2
    lines = [f"  {cmd:<{width}}# {why}" if why else f"  {cmd}" for cmd, why in steps]
    print(f"created {root}\n\n" + "\n".join(lines))
    return 0
