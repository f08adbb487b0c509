"""``python -m kge.box2d.testbed`` as the real-window test runs it, reporting what the
testbed did as JSON lines on stdout so the test can wait for each before its next key.

Run as a script with the testbed's own arguments. It replaces the window backend's
driver with one that reports, and then calls the testbed's ``main``: the window, the
keys (typed by xdotool under Xvfb) and the exit summary are the command's own.
"""

from __future__ import annotations

import json
import sys
from typing import Any

from kge.box2d.testbed import window
from kge.box2d.testbed.__main__ import main


def report(**what: Any) -> None:
    print(json.dumps(what), flush=True)


class ReportingDriver(window.TestDriver):
    """The testbed's driver, reporting its first frame, each key and the example's
    ``broke`` flag (pybox2d's breakable example) when it turns True."""

    broke = False

    def on_fixed_update(self, dt: float) -> None:
        super().on_fixed_update(dt)
        if self.frame == 1:
            report(ready=True)
        if getattr(self.test, "broke", False) and not self.broke:
            self.broke = True
            report(broke=True, frame=self.frame, bodies=self.test.world.bodyCount)

    def on_key_down(self, key: int) -> None:
        report(key=int(key), frame=self.frame)
        super().on_key_down(key)


if __name__ == "__main__":
    window.TestDriver = ReportingDriver  # type: ignore[misc]
    raise SystemExit(main(sys.argv[1:]))
