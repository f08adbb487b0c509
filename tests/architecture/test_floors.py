"""The floors of the house hold: import-linter's contracts pass, a planted upward
import breaks them, and no import cycle exists inside ``kge`` (lazy imports count)."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.architecture.import_graph import PACKAGE_ROOT, cycles, import_graph

REPO = PACKAGE_ROOT.parent
LINT = [sys.executable, "-c", "from importlinter.cli import lint_imports_command; lint_imports_command()"]


def lint(cwd: Path, pythonpath: Path) -> subprocess.CompletedProcess[str]:
    env = {"PATH": "/usr/bin:/bin", "PYTHONPATH": str(pythonpath)}
    return subprocess.run(
        [*LINT, "--no-cache"], cwd=cwd, env=env, capture_output=True, text=True, timeout=300
    )


def test_import_linter_contracts_pass() -> None:
    result = lint(REPO, REPO)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "0 broken" in result.stdout


@pytest.mark.parametrize(
    ("module", "planted", "contract"),
    [
        # a component reaching up to the App (an upward import, lazy inside a function)
        ("components/transform.py", "def _planted():\n    import kge.app\n", "Floors"),
        # physics reaching the render floor beside-and-above it
        ("physics/tiny.py", "from kge.render import images as _planted\n", "Floors"),
        # the core reaching pyglet through a render module (indirect)
        ("world.py", "def _planted():\n    from kge.render import passes\n", "Floors"),
        # the App naming a subsystem instead of taking it from a plugin
        ("app.py", "def _planted():\n    import kge.systems.audio\n", "The App names no subsystem"),
    ],
)
def test_planted_upward_import_breaks_a_contract(
    tmp_path: Path, module: str, planted: str, contract: str
) -> None:
    shutil.copytree(PACKAGE_ROOT, tmp_path / "kge", ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copy(REPO / "pyproject.toml", tmp_path / "pyproject.toml")
    target = tmp_path / "kge" / module
    target.write_text(target.read_text() + "\n\n" + planted)
    result = lint(tmp_path, tmp_path)
    assert result.returncode != 0, result.stdout
    broken = result.stdout.split("Broken contracts", 1)[-1]
    assert contract in broken, result.stdout


def test_no_import_cycles_inside_kge() -> None:
    graph = import_graph()
    assert len(graph) == len(list(PACKAGE_ROOT.rglob("*.py")))  # every module was read
    assert cycles(graph) == []


def test_cycle_finder_sees_lazy_imports_and_skips_type_checking(tmp_path: Path) -> None:
    pkg = tmp_path / "kge"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("")
    (pkg / "a.py").write_text("def f():\n    from kge import b\n")
    (pkg / "b.py").write_text("import kge.a\n")
    (pkg / "c.py").write_text(
        "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    import kge.d\n"
    )
    (pkg / "d.py").write_text("import kge.c\n")
    assert cycles(import_graph(pkg)) == [["kge.a", "kge.b"]]
