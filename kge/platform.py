"""Facts about the machine kge runs on, kept in one low module every floor may ask.

>>> import os
>>> os.environ["KGE_HEADLESS"] = "1"; has_display()
False
>>> del os.environ["KGE_HEADLESS"]
"""

from __future__ import annotations

import os
import stat
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


def regular_file_size(path: str | os.PathLike[str]) -> int:
    """The size of the regular file at ``path``, or a ``ValueError`` whose message
    completes "<the file> ...": ``not found``, ``unreadable (<why>)`` or ``is not a
    regular file`` (a folder, a device or a pipe, which a loader must not open)."""
    try:
        st = os.stat(path)
    except FileNotFoundError:
        raise ValueError("not found") from None
    except OSError as exc:
        raise ValueError(f"unreadable ({exc})") from None
    if not stat.S_ISREG(st.st_mode):
        raise ValueError("is not a regular file")
    return st.st_size
