"""``Cursor``: how the mouse pointer looks over the game's window (``app.cursor``).

Pure data, so games and tests set it headless; the window applies it when it changes
(pyglet's ``set_mouse_visible``, ``set_exclusive_mouse`` and an image cursor):

* ``visible``: False hides the pointer over the window (a game drawing its own
  crosshair);
* ``locked``: True captures the pointer (first-person aiming, a camera dragged without
  end): hidden, held in the window, and motion keeps arriving as ``Input`` moves;
* ``image``: an asset name or path of a picture drawn as the pointer, with its
  ``hotspot`` (the pixel that points, from the image's top-left corner).

>>> from kge.cursor import Cursor
>>> cursor = Cursor()
>>> cursor.set(image="crosshair.png", hotspot=(8, 8))
>>> cursor.image, cursor.hotspot, cursor.version
('crosshair.png', (8, 8), 1)
>>> cursor.set(hotspot=(-1, 0))
Traceback (most recent call last):
...
kge.errors.ValidationError: Cursor.hotspot must be two whole pixels >= 0, got (-1, 0)
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from kge.errors import ValidationError
from kge.validate import boolean

_UNSET: Any = object()


@dataclass(slots=True)
class Cursor:
    """The pointer's look (see the module docstring); ``version`` counts changes."""

    visible: bool = True
    locked: bool = False
    image: str | None = None
    hotspot: tuple[int, int] = (0, 0)
    version: int = 0

    def set(self, *, visible: bool = _UNSET, locked: bool = _UNSET,
            image: str | None = _UNSET, hotspot: tuple[int, int] = _UNSET) -> None:
        """Change some of the look, all checked before any is changed."""
        new: dict[str, Any] = {}
        if visible is not _UNSET:
            new["visible"] = boolean(visible, "Cursor", "visible")
        if locked is not _UNSET:
            new["locked"] = boolean(locked, "Cursor", "locked")
        if image is not _UNSET:
            if image is not None and (not isinstance(image, str) or not image):
                raise ValidationError(
                    f"Cursor.image must be an image's asset name or path, or None, got {image!r}"
                )
            new["image"] = image
        if hotspot is not _UNSET:
            ok = isinstance(hotspot, tuple | list) and len(hotspot) == 2 and all(
                isinstance(v, int) and not isinstance(v, bool) and v >= 0 for v in hotspot)
            if not ok:
                raise ValidationError(
                    f"Cursor.hotspot must be two whole pixels >= 0, got {hotspot!r}")
            new["hotspot"] = (int(hotspot[0]), int(hotspot[1]))
        for name, value in new.items():
            setattr(self, name, value)
        self.version += 1

    def hide(self) -> None:
        self.set(visible=False)

    def show(self) -> None:
        self.set(visible=True)

    def lock(self) -> None:
        """Capture the pointer (hidden, held in the window)."""
        self.set(locked=True)

    def unlock(self) -> None:
        self.set(locked=False)


def apply(cursor: Cursor, window: Any, load_image: Any) -> None:
    """Make ``window`` (a pyglet window) show ``cursor``; ``load_image(name)`` gives the
    pyglet image of an asset name (the windowed backend calls this when it changed)."""
    window.set_exclusive_mouse(cursor.locked)
    window.set_mouse_visible(cursor.visible and not cursor.locked)
    if cursor.image is None:
        window.set_mouse_cursor(None)
        return
    import pyglet

    image = load_image(cursor.image)
    if cursor.hotspot[0] >= image.width or cursor.hotspot[1] >= image.height:
        raise ValidationError(f"Cursor.hotspot {cursor.hotspot} is outside the "
                              f"{image.width}x{image.height} image {cursor.image!r}")
    # pyglet counts the hot spot from the bottom-left corner
    window.set_mouse_cursor(pyglet.window.ImageMouseCursor(
        image, cursor.hotspot[0], image.height - 1 - cursor.hotspot[1]))
