"""One real window under Xvfb, driven by xdotool: a click, typing and Enter reach the UI.

Needs the Debian packages xvfb and xdotool (``tools/bootstrap.sh`` installs them); the
test installs nothing and fails, naming them, when they are absent. It never sleeps:
after each input it waits for the app to report the result (a line on its stdout),
with a generous deadline that only a hung app reaches.
"""

from __future__ import annotations

import json
import os
import select
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


class Reports:
    """The app's report lines, read straight from the pipe (no buffered reader, whose
    buffer select() cannot see)."""

    def __init__(self, app: subprocess.Popen[bytes]) -> None:
        assert app.stdout is not None
        self.app, self.fd = app, app.stdout.fileno()
        self.seen: list[str] = []
        self._partial = b""

    def wait_for(self, want: str) -> None:
        """Read until the app reports ``want`` (the condition, not a delay)."""
        deadline = time.monotonic() + 60.0  # a hung app, not a slow machine, reaches this
        while want not in self.seen:
            left = deadline - time.monotonic()
            assert left > 0, f"no {want!r} from the app in 60 s; it said {self.seen}"
            ready, _, _ = select.select([self.fd], [], [], min(left, 1.0))
            if not ready:
                continue
            chunk = os.read(self.fd, 4096)
            assert chunk, f"the app ended ({self.app.wait()}) before {want!r}: {self.seen}"
            *lines, self._partial = (self._partial + chunk).split(b"\n")
            self.seen += [line.decode().strip() for line in lines]


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
                               env=env, stdout=subprocess.PIPE)  # fmt: skip
        reports = Reports(app)
        wid = _xdo(display, "search", "--sync", "--name", "kge-smoke").splitlines()[0]
        reports.wait_for("ready")  # the UI is laid out and drawn
        _xdo(display, "windowfocus", "--sync", wid)
        _xdo(display, "mousemove", "--window", wid, "200", "110", "click", "1")  # the field
        reports.wait_for("focused")
        _xdo(display, "type", "--delay", "30", "hello")
        reports.wait_for("typed hello")
        _xdo(display, "key", "Return")
        reports.wait_for("submitted hello")
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
