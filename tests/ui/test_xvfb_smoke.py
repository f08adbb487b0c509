"""One real window under Xvfb, driven by xdotool: clicks, typing, Enter and the system
clipboard (copy in one field, paste in another through X11's CLIPBOARD) reach the UI.

The app reports each thing its UI did as a JSON line; the test waits for the line it
expects before the next input (never a fixed sleep). Needs the Debian packages xvfb
and xdotool (``tools/bootstrap.sh`` installs them); the test installs nothing and
fails, naming them, when they are absent.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from .. import xvfb
from ..xvfb import TIMEOUT, Reports, virtual_display

HERE = Path(__file__).parent


def test_real_window_clicks_typing_enter_and_the_system_clipboard(tmp_path: Path) -> None:
    app = None
    with virtual_display("800x600x24") as (display, env):

        def xdo(*args: str) -> str:
            return xvfb.xdo(display, *args)

        try:
            app = subprocess.Popen([sys.executable, str(HERE / "xvfb" / "smoke_app.py")], env=env,
                                   stdout=subprocess.PIPE)  # fmt: skip
            reports = Reports(app)
            wid = xdo("search", "--sync", "--name", "kge-smoke").splitlines()[0]
            reports.wait(lambda r: r.get("ready"), "that it was ready")
            xdo("windowfocus", "--sync", wid)
            xdo("mousemove", "--window", wid, "200", "90", "click", "1")  # the first field
            reports.wait(lambda r: r.get("focus") == "first", "the first field's focus")
            xdo("type", "--delay", "20", "hello")
            reports.wait(lambda r: r.get("field") == "first" and r.get("text") == "hello", "hello")
            xdo("key", "Return")
            reports.wait(lambda r: r.get("submitted") == "hello", "the submit")
            xdo("key", "ctrl+a", "ctrl+c")
            copied = reports.wait(lambda r: r.get("clipboard") == "hello", "the copy")
            assert copied["system"] is True  # through pyglet's X11 window, not the fallback
            xdo("mousemove", "--window", wid, "200", "140", "click", "1")  # the second field
            reports.wait(lambda r: r.get("focus") == "second", "the second field's focus")
            xdo("key", "ctrl+v")
            reports.wait(lambda r: r.get("field") == "second" and r.get("text") == "hello", "paste")
            xdo("mousemove", "--window", wid, "200", "200", "click", "1")  # Done
            done = reports.wait(lambda r: r.get("clicked"), "the click on Done")
            assert done["frames"] > 5
            assert app.wait(timeout=TIMEOUT) == 0
        finally:
            if app is not None and app.poll() is None:
                app.kill()
                app.wait(timeout=10)
