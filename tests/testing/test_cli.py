"""The `kge` command: a version, a usage, and each command's own help."""

from __future__ import annotations

import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from kge.__main__ import COMMANDS, main

ROOT = Path(__file__).resolve().parents[2]


def declared_version() -> str:
    with open(ROOT / "pyproject.toml", "rb") as f:
        return str(tomllib.load(f)["project"]["version"])


@pytest.mark.parametrize("flag", ["--version", "-V"])
def test_version_prints_the_declared_version(flag: str, capsys: pytest.CaptureFixture[str]) -> None:
    assert main([flag]) == 0
    assert capsys.readouterr().out == f"kge {declared_version()}\n"


def test_no_command_prints_usage_naming_every_command(capsys: pytest.CaptureFixture[str]) -> None:
    assert main([]) == 0
    out = capsys.readouterr().out
    assert out.startswith("usage: kge [--version]")
    for name in COMMANDS:
        assert f"\n  {name} " in out


def test_unknown_command_is_an_error_on_stderr(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["fly"]) == 2
    captured = capsys.readouterr()
    assert "unknown command 'fly'" in captured.err and captured.out == ""


@pytest.mark.parametrize("command", ["new", "demo", "testbed", "bench", "export", "schedule"])
def test_each_command_has_its_own_help(command: str) -> None:
    # a subprocess: argparse's --help exits, and the bench's import is heavy
    run = subprocess.run([sys.executable, "-m", "kge", command, "--help"], cwd=ROOT,
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    assert run.stdout.startswith(f"usage: kge {command}"), run.stdout[:80]


def test_the_new_project_readme_points_at_kge_2_not_the_unrelated_package(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    assert main(["new", "moon-base"]) == 0
    readme = (tmp_path / "moon-base" / "README.md").read_text()
    assert "pypi.org/project/kge" not in readme
    assert "pip install -e path/to/kge" in readme
