"""Re-make docs/images/editor.png and editor-play.png (headless): the platformer's first
level in ``kge edit`` with the player selected, then playing inside the editor.

Run from the repository: ``.venv/bin/python tools/editor_screenshots.py``.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

os.environ.setdefault("PYGLET_HEADLESS", "1")
ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT), str(ROOT / "examples")]


def main() -> None:
    import platformer

    from kge.editor.app import editor_app

    app, ed = editor_app(platformer.LEVELS / "level1.scene.toml", headless=True,
                         size=(1280, 720), hot_reload=False)
    app.step()
    player = next(e for e in ed.model.entities() if ed.model.name(e) == "player")
    ed.model.select(player)
    ed.tool = "move"
    ed.frame()
    app.step(2)
    app.screenshot(ROOT / "docs" / "images" / "editor.png")
    ed.play()
    for _ in range(90):
        app.advance(1 / 60)
    app.screenshot(ROOT / "docs" / "images" / "editor-play.png")
    ed.stop()
    app.close()


if __name__ == "__main__":
    main()
