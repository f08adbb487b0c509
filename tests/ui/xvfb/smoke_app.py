"""The app the Xvfb smoke test drives: a text field and a button in a real window.

Run as a script with DISPLAY set; writes what the UI received to the JSON file
named on the command line, then quits (or gives up after a few seconds).
"""

from __future__ import annotations

import json
import sys

from kge import App, Button, ButtonClicked, TextInput, TextSubmitted, UIEvents, UINode, World
from kge.schedule import Stage, System


class Record(System):
    """Writes what the UI received to ``out`` when the button is clicked, then quits."""

    stage = Stage.UPDATE

    def __init__(self, out: str) -> None:
        self.out = out
        self.got: dict[str, object] = {"submitted": None, "clicked": False, "frames": 0}

    def process(self, dt: float) -> None:
        self.got["frames"] = int(str(self.got["frames"])) + 1
        events = self.world.resource(UIEvents)
        for ev in events.of(TextSubmitted):
            self.got["submitted"] = ev.text
        if events.of(ButtonClicked):
            self.got["clicked"] = True
            with open(self.out, "w", encoding="utf-8") as f:
                json.dump(self.got, f)
            self.world.resource(App).quit()


def scene(world: World, out: str) -> None:
    # 400 x 300 window: field centred 40 px above the middle, button 40 px below
    world.spawn(UINode(offset=(0, 40), width=200, height=30), TextInput(placeholder="name"))
    world.spawn(UINode(offset=(0, -40), width=120, height=36), Button("Done"))
    world.add_system(Record(out))


if __name__ == "__main__":  # imported (pytest's doctest collection), it must do nothing
    app = App(scene, headless=False, size=(400, 300), title="kge-smoke", out=sys.argv[1])
    app.run(frames=60 * 20)  # a safety stop: the test normally ends it by clicking Done
