"""One real window under Xvfb, driven by xdotool: a click, typing and Enter reach the UI.

Needs the Debian packages xvfb and xdotool (``tools/bootstrap.sh`` installs them); the
test installs nothing and fails, naming them, when they are absent.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

HERE = Path(__file__).parent


def _need(tool: str) -> str:
    path = shutil.which(tool)
    if path is None:
        pytest.fail(
            f"{tool} is not installed: run tools/bootstrap.sh (Debian packages xvfb, xdotool)"
        )
    return path


def _xdo(display: str, *args: str) -> str:
    out = subprocess.run(
        [_need("xdotool"), *args], env={**os.environ, "DISPLAY": display},
        capture_output=True, text=True, timeout=30, check=True,
    )  # fmt: skip
    return out.stdout.strip()


def test_real_window_click_typing_and_enter_under_xvfb(tmp_path: Path) -> None:
    xvfb = _need("Xvfb")
    _need("xdotool")
    read, write = os.pipe()
    server = subprocess.Popen(
        [xvfb, "-displayfd", str(write), "-screen", "0", "800x600x24", "-nolisten", "tcp"],
        pass_fds=(write,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
    )  # fmt: skip
    os.close(write)
    app = None
    try:
        number = b""
        while not number.endswith(b"\n"):
            chunk = os.read(read, 16)
            assert chunk, "Xvfb exited before reporting its display"
            number += chunk
        display = f":{number.decode().strip()}"
        out = tmp_path / "got.json"
        env = {k: v for k, v in os.environ.items() if k not in ("PYGLET_HEADLESS", "KGE_HEADLESS")}
        env.update(DISPLAY=display, PYGLET_AUDIO="silent")
        app = subprocess.Popen([sys.executable, str(HERE / "xvfb" / "smoke_app.py"), str(out)],
                               env=env)  # fmt: skip
        wid = _xdo(display, "search", "--sync", "--name", "kge-smoke").splitlines()[0]
        time.sleep(0.5)  # a few frames: the layout exists
        _xdo(display, "windowfocus", "--sync", wid)
        _xdo(display, "mousemove", "--window", wid, "200", "110", "click", "1")  # the field
        time.sleep(0.3)
        _xdo(display, "type", "--delay", "30", "hello")
        _xdo(display, "key", "Return")
        time.sleep(0.3)
        _xdo(display, "mousemove", "--window", wid, "200", "190", "click", "1")  # Done
        assert app.wait(timeout=30) == 0
        got = json.loads(out.read_text())
        assert got["submitted"] == "hello" and got["clicked"] is True and got["frames"] > 5
    finally:
        if app is not None and app.poll() is None:
            app.kill()
        server.terminate()
        server.wait(timeout=10)
        os.close(read)
