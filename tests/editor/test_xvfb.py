"""``kge edit`` in a real window under Xvfb, driven by xdotool: click an entity, delete it
with the Delete key, save with Ctrl+S, quit with Ctrl+Q. Each step waits for the editor's
own report of what it shows (written every frame), never for a fixed time."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from .test_model import LEVEL

HERE = Path(__file__).parent


def _need(tool: str) -> str:
    path = shutil.which(tool)
    if path is None:
        pytest.fail(f"{tool} is not installed: run tools/bootstrap.sh (Debian xvfb, xdotool)")
    return path


def _xdo(display: str, *args: str) -> str:
    out = subprocess.run([_need("xdotool"), *args], env={**os.environ, "DISPLAY": display},
                         capture_output=True, text=True, timeout=30, check=True)
    return out.stdout.strip()


def _until(report: Path, check: Callable[[dict[str, Any]], bool], proc: subprocess.Popen[bytes],
           what: str, timeout: float = 60.0) -> dict[str, Any]:
    """The editor's report once ``check`` holds (it is rewritten every frame)."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        assert proc.poll() is None, f"the editor exited while waiting for: {what}"
        try:
            data = json.loads(report.read_text())
        except (OSError, ValueError):
            data = None
        if data is not None and check(data):
            return data
        time.sleep(0.02)  # a poll interval, not a wait for something to have happened
    raise AssertionError(f"the editor never showed: {what}")


def test_kge_edit_in_a_real_window(tmp_path: Path) -> None:
    xvfb = _need("Xvfb")
    _need("xdotool")
    scene = tmp_path / "level.scene.toml"
    scene.write_text(LEVEL)
    report = tmp_path / "report.json"
    read, write = os.pipe()
    server = subprocess.Popen(
        [xvfb, "-displayfd", str(write), "-screen", "0", "1100x800x24", "-nolisten", "tcp"],
        pass_fds=(write,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write)
    proc = None
    try:
        number = b""
        while not number.endswith(b"\n"):
            chunk = os.read(read, 16)
            assert chunk, "Xvfb exited before reporting its display"
            number += chunk
        display = f":{number.decode().strip()}"
        env = {k: v for k, v in os.environ.items() if k not in ("PYGLET_HEADLESS", "KGE_HEADLESS")}
        env.update(DISPLAY=display, PYGLET_AUDIO="silent")
        proc = subprocess.Popen([sys.executable, str(HERE / "xvfb" / "editor_driver.py"),
                                 str(scene), str(report)], env=env)
        wid = _xdo(display, "search", "--sync", "--name", "kge edit").splitlines()[0]
        data = _until(report, lambda d: d["frames"] >= 3, proc, "three frames")
        _xdo(display, "windowfocus", "--sync", wid)
        x, y = data["crate"]
        _xdo(display, "mousemove", "--window", wid, str(int(x)), str(int(y)), "click", "1")
        _until(report, lambda d: d["selection"] == ["Crate"], proc, "the crate selected")
        _xdo(display, "key", "--window", wid, "Delete")
        _until(report, lambda d: "Crate" not in d["names"] and d["dirty"], proc, "it deleted")
        _xdo(display, "key", "--window", wid, "ctrl+s")
        _until(report, lambda d: not d["dirty"], proc, "it saved")
        text = scene.read_text()
        assert 'name = "Crate"' not in text and 'name = "Ground"' in text
        _xdo(display, "key", "--window", wid, "ctrl+q")
        assert proc.wait(timeout=60) == 0
    finally:
        if proc is not None and proc.poll() is None:
            proc.kill()
        server.terminate()
        server.wait(timeout=10)
        os.close(read)
