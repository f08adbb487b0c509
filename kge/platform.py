"""Facts about the machine kge runs on, kept in one low module every floor may ask.

>>> import os
>>> os.environ["KGE_HEADLESS"] = "1"; has_display()
False
>>> del os.environ["KGE_HEADLESS"]
"""

from __future__ import annotations

import os
import sys


def has_display() -> bool:
    """True when a window can be opened (a desktop, or X11/Wayland on Linux).

    ``PYGLET_HEADLESS`` or ``KGE_HEADLESS`` in the environment force headless mode,
    so a test run never opens a window even on a desktop.
    """
    if os.environ.get("PYGLET_HEADLESS") or os.environ.get("KGE_HEADLESS"):
        return False
    if sys.platform.startswith("linux") or "bsd" in sys.platform:
        return bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))
    return True
