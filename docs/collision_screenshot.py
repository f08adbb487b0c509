"""Make ``docs/images/collision.png``: the four Collision Module testbed samples.

Run ``python docs/collision_screenshot.py`` (headless is fine: it renders
offscreen through EGL). Each tile is the sample framed as the testbed frames it,
after a few seconds of game time.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

os.environ.setdefault("PYGLET_HEADLESS", "1")
sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from kge import App
from kge.testbed import get_sample
from kge.testbed.showcase import contact_sheet, frame_sample, grab

SLUGS = ("distance-test", "time-of-impact", "polygon-collision", "dynamic-tree")
STEPS = {"distance-test": 150, "time-of-impact": 60, "polygon-collision": 30,
         "dynamic-tree": 120}


def main() -> None:
    tiles = []
    for slug in SLUGS:
        sample = get_sample(slug)
        app = App(sample.setup, headless=True, size=(640, 480), background=(20, 22, 28))
        frame_sample(app, sample)
        app.step(STEPS[slug])
        tiles.append(grab(app))
        app.close()
    out = Path(__file__).resolve().parent / "images" / "collision.png"
    contact_sheet(tiles, out, columns=2, scale=1)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
