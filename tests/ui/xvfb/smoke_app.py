"""The app the Xvfb test drives: two text fields and a button in a real window.

Run as a script with DISPLAY set. It prints one JSON line to stdout for everything the
UI does (ready, focus, text, submit, clipboard, click), so the test can wait for each
before its next input instead of sleeping; it quits when Done is clicked (or after
twenty seconds of frames, a safety stop).
"""

from __future__ import annotations

import json
import sys
from typing import Any

from kge import (
    App,
    Button,
    ButtonClicked,
    FocusChanged,
    TextInput,
    TextSubmitted,
    UINode,
    ValueChanged,
    World,
)
from kge.schedule import Stage, System
from kge.ui.state import UIState


def say(**what: Any) -> None:
    print(json.dumps(what), flush=True)


class Report(System):
    """Prints what the UI did this frame (see the module docstring)."""

    stage = Stage.UPDATE

    def __init__(self, fields: dict[int, str]) -> None:
        self.fields = fields
        self.frames = 0
        self.clipboard = ""

    def process(self, dt: float) -> None:
        world = self.world
        self.frames += 1
        if self.frames == 3:  # drawn and laid out: input can come
            say(ready=True)
        for ev in world.events(FocusChanged, ValueChanged, TextSubmitted, ButtonClicked):
            if isinstance(ev, FocusChanged) and ev.entity in self.fields:
                say(focus=self.fields[ev.entity])
            elif isinstance(ev, ValueChanged) and ev.entity in self.fields:
                say(field=self.fields[ev.entity], text=ev.value)
            elif isinstance(ev, TextSubmitted):
                say(submitted=ev.text)
            elif isinstance(ev, ButtonClicked):
                say(clicked=True, frames=self.frames)
                world.resource(App).quit()
        store = world.resource(UIState).store
        if store.text != self.clipboard:
            self.clipboard = store.text
            say(clipboard=store.text, system=store.system)


def scene(world: World) -> None:
    # a 400 x 300 window: the fields' centres 90 and 140 px from the top, Done at 200
    first = world.spawn(UINode(offset=(0, 60), width=200, height=30), TextInput(placeholder="name"))
    second = world.spawn(UINode(offset=(0, 10), width=200, height=30), TextInput())
    world.spawn(UINode(offset=(0, -50), width=120, height=36), Button("Done"))
    world.add_system(Report({first: "first", second: "second"}))


if __name__ == "__main__":  # imported (pytest's doctest collection), it must do nothing
    app = App(scene, headless=False, size=(400, 300), title="kge-smoke")
    app.run(frames=60 * 20)
    sys.exit(0)
