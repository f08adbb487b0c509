"""Suite-wide setup: headless pyglet (EGL) and the silent audio driver.

Set before anything imports pyglet, so render and audio tests run on machines
with no display and no sound device.
"""

import os

os.environ.setdefault("PYGLET_HEADLESS", "1")
os.environ.setdefault("PYGLET_AUDIO", "silent")
os.environ.setdefault("KGE_HEADLESS", "1")
os.environ.setdefault("PYGLET_DEBUG_GL", "1")  # a GL error fails the test that made it

# The examples import each other (kge_required, game_menus) as `python examples/x.py`
# would find them: from their own folder. Tests that load an example need the same.
import sys as _sys
from pathlib import Path as _Path

_EXAMPLES = str(_Path(__file__).resolve().parents[1] / "examples")
if _EXAMPLES not in _sys.path:
    _sys.path.insert(0, _EXAMPLES)
