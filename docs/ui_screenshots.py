"""Make the pictures of ``docs/ui.md`` and ``docs/ui-scenes-input.md`` from the UI
testbed samples.

Run ``python docs/ui_screenshots.py`` (headless is fine: EGL renders offscreen).
Everything drawn is built from components and the default theme; no image file.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

os.environ.setdefault("PYGLET_HEADLESS", "1")
os.environ.setdefault("PYGLET_AUDIO", "silent")
sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from kge import App, Key
from kge.testbed.samples.ui import pause_overlay, scene_transitions, widget_gallery
from kge.testbed.samples.ui_editor import editor_widgets
from kge.ui.state import UIState
from kge.transitions import Wipe

OUT = Path(__file__).resolve().parent / "images"


def main() -> None:
    OUT.mkdir(exist_ok=True)
    app = App(widget_gallery, headless=True, size=(1280, 720))
    app.step()
    app.input.press(Key.TAB)  # focus the first button: the focus ring shows
    app.step()
    app.screenshot(str(OUT / "ui-gallery.png"))
    app.close()

    app = App(editor_widgets, headless=True, size=(1280, 720))
    app.step()
    tree = app.world.resource(UIState).layout
    cam = next(e for e in tree.order if getattr(tree.widget.get(e), "items", None))
    app.world.resource(UIState).focused = cam  # the tree, focused
    app.step()
    app.screenshot(str(OUT / "ui-editor.png"))
    app.close()

    app = App(pause_overlay, headless=True, size=(800, 480))
    app.step(90)
    app.input.press(Key.P)
    app.step()
    app.screenshot(str(OUT / "ui-pause-overlay.png"))
    app.close()

    app = App(scene_transitions, headless=True, size=(800, 480))
    app.step()
    app.render()
    from kge.testbed.samples.ui import _red_room

    app.replace_scene(_red_room, transition=Wipe(0.6, direction="left"))
    app.render()  # the picture of the blue room is taken
    app.advance(0.3)
    app.screenshot(str(OUT / "ui-transition-wipe.png"))
    app.close()


if __name__ == "__main__":
    main()
