"""pybox2d's own unit tests, run unmodified with ``import Box2D`` giving kge.box2d.

The test files come from the installed pybox2d wheel (``Box2D/tests``, found
through its metadata: the dev extra installs box2d 2.3.10); none is copied into
kge. Each pybox2d test is one test here. Collection reads the files' syntax
only; a test's module is loaded while kge.box2d is installed as ``Box2D`` (the
``installed`` fixture), so its ``from Box2D import *`` and ``__import__('Box2D')``
get kge.box2d, and the previous ``Box2D`` modules (the real pybox2d, when other
tests imported it) come back afterwards.
"""

from __future__ import annotations

import ast
import importlib.util
import unittest
from pathlib import Path
from types import ModuleType

import pytest

from kge.box2d.wheel import pybox2d_dir

TESTS = pybox2d_dir("tests")


def _test_ids(folder: Path | None) -> list[str]:
    """``file.py::Class::method`` for unittest methods, ``file.py::function`` for functions."""
    if folder is None:
        return []
    out = []
    for path in sorted(folder.glob("*.py")):
        tree = ast.parse(path.read_text())
        for node in tree.body:
            if isinstance(node, ast.ClassDef):
                out += [f"{path.name}::{node.name}::{f.name}" for f in node.body
                        if isinstance(f, ast.FunctionDef) and f.name.startswith("test")]
            elif isinstance(node, ast.FunctionDef) and node.name.startswith("test"):
                out.append(f"{path.name}::{node.name}")
    return out


IDS = _test_ids(TESTS)


def _load(path: Path) -> ModuleType:
    spec = importlib.util.spec_from_file_location(f"_pybox2d_tests_{path.stem}", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_wheel_ships_pybox2d_tests() -> None:
    if TESTS is None:
        pytest.skip("pybox2d (box2d 2.3.10, the dev extra) is not installed")
    assert len(IDS) >= 36  # 2.3.10: 35 unittest methods and one function


@pytest.mark.parametrize("test_id", IDS)
def test_pybox2d_test_passes_on_kge(test_id: str, installed: ModuleType) -> None:
    assert TESTS is not None
    filename, *names = test_id.split("::")
    module = _load(TESTS / filename)
    if len(names) == 1:
        getattr(module, names[0])()
        return
    case = getattr(module, names[0])(names[1])
    result = unittest.TestResult()
    case.run(result)
    problems = result.errors + result.failures
    assert not problems, problems[0][1]
