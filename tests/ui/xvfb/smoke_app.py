"""The app the Xvfb smoke test drives: a text field and a button in a real window.

Run as a script with DISPLAY set. It tells the test what happened, one line on stdout
per milestone, so the test waits for conditions instead of sleeping: ``ready`` once the
UI has been laid out and drawn, ``focused`` when the field takes the focus, ``typed
TEXT`` as the field's text changes, ``submitted TEXT`` on Enter. Clicking the button
writes what the UI received to the JSON file named on the command line and quits (a
safety stop ends it after twenty seconds of frames).
"""

from __future__ import annotations

import json
import sys

from kge import App, Button, ButtonClicked, TextInput, TextSubmitted, UINode, World
from kge.schedule import Stage, System
from kge.ui.events import FocusChanged


def tell(line: str) -> None:
    print(line, flush=True)


class Record(System):
    """Reports the UI's events to the test and writes them out when Done is clicked."""

    stage = Stage.UPDATE

    def __init__(self, out: str, field: int) -> None:
        self.out = out
        self.field = field
        self.text = ""
        self.got: dict[str, object] = {"submitted": None, "clicked": False, "frames": 0}

    def process(self, dt: float) -> None:
        world = self.world
        frames = int(str(self.got["frames"])) + 1
        self.got["frames"] = frames
        if frames == 3:  # the window has drawn the laid-out UI twice
            tell("ready")
        for change in world.events(FocusChanged):
            if change.entity == self.field:
                tell("focused")
        text = world.get(self.field, TextInput).text
        if text != self.text:
            self.text = text
            tell(f"typed {text}")
        for ev in world.events(TextSubmitted):
            self.got["submitted"] = ev.text
            tell(f"submitted {ev.text}")
        if world.events(ButtonClicked):
            tell("clicked")
            self.got["clicked"] = True
            with open(self.out, "w", encoding="utf-8") as f:
                json.dump(self.got, f)
            world.resource(App).quit()


def scene(world: World, out: str) -> None:
    # 400 x 300 window: field centred 40 px above the middle, button 40 px below
    field = world.spawn(UINode(offset=(0, 40), width=200, height=30), TextInput(placeholder="name"))
    world.spawn(UINode(offset=(0, -40), width=120, height=36), Button("Done"))
    world.add_system(Record(out, field))


if __name__ == "__main__":  # imported (pytest's doctest collection), it must do nothing
    app = App(scene, headless=False, size=(400, 300), title="kge-smoke", out=sys.argv[1])
    app.run(frames=60 * 20)  # a safety stop: the test normally ends it by clicking Done
