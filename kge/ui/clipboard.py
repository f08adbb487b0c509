"""The clipboard text widgets copy to and paste from: the operating system's, through
pyglet's window, or an in-process one when there is no window (headless, tests).

The renderer attaches the App's window (:meth:`Clipboard.attach`) when it draws the
UI; anything with pyglet's ``get_clipboard_text`` / ``set_clipboard_text`` works. A
window that cannot reach the system clipboard (pyglet's headless EGL one raises
``NotImplementedError``) leaves the in-process text in charge:

>>> c = Clipboard()
>>> c.set("hello"); c.get()
'hello'
>>> class Broken:
...     def get_clipboard_text(self): raise NotImplementedError
...     def set_clipboard_text(self, text): raise NotImplementedError
>>> c.attach(Broken()); c.set("still here"); c.get()
'still here'
"""

from __future__ import annotations

from typing import Any, Protocol


class ClipboardOwner(Protocol):
    """pyglet's window clipboard methods."""

    def get_clipboard_text(self) -> str: ...

    def set_clipboard_text(self, text: str) -> None: ...


class Clipboard:
    """The App's clipboard (one for all its scenes; see the module docstring)."""

    def __init__(self) -> None:
        self.text = ""  #: the in-process copy (what headless runs use)
        self.backend: ClipboardOwner | None = None
        self.system = False  #: the last call reached the system clipboard

    def attach(self, backend: Any) -> None:
        """Use ``backend`` (a pyglet window) for the system clipboard."""
        if hasattr(backend, "get_clipboard_text") and hasattr(backend, "set_clipboard_text"):
            self.backend = backend

    def set(self, text: str) -> None:
        self.text = str(text)
        self.system = False
        if self.backend is not None:
            try:
                self.backend.set_clipboard_text(self.text)
                self.system = True
            except Exception:  # no system clipboard here (headless pyglet, a dead display)
                self.backend = None

    def get(self) -> str:
        if self.backend is not None:
            try:
                got = self.backend.get_clipboard_text()
                self.system = True
                if isinstance(got, str):
                    return got
            except Exception:
                self.backend = None
        self.system = False
        return self.text
