"""``python -m kge.box2d.testbed`` in a real window under Xvfb, its keys typed by xdotool.

Needs the Debian packages xvfb and xdotool (``tools/bootstrap.sh`` installs them); the
test installs nothing and fails, naming them, when they are absent.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import time

import pytest

from kge.box2d.testbed import examples


def _need(tool: str) -> str:
    path = shutil.which(tool)
    if path is None:
        pytest.fail(
            f"{tool} is not installed: run tools/bootstrap.sh (Debian packages xvfb, xdotool)")
    return path


def _xdo(display: str, *args: str) -> str:
    out = subprocess.run([_need("xdotool"), *args], env={**os.environ, "DISPLAY": display},
                         capture_output=True, text=True, timeout=30, check=True)
    return out.stdout.strip()


def test_breakable_in_a_window_breaks_on_b_and_closes_on_escape() -> None:
    if examples.examples_dir() is None:
        pytest.skip("pybox2d (box2d 2.3.10, the dev extra) is not installed")
    xvfb = _need("Xvfb")
    _need("xdotool")
    read, write = os.pipe()
    server = subprocess.Popen(
        [xvfb, "-displayfd", str(write), "-screen", "0", "800x600x24", "-nolisten", "tcp"],
        pass_fds=(write,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write)
    app = None
    try:
        number = b""
        while not number.endswith(b"\n"):
            chunk = os.read(read, 16)
            assert chunk, "Xvfb exited before reporting its display"
            number += chunk
        display = f":{number.decode().strip()}"
        env = {k: v for k, v in os.environ.items() if k not in ("PYGLET_HEADLESS", "KGE_HEADLESS")}
        env.update(DISPLAY=display, PYGLET_AUDIO="silent")
        app = subprocess.Popen(
            [sys.executable, "-m", "kge.box2d.testbed", "breakable", "--frames", "1800"],
            env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        wid = _xdo(display, "search", "--sync", "--name", "kge.box2d testbed").splitlines()[0]
        time.sleep(0.5)  # a few frames: the test is running
        _xdo(display, "windowfocus", "--sync", wid)
        _xdo(display, "key", "b")  # the example's own key: break the body in two
        time.sleep(0.5)
        _xdo(display, "key", "Escape")  # the testbed's: quit
        out, err = app.communicate(timeout=30)
        assert app.returncode == 0, err
        assert "breakable:" in out and "4 bodies" in out, out  # broken: two pieces
        frames = int(out.split("breakable: ")[1].split(" frames")[0])
        assert frames < 1800  # Escape closed it, not the safety stop
    finally:
        if app is not None and app.poll() is None:
            app.kill()
        server.terminate()
        server.wait(timeout=10)
        os.close(read)
