"""``python -m kge.box2d.testbed`` in a real window under Xvfb, its keys typed by xdotool.

Needs the Debian packages xvfb and xdotool (``tools/bootstrap.sh`` installs them); the
test installs nothing and fails, naming them, when they are absent.
"""

from __future__ import annotations

import subprocess
import sys
import time

import pytest

from kge.box2d.testbed import examples

from ..xvfb import virtual_display, xdo


def test_breakable_in_a_window_breaks_on_b_and_closes_on_escape() -> None:
    if examples.examples_dir() is None:
        pytest.skip("pybox2d (box2d 2.3.10, the dev extra) is not installed")
    app = None
    with virtual_display() as (display, env):
        try:
            app = subprocess.Popen(
                [sys.executable, "-m", "kge.box2d.testbed", "breakable", "--frames", "1800"],
                env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            wid = xdo(display, "search", "--sync", "--name", "kge.box2d testbed").splitlines()[0]
            time.sleep(0.5)  # a few frames: the test is running
            xdo(display, "windowfocus", "--sync", wid)
            xdo(display, "key", "b")  # the example's own key: break the body in two
            time.sleep(0.5)
            xdo(display, "key", "Escape")  # the testbed's: quit
            out, err = app.communicate(timeout=30)
            assert app.returncode == 0, err
            assert "breakable:" in out and "4 bodies" in out, out  # broken: two pieces
            frames = int(out.split("breakable: ")[1].split(" frames")[0])
            assert frames < 1800  # Escape closed it, not the safety stop
        finally:
            if app is not None and app.poll() is None:
                app.kill()
