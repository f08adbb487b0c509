"""kge export: plans and errors, and one real build of a `kge new` project that runs
headless in a clean environment (no Python on PATH, no PYTHONPATH, another folder) and
draws its frame, with an image asset that travelled inside the build."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from kge.__main__ import main as kge_main
from kge.export import ExportError, export, plan
from kge.export.build import KGE_TOOLS, kge_modules, pyinstaller_args

MAGENTA = (230, 40, 200)


def new_project(where: Path, name: str = "moon-base") -> Path:
    cwd = Path.cwd()
    os.chdir(where)
    try:
        assert kge_main(["new", name]) == 0
    finally:
        os.chdir(cwd)
    return where / name


def test_plan_reads_the_project(tmp_path: Path) -> None:
    root = new_project(tmp_path)
    (root / "moon_base" / "assets").mkdir()
    (root / "moon_base" / "assets" / "coin.png").write_bytes(b"not read by the plan")
    p = plan(root)
    assert (p.name, p.package) == ("moon-base", "moon_base")
    assert p.executable == root / "dist" / "moon-base" / "moon-base"
    assert [(f.name, dest) for f, dest in p.data] == [("coin.png", "moon_base/assets")]
    one = plan(root, tmp_path / "out", onefile=True, name="Moon")
    assert one.executable == tmp_path / "out" / "Moon"


def test_the_build_leaves_kge_tools_and_heavy_libraries_out(tmp_path: Path) -> None:
    root = new_project(tmp_path)
    args = pyinstaller_args(plan(root), tmp_path)
    hidden = {args[i + 1] for i, a in enumerate(args) if a == "--hidden-import"}
    excluded = {args[i + 1] for i, a in enumerate(args) if a == "--exclude-module"}
    assert {"kge.app", "kge.render.sprites", "moon_base"} <= hidden
    assert not any(h.startswith(KGE_TOOLS) for h in hidden)
    assert {"torch", "ray", "kge.gym", "kge.testbed"} <= excluded
    assert set(kge_modules()) <= hidden


@pytest.mark.parametrize(("setup", "message"), [
    (lambda root: (root / "pyproject.toml").unlink(), "no pyproject.toml"),
    (lambda root: (root / "pyproject.toml").write_text("[project\n"), "cannot read it"),
    (lambda root: (root / "moon_base" / "__main__.py").unlink(), "no package with a __main__"),
    (lambda root: (root / "other").mkdir() or (root / "other" / "__init__.py").touch()
     or (root / "other" / "__main__.py").touch(), "several packages"),
])
def test_a_project_that_cannot_be_exported_is_named(tmp_path: Path, setup, message: str) -> None:
    root = new_project(tmp_path)
    setup(root)
    with pytest.raises(ExportError, match=message):
        plan(root)


def test_without_pyinstaller_the_error_says_how_to_install_it(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import importlib.util

    root = new_project(tmp_path)
    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec",
                        lambda name, *a: None if name == "PyInstaller" else real(name, *a))
    with pytest.raises(ExportError, match="pip install 'pyinstaller"):
        export(root)


def test_dry_run_says_what_it_would_build(tmp_path: Path, capsys) -> None:
    root = new_project(tmp_path)
    assert kge_main(["export", str(root), "--dry-run"]) == 0
    assert f"would build {root / 'dist' / 'moon-base' / 'moon-base'}" in capsys.readouterr().out


@pytest.mark.slow
def test_an_exported_game_runs_in_a_clean_environment(tmp_path: Path) -> None:
    root = new_project(tmp_path)
    assets = root / "moon_base" / "assets"
    assets.mkdir()
    Image.new("RGBA", (4, 4), (*MAGENTA, 255)).save(assets / "coin.png")
    game = root / "moon_base" / "game.py"
    text = game.read_text()
    # the coin's art comes from a file of the package, found next to the module
    text = text.replace("Sprite(solid(4, 4, COIN_COLOR), size=(0.6, 0.6))",
                        'Sprite("coin.png", size=(0.6, 0.6))')
    text = text.replace("    world.insert_resource(Score())",
                        "    world.insert_resource(Score())\n"
                        "    world.insert_resource(Assets(anchor=__file__))")
    text = text.replace("from kge.sound import tone", "from kge.assets import Assets\nfrom kge.sound import tone")
    game.write_text(text)

    exe = export(root, tmp_path / "dist", quiet=True)
    assert exe.is_file() and os.access(exe, os.X_OK)

    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    shot = elsewhere / "last.png"
    env = {"PATH": "/usr/bin:/bin", "HOME": str(elsewhere), "PYGLET_HEADLESS": "1",
           "PYGLET_AUDIO": "silent"}
    run = subprocess.run([str(exe), "90", "--screenshot", str(shot)], cwd=elsewhere, env=env,
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr[-2000:]
    px = np.asarray(Image.open(shot).convert("RGB")).astype(int)
    player = np.all(np.abs(px - (90, 200, 255)) <= 8, axis=-1).sum()
    coin = np.all(np.abs(px - MAGENTA) <= 8, axis=-1).sum()
    assert player > 200, "the player's sprite is not drawn"
    assert coin > 200, "the coin's image (a file inside the build) is not drawn"
