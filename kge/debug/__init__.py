"""Debug tools: immediate-mode gizmos, the in-game console, the live inspector.

* :class:`Gizmos` (a resource): lines, arrows, circles and text for one frame, from
  any system or script, headless or not (:mod:`kge.debug.gizmos`);
* :class:`Console`: a registry of named commands run from a line of text, never
  ``eval`` (:mod:`kge.debug.console`), drawn over the game with the backquote key;
* :class:`Inspector`: a running world's entities and fields, read and edited from
  text (:mod:`kge.debug.inspector`), F3 in a window;
* per-system timings live in the schedule (:mod:`kge.timings`), F4 in a window.

:class:`DebugPlugin` (one of the default plugins) installs them.
"""

from kge.debug.console import Console, ConsoleError, ConsoleResult
from kge.debug.gizmos import Gizmos, GizmoText
from kge.debug.inspector import FieldRow, Inspector
from kge.debug.plugin import DebugPlugin

__all__ = [
    "Console",
    "ConsoleError",
    "ConsoleResult",
    "DebugPlugin",
    "FieldRow",
    "GizmoText",
    "Gizmos",
    "Inspector",
]
