"""``kge new NAME`` makes a project whose game runs and whose tests pass with no edits."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from kge.__main__ import main
from kge.scaffold import ScaffoldError, create, package_name


def test_kge_new_project_runs_and_its_tests_pass(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.chdir(tmp_path)
    assert main(["new", "space-miner"]) == 0
    told = capsys.readouterr().out
    assert "python -m space_miner" in told and "pytest" in told
    root = tmp_path / "space-miner"
    assert sorted(p.relative_to(root).as_posix() for p in root.rglob("*.*")) == [
        "README.md", "pyproject.toml", "space_miner/__init__.py", "space_miner/__main__.py",
        "space_miner/game.py", "tests/test_game.py",
    ]  # fmt: skip
    env = {**os.environ, "PYGLET_HEADLESS": "1", "PYGLET_AUDIO": "silent"}
    tests = subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider"],
        cwd=root, env=env, capture_output=True, text=True, timeout=300,
    )  # fmt: skip
    assert tests.returncode == 0, tests.stdout + tests.stderr
    assert "3 passed" in tests.stdout
    game = subprocess.run(
        [sys.executable, "-m", "space_miner", "30"],
        cwd=root, env=env, capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert game.returncode == 0, game.stderr


def test_unusable_names_and_existing_folders_are_refused(tmp_path: Path) -> None:
    assert package_name("My-Game 2") == "my_game_2"
    for bad in ("2fast", "class", "kge", ""):
        with pytest.raises(ScaffoldError, match="cannot name a Python package"):
            package_name(bad)
    create("demo", tmp_path)
    with pytest.raises(ScaffoldError, match="already exists"):
        create("demo", tmp_path)
