"""``python -m kge.box2d.testbed`` in a real window under Xvfb, its keys typed by xdotool.

The testbed runs through ``xvfb/testbed_driver.py``, which reports its first frame,
each key it receives and the example's state as JSON lines: the test waits for each
report before its next key (never a fixed sleep). Needs the Debian packages xvfb and
xdotool (``tools/bootstrap.sh`` installs them); the test installs nothing and fails,
naming them, when they are absent.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from kge.box2d.testbed import examples
from kge.keys import Key

from ..xvfb import TIMEOUT, Reports, virtual_display, xdo

DRIVER = Path(__file__).parent / "xvfb" / "testbed_driver.py"


def test_breakable_in_a_window_breaks_on_b_and_closes_on_escape() -> None:
    if examples.examples_dir() is None:
        pytest.skip("pybox2d (box2d 2.3.10, the dev extra) is not installed")
    app = None
    with virtual_display() as (display, env):
        try:
            app = subprocess.Popen(
                [sys.executable, str(DRIVER), "breakable", "--frames", "100000"],
                env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
            reports = Reports(app)
            wid = xdo(display, "search", "--sync", "--name", "kge.box2d testbed").splitlines()[0]
            # the example has stepped (its b key needs a velocity cached by a step)
            reports.wait(lambda r: r.get("ready"), "its first frame")
            xdo(display, "windowfocus", "--sync", wid)
            xdo(display, "key", "b")  # the example's own key: break the body in two
            pressed = reports.wait(lambda r: r.get("key") == Key.B, "the b key")
            broke = reports.wait(lambda r: r.get("broke"), "the break")
            assert broke["bodies"] == 4 and broke["frame"] > pressed["frame"]
            xdo(display, "key", "Escape")  # the testbed's: quit
            reports.wait(lambda r: r.get("key") == Key.ESCAPE, "the Escape key")
            assert app.wait(timeout=TIMEOUT) == 0, app.stderr.read() if app.stderr else ""
            out = "\n".join(reports.rest())
            assert "breakable:" in out and "4 bodies" in out, out  # broken: two pieces
            frames = int(out.split("breakable: ")[1].split(" frames")[0])
            assert frames < 100000  # Escape closed it, not the safety stop
        finally:
            if app is not None and app.poll() is None:
                app.kill()
                app.wait(timeout=10)
