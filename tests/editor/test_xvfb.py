"""``kge edit`` in a real window under Xvfb, driven by xdotool: click an entity, delete it
with the Delete key, close the window (the unsaved-changes prompt; Cancel keeps it
open), save with Ctrl+S, and close it again (clean: it quits). Each step waits for the editor's
own report of what it shows (written every frame), never for a fixed time."""

from __future__ import annotations

import json
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from ..xvfb import close_window, virtual_display, xdo
from .test_model import LEVEL

HERE = Path(__file__).parent




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
    scene = tmp_path / "level.scene.toml"
    scene.write_text(LEVEL)
    report = tmp_path / "report.json"
    proc = None
    with virtual_display("1100x800x24") as (display, env):
        try:
            proc = subprocess.Popen([sys.executable, str(HERE / "xvfb" / "editor_driver.py"),
                                     str(scene), str(report)], env=env)
            wid = xdo(display, "search", "--sync", "--name", "kge edit").splitlines()[0]
            data = _until(report, lambda d: d["frames"] >= 3, proc, "three frames")
            xdo(display, "windowfocus", "--sync", wid)
            x, y = data["crate"]
            xdo(display, "mousemove", "--window", wid, str(int(x)), str(int(y)), "click", "1")
            _until(report, lambda d: d["selection"] == ["Crate"], proc, "the crate selected")
            xdo(display, "key", "--window", wid, "Delete")
            _until(report, lambda d: "Crate" not in d["names"] and d["dirty"], proc, "it deleted")
            close_window(display, wid)  # the window manager's close button
            data = _until(report, lambda d: d["dialog"] == "unsaved" and "Cancel" in d["buttons"],
                          proc, "the unsaved-changes prompt")
            x, y = data["buttons"]["Cancel"]
            xdo(display, "mousemove", "--window", wid, str(int(x)), str(int(y)), "click", "1")
            _until(report, lambda d: d["dialog"] == "" and d["dirty"], proc, "the prompt gone")
            xdo(display, "key", "--window", wid, "ctrl+s")
            _until(report, lambda d: not d["dirty"], proc, "it saved")
            text = scene.read_text()
            assert 'name = "Crate"' not in text and 'name = "Ground"' in text
            close_window(display, wid)  # nothing unsaved: the editor quits at once
            assert proc.wait(timeout=60) == 0
        finally:
            if proc is not None and proc.poll() is None:
                proc.kill()
