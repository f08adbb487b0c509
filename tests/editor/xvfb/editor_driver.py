"""Runs ``kge edit`` on a scene in a real window and writes what it shows to a JSON file
every frame (the Xvfb test reads it to sync on the editor's own state, never on time)."""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path

from kge.components.ui import Button
from kge.editor.app import editor_app
from kge.schedule import Stage, System
from kge.ui.interact import UIState


class Report(System):
    stage = Stage.LATE

    def __init__(self, out: Path, editor: object) -> None:
        self.out = out
        self.editor = editor
        self.frames = 0

    def process(self, dt: float) -> None:
        ed = self.editor
        m = ed.model  # type: ignore[attr-defined]
        self.frames += 1
        crate = next((e for e in m.entities() if m.name(e) == "Crate"), None)
        x, y = ed.to_screen(m.world_pose(crate)[:2]) if crate else (0.0, 0.0)  # type: ignore[attr-defined]
        h = ed.app.size[1]  # type: ignore[attr-defined]
        ui = ed.ui  # type: ignore[attr-defined]
        boxes = ui.resource(UIState).layout.boxes
        buttons = {ui.get(e, Button).text: [boxes[e].center[0], h - boxes[e].center[1]]
                   for e in ed.dialog if ui.exists(e) and ui.has(e, Button) and e in boxes}  # type: ignore[attr-defined]
        data = {"frames": self.frames, "selection": [m.name(e) for e in m.selection],
                "names": [m.name(e) for e in m.entities()], "dirty": m.dirty,
                "dialog": ed.dialog_kind, "buttons": buttons,  # type: ignore[attr-defined]
                "crate": [x, h - y]}  # window pixels from the top-left, as xdotool counts
        tmp = self.out.with_suffix(".tmp")
        tmp.write_text(json.dumps(data))
        os.replace(tmp, self.out)


def main() -> None:
    scene, out = Path(sys.argv[1]), Path(sys.argv[2])
    app, editor = editor_app(scene, size=(1000, 700), hot_reload=False)
    app.world.add_system(Report(out, editor))
    app.run()
    app.close()


if __name__ == "__main__":
    main()
