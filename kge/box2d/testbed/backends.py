"""Choosing a testbed backend: a window when there is a display, else headless frames."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from kge.box2d.testbed.framework import Backend

#: frames a headless run steps when none are asked for (10 s at 60 Hz)
HEADLESS_FRAMES = 600


def default_backend() -> Backend:
    """A window when a display is available, else :data:`HEADLESS_FRAMES` headless frames."""
    from kge.platform import has_display

    if has_display():
        from kge.box2d.testbed.window import WindowBackend

        return WindowBackend()
    from kge.box2d.testbed.headless import HeadlessBackend

    return HeadlessBackend(HEADLESS_FRAMES)
